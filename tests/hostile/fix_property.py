"""The fix property: a random well-formed launch file (XML or Python) with CR, CRLF and LF
line ends, a byte order mark, tabs, multi-byte text and line separators around random
fixable and unfixable transforms; after the fixes, exactly the named words changed and the
file still parses. Shared by ``test_fix_property.py`` (bounded) and
``scripts/fuzz_fix.py`` (long runs)."""

from __future__ import annotations

from hypothesis import strategies as st

from launch_linter.engine import LintOptions, lint_bytes
from launch_linter.fix import apply_edits

OPTIONS = LintOptions(select=frozenset({"leading_slash"}))
NEWLINES = st.sampled_from(["\n", "\r\n", "\r"])
FILLER = st.text(alphabet=st.sampled_from(
    [*"ab <>/=\"'\t", "é", "日", "本", "\u2028", "\x85", "\x0c", "😀", "\u202e", "ß"]),
    max_size=12)
"""Text for comments: markup characters, tabs, multi-byte text, separators that are no
line end for the parsers (U+2028, NEL, form feed in Python) though ``str.splitlines``
splits there."""


def _comment(kind: str, text: str) -> str:
    if kind == "xml":
        return "<!--" + text.replace("-", "").replace("\x0c", "") + "-->"  # no FF in XML
    return "# " + text.replace("\r", "").replace("\n", "")


def _xml_node(index: int, fixable: bool, before_args: str, spacing: str) -> str:
    parent = f"/p{index}" if fixable else f"p{index}"
    return (f'<node pkg="tf" {before_args}type="static_transform_publisher" name="n{index}"'
            f'{spacing}args="0 0 0{spacing}0 0 0 {parent} c{index} 100"/>')


def _python_node(index: int, fixable: bool, quote: str, spacing: str) -> str:
    parent = f"/p{index}" if fixable else f"p{index}"
    words = ["0"] * 6 + [parent, f"c{index}"]
    items = ", ".join(quote + w + quote for w in words)
    return (f"Node(package='tf2_ros', executable='static_transform_publisher',{spacing}"
            f"name='n{index}', arguments=[{items}]),")


@st.composite
def launch_files(draw: st.DrawFn) -> tuple[str, bytes, bytes]:
    """(kind, file bytes, the bytes every fix applied must give)."""
    kind = draw(st.sampled_from(["xml", "py"]))
    count = draw(st.integers(1, 6))
    fixable = draw(st.lists(st.booleans(), min_size=count, max_size=count))
    bom = draw(st.booleans())
    pieces: list[tuple[str, str]] = []  # (as written, as fixed)
    for index in range(count):
        newline = draw(NEWLINES)
        filler = _comment(kind, draw(FILLER))
        if kind == "xml":
            indent = draw(st.sampled_from(["", "\t", "  "]))
            spacing = draw(st.sampled_from([" ", "\t", newline + "\t", "  "]))
            before = draw(st.sampled_from(["", 'output="screen" ', 'ns="é日" ']))
            written = _xml_node(index, fixable[index], before, spacing)
            pieces.append((indent + filler + newline + indent + written + newline,
                           indent + filler + newline + indent
                           + _xml_node(index, False, before, spacing) + newline))
        else:
            quote = draw(st.sampled_from(["'", '"']))
            spacing = draw(st.sampled_from([" ", "\t", newline + "        "]))
            written = _python_node(index, fixable[index], quote, spacing)
            pieces.append(("        " + filler + newline + "        " + written + newline,
                           "        " + filler + newline + "        "
                           + _python_node(index, False, quote, spacing) + newline))
    newline = draw(NEWLINES)
    if kind == "xml":
        head, tail = "<launch>" + newline, "</launch>" + newline
    else:
        head = newline.join([
            "from launch import LaunchDescription",
            "from launch_ros.actions import Node  # " + draw(FILLER).replace("\r", "")
            .replace("\n", ""),
            "def generate_launch_description():",
            "    return LaunchDescription([", ""])
        tail = "    ])" + newline
    prefix = "\ufeff" if bom else ""
    before = prefix + head + "".join(p[0] for p in pieces) + tail
    after = prefix + head + "".join(p[1] for p in pieces) + tail
    return kind, before.encode("utf-8"), after.encode("utf-8")


def check_fix_property(kind: str, data: bytes, expected: bytes) -> None:
    """Every fix located applies, and the result is ``expected`` and parses."""
    name = "robot.launch" if kind == "xml" else "robot.launch.py"
    result = lint_bytes(data, name, OPTIONS)
    assert all(f.status.value == "ok" for f in result.files), result.diagnostics
    fixes = [d.fix for d in result.diagnostics if d.fix is not None]
    skipped: list[str] = []
    out, applied = apply_edits(data, fixes, skipped)
    assert not skipped and len(applied) == len(fixes)
    assert out == expected, (data, out)
    again = lint_bytes(out, name, OPTIONS)
    assert all(f.status.value == "ok" for f in again.files), again.diagnostics
    assert not [d for d in again.diagnostics if d.rule == "leading_slash"]
