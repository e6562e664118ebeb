"""A ``<rosparam>`` text or file that is not YAML: roslaunch's ``load_rosparam`` refuses
it ("contains invalid YAML"). Only the syntax is judged (PyYAML's scanner, parser and
composer), never tags; without PyYAML nothing is judged.
"""

from __future__ import annotations

import os

from launch_linter.frontends.params import (
    MAX_CACHED,
    MAX_PARAM_FILE_BYTES,
    read_yaml_file_placed,
)
from launch_linter.resolve.xml_safe import read_file_within

_syntax_cache: dict[str, str | None] = {}
"""The syntax error of each parameter file that could not be read (see
``params._cache``)."""


def yaml_syntax_error(text: str) -> str | None:
    """PyYAML's scanner, parser or composer error in ``text`` (roslaunch's ``load_rosparam``
    gives up on it: "contains invalid YAML"); None when the text composes, when it is too
    large or too deep to tell, or without PyYAML. Tags are not constructed: rosparam adds
    its own (``!degrees``), so only the syntax is judged. LibYAML's quick loader decides
    the usual, valid text; a failure is confirmed with the pure-Python ``SafeLoader``,
    the one ``yaml.safe_load`` (roslaunch's) uses, whose message it gives."""
    try:
        import yaml  # type: ignore[import-untyped]
    except ImportError:
        return None
    if len(text) > MAX_PARAM_FILE_BYTES:
        return None
    loaders = [yaml.SafeLoader]
    if hasattr(yaml, "CSafeLoader"):
        loaders.insert(0, yaml.CSafeLoader)
    for kind in loaders:
        loader = kind(text)
        try:
            loader.get_single_node()
        except (yaml.scanner.ScannerError, yaml.parser.ParserError,
                yaml.composer.ComposerError) as exc:
            problem = str(exc)
        except (yaml.YAMLError, RecursionError, ValueError):
            return None
        else:
            return None
        finally:
            loader.dispose()
    written = problem.replace('in "<unicode string>", ', "").replace('in "<file>", ', "")
    return " ".join(written.split())[:300]


def yaml_file_syntax_error(path: str) -> str | None:
    """:func:`yaml_syntax_error` of a parameter file; the file is read again only when
    :func:`read_yaml_file_placed` could not read its document."""
    _, why, _ = read_yaml_file_placed(path)
    if why is None:
        return None
    try:
        status = os.stat(path)
        key = f"{path}\x00{status.st_mtime_ns}\x00{status.st_size}"
        if key in _syntax_cache:
            return _syntax_cache[key]
        data = read_file_within(path, MAX_PARAM_FILE_BYTES)
    except OSError:
        return None
    if len(_syntax_cache) >= MAX_CACHED:
        _syntax_cache.clear()
    found = _syntax_cache[key] = yaml_syntax_error(data.decode("utf-8", "replace"))
    return found
