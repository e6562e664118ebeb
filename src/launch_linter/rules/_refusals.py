"""The findings of the rules that say ``ros2 launch`` or roslaunch refuses a file."""

from __future__ import annotations

from collections.abc import Iterator

from launch_linter.model.diagnostic import Severity
from launch_linter.model.record import replace
from launch_linter.rules._api import Finding, RuleContext, frontend_findings

NEVER_LAUNCHED = "file_never_launched"
"""The rule whose problem marks a root file that nothing runs (``file_never_launched``)."""


def refusal_findings(context: RuleContext, rule_id: str) -> Iterator[Finding]:
    """The front-end's problems of ``rule_id``; at info in a file that nothing runs (a
    ``file_never_launched`` problem there says why, once)."""
    never = {p.path for p in context.tree.problems if p.rule == NEVER_LAUNCHED}
    for finding in frontend_findings(context, rule_id):
        yield replace(finding, severity=Severity.INFO) if finding.path in never else finding
