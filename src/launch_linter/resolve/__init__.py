"""Static resolution of launch-file substitutions, without executing anything."""
