"""Launch-Linter as an ament linter (``ament_launch_linter``)."""
