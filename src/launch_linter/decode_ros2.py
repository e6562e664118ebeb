"""Decode ROS 2 ``static_transform_publisher`` arguments as the program reads them.

The ROS 2 program (``tf2_ros``'s ``static_transform_broadcaster_program``) first drops
the ``--ros-args ... [--]`` section, then reads the flags ``--x --y --z --qx --qy --qz
--qw --roll --pitch --yaw --frame-id --child-frame-id`` (each takes the next item as its
value, whatever it looks like) and ``-h``/``--help``. Whatever is not a flag is an
old-style positional argument: exactly 8 (``x y z yaw pitch roll parent child``) or 9
(``x y z qx qy qz qw parent child``) are accepted with a deprecation warning (recent
distributions removed them), any other count stops it with "Extra unparsed arguments on
command-line". Flags and positionals together, roll/pitch/yaw together with a
quaternion, and an empty frame id stop it too. Numbers go through ``std::stod``: junk is
an error, trailing text after a number is silently ignored, and an out-of-range number
throws. A quaternion starts at (0, 0, 0, 1) and each flag overwrites one component.

As in :mod:`launch_linter.decode`, the result is the developer's intended reading, with
the program's objections kept apart: ``arity_issue`` for counts and shapes (reported by
``bad_arity``), ``number_issues`` for numbers, and ``arg_issues`` for the ROS 2 specific
mistakes, each reported by its own rule. ``NumberIssue.index`` is the slot in the
``x y z`` + rotation layout of the form, whichever way the value was written.

The component ``tf2_ros::StaticTransformBroadcasterNode`` is decoded from its parameters
``translation.{x,y,z}``, ``rotation.{x,y,z,w}``, ``frame_id`` and ``child_frame_id``,
whose defaults are 0, (0, 0, 0, 1), ``/frame`` and ``/child``.
"""

from __future__ import annotations

import difflib
import math
import re
import sys
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

from launch_linter.model.transform import (
    DECODED_FIELDS,
    ArgForm,
    ArgIssue,
    ArgIssueKind,
    Field,
    NumberIssue,
    Rotation,
    RotationKind,
)

TRANSLATION_FLAGS = ("--x", "--y", "--z")
QUATERNION_FLAGS = ("--qx", "--qy", "--qz", "--qw")
RPY_FLAGS = ("--roll", "--pitch", "--yaw")
FRAME_FLAGS = ("--frame-id", "--child-frame-id")
VALUE_FLAGS = TRANSLATION_FLAGS + QUATERNION_FLAGS + RPY_FLAGS + FRAME_FLAGS
HELP_FLAGS = ("-h", "--help")
TF2_TOLERANCE = 0.01
"""tf2 rejects a quaternion whose squared norm is this far from 1."""

COMPONENT_PARAMS = (
    "translation.x", "translation.y", "translation.z",
    "rotation.x", "rotation.y", "rotation.z", "rotation.w",
    "frame_id", "child_frame_id",
)
COMPONENT_DEFAULT_FRAMES = ("/frame", "/child")

# strtod's grammar: decimal or hexadecimal floats, inf/infinity, nan with an optional tag.
_STRTOD = re.compile(
    r"""[+-]?(
        0[xX](?P<hex>([0-9a-fA-F]+\.?[0-9a-fA-F]*|\.[0-9a-fA-F]+)([pP][+-]?\d+)?)
      | (?P<dec>(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?)
      | (?P<inf>inf(inity)?) | (?P<nan>nan(\([0-9A-Za-z_]*\))?)
    )""",
    # ASCII: ``\d`` would take other scripts' digits ('٣'), which the C library refuses.
    re.VERBOSE | re.IGNORECASE | re.ASCII,
)

_EXPONENT = re.compile(r"[eEpP]")
_SHORT_DECIMAL = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)")


def stod(text: str) -> tuple[float | None, str]:
    """``std::stod``: the value (None when it throws) and ``ok``, ``partial`` (trailing
    text ignored), ``invalid`` (no number: invalid_argument) or ``range`` (out_of_range)."""
    if len(text) <= 20 and _SHORT_DECIMAL.fullmatch(text):
        # Most arguments: a short plain decimal, never out of range, read as Python does.
        return float(text), "ok"
    stripped = text.lstrip(" \t\n\v\f\r")
    match = _STRTOD.match(stripped)
    if match is None:
        return None, "invalid"
    number = match.group(0)
    sign = -1.0 if number.startswith("-") else 1.0
    try:
        if match.group("hex") is not None:
            value = sign * float.fromhex(match.group("hex"))
        elif match.group("nan") is not None:
            value = math.nan
        else:
            value = float(number)
    except OverflowError:
        return None, "range"
    if match.group("dec") is not None or match.group("hex") is not None:
        # The hex group excludes its 0x prefix, so only digits and the point remain.
        mantissa = _EXPONENT.split(match.group("dec") or match.group("hex"), 1)[0]
        nonzero = any(c not in "0." for c in mantissa)
        tiny = value != 0.0 and abs(value) < sys.float_info.min
        if math.isinf(value) or (nonzero and value == 0.0) or tiny:
            return None, "range"
    return value, "ok" if match.end() == len(stripped) else "partial"


@dataclass(frozen=True)
class Ros2Decoded:
    form: ArgForm
    """``YPR``, ``QUATERNION`` or ``INVALID`` (nothing could be decoded)."""
    parent: str | None
    child: str | None
    translation: tuple[float, float, float] | None
    rotation: Rotation | None
    arity_issue: str | None
    number_issues: tuple[NumberIssue, ...]
    arg_issues: tuple[ArgIssue, ...]
    sources: Mapping[Field, tuple[int, ...]] = field(default_factory=dict)
    """For ``parent``, ``child``, ``translation`` and ``rotation``: the input items read."""
    unresolved: frozenset[Field] = frozenset()
    """Those of the four fields read from an unresolved input item."""

    def __init__(self, form: ArgForm, parent: str | None, child: str | None,
                 translation: tuple[float, float, float] | None, rotation: Rotation | None,
                 arity_issue: str | None, number_issues: tuple[NumberIssue, ...],
                 arg_issues: tuple[ArgIssue, ...],
                 sources: Mapping[Field, tuple[int, ...]] | None = None,
                 unresolved: frozenset[Field] = frozenset()) -> None:
        # One per static transform publisher, ten fields: put in the instance's dict,
        # a fifth of the cost of the frozen dataclass's ``object.__setattr__`` per field
        # (assignment is still refused). ``sources`` defaults to a new empty dict.
        fields = self.__dict__
        fields["form"] = form
        fields["parent"] = parent
        fields["child"] = child
        fields["translation"] = translation
        fields["rotation"] = rotation
        fields["arity_issue"] = arity_issue
        fields["number_issues"] = number_issues
        fields["arg_issues"] = arg_issues
        fields["sources"] = {} if sources is None else sources
        fields["unresolved"] = unresolved


def _flag_like(word: str) -> bool:
    return word.startswith("-") and len(word) > 1 and stod(word)[1] == "invalid"


def _suggest(word: str, following: str | None) -> ArgIssue:
    """An unknown flag, with the flag probably meant: ``split`` when it is ``-- NAME``."""
    if word == "--" and following is not None and "--" + following in VALUE_FLAGS:
        return ArgIssue(ArgIssueKind.UNKNOWN_FLAG, (word,), ("--" + following,), split=True)
    candidates = difflib.get_close_matches(
        word.replace("_", "-").lower(), VALUE_FLAGS + HELP_FLAGS, n=1, cutoff=0.6
    )
    return ArgIssue(ArgIssueKind.UNKNOWN_FLAG, (word,), tuple(candidates[:1]))


class _Reader:
    """One decoding of an argv list; ``items`` are indexed as the caller gave them."""

    def __init__(self, items: Sequence[str], unresolved: frozenset[int]) -> None:
        self.items = items
        self.unresolved = unresolved
        self.numbers: list[NumberIssue] = []
        self.issues: list[ArgIssue] = []
        self.arity: str | None = None

    def resolved(self, index: int) -> bool:
        return index not in self.unresolved

    def number(self, index: int, word: str, slot: int) -> float:
        """``word`` (read from item ``index``) as the program reads it into ``slot``."""
        if not self.resolved(index):
            return 0.0
        value, status = stod(word)
        if status in ("invalid", "range"):
            self.numbers.append(NumberIssue(slot, word, None))
            return 0.0
        assert value is not None
        if status == "partial" or not math.isfinite(value):
            self.numbers.append(NumberIssue(slot, word, value))
        return value


def _strip_ros_args(items: Sequence[str], unresolved: frozenset[int]) -> list[int]:
    kept: list[int] = []
    inside = False
    for index, item in enumerate(items):
        known = index not in unresolved
        if inside:
            inside = not (known and item == "--")
            continue
        if known and item == "--ros-args":
            inside = True
            continue
        kept.append(index)
    return kept


def _expand(items: Sequence[str], unresolved: frozenset[int], kept: list[int]
            ) -> tuple[list[tuple[int, str]], list[str]]:
    """argv as (item index, word); items holding several words are split for the
    intended reading and returned apart, because the program sees each as one word."""
    words: list[tuple[int, str]] = []
    joined: list[str] = []
    flag_value_next = False
    for index in kept:
        item = items[index]
        if flag_value_next or index in unresolved or len(item.split()) < 2:
            words.append((index, item))
            flag_value_next = index not in unresolved and item in VALUE_FLAGS
            continue
        joined.append(item)
        words.extend((index, word) for word in item.split())
        flag_value_next = False
    return words, joined


def decode_ros2(items: Sequence[str], unresolved: frozenset[int] = frozenset()) -> Ros2Decoded:
    """Decode a ROS 2 argv list (without the program name); ``unresolved`` holds the
    indices of items whose value is unknown (each stays one item, whatever its value)."""
    reader = _Reader(items, unresolved)
    words, joined = _expand(items, unresolved, _strip_ros_args(items, unresolved))
    flags: dict[str, tuple[int, str]] = {}
    bare: list[tuple[int, str]] = []
    help_asked = False
    position = 0
    while position < len(words):
        index, word = words[position]
        known = reader.resolved(index)
        if known and word in VALUE_FLAGS:
            if position == len(words) - 1:
                reader.arity = (
                    f"'{word}' is the last argument and has no value: the program stops "
                    f"with 'Not enough arguments for {word}'"
                )
                break
            if word in flags:
                _overwritten(reader, word, *flags[word])
            flags[word] = words[position + 1]
            position += 2
            continue
        if known and word in HELP_FLAGS:
            help_asked = True
        else:
            bare.append((index, word))
        position += 1

    for item in joined:
        reader.issues.append(ArgIssue(ArgIssueKind.SINGLE_STRING, (item,)))
    if help_asked:
        reader.arity = (
            "'--help' makes the program print its usage and exit: no transform is published"
        )
        return _result(reader, ArgForm.INVALID, None, None, None, None, {})

    positional = _drop_unknown_flags(reader, bare)
    if len(positional) in (8, 9):
        return _positional(reader, positional, flags)
    if positional and not flags:
        _wrong_count(reader, positional)
        if len(positional) == 10:
            return _layout(reader, positional, 4)
        return _result(reader, ArgForm.INVALID, None, None, None, None, {})
    if positional:
        extra = " ".join(repr(word) for _, word in positional)
        reader.arity = (
            f"extra argument(s) {extra} next to the flags: the program stops with "
            f"'Extra unparsed arguments on command-line'"
        )
    return _flags(reader, flags)


_FLAG_SLOTS = {
    "--x": 0, "--y": 1, "--z": 2, "--yaw": 3, "--pitch": 4, "--roll": 5,
    "--qx": 3, "--qy": 4, "--qz": 5, "--qw": 6,
}


def _overwritten(reader: _Reader, flag: str, index: int, word: str) -> None:
    """A flag given again: the program still parses the earlier value when it meets it
    (``std::stod`` in ``DoubleOption::visit``), so a bad one stops it even though a later
    occurrence would be good. Text after a number is ignored, and the value is replaced."""
    slot = _FLAG_SLOTS.get(flag)
    if slot is None or not reader.resolved(index):
        return
    if stod(word)[1] in ("invalid", "range"):
        reader.numbers.append(NumberIssue(slot, word, None))


def _drop_unknown_flags(reader: _Reader, bare: list[tuple[int, str]]) -> list[tuple[int, str]]:
    """Report unknown flags; what is left (minus each one's value) is positional."""
    positional: list[tuple[int, str]] = []
    skip = 0
    for position, (index, word) in enumerate(bare):
        if skip:
            skip -= 1
            continue
        if not reader.resolved(index) or not _flag_like(word):
            positional.append((index, word))
            continue
        following = bare[position + 1][1] if position + 1 < len(bare) else None
        reader.issues.append(_suggest(word, following))
        if word == "--" and following is not None and "--" + following in VALUE_FLAGS:
            skip = 2  # '-- yaw 90': the flag's name and its value
        elif following is not None and not _flag_like(following):
            skip = 1
    return positional


def _wrong_count(reader: _Reader, positional: list[tuple[int, str]]) -> None:
    count = len(positional)
    if count == 10:
        reader.arity = (
            "ROS 2 static_transform_publisher takes no period: with 10 arguments it stops "
            "with 'Extra unparsed arguments on command-line'"
        )
        return
    note = ""
    if any(not reader.resolved(index) for index, _ in positional):
        note = " (a substitution is one argument, even when its value holds spaces)"
    reader.arity = (
        f"ROS 2 static_transform_publisher takes flags (--x X ... --frame-id PARENT "
        f"--child-frame-id CHILD) or 8 or 9 old-style arguments, not {count}{note}: it "
        f"stops with 'Extra unparsed arguments on command-line'"
    )


def _positional(reader: _Reader, positional: list[tuple[int, str]],
                flags: dict[str, tuple[int, str]]) -> Ros2Decoded:
    words = [word for _, word in positional]
    resolved = [reader.resolved(index) for index, _ in positional]
    rotation_size = 3 if len(positional) == 8 else 4
    if rotation_size == 4 and resolved[6] and resolved[8] and (
        stod(words[6])[1] == "invalid" and stod(words[8])[1] == "ok"
    ):
        reader.arity = (
            f"ROS 2 static_transform_publisher takes no period: with 9 arguments it reads "
            f"'{words[6]}' as qw and stops with 'Failed to parse qw argument as float'"
        )
        rotation_size = 3
    new_style = [f for f in flags if f not in RPY_FLAGS]
    if new_style:
        reader.issues.append(ArgIssue(ArgIssueKind.MIXED_STYLES, tuple(new_style)))
    elif flags:
        # Only rpy flags: the program silently replaces them with the positional rotation.
        reader.issues.append(ArgIssue(ArgIssueKind.MIXED_STYLES, tuple(flags), fatal=False))
    names = ("--x", "--y", "--z") + (
        ("--yaw", "--pitch", "--roll") if rotation_size == 3 else QUATERNION_FLAGS
    )
    reader.issues.append(
        ArgIssue(ArgIssueKind.POSITIONAL, tuple(words), names + FRAME_FLAGS)
    )
    return _layout(reader, positional, rotation_size)


def _layout(reader: _Reader, positional: list[tuple[int, str]], rotation_size: int
            ) -> Ros2Decoded:
    """The positional layout ``x y z`` + rotation + ``parent child`` [+ period]."""
    numeric = 3 + rotation_size
    indices = [index for index, _ in positional]
    values = [
        reader.number(index, word, slot)
        for slot, (index, word) in enumerate(positional[:numeric])
    ]
    kind = RotationKind.YPR if rotation_size == 3 else RotationKind.QUATERNION
    for offset in (0, 1):
        index, word = positional[numeric + offset]
        if word == "" and reader.resolved(index):
            reader.issues.append(ArgIssue(
                ArgIssueKind.MISSING_FRAME, (FRAME_FLAGS[offset],),
                ("positional", str(numeric + offset + 1)),
            ))
    return _result(
        reader, ArgForm(kind.value), positional[numeric][1], positional[numeric + 1][1],
        (values[0], values[1], values[2]), Rotation(kind, tuple(values[3:numeric])),
        {
            Field.TRANSLATION: tuple(indices[:3]),
            Field.ROTATION: tuple(indices[3:numeric]),
            Field.PARENT: (indices[numeric],),
            Field.CHILD: (indices[numeric + 1],),
        },
    )


def _flags(reader: _Reader, flags: dict[str, tuple[int, str]]) -> Ros2Decoded:
    rpy = [f for f in RPY_FLAGS if f in flags]
    quaternion = [f for f in QUATERNION_FLAGS if f in flags]
    translation = tuple(
        reader.number(*flags[f], slot) if f in flags else 0.0
        for slot, f in enumerate(TRANSLATION_FLAGS)
    )
    rotation: Rotation | None
    if rpy and quaternion:
        reader.issues.append(
            ArgIssue(ArgIssueKind.RPY_AND_QUATERNION, tuple(rpy), tuple(quaternion))
        )
        rotation = None
    elif quaternion:
        defaults = (0.0, 0.0, 0.0, 1.0)
        values = tuple(
            reader.number(*flags[f], 3 + slot) if f in flags else defaults[slot]
            for slot, f in enumerate(QUATERNION_FLAGS)
        )
        rotation = Rotation(RotationKind.QUATERNION, values)
        missing = [f for f in QUATERNION_FLAGS if f not in flags]
        norm = sum(v * v for v in values)
        if missing and math.isfinite(norm) and abs(norm - 1.0) >= TF2_TOLERANCE:
            reader.issues.append(
                ArgIssue(ArgIssueKind.PARTIAL_QUATERNION, tuple(missing), values=values)
            )
    else:
        # Rotation values keep the ypr layout (yaw, pitch, roll) of the positional form.
        order = ("--yaw", "--pitch", "--roll")
        rotation = Rotation(RotationKind.YPR, tuple(
            reader.number(*flags[f], 3 + slot) if f in flags else 0.0
            for slot, f in enumerate(order)
        ))
    frames: list[str | None] = []
    for flag in FRAME_FLAGS:
        value = flags[flag][1] if flag in flags else None
        if value is None or (value == "" and reader.resolved(flags[flag][0])):
            reader.issues.append(ArgIssue(
                ArgIssueKind.MISSING_FRAME, (flag,), () if value is None else ("empty",),
            ))
            value = None
        frames.append(value)
    sources = {
        Field.TRANSLATION: tuple(flags[f][0] for f in TRANSLATION_FLAGS if f in flags),
        Field.ROTATION: tuple(flags[f][0] for f in rpy + quaternion),
        Field.PARENT: tuple(flags[f][0] for f in FRAME_FLAGS[:1] if f in flags),
        Field.CHILD: tuple(flags[f][0] for f in FRAME_FLAGS[1:] if f in flags),
    }
    form = ArgForm.QUATERNION if quaternion and not rpy else ArgForm.YPR
    return _result(reader, form, frames[0], frames[1],
                   (translation[0], translation[1], translation[2]), rotation, sources)


def _result(reader: _Reader, form: ArgForm, parent: str | None, child: str | None,
            translation: tuple[float, float, float] | None, rotation: Rotation | None,
            sources: Mapping[Field, tuple[int, ...]]) -> Ros2Decoded:
    return Ros2Decoded(
        form=form,
        parent=parent,
        child=child,
        translation=translation,
        rotation=rotation,
        arity_issue=reader.arity,
        number_issues=tuple(reader.numbers),
        arg_issues=tuple(reader.issues),
        sources=sources,
        unresolved=frozenset(
            key for key in DECODED_FIELDS
            if any(i in reader.unresolved for i in sources.get(key, ()))
        ),
    )


@dataclass(frozen=True)
class ComponentParam:
    """A parameter given to the component: its text, and whether launch passes it as a
    string (rather than a number) to the node."""

    text: str
    is_string: bool
    resolved: bool = True


def decode_component(params: Mapping[str, ComponentParam], complete: bool = True
                     ) -> Ros2Decoded:
    """Decode ``tf2_ros::StaticTransformBroadcasterNode`` parameters. ``complete`` is
    False when some parameters come from a source the linter cannot read (a file), so
    that absent ones may be set there."""
    items = [params[name].text if name in params else "" for name in COMPONENT_PARAMS]
    unresolved = frozenset(
        position for position, name in enumerate(COMPONENT_PARAMS)
        if (name in params and not params[name].resolved) or (name not in params and not complete)
    )
    reader = _Reader(items, unresolved)
    defaults = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)
    values: list[float] = []
    for slot, name in enumerate(COMPONENT_PARAMS[:7]):
        param = params.get(name)
        if param is None or not param.resolved:
            values.append(defaults[slot])
        elif param.is_string:
            # The node declares doubles: a string parameter makes it throw at start-up.
            reader.numbers.append(NumberIssue(slot, param.text, None))
            values.append(defaults[slot])
        else:
            values.append(reader.number(slot, param.text, slot))
    frames = [
        params[name].text if name in params else default
        for name, default in zip(COMPONENT_PARAMS[7:], COMPONENT_DEFAULT_FRAMES)
    ]
    for name in COMPONENT_PARAMS[7:]:
        param = params.get(name)
        if param is not None and param.resolved and param.text == "":
            reader.issues.append(ArgIssue(ArgIssueKind.MISSING_FRAME, (name,), ("parameter",)))
    absent = [name for name in COMPONENT_PARAMS[7:] if name not in params]
    if absent and complete:
        reader.issues.append(
            ArgIssue(ArgIssueKind.DEFAULT_FRAMES, tuple(absent), (frames[0], frames[1]))
        )
    sources = {
        Field.TRANSLATION: (0, 1, 2),
        Field.ROTATION: (3, 4, 5, 6),
        Field.PARENT: (7,),
        Field.CHILD: (8,),
    }
    return _result(reader, ArgForm.QUATERNION, frames[0], frames[1],
                   (values[0], values[1], values[2]),
                   Rotation(RotationKind.QUATERNION, tuple(values[3:7])), sources)
