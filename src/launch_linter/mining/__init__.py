"""Belief mining: a corpus of launch files in SQLite, and the MAY-Implied beliefs it holds.

``ingest`` reads a corpus into the store, ``beliefs`` counts beliefs from the stored
transforms, ``stats`` scores them; ``store`` is the only module that speaks SQL.
"""
