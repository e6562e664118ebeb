"""Reporters: diagnostics and transforms to text."""
