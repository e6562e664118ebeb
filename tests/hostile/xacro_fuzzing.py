"""Mutation fuzzing of the xacro reader, seeded from the repository's xacro and URDF
fixtures: each case is expanded with the real expander; properties: no exception, an
expansion or problems with 1-based lines, each within a few seconds of CPU (the
expander's own bounds). Used by ``test_xacro_fuzz.py`` (seconds) and
``scripts/fuzz_xacro.py`` (long runs)."""

from __future__ import annotations

import time
from pathlib import Path

from hypothesis import strategies as st

from launch_linter.frontends.robot.xacro import expand

REPO = Path(__file__).resolve().parents[2]
CPU_SECONDS = 5.0
TOKENS = (
    b"${", b"}", b"$(", b")", b"$${", b"$$(", b"${1+1}", b"${a*a}", b"${'x'*10**9}",
    b"$(arg a)", b"$(find p)", b"$(eval 9**9**9)", b"$(env HOME)",
    b'<xacro:property name="a" value="${a}${a}"/>', b'<xacro:arg name="a" default="1"/>',
    b'<xacro:macro name="m" params="x *b **c"><xacro:m x="1"/></xacro:macro>', b"<xacro:m/>",
    b'<xacro:include filename="/dev/zero"/>', b'<xacro:include filename="self.xacro"/>',
    b'<xacro:if value="${1}">', b"</xacro:if>", b'<xacro:insert_block name="b"/>',
    b'<joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint>',
    b"<!--", b"-->", b"&#10;", b"&#x202e;", b"\xef\xbb\xbf", b"\x00", b"\r", b"\r\n",
    b"<![CDATA[", b"]]>", b"nan", b"inf", b"1e999", b"'", b'"', b"\\",
)


def seeds() -> list[bytes]:
    return [path.read_bytes() for path in sorted((REPO / "tests").rglob("*"))
            if path.is_file() and path.name.endswith((".xacro", ".urdf"))
            and path.stat().st_size <= 64 * 1024]


@st.composite
def mutated(draw: st.DrawFn, pool: list[bytes]) -> bytes:
    buffer = bytearray(draw(st.sampled_from(pool)))
    for _ in range(draw(st.integers(0, 8))):
        where = draw(st.integers(0, len(buffer)))
        operation = draw(st.integers(0, 4))
        if operation <= 1:
            buffer[where:where] = draw(st.sampled_from(TOKENS))
        elif operation == 2:
            buffer[where:where + draw(st.integers(1, 64))] = b""
        elif operation == 3:
            span = bytes(buffer[where:where + draw(st.integers(1, 256))])
            buffer[where:where] = span * draw(st.integers(1, 50))
        else:
            buffer[where:where] = draw(st.binary(min_size=1, max_size=16))
    return bytes(buffer)


def check_xacro_case(folder: Path, data: bytes) -> None:
    """Expand one mutated file; raise AssertionError when a property fails."""
    path = folder / "self.xacro"
    path.write_bytes(data)
    started = time.process_time()
    expansion = expand(str(path), {"a": "1"}, lambda name: str(folder))
    spent = time.process_time() - started
    assert spent < CPU_SECONDS, spent
    for problem in expansion.problems:
        assert problem.line >= 1, problem
