"""The study's Table IV as a command: lint the young repositories of a mined corpus with the
beliefs of its mature ones, count faults per rule beside the study's figures, and follow each
fault through the file's history to see whether developers fixed it."""
