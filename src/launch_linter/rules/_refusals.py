"""The findings of the rules that say ``ros2 launch`` or roslaunch refuses a file."""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Severity
from launch_linter.model.record import replace
from launch_linter.rules._api import Finding, RuleContext, finding_of

NEVER_LAUNCHED = "file_never_launched"
"""The rule whose problem marks a root file that nothing runs (``file_never_launched``)."""


def refusal_findings(context: RuleContext, rule_id: str) -> Iterator[Finding]:
    """The front-end's problems of ``rule_id``; at info in a file that nothing runs (a
    ``file_never_launched`` problem there says why, once)."""
    problems = context.tree.problems
    never = {p.path for p in problems if p.rule == NEVER_LAUNCHED}
    for problem in problems:
        if problem.rule != rule_id:
            continue
        finding = finding_of(problem)
        yield replace(finding, severity=Severity.INFO) if problem.path in never else finding
