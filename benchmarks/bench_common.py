"""What the benchmark scripts share: the floors (read + expat, read + ``ast.parse``), the
``median [lowest..highest]`` figure, the machine's load, and roslaunch's own loader timed
per file through ``scripts/roslaunch_oracle_driver.py``.

The scripts run as ``python benchmarks/<script>.py``, so this folder is on their path."""

from __future__ import annotations

import ast
import json
import os
import statistics
import subprocess
import time
import typing
from collections.abc import Sequence
from xml.parsers import expat

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DRIVER = os.path.join(ROOT, "scripts", "roslaunch_oracle_driver.py")
SYSTEM_PYTHON = "/usr/bin/python3"

# typing's spellings: the alias is evaluated at run time (Python 3.8).
Pass = typing.Callable[[typing.Sequence[str]], None]
"""One pass over files (a floor, a front-end, a whole check)."""


def spread(values: Sequence[float], scale: float = 1.0, digits: int = 0) -> str:
    """``median [lowest..highest]`` of ``values`` times ``scale``."""
    med = statistics.median(values) * scale
    low, high = min(values) * scale, max(values) * scale
    return f"{med:.{digits}f} [{low:.{digits}f}..{high:.{digits}f}]"


def load_average() -> str:
    try:
        with open("/proc/loadavg", encoding="ascii") as handle:
            return "load average " + " ".join(handle.read().split()[:3])
    except OSError:
        return "load average unknown"


def read(path: str) -> bytes:
    with open(path, "rb") as handle:
        return handle.read()


def expat_pass(paths: Sequence[str]) -> None:
    for path in paths:
        parser = expat.ParserCreate()
        try:  # noqa: SIM105 - contextlib.suppress would cost more than the floor's parse
            parser.Parse(read(path), True)
        except expat.ExpatError:
            pass


def ast_pass(paths: Sequence[str]) -> None:
    for path in paths:
        try:  # noqa: SIM105
            ast.parse(read(path))
        except (SyntaxError, ValueError):
            pass


def timed(function: Pass, paths: Sequence[str]) -> tuple[float, float]:
    """CPU and wall-clock seconds per file of one pass."""
    wall, cpu = time.perf_counter(), time.process_time()
    function(paths)
    count = len(paths)
    return (time.process_time() - cpu) / count, (time.perf_counter() - wall) / count


def roslaunch_per_file(paths: Sequence[str],
                       runs: int) -> tuple[list[float], list[float]] | None:
    """CPU and wall seconds per file of each run of roslaunch's ``XmlLoader`` over
    ``paths``; None when the system Python cannot import roslaunch."""
    if not os.path.exists(SYSTEM_PYTHON):
        return None
    probe = subprocess.run([SYSTEM_PYTHON, "-c", "import roslaunch"], capture_output=True,
                           check=False)
    if probe.returncode != 0:
        return None
    request = {"package_path": [], "repeat": runs,
               "files": [{"path": os.path.abspath(p)} for p in paths]}
    done = subprocess.run([SYSTEM_PYTHON, DRIVER], input=json.dumps(request), text=True,
                          capture_output=True, env={}, check=True, timeout=3600)
    result = json.loads(done.stdout.splitlines()[-1])
    count = len(paths)
    return ([float(r) / count for r in result["cpu_runs"]],
            [float(r) / count for r in result["runs"]])
