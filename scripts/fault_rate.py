"""Detection rate of the real-fault benchmark (tests/faults), per class.

Each case folder holds a user's reported fault (``fault/``), its fixed version
(``fixed/``) and ``case.json``: the source URL, the class, the entry file to lint, the
accepted locations (the fault's line, or its other publisher's) and the rule expected. A
case is *found* when a warning or error lands on one of its locations, and the fixed
version is *silent* when linting it gives no warning or error at all. ``expected_miss``
in case.json names why the linter cannot find it yet (the test marks those xfail).

``holdout: true`` marks the hold-out set: faults collected after the rules, chosen before
the linter was run on them (docs/evaluation/fault_rate.md); their rate is reported apart
from the benchmark the rules were built alongside.

    python scripts/fault_rate.py            # per-class tables (benchmark, hold-out) and cases
    python scripts/fault_rate.py --holdout  # the hold-out set only (all batches, then each)
    python scripts/fault_rate.py --json     # one record per case
"""

from __future__ import annotations

import argparse
import json
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from launch_linter import LintOptions, lint_paths

ROOT = Path(__file__).resolve().parent.parent
CASES = ROOT / "tests" / "faults"
LOUD = ("warning", "error")


@dataclass(frozen=True)
class Outcome:
    case: str
    klass: str
    source: str
    found: bool
    rules_at_fault: tuple[str, ...]
    quiet_at_fault: tuple[str, ...]
    """Rules that report at the fault's line at info only."""
    fixed_loud: tuple[str, ...]
    expected_miss: str | None
    holdout: bool
    batch: int
    """The hold-out batch (1 when case.json names none); 0 outside the hold-out set."""

    @property
    def passed(self) -> bool:
        return self.found and not self.fixed_loud


def load_case(folder: Path) -> dict[str, Any]:
    data: dict[str, Any] = json.loads((folder / "case.json").read_text(encoding="utf-8"))
    return data


def case_folders() -> list[Path]:
    return sorted(p for p in CASES.iterdir() if (p / "case.json").is_file())


def _shown(path: str, folder: Path) -> str:
    """The diagnostic's file as case.json names it: relative to the case's fault/ or fixed/
    folder (a location may sit in a subfolder), else its bare name."""
    try:
        return Path(path).resolve().relative_to(folder.resolve()).as_posix()
    except ValueError:
        return Path(path).name


def _lint(folder: Path, entry: str, case: dict[str, Any]) -> list[tuple[str, int, str, str]]:
    # A case that holds packages (a package.xml) is linted as its workspace, the way a user
    # lints a repository: its folder is the package path. Loose files (a trim that wrote
    # package lookups as the file's folder) have no package to find.
    packages = (str(folder),) if next(folder.rglob("package.xml"), None) else ()
    options = LintOptions(package_paths=packages, args=dict(case.get("args", {})),
                          ros_distro=case.get("ros_distro"))
    result = lint_paths([str(folder / entry)], options)
    return [(_shown(d.path, folder), d.line, d.rule, d.severity.value)
            for d in result.diagnostics]


def run_case(folder: Path) -> Outcome:
    case = load_case(folder)
    entry = case["entry"]
    wanted = {(loc["file"], loc["line"]) for loc in case["locations"]}
    fault = _lint(folder / "fault", entry, case)
    at_fault = tuple(sorted({rule for name, line, rule, level in fault
                             if level in LOUD and (name, line) in wanted}))
    quiet = tuple(sorted({rule for name, line, rule, level in fault
                          if level not in LOUD and (name, line) in wanted} - set(at_fault)))
    fixed = _lint(folder / "fixed", case.get("fixed_entry", entry), case)
    fixed_loud = tuple(sorted(f"{name}:{line} {rule}" for name, line, rule, level in fixed
                              if level in LOUD))
    return Outcome(folder.name, case["class"], case["source"], bool(at_fault), at_fault,
                   quiet, fixed_loud, case.get("expected_miss"), bool(case.get("holdout")),
                   int(case.get("batch", 1)) if case.get("holdout") else 0)


def _table(title: str, outcomes: list[Outcome]) -> None:
    by_class: dict[str, list[Outcome]] = {}
    for o in outcomes:
        by_class.setdefault(o.klass, []).append(o)
    print(title)
    print(f"{'class':32} found  fixed-silent  both")
    for klass in sorted(by_class):
        group = by_class[klass]
        print(f"{klass:32} {sum(o.found for o in group):2}/{len(group):<2}  "
              f"{sum(not o.fixed_loud for o in group):2}/{len(group):<2}        "
              f"{sum(o.passed for o in group):2}/{len(group)}")
    total = len(outcomes)
    passed = sum(o.passed for o in outcomes)
    print(f"{'all':32} {sum(o.found for o in outcomes):2}/{total:<2}  "
          f"{sum(not o.fixed_loud for o in outcomes):2}/{total:<2}        {passed:2}/{total}"
          f"  ({100.0 * passed / max(total, 1):.0f}%)")
    quiet = sum(1 for o in outcomes if not o.found and o.quiet_at_fault)
    print(f"not found at warning/error but reported at the fault's line at info: {quiet}")
    print()


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--json", action="store_true", help="one JSON record per case")
    parser.add_argument("--holdout", action="store_true", help="the hold-out set only")
    args = parser.parse_args(argv)
    folders = case_folders()
    if args.holdout:
        folders = [f for f in folders if load_case(f).get("holdout")]
    outcomes = [run_case(folder) for folder in folders]
    if args.json:
        for o in outcomes:
            print(json.dumps({"case": o.case, "class": o.klass, "source": o.source,
                              "holdout": o.holdout, "batch": o.batch, "found": o.found,
                              "rules": list(o.rules_at_fault),
                              "info_rules": list(o.quiet_at_fault),
                              "fixed_loud": list(o.fixed_loud),
                              "expected_miss": o.expected_miss}))
        return 0
    benchmark = [o for o in outcomes if not o.holdout]
    holdout = [o for o in outcomes if o.holdout]
    if benchmark:
        _table("benchmark (built alongside the rules)", benchmark)
    if holdout:
        _table("hold-out (chosen before measuring)", holdout)
        for batch in sorted({o.batch for o in holdout}):
            _table(f"hold-out batch {batch}", [o for o in holdout if o.batch == batch])
    for o in outcomes:
        mark = "ok  " if o.passed else "MISS"
        why = f"  [{o.expected_miss}]" if o.expected_miss and not o.passed else ""
        loud = f"  fixed still reports {', '.join(o.fixed_loud)}" if o.fixed_loud else ""
        if not o.found and o.quiet_at_fault:
            loud += f"  (info: {', '.join(o.quiet_at_fault)})"
        tag = f"H{o.batch}" if o.holdout else "  "
        print(f"{mark}{tag}{o.case:34} {','.join(o.rules_at_fault) or '-':24}{loud}{why}")
        print(f"       {o.source}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
