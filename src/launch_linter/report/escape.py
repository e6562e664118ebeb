"""Output that a launch file cannot forge.

Paths, frame ids, node names and quoted values come from untrusted files. In text output a
newline would start a line that looks like a real diagnostic and an ESC byte would drive the
terminal; in JSON, SARIF and graphs a lone surrogate cannot be encoded and NaN is not JSON.
Every string from a file goes through :func:`printable` (text, graphs) or
:func:`json_safe` (JSON documents) on its way out.
"""

from __future__ import annotations

import math
import re

TYPE_CHECKING = False  # typing is not imported at run time: start-up (docs/performance.md)
if TYPE_CHECKING:
    from typing import Any

# The patterns are compiled on first use (``re`` keeps them): their character classes
# reach past U+00FF, and compiling the three took 2 ms, a twentieth of a cached run's
# start-up, which never needs them. Each function first asks ``str.isprintable`` or
# ``str.isascii`` (C speed, no pattern): every character the patterns match is one that
# ``isprintable`` refuses, and every one but DEL is outside ASCII.

# C0 and C1 controls, DEL, the line and paragraph separators, the bidirectional overrides
# and isolates (which reorder what a terminal shows), and lone surrogates.
_UNSAFE = "[\x00-\x1f\x7f-\x9f\u2028\u2029\u202a-\u202e\u2066-\u2069\ud800-\udfff]"


def _escape(match: re.Match[str]) -> str:
    code = ord(match.group())
    return f"\\x{code:02x}" if code < 0x100 else f"\\u{code:04x}"


def printable(text: str) -> str:
    """``text`` with every control, separator, bidi override and lone surrogate shown as a
    ``\\xNN``/``\\uNNNN`` escape: one line, safe for a terminal, encodable as UTF-8."""
    if text.isprintable():
        return text
    return re.sub(_UNSAFE, _escape, text)


_SURROGATE = "[\ud800-\udfff]"
_RAW_IN_JSON = "[\x7f-\x9f\u2028\u2029\u202a-\u202e\u2066-\u2069]"
"""What ``json`` leaves raw with ``ensure_ascii=False`` that a reader's terminal or editor
would act on (C1 controls, separators, bidi overrides); C0 controls it escapes itself."""


def json_escaped(text: str) -> str:
    """JSON text with those characters as ``\\uNNNN`` escapes: the same document for a
    JSON reader, inert for a person reading it (only strings can hold them)."""
    if text.isascii() and "\x7f" not in text:
        return text
    return re.sub(_RAW_IN_JSON, lambda match: f"\\u{ord(match.group()):04x}", text)



def json_safe(value: Any) -> Any:
    """``value`` with non-finite floats as null and lone surrogates escaped (as text), so
    that the document is valid JSON and encodable as UTF-8. Documents are shallow: the
    recursion follows our own structure, not the input's."""
    if isinstance(value, str):
        if value.isprintable():
            return value
        return re.sub(_SURROGATE, _escape, value)
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {json_safe(k): json_safe(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [json_safe(v) for v in value]
    return value
