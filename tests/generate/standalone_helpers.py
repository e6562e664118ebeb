"""Helpers for the generator tests: generated files, running them, running the package."""

from __future__ import annotations

import ast
import contextlib
import functools
import io
import json
import os
import subprocess
import sys
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from launch_linter.cli import main as cli_main
from launch_linter.engine import LintOptions, discover, lint_paths
from launch_linter.model.beliefs import BELIEF_FORMAT
from launch_linter.resolve.safe_eval import subscript_index

REPO = Path(__file__).resolve().parents[2]
FIXTURES = Path(__file__).resolve().parent / "fixtures"

HOSTILE = (
    "quote'single",
    'quote"double',
    'triple"""double',
    "triple'''single",
    "back\\slash\\",
    "jinja{{ GENERATED }}",
    "jinja{% raw %}",
    "jinja{# comment",
    "new\nline = 1",
    "carriage\rreturn",
    "tab\tand\x0bvtab\x0cff",
    "unicode_é_中文_🙂",
    "bidi\u202eoverride",
    "line\u2028separator",
    "nul\x00byte",
    "'); __import__('os').system('touch PWNED'); ('",
    '"""); import os; os.system("touch PWNED"); ("""',
    "# not a comment\n__import__('os').system('touch PWNED')",
    "\\",
)
"""Names that must neither break nor inject into a generated file."""

BELIEFS: dict[str, Any] = {
    "format": BELIEF_FORMAT,
    "p0": 0.9,
    "mature_commits": 30,
    "source": {"corpus": "tests", "files": 0, "transforms": 0, "created": "never"},
    "beliefs": [
        {"class": "sig_implication", "if": ["map", "odom"], "then": ["odom", "base_link"],
         "n": 40, "e": 39, "z": 2.1},
        {"class": "sig_implication", "if": ["base_link", "laser"], "then": ["base_link", "imu"],
         "n": 12, "e": 11, "z": 0.4},
        {"class": "name_implication", "if": "base_to_laser", "then": "base_to_camera",
         "n": 20, "e": 19, "z": 1.5},
        {"class": "sig_null_disp", "if": ["world", "map"], "n": 30, "e": 30, "z": 3.16},
        {"class": "name_null_disp", "if": "base_to_laser", "n": 9, "e": 9, "z": 1.05},
        {"class": "sig_null_rot", "if": ["map", "odom"], "n": 50, "e": 49, "z": 2.35},
        {"class": "name_null_rot", "if": "map_to_odom", "n": 25, "e": 24, "z": 1.0},
        *(
            {"class": cls, "if": name, "then": name + "_partner", "n": 10, "e": 10, "z": 1.05}
            for name in HOSTILE
            for cls in ("name_implication",)
        ),
        *(
            {"class": "sig_null_rot", "if": [name, "child"], "n": 10, "e": 10, "z": 1.05}
            for name in HOSTILE
        ),
    ],
}
"""Beliefs for the fixtures: each of tests/generate/fixtures/implied.launch's transforms
breaks one, one is below the usual threshold, and the hostile names are antecedents."""


def _version_of(python: Path) -> tuple[int, int] | None:
    try:
        done = subprocess.run(
            [str(python), "-I", "-c", "import sys; print(*sys.version_info[:2])"],
            capture_output=True, text=True, timeout=30, check=False,
        )
    except OSError:
        return None
    words = done.stdout.split()
    return (int(words[0]), int(words[1])) if done.returncode == 0 and len(words) == 2 else None


NEWEST_MINOR = 13
"""The newest Python 3 the tests look for."""


@functools.lru_cache(maxsize=None)
def other_pythons() -> tuple[str, ...]:
    """Working interpreters of Python 3.8 to 3.13 other than this one (pyenv's, then those
    on PATH), oldest first."""
    found: dict[tuple[int, int], str] = {}
    versions = Path(os.environ.get("PYENV_ROOT", Path.home() / ".pyenv")) / "versions"
    folders = [p for p in os.environ.get("PATH", "").split(os.pathsep) if p]
    for minor in range(8, NEWEST_MINOR + 1):
        if minor == sys.version_info[1]:
            continue
        name = f"python3.{minor}"
        paths = sorted(versions.glob(f"3.{minor}.*/bin/{name}")) if versions.is_dir() else []
        paths.extend(Path(d) / name for d in folders)
        for path in paths:
            if path.is_file() and _version_of(path) == (3, minor):
                found[(3, minor)] = str(path)
                break
    return tuple(found[k] for k in sorted(found))


def oldest_python() -> str | None:
    """A Python 3.8 interpreter, if one can be found."""
    pythons = other_pythons()
    return pythons[0] if pythons and _version_of(Path(pythons[0])) == (3, 8) else None


@dataclass(frozen=True)
class Generated:
    path: Path
    text: str
    beliefs: str
    min_z: float

    @property
    def tree(self) -> ast.Module:
        return ast.parse(self.text)

    def assigned(self, name: str) -> Any:
        """The literal value of a top-level ``name = ...`` in the generated file."""
        for node in self.tree.body:
            if (
                isinstance(node, ast.Assign)
                and isinstance(node.targets[0], ast.Name)
                and node.targets[0].id == name
            ):
                return ast.literal_eval(node.value)
        raise KeyError(name)

    def modules(self) -> dict[str, str]:
        """``MODULES[name] = '''...'''`` assignments: name to text (leading newline kept)."""
        out: dict[str, str] = {}
        for node in self.tree.body:
            if (
                isinstance(node, ast.Assign)
                and isinstance(node.targets[0], ast.Subscript)
                and isinstance(node.targets[0].value, ast.Name)
                and node.targets[0].value.id == "MODULES"
            ):
                key = ast.literal_eval(subscript_index(node.targets[0]))
                out[key] = ast.literal_eval(node.value)
        return out


def run_standalone(
    script: Path,
    args: Sequence[str],
    cwd: Path = REPO,
    python: str = sys.executable,
    flags: Sequence[str] = ("-I", "-S"),
) -> subprocess.CompletedProcess[str]:
    """Run a generated linter as a user would; ``-I -S`` leaves only the standard library
    importable (no site-packages, so not the installed package either)."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYTHON")}
    return subprocess.run(
        [python, *flags, str(script), *args],
        cwd=cwd, env=env, capture_output=True, text=True, encoding="utf-8", timeout=300,
        check=False,
    )


@contextlib.contextmanager
def _chdir(path: Path) -> Iterator[None]:
    before = os.getcwd()
    os.chdir(path)
    try:
        yield
    finally:
        os.chdir(before)


def run_check(args: Sequence[str], cwd: Path = REPO) -> tuple[int, str, str]:
    """``launch-linter check ARGS`` in this process: (exit status, stdout, stderr)."""
    out, err = io.StringIO(), io.StringIO()
    with _chdir(cwd), contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        status = cli_main(["check", *args])
    return status, out.getvalue(), err.getvalue()


def json_pair(
    generated: Generated,
    args: Sequence[str],
    cwd: Path = REPO,
    python: str = sys.executable,
    flags: Sequence[str] = ("-I", "-S"),
) -> tuple[dict[str, Any], dict[str, Any]]:
    """The JSON documents of ``launch-linter check`` and of the generated linter."""
    full = ["--format", "json", *args]
    status, out, err = run_check(["--beliefs", generated.beliefs, "--min-z",
                                  repr(generated.min_z), *full], cwd)
    assert status in (0, 1), err
    done = run_standalone(generated.path, full, cwd, python, flags)
    assert done.returncode == status, done.stderr
    return json.loads(out), json.loads(done.stdout)


def _names_yaml(path: str) -> bool:
    """Whether a launch file names a YAML parameter file (``<rosparam file=>``,
    ``parameters=[...yaml]``) or a xacro file reads one (``load_yaml(name)``, the name
    perhaps from a property): its tree then reads YAML that ``tree.files`` does not list."""
    try:
        text = (REPO / path).read_text(encoding="utf-8", errors="replace")
    except OSError:
        return False
    return ".yaml" in text or ".yml" in text or "load_yaml(" in text


def launch_fixtures(yaml: bool = True) -> list[str]:
    """Every launch file under tests/ and examples/ as the linter discovers them, relative
    to the repository; with ``yaml=False`` only those whose tree includes no YAML file."""
    found = discover([str(REPO / "tests"), str(REPO / "examples")])
    paths = sorted(str(Path(f.path).relative_to(REPO)) for f in found)
    if yaml:
        return paths
    with _chdir(REPO):
        result = lint_paths(paths, LintOptions(select=frozenset({"parse_error"})))
    with_yaml = {
        tree.root for tree in result.trees
        if any(f.endswith((".yaml", ".yml")) or _names_yaml(f) for f in tree.files)
        # A description's xacro files are not in tree.files: those its joints are written in.
        or any(_names_yaml(joint.path) for joint in tree.joints)
    }
    return [p for p in paths if p not in with_yaml]
