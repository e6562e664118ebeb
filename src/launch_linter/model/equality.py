"""An unresolved condition that compares one value with a constant, read from its text.

Two branches on the same unknown value with different constants (``$(eval
env('RUN_TYPE') == 'simulation')`` and ``== 'uav'``; ``LaunchConfigurationEquals('mode',
'sim')`` and ``'real'``; ``xacro:if value="${mode == 'a'}"`` and ``'b'``) are
alternatives: at most one runs. This module reads such a test from the condition's text
(never evaluating it) as (subject, constant, equal); texts it does not recognise give
None, and then nothing is assumed.

A condition on a value's truth is a test too: ``IfCondition(x)`` (``x`` true),
``UnlessCondition(x)``, ``IfCondition(PythonExpression(['not ', x]))`` (``x`` false),
``$(eval not arg('x'))``. Such a test has the constant :data:`TRUTH`, and it excludes an
equality test of the same value with a boolean word of the other truth (or with a word
that is not boolean: launch then refuses the truth test).
"""

from __future__ import annotations

import re

TYPE_CHECKING = False  # typing is not imported at run time: start-up (docs/performance.md)
if TYPE_CHECKING:
    from typing import Tuple

    Test = Tuple[str, str, bool]
    """(normalised subject, constant, True for ``==`` / False for ``!=``)."""

MAX_TEXT = 500
TRUTH = "\x00truth"
"""The constant of a truth test: (subject, TRUTH, True) holds when the value is true."""
_TRUE_WORDS = ("true", "1")
_FALSE_WORDS = ("false", "0")
# Patterns as text, compiled on first use and kept by ``re``: compiling the thirteen at
# import took 1.7 ms, a twentieth of a start-up that often never needs them.
_LAUNCH_EQUALS = r"""LaunchConfiguration(Not)?Equals\(\s*(['"])(\w+)\2\s*,\s*(['"])(.*?)\4\s*\)"""
_EVAL = r"(?s)\$\(eval\s+(.*)\)"
_XACRO = r"(?s)xacro:\$\{(.*)\}"
_QUOTED = r"""(?s)(['"])(.*)\1"""
_LIST_ITEM = (
    r"""\s*(('[^'\\]*'|"[^"\\]*")|(LaunchConfiguration\(\s*(?:'\w+'|"\w+")\s*\)|[A-Za-z_]\w*))"""
    r"""\s*(?:,|$)""")
_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_SUBJECT_FORMS = (
    (r"""^arg\((['"])(\w+)\1\)$""", "{}"),
    (r"""^\$\((?:var|arg)\s+(\w+)\)$""", "{}"),
    (r"""^(?:opt)?env\((['"])(\w+)\1(?:,.*)?\)$""", "env:{}"),
    (r"""^\$\((?:opt)?env\s+(\w+)(?:\s.*)?\)$""", "env:{}"),
    (r"""^LaunchConfiguration\((['"])(\w+)\1\)$""", "{}"),
    # nav2_common's LaunchConfigAsBool: a launch configuration read as a boolean.
    (r"""^LaunchConfigAsBool\((['"])(\w+)\1\)$""", "{}"),
)
_NOT = r"(?s)^not\s*(?:\((.*)\)|(.*))$"


def equality_test(text: str) -> Test | None:
    """The comparison a condition's text makes, or None when it is not one."""
    if len(text) > MAX_TEXT:
        return None
    text = text.strip()
    match = re.fullmatch(_LAUNCH_EQUALS, text)
    if match:
        return match.group(3), match.group(5), match.group(1) is None
    if text.startswith("PythonExpression([") and text.endswith("])"):
        return _comparison(_joined(text[len("PythonExpression(["):-2]))
    for form in (_EVAL, _XACRO):
        match = re.fullmatch(form, text)
        if match:
            return _comparison(_unquote(match.group(1).strip()))
    return None


def truth_test(text: str) -> Test | None:
    """The truth test a condition's text makes (``x``, ``not x``) as ``(subject, TRUTH,
    True when x must be true)``, or None when it is not one."""
    if len(text) > MAX_TEXT:
        return None
    text = text.strip()
    expression = None
    if text.startswith("PythonExpression([") and text.endswith("])"):
        expression = _joined(text[len("PythonExpression(["):-2])
    else:
        match = re.fullmatch(_EVAL, text)
        if match:
            expression = _unquote(match.group(1).strip())
    if expression is None:
        name = _subject(text)
        return None if name is None else (name, TRUTH, True)
    expression = expression.strip()
    negated = re.fullmatch(_NOT, expression)
    inner = expression if negated is None else (negated.group(1) or negated.group(2) or "")
    name = _subject(inner.strip())
    return None if name is None else (name, TRUTH, negated is None)


def _joined(items: str) -> str:
    """The text a ``PythonExpression([...])`` list makes: its string pieces joined, each
    variable (a ``LaunchConfiguration``) standing as its name, and a
    ``LaunchConfiguration('x')`` written in the list as itself."""
    pieces: list[str] = []
    for match in re.finditer(_LIST_ITEM, items):
        text, name = match.group(2), match.group(3)
        pieces.append(text[1:-1] if text is not None else name)
    return "".join(pieces)


def _unquote(expression: str) -> str:
    """ROS 2 writes ``$(eval '...')`` with the expression quoted (inner quotes escaped)."""
    quoted = re.fullmatch(_QUOTED, expression)
    if quoted and "\\" + quoted.group(1) in quoted.group(2):
        return quoted.group(2).replace("\\" + quoted.group(1), quoted.group(1))
    return expression


def _comparison(expression: str) -> Test | None:
    operators = re.findall(r"==|!=", expression)
    if len(operators) != 1 or re.search(r"\b(?:and|or|not|if)\b", expression):
        return None
    left, right = (side.strip() for side in expression.split(operators[0]))
    for subject, constant in ((left, right), (right, left)):
        value = _constant(constant)
        name = _subject(subject)
        if value is not None and name is not None:
            return name, value, operators[0] == "=="
    return None


def _constant(text: str) -> str | None:
    quoted = re.fullmatch(_QUOTED, text)
    if quoted and "$" not in quoted.group(2) and quoted.group(1) not in quoted.group(2):
        return quoted.group(2)
    if re.fullmatch(_NUMBER, text):
        return repr(float(text))
    if text in ("True", "False", "true", "false"):
        return text.lower()
    return None


def _subject(text: str) -> str | None:
    quoted = re.fullmatch(_QUOTED, text)
    if quoted:
        text = quoted.group(2).strip()
    compact = re.sub(r"\s+", "", text) if "$(" not in text else text.strip()
    for pattern, spelling in _SUBJECT_FORMS:
        match = re.fullmatch(pattern, compact)
        if match:
            return spelling.format(match.group(match.lastindex or 1))
    if re.fullmatch(r"[A-Za-z_]\w*", compact):
        return compact
    return None


def exclusive(first: Test, second: Test) -> bool:
    """Whether two tests of one subject can never both hold."""
    if first[0] != second[0]:
        return False
    if first[1] == TRUTH or second[1] == TRUTH:
        return _truth_excludes(first, second)
    if first[2] and second[2]:
        return first[1] != second[1]
    if first[2] != second[2]:
        return first[1] == second[1]
    return False


def _truth_excludes(first: Test, second: Test) -> bool:
    """Whether a truth test excludes another test of its subject: another truth test of
    the other truth; ``== word`` where the word is boolean of the other truth or not
    boolean at all (launch refuses to read it as a truth)."""
    truth, other = (first, second) if first[1] == TRUTH else (second, first)
    if other[1] == TRUTH:
        return truth[2] != other[2]
    if not other[2]:
        return False
    word = other[1].lower()
    if word in _TRUE_WORDS:
        return not truth[2]
    if word in _FALSE_WORDS:
        return truth[2]
    return True
