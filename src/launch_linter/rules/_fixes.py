"""Fixes that rules offer, as edits of a transform's argument words (see ``Fix``).

A rule knows the words a transform was written with (``StaticTransform.tokens``), not
where they sit in the file; :mod:`launch_linter.fix` finds them there and refuses to fix
when the attribute is not plain text (a substitution, an entity) or reads differently.
"""

from __future__ import annotations

from collections.abc import Sequence

from launch_linter.model.diagnostic import Applicability, Fix, TokenEdit
from launch_linter.model.transform import StaticTransform

ROS2_DISTROS = (
    "ardent", "bouncy", "crystal", "dashing", "eloquent", "foxy", "galactic", "humble",
    "iron", "jazzy", "kilted", "lyrical", "rolling",
)  # fmt: skip
"""ROS 2 distributions, oldest first (rolling is always the newest)."""

FLAGS_FROM = "humble"
"""The oldest distribution the positional-to-flags rewrite is offered as safe for."""

YPR_FLAGS = ("--x", "--y", "--z", "--yaw", "--pitch", "--roll")
QUATERNION_FLAGS = ("--x", "--y", "--z", "--qx", "--qy", "--qz", "--qw")
PARENT_FLAGS = ("--frame-id",)
CHILD_FLAGS = ("--child-frame-id",)


def distro_at_least(distro: str | None, oldest: str) -> bool:
    """Whether the ROS 2 distribution ``distro`` is ``oldest`` or newer (unknown: no)."""
    if distro is None or distro not in ROS2_DISTROS:
        return False
    return ROS2_DISTROS.index(distro) >= ROS2_DISTROS.index(oldest)


def fixable(transform: StaticTransform) -> bool:
    """Only transforms whose words are all known and plain can be fixed."""
    return bool(transform.tokens) and not any("$(" in t for t in transform.tokens)


def _positional_indices(tokens: Sequence[str]) -> tuple[int, ...] | None:
    """Indices of the words that are not ROS remappings; None when flags are used."""
    if any(t.startswith("--") for t in tokens):
        return None
    return tuple(i for i, t in enumerate(tokens) if ":=" not in t)


def value_index(transform: StaticTransform, position: int) -> int | None:
    """The index in ``tokens`` of the ``position``-th number of the transform (0-2 the
    translation, then yaw/pitch/roll or qx/qy/qz/qw), positional or after its flag."""
    tokens = transform.tokens
    positional = _positional_indices(tokens)
    if positional is not None:
        return positional[position] if position < len(positional) else None
    rotation = transform.rotation
    flags = YPR_FLAGS if rotation is None or rotation.kind.value == "ypr" else QUATERNION_FLAGS
    if position >= len(flags):
        return None
    return _after_flag(tokens, (flags[position],))


def _after_flag(tokens: Sequence[str], flags: Sequence[str]) -> int | None:
    found = [i + 1 for i, t in enumerate(tokens[:-1]) if t in flags]
    return found[0] if len(found) == 1 else None


def frame_index(transform: StaticTransform, role: str) -> int | None:
    """The index in ``tokens`` of the parent or child frame id."""
    tokens = transform.tokens
    positional = _positional_indices(tokens)
    if positional is None:
        return _after_flag(tokens, PARENT_FLAGS if role == "parent" else CHILD_FLAGS)
    rotation = transform.rotation
    if rotation is None:
        return None
    first = 6 if rotation.kind.value == "ypr" else 7
    position = first if role == "parent" else first + 1
    return positional[position] if position < len(positional) else None


def replace_words(
    transform: StaticTransform,
    applicability: Applicability,
    message: str,
    replacements: Sequence[tuple[int, int, str]],
    safe_from_distro: str | None = None,
) -> Fix:
    """A fix replacing ``tokens[start:end]`` by text, for each (start, end, text)."""
    return Fix(
        applicability,
        message,
        tokens=tuple(transform.tokens),
        token_edits=tuple(TokenEdit(a, b, text) for a, b, text in replacements),
        safe_from_distro=safe_from_distro,
    )


def number_text(value: float) -> str:
    """A number as short as it can be written without losing float precision beyond 9
    significant digits (what a launch file author would write)."""
    text = format(value, ".9g")
    return "0" if text in ("-0", "0") else text
