from __future__ import annotations

import io

from launch_linter.mining.progress import Progress


class Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_bar_is_drawn_on_a_terminal() -> None:
    out = Terminal()
    bar = Progress("parsing", 4, out)
    bar.advance(2)
    bar.advance(2)
    bar.finish()
    text = out.getvalue()
    assert "\rparsing [###############               ] 2/4" in text
    assert text.endswith("] 4/4\n")


def test_nothing_is_drawn_elsewhere() -> None:
    out = io.StringIO()
    bar = Progress("parsing", 4, out)
    bar.advance(4)
    bar.finish()
    assert out.getvalue() == ""
