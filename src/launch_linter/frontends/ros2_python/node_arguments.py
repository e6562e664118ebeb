"""What a launch_ros node action is given, read from its keywords: its parameters (dicts
flattened, parameter files), its remappings, and the Foxy-era keywords launch_ros no longer
accepts. A layer of the interpreter between the calls it models and the launch API."""

from __future__ import annotations

import ast

from launch_linter.frontends.ros2_actions import Params, ParamsFile, ParamsUnknown, Where
from launch_linter.frontends.ros2_python.calls import Calls
from launch_linter.frontends.ros2_python.values import (
    LEGACY_KEYWORDS,
    LazyStr,
    LinedDict,
    ParamFileVal,
    SubsVal,
    Unknown,
)
from launch_linter.resolve.ros2_substitution import Subs, literal


class NodeArguments(Calls):
    """The node actions' keywords, read for the launch API's handlers."""

    def legacy_keywords(self, name: str, kwargs: dict[str, object], node: ast.Call) -> None:
        """Kept as a note: a Foxy-era keyword is evidence of a Foxy target and an error on
        later distributions (the rule ros2_removed_keyword decides with the target
        distribution). Noted where the first one is written: the word that must change."""
        replaced = LEGACY_KEYWORDS.get(name, {})
        legacy = [k for k in replaced if k in kwargs]
        if not legacy or (self.branches and "ROS_DISTRO" not in self.environ):
            # Under a Python condition the linter cannot decide (often the distribution
            # itself: realsense-ros's rs_launch.py has a Dashing/Eloquent branch), the
            # keywords are no evidence of the file's target; with the distribution given,
            # the rule judges them.
            return
        written = [k for k in node.keywords if k.arg in legacy]
        at: ast.AST = node
        if written and not self.call_sites:
            first = min(written, key=lambda k: (k.value.lineno, k.value.col_offset))
            # ast.keyword has a position from Python 3.9 on; its value's on 3.8.
            at = first if hasattr(first, "lineno") else first.value
        self.problem("ros2_removed_keyword", at, f"{name} keyword(s) " + ", ".join(
            f"{k}= (now {replaced[k]}=)" for k in legacy))

    def remappings(self, value: object, node: ast.Call) -> tuple[tuple[Subs, Subs], ...] | None:
        """``remappings=[(from, to), ...]`` as written; none given is no remapping; None
        when it is not a list of pairs."""
        if value is None:
            return ()
        if not isinstance(value, (list, tuple)):
            return None
        pairs: list[tuple[Subs, Subs]] = []
        for item in value:
            if not isinstance(item, (list, tuple)) or len(item) != 2:
                return None
            pairs.append((self.subs(item[0], node, "remapping"),
                          self.subs(item[1], node, "remapping")))
        return tuple(pairs)

    def parameters(self, value: object, node: ast.Call
                   ) -> tuple[Params | ParamsFile | ParamsUnknown, ...]:
        if value is None:
            return ()
        if not isinstance(value, (list, tuple)):
            return (ParamsUnknown(f"line {node.lineno}: parameters are not a list"),)
        out: list[Params | ParamsFile | ParamsUnknown] = []
        for entry in value:
            if isinstance(entry, dict):
                items: list[tuple[str, Subs]] = []
                places: list[Where | None] = []
                if not self.flatten(entry, "", items, node, places):
                    out.append(ParamsUnknown(f"line {node.lineno}: a parameter name or value "
                                             f"is unknown"))
                out.append(Params(tuple(items), tuple(places)))
            elif isinstance(entry, (str, SubsVal, LazyStr)):
                out.append(ParamsFile(self.subs(entry, node, "parameter file")))
            elif isinstance(entry, ParamFileVal):
                out.append(ParamsFile(self.subs(entry.path, node, "parameter file"),
                                      entry.substituted))
            else:
                reason = entry.describe() if isinstance(entry, Unknown) else (
                    f"line {node.lineno}: parameters from a file")
                out.append(ParamsUnknown(reason))
        return tuple(out)

    def flatten(self, entry: dict[object, object], prefix: str,
                items: list[tuple[str, Subs]], node: ast.Call,
                places: list[Where | None], place: Where | None = None) -> bool:
        """``entry``'s parameters into ``items`` (nested names joined with ``.``), and
        where each key is written into ``places`` (a nested key without a line of its own:
        its parent's)."""
        complete = True
        for key, value in entry.items():
            if not isinstance(key, str):
                complete = False
                continue
            here = (entry.places.get(key, place) if isinstance(entry, LinedDict) else place)
            if isinstance(value, dict):
                complete = self.flatten(value, f"{prefix}{key}.", items, node, places,
                                        here) and complete
                continue
            count = len(items)
            if isinstance(value, bool):
                items.append((prefix + key, literal(str(value).lower())))
            elif isinstance(value, (int, float)):
                items.append((prefix + key, literal(repr(value))))
            elif isinstance(value, (str, SubsVal, LazyStr, Unknown)):
                items.append((prefix + key, self.subs(value, node, "parameter")))
            if len(items) > count:
                places.append(here)
        return complete
