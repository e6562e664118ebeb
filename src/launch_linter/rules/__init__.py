"""The rule registry: every rule module, in the order of the rules table."""

from __future__ import annotations

from launch_linter.rules import parse_error, roslaunch_error, unresolved, unused_suppression
from launch_linter.rules._api import Rule, RuleContext, rule_from_module

RULE_MODULES = (
    parse_error,
    roslaunch_error,
    unresolved,
    unused_suppression,
)

RULES: tuple[Rule, ...] = tuple(rule_from_module(m) for m in RULE_MODULES)
RULES_BY_ID: dict[str, Rule] = {r.id: r for r in RULES}

__all__ = ["RULES", "RULES_BY_ID", "Rule", "RuleContext"]
