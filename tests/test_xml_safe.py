"""The safe XML reader: positions, comments, text, and what it refuses."""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from launch_linter.model.diagnostic import NO_ELEMENT_AT_ALL
from launch_linter.model.launch import may_hold_directive
from launch_linter.resolve.xml_safe import (
    MAX_BYTES,
    MAX_DEPTH,
    MAX_ELEMENTS,
    FileTooLarge,
    XmlError,
    parse_xml,
    read_file_within,
    read_regular_file,
)


def test_positions_are_one_based_line_and_column_of_the_start_tag() -> None:
    data = b'<launch>\n  <group>\n\t<node a="1"\n        b="2"/></group>\n</launch>\n'
    document = parse_xml(data)
    launch = document.root
    group = launch.children[0]
    node = group.children[0]
    assert (launch.tag, launch.line, launch.column) == ("launch", 1, 1)
    assert (group.line, group.column) == (2, 3)
    assert (node.line, node.column) == (3, 2)
    assert node.attrib == {"a": "1", "b": "2"}
    assert document.element_lines == [1, 2, 3]


def test_column_counts_characters_not_bytes() -> None:
    document = parse_xml('<launch><!-- é --><x/>é<y/></launch>'.encode())
    x, y = document.root.children
    assert x.column == len("<launch><!-- é -->") + 1
    assert y.column == len("<launch><!-- é --><x/>é") + 1


def test_attributes_keep_document_order_and_normalised_whitespace() -> None:
    document = parse_xml(b'<launch z="1" a="x\n\ty" m="&quot;q&quot;"/>')
    assert list(document.root.attrib) == ["z", "a", "m"]
    assert document.root.attrib["a"] == "x  y"
    assert document.root.attrib["m"] == '"q"'


def test_comments_are_kept_with_the_line_they_end_on() -> None:
    document = parse_xml(b"<launch>\n<!-- one -->\n<!-- two\nlines -->\n</launch>")
    assert document.comments == [(2, " one "), (4, " two\nlines ")]


def test_without_directives_no_comments_or_element_lines_are_kept() -> None:
    data = b"<launch>\n<!-- one -->\n<node/>\n</launch>"
    document = parse_xml(data, directives=False)
    assert document.comments == []
    assert document.element_lines == []
    assert document.root.children[0].line == 3
    many = b"<a>" + b"<b/>" * MAX_ELEMENTS + b"</a>"
    with pytest.raises(XmlError, match="more than"):
        parse_xml(many, directives=False)


def test_a_directive_may_be_held_when_the_marker_is_spelt_or_the_text_is_utf16() -> None:
    assert may_hold_directive(b"<!-- launch-linter: disable=x -->")
    assert may_hold_directive("<!-- launch-linter: disable=x -->".encode("utf-16"))
    assert not may_hold_directive(b"<launch><!-- launch linter --></launch>")


def test_a_regular_file_is_read_whole_or_up_to_the_limit(tmp_path: Path) -> None:
    path = tmp_path / "big.launch"
    data = bytes(range(256)) * 2000  # 512,000 bytes: more than one piece
    path.write_bytes(data)
    assert read_regular_file(str(path), len(data) + 1) == data
    assert read_regular_file(str(path), 1000) == data[:1000]
    assert read_regular_file(str(path), 300_000) == data[:300_000]
    empty = tmp_path / "empty.launch"
    empty.write_bytes(b"")
    assert read_regular_file(str(empty), 10) == b""


def test_text_is_kept_only_for_the_tags_asked_for() -> None:
    data = b"<launch><rosparam>a: 1<x/>b</rosparam><param>no</param></launch>"
    plain = parse_xml(data)
    assert [c.text for c in plain.root.children] == ["", ""]
    kept = parse_xml(data, text_tags=("rosparam",))
    rosparam, param = kept.root.children
    assert rosparam.text == "a: 1b"
    assert rosparam.children[0].text == ""
    assert param.text == ""


def test_collect_lists_elements_of_a_tag_anywhere() -> None:
    document = parse_xml(b"<a><launch/><b><launch x='1'/></b></a>", collect=("launch",))
    assert [e.get("x") for e in document.collected] == [None, "1"]


@pytest.mark.parametrize(
    ("data", "fragment"),
    [
        (b"<launch><node></launch>", "mismatched tag"),
        (b"", "no element found"),
        (b"<launch>\xff\xfe</launch>", "not well-formed"),
        (b"<launch/><launch/>", "junk after document element"),
        (b"<launch>&undefined;</launch>", "undefined entity"),
    ],
)
def test_malformed_xml_is_an_error_with_a_position(data: bytes, fragment: str) -> None:
    with pytest.raises(XmlError) as caught:
        parse_xml(data)
    assert fragment in caught.value.message
    assert caught.value.line >= 1 and caught.value.column >= 1


@pytest.mark.parametrize(
    ("data", "holds_none"),
    [(b"", True), (b'<?xml version="1.0"?>\n<!-- later -->\n', True), (b"  \n", True),
     (b"<launch>\n  <node/>\n", False)],
)
def test_a_file_without_any_element_is_told_from_a_root_left_open(
        data: bytes, holds_none: bool) -> None:
    """expat says "no element found" for both; only the first is an empty placeholder."""
    with pytest.raises(XmlError) as caught:
        parse_xml(data)
    assert caught.value.message.startswith("no element found")
    assert caught.value.message.endswith(NO_ELEMENT_AT_ALL) is holds_none


@pytest.mark.parametrize(
    ("data", "line", "tag"),
    [
        # jackal_control's control.launch: '</group' and no '>' (expat stops at line 3).
        (b"<launch>\n  <group>\n  </group\n\n  <node/>\n</launch>\n", 3, "</group"),
        (b'<launch>\n  <node name="a"\n  <param name="x"/>\n</launch>', 2, "<node"),
    ],
)
def test_a_tag_left_without_its_end_is_placed_where_it_starts(data: bytes, line: int,
                                                               tag: str) -> None:
    with pytest.raises(XmlError) as caught:
        parse_xml(data)
    assert (caught.value.line, caught.value.column) == (line, 3)
    assert f"'{tag}' is not closed" in caught.value.message
    assert "invalid token" in caught.value.message and caught.value.malformed


@pytest.mark.parametrize(
    "data",
    [
        b'<launch>\n  <node args="x > y"\n  <param/>\n</launch>',  # a '>' in a value
        b"<launch>\n  <node></launch>",  # expat's own place is the fault's
        b"<launch>\n  <node/> & <node/>\n</launch>",  # not at a '<'
    ],
)
def test_other_errors_stay_where_expat_stops(data: bytes) -> None:
    with pytest.raises(XmlError) as caught:
        parse_xml(data)
    assert "is not closed" not in caught.value.message and caught.value.line >= 2


@pytest.mark.parametrize(
    ("data", "line", "tag"),
    [
        # turtlebot3_manipulation_gazebo's '<include file=".../x.launch/">': expat stops at
        # '</launch>' two lines on; the include is what is left open.
        (b'<launch>\n  <include file="x.launch/">\n\n</launch>\n', 2, "include"),
        (b"<robot>\n  <link>\n    <visual>\n  </link>\n</robot>", 3, "visual"),
        (b"<launch>\n <group>\n  <arg name='a'>\n </group>\n</launch>", 3, "arg"),
    ],
)
def test_an_element_an_outer_end_tag_leaves_open_is_placed_where_it_starts(
        data: bytes, line: int, tag: str) -> None:
    with pytest.raises(XmlError) as caught:
        parse_xml(data)
    assert caught.value.line == line and caught.value.malformed
    assert f"'<{tag}>' is never closed" in caught.value.message
    assert "mismatched tag" in caught.value.message


def test_a_stray_end_tag_stays_where_expat_stops() -> None:
    """An end tag that closes nothing open is itself the fault."""
    with pytest.raises(XmlError) as caught:
        parse_xml(b"<launch>\n  <node/>\n  </group>\n</launch>")
    assert caught.value.line == 3 and caught.value.message == "mismatched tag"


def test_a_tag_left_open_after_20000_lines_is_found_at_once() -> None:
    data = b"<launch>\n" + b'  <arg name="a" default="1"/>\n' * 20_000 + b"  </group\n<x/>"
    started = time.perf_counter()
    with pytest.raises(XmlError) as caught:
        parse_xml(data)
    assert caught.value.line == 20_002 and time.perf_counter() - started < 5


def test_internal_entity_declarations_are_refused() -> None:
    data = b'<?xml version="1.0"?>\n<!DOCTYPE launch [\n<!ENTITY a "x">\n]>\n<launch>&a;</launch>'
    with pytest.raises(XmlError) as caught:
        parse_xml(data)
    assert "entity declaration 'a' refused" in caught.value.message
    assert caught.value.line == 3


def test_external_entities_are_refused_and_never_read(tmp_path: Path) -> None:
    secret = tmp_path / "secret.txt"
    secret.write_text("TOP SECRET")
    data = (
        f'<!DOCTYPE launch [<!ENTITY s SYSTEM "file://{secret}">]><launch a="&s;"/>'
    ).encode()
    with pytest.raises(XmlError) as caught:
        parse_xml(data)
    assert "TOP SECRET" not in str(caught.value)


def test_a_doctype_without_entities_is_fine() -> None:
    document = parse_xml(b'<!DOCTYPE launch SYSTEM "http://example.invalid/x.dtd"><launch/>')
    assert document.root.tag == "launch"


def test_depth_is_bounded() -> None:
    deep = b"<a>" * MAX_DEPTH + b"</a>" * MAX_DEPTH
    assert parse_xml(deep).root.tag == "a"
    deeper = b"<a>" * (MAX_DEPTH + 1) + b"</a>" * (MAX_DEPTH + 1)
    with pytest.raises(XmlError, match="nested deeper"):
        parse_xml(deeper)


def test_element_count_is_bounded() -> None:
    many = b"<a>" + b"<b/>" * MAX_ELEMENTS + b"</a>"
    with pytest.raises(XmlError, match="more than"):
        parse_xml(many)


def test_size_is_bounded() -> None:
    with pytest.raises(XmlError, match="larger than"):
        parse_xml(b" " * (MAX_BYTES + 1))


def test_read_file_within_takes_a_file_of_the_limit_and_refuses_one_byte_more(
        tmp_path: Path) -> None:
    path = tmp_path / "f"
    path.write_bytes(b"x" * 10)
    assert read_file_within(str(path), 10) == b"x" * 10
    with pytest.raises(FileTooLarge) as refused:
        read_file_within(str(path), 9)
    assert isinstance(refused.value, OSError) and refused.value.strerror == "larger than 9 bytes"
