"""The results cache: a root file's findings, reused while everything its lint read holds.

ruff's model. One cache file per *run key*: the tool (version and the stamp of its own
source files), the effective options and configuration and the working folder (paths are
shown relative to it). In it, per root launch file, the findings before they are finished
(suppressions, per-path ignores, fixes located) and the stamp (kind, size, modification
time, content digest) of every path its lint looked at (``resolve.reads``); shared work
(the package crawl, a robot description) is stored once as a group that entries name. An
entry is reused only when every stamp still holds; the finishing steps run on every run.

The cache is untrusted input like any other: JSON (never pickle), bounded in size,
checked field by field when used; a file or entry that does not check out is ignored and
rewritten. A folder that cannot be written (a read-only tree) leaves the run uncached,
silently.
"""

from __future__ import annotations

import contextlib
import json
import os
import sys
from collections.abc import Callable, Iterable
from enum import Enum

from launch_linter.model import record
from launch_linter.model.beliefs import BeliefSet
from launch_linter.model.diagnostic import (
    Applicability,
    Belief,
    Category,
    Diagnostic,
    Edit,
    Fix,
    Location,
    Severity,
    TokenEdit,
)
from launch_linter.model.launch import Comment, FileRecord, FileStatus, LaunchTree
from launch_linter.resolve import reads
from launch_linter.resolve.xml_safe import read_file_within, read_regular_file
from launch_linter.workspace.discovery import InputFile

CACHE_FOLDER = reads.CACHE_FOLDER
FORMAT = "launch-linter-cache/1"
MAX_CACHE_BYTES = 64 * 1024 * 1024
"""Largest cache file read or written; a larger one is left alone and not written."""
MAX_CACHE_FILES = 8
"""Cache files (run keys) kept in the folder; the least recently written go first."""
_GITIGNORE = "# Created by launch-linter: the results cache, never committed.\n*\n"
_CACHEDIR_TAG = ("Signature: 8a477f597d28d172789f06886806bc55\n"
                 "# This file marks the results cache of launch-linter.\n")

TYPE_CHECKING = False  # typing is not imported at run time: start-up (docs/performance.md)
if TYPE_CHECKING:
    from typing import Any, List, Optional, Tuple

    Linted = Tuple[Optional[LaunchTree], FileRecord, List[Diagnostic]]

_CODEC_FIELDS: dict[type[record.Record], tuple[str, ...]] = {
    Diagnostic: ("rule", "category", "severity", "path", "line", "column", "message", "node",
                 "related", "belief", "fix"),
    Location: ("path", "line", "column"),
    Belief: ("cls", "antecedent", "consequent", "n", "e", "z"),
    Fix: ("applicability", "message", "tokens", "token_edits", "edits", "safe_from_distro"),
    TokenEdit: ("start", "end", "text"),
    Edit: ("path", "start", "end", "content", "expected"),
    FileRecord: ("path", "status", "transforms"),
    Comment: ("path", "line", "text"),
}
"""The fields this module writes and reads, per class: a class that gains a field turns
the cache off (``codec_matches``) until the codec learns it (``tests/test_results_cache``)."""


def codec_matches() -> bool:
    return all(record.fields(cls) == names
               for cls, names in _CODEC_FIELDS.items())


class CacheFormatError(ValueError):
    """A cache entry does not have the shape this version writes."""


# -- keys ----------------------------------------------------------------------------------


def canonical(value: Any) -> Any:
    """``value`` as JSON data that is equal exactly when the values are: dataclasses by
    their compared fields, enums by class and value, sets and mappings sorted. A type it
    does not know raises ``TypeError`` (the cache is then not used: a key that missed a
    part of the options could reuse wrong results)."""
    if value is None or isinstance(value, (bool, int, str)):
        return value
    if isinstance(value, float):
        return ["float", repr(value)]
    if isinstance(value, Enum):
        return [type(value).__name__, canonical(value.value)]
    if isinstance(value, BeliefSet) and value.origin is not None:
        # A stored set by what it is decoded from, left undecoded (``BeliefSet.stored``).
        return ["StoredBeliefSet", value.source, canonical(value.min_z), value.origin]
    if isinstance(value, record.Record):
        return [type(value).__name__, [[name, canonical(getattr(value, name))]
                                       for name in record.compared_fields(value)]]
    if isinstance(value, dict):
        return ["dict", sorted(([canonical(k), canonical(v)] for k, v in value.items()),
                               key=json.dumps)]
    if isinstance(value, (list, tuple)):
        return [canonical(v) for v in value]
    if isinstance(value, (set, frozenset)):
        return ["set", sorted((canonical(v) for v in value), key=json.dumps)]
    raise TypeError(f"no canonical form for {type(value).__name__}")


def tool_stamp(version: str) -> list[object]:
    """The version, and the names, sizes and modification times of the package's files:
    an installed release never changes them, a development checkout does with each edit.
    A standalone linter's modules have no files (no ``__file__``): the script that embeds
    them, and the beliefs, stands for them; without one, no cache (``OSError``)."""
    here = globals().get("__file__")
    if here is None:
        script = getattr(sys.modules.get("__main__"), "__file__", None)
        if not isinstance(script, str):
            raise OSError("no file holds the linter's code")
        info = os.stat(script)
        return [version, [os.path.abspath(script), info.st_size, info.st_mtime_ns]]
    package = os.path.dirname(os.path.abspath(here))
    stamp: list[object] = [version]
    pending = [package]
    while pending:
        folder = pending.pop()
        try:
            entries = sorted(os.scandir(folder), key=lambda e: e.name)
        except OSError:
            continue
        for entry in entries:
            if entry.is_dir(follow_symlinks=False):
                if entry.name != "__pycache__":
                    pending.append(entry.path)
            elif entry.name.endswith((".py", ".json", ".toml", ".yaml")):
                info = entry.stat()
                stamp.append([entry.path[len(package):], info.st_size, info.st_mtime_ns])
    return stamp


NOT_KEYED = ("jobs",)
"""Options that never change a result (``--jobs``: the same output in any number of
processes, which ``scripts/output_identity.py --jobs`` checks)."""


def run_key(version: str, options: record.Record, configuration: object, folder: str) -> str:
    """The run key: tool, options (but ``NOT_KEYED``), configuration and working folder."""
    kept = [[name, canonical(getattr(options, name))] for name in record.compared_fields(options)
            if name not in NOT_KEYED]
    text = json.dumps([FORMAT, tool_stamp(version), type(options).__name__, kept,
                       canonical(configuration), folder], separators=(",", ":"))
    return reads.digest(text.encode("utf-8"))


# -- encoding ------------------------------------------------------------------------------


def _location(value: Location) -> list[object]:
    return [value.path, value.line, value.column]


def _belief(value: Belief) -> list[object]:
    def key(part: tuple[str, ...] | str | None) -> object:
        return list(part) if isinstance(part, tuple) else part

    return [value.cls, key(value.antecedent), key(value.consequent), value.n, value.e,
            repr(value.z)]


def _fix(value: Fix) -> list[object]:
    return [value.applicability.value, value.message, list(value.tokens),
            [[t.start, t.end, t.text] for t in value.token_edits],
            [[e.path, e.start, e.end, e.content, e.expected] for e in value.edits],
            value.safe_from_distro]


def encode_diagnostic(d: Diagnostic) -> list[object]:
    return [d.rule, d.category.value, d.severity.value, d.path, d.line, d.column, d.message,
            d.node, [_location(r) for r in d.related],
            None if d.belief is None else _belief(d.belief),
            None if d.fix is None else _fix(d.fix)]


def encode_linted(linted: Linted) -> list[object]:
    tree, record, diagnostics = linted
    directives = None if tree is None else [
        tree.root, tree.status.value, list(tree.files),
        [[c.path, c.line, c.text] for c in tree.comments],
        [[p, line] for p, line in tree.element_lines],
    ]
    return [[record.path, record.status.value, record.transforms], directives,
            [encode_diagnostic(d) for d in diagnostics]]


# -- decoding: every field checked ---------------------------------------------------------


def _list(value: object, length: int | None = None) -> list[Any]:
    if not isinstance(value, list) or (length is not None and len(value) != length):
        raise CacheFormatError("not a list of the expected length")
    return value


def _str(value: object) -> str:
    if not isinstance(value, str):
        raise CacheFormatError("not a string")
    return value


def _optional_str(value: object) -> str | None:
    return None if value is None else _str(value)


def _int(value: object) -> int:
    if isinstance(value, bool) or not isinstance(value, int):
        raise CacheFormatError("not an integer")
    return value


def _key(value: object) -> tuple[str, ...] | str:
    return tuple(_str(v) for v in value) if isinstance(value, list) else _str(value)


def _decode_belief(value: object) -> Belief:
    cls, antecedent, consequent, n, e, z = _list(value, 6)
    return Belief(_str(cls), _key(antecedent), None if consequent is None else _key(consequent),
                  _int(n), _int(e), float(_str(z)))


def _decode_fix(value: object) -> Fix:
    applicability, message, tokens, token_edits, edits, distro = _list(value, 6)
    return Fix(
        Applicability(applicability), _str(message), tuple(_str(t) for t in _list(tokens)),
        tuple(TokenEdit(_int(s), _int(e), _str(t))
              for s, e, t in (_list(x, 3) for x in _list(token_edits))),
        tuple(Edit(_str(p), _int(s), _int(e), _str(c), _optional_str(x))
              for p, s, e, c, x in (_list(edit, 5) for edit in _list(edits))),
        _optional_str(distro),
    )


def decode_diagnostic(value: object) -> Diagnostic:
    rule, category, severity, path, line, column, message, node, related, belief, fix = \
        _list(value, 11)
    return Diagnostic(
        _str(rule), Category(category), Severity(severity), _str(path), _int(line),
        _int(column), _str(message), _optional_str(node),
        tuple(Location(_str(p), _int(ln), _int(c))
              for p, ln, c in (_list(r, 3) for r in _list(related))),
        None if belief is None else _decode_belief(belief),
        None if fix is None else _decode_fix(fix),
    )


def decode_linted(value: object) -> Linted:
    record, directives, diagnostics = _list(value, 3)
    path, status, transforms = _list(record, 3)
    tree = None
    if directives is not None:
        root, tree_status, files, comments, element_lines = _list(directives, 5)
        tree = LaunchTree(
            _str(root), FileStatus(tree_status), (), (), tuple(_str(f) for f in _list(files)),
            comments=tuple(Comment(_str(p), _int(ln), _str(t))
                           for p, ln, t in (_list(c, 3) for c in _list(comments))),
            element_lines=tuple((_str(p), _int(ln))
                                for p, ln in (_list(e, 2) for e in _list(element_lines))),
        )
    return (tree, FileRecord(_str(path), FileStatus(status), _int(transforms)),
            [decode_diagnostic(d) for d in _list(diagnostics)])


def _encode_stamps(stamps: dict[str, reads.Stamp]) -> list[list[object]]:
    return [[path, *stamp] for path, stamp in sorted(stamps.items())]


def _decode_stamp(value: object) -> tuple[str, reads.Stamp]:
    path, kind, size, mtime_ns, content = _list(value, 5)
    if kind not in (reads.FILE, reads.FOLDER, reads.OTHER, reads.ABSENT):
        raise CacheFormatError("unknown kind")
    return _str(path), (kind, _int(size), _int(mtime_ns), _optional_str(content))


# -- the cache -----------------------------------------------------------------------------


class ResultsCache:
    """The entries of one run key, read from and written to one file of ``folder``.

    ``get`` an input's result if every stamp still holds, ``put`` a result with the log of
    what linting it read, ``save`` when the run is over (only if something changed)."""

    def __init__(self, folder: str, key: str) -> None:
        self.folder = folder
        self.key = key
        self.path = os.path.join(folder, f"results-{key[:32]}.json")
        self._entries: dict[str, Any] = {}
        self._groups: dict[str, Any] = {}
        self._discovery: Any = None
        self._derived: dict[str, Any] = {}
        self._group_names: dict[int, tuple[reads.ReadLog, str]] = {}
        self._changed = False
        self._freshness = reads.Freshness(read_regular_file)
        self._group_holds: dict[str, bool] = {}
        self.hits = 0
        self.missed: list[str] = []
        """The inputs this cache could not answer (absolute paths), in order."""
        self._load()

    @staticmethod
    def open(folder: str, version: str, options: record.Record,
             configuration: object = None) -> ResultsCache | None:
        """The cache in ``folder`` for the tool's ``version``, these options (a
        ``LintOptions``) and ``configuration`` (a ``Config``), or None when none can be
        used."""
        if not codec_matches():
            return None
        try:
            key = run_key(version, options, configuration, os.getcwd())
        except (TypeError, ValueError, OSError):
            return None
        return ResultsCache(folder, key)

    def _load(self) -> None:
        try:
            data = read_file_within(self.path, MAX_CACHE_BYTES)
        except (OSError, ValueError):
            return
        try:
            document = json.loads(data.decode("utf-8"))
        except (ValueError, RecursionError):
            return
        if not isinstance(document, dict) or document.get("format") != FORMAT \
                or document.get("key") != self.key:
            return
        entries, groups = document.get("entries"), document.get("groups")
        if isinstance(entries, dict) and isinstance(groups, dict):
            self._entries, self._groups = entries, groups
            self._discovery = document.get("discovery")
            derived = document.get("derived")
            if isinstance(derived, dict):
                self._derived = derived

    def discovered(self, question: object,
                   discover: Callable[[], list[InputFile]]) -> list[InputFile]:
        """What ``discover()`` finds, from the cache while every folder it listed and file
        it read holds for the same ``question`` (the paths given, exclusions, whether
        ``.gitignore`` counts): a folder walk is most of a run whose results are cached."""
        self.refresh()
        asked = reads.digest(json.dumps(canonical(question)).encode("utf-8"))
        try:
            found = self._discovery_holds(asked)
        except (CacheFormatError, TypeError, ValueError):
            found = None
        if found is not None:
            return found
        with reads.recording() as log:
            found = discover()
        if not log.is_unstable() and not log.groups:
            self._discovery = {"question": asked, "stamps": _encode_stamps(log.stamps),
                               "inputs": [[i.path, i.display] for i in found]}
            self._changed = True
        return found

    def _discovery_holds(self, asked: str) -> list[InputFile] | None:
        stored = self._discovery
        if not isinstance(stored, dict) or stored.get("question") != asked:
            return None
        if not self._stamps_hold(_list(stored.get("stamps"))):
            return None
        return [InputFile(_str(path), _str(display))
                for path, display in (_list(i, 2) for i in _list(stored.get("inputs")))]

    def count(self, name: str, compute: Callable[[], int]) -> int:
        """A count that the run key decides (``compute()`` gives it), kept with the key:
        the number of beliefs the JSON report states, which would otherwise mean decoding
        the beliefs file on every run."""
        known = self._derived.get(name)
        if isinstance(known, int) and not isinstance(known, bool) and known >= 0:
            return known
        self._derived[name] = value = compute()
        self._changed = True
        return value

    def refresh(self) -> None:
        """Forget which stamps were found to hold: a new run looks at the files again (a
        cache kept in a process, by an editor, serves many runs)."""
        self._freshness = reads.Freshness(read_regular_file)
        self._group_holds = {}

    def get(self, item: InputFile) -> Linted | None:
        """The result of ``item`` if its entry exists, checks out and still holds."""
        entry = self._entries.get(item.path)
        if entry is None:
            self.missed.append(item.path)
            return None
        try:
            found = self._still_holds(entry, item)
        except (CacheFormatError, TypeError, ValueError, KeyError):
            found = None
        if found is None:
            self.missed.append(item.path)
            del self._entries[item.path]
            self._changed = True
        else:
            self.hits += 1
        return found

    def _still_holds(self, entry: object, item: InputFile) -> Linted | None:
        if not isinstance(entry, dict) or entry.get("display") != item.display:
            return None
        if not self._stamps_hold(_list(entry.get("stamps"))):
            return None
        for group in _list(entry.get("groups")):
            if not self._group_still_holds(_str(group)):
                return None
        return decode_linted(entry.get("result"))

    def _group_still_holds(self, group: str) -> bool:
        known = self._group_holds.get(group)
        if known is None:
            stamps = self._groups.get(group)
            known = isinstance(stamps, list) and self._stamps_hold(stamps)
            self._group_holds[group] = known
        return known

    def _stamps_hold(self, stamps: list[Any]) -> bool:
        """Whether every stored stamp still holds (this run checks each path once)."""
        holds = self._freshness.holds
        return all(holds(*_decode_stamp(raw)) for raw in stamps)

    def put(self, item: InputFile, linted: Linted, log: reads.ReadLog) -> None:
        """Keep ``linted`` for ``item``, as long as what ``log`` recorded holds. A result
        the linter failed on, or whose inputs changed while it was read, is not kept."""
        if linted[1].status is FileStatus.INTERNAL_ERROR or log.is_unstable():
            return
        names = [self._group_name(group) for group in log.closure()]
        self._entries[item.path] = {
            "display": item.display,
            "stamps": _encode_stamps(log.stamps),
            "groups": names,
            "result": encode_linted(linted),
        }
        self._changed = True

    def _group_name(self, group: reads.ReadLog) -> str:
        """The name (the digest of its stamps) under which ``group`` is stored; worked out
        once per log, which many roots share (the package crawl)."""
        known = self._group_names.get(id(group))
        if known is not None and known[0] is group:
            return known[1]
        stamps = _encode_stamps(group.stamps)
        name = reads.digest(json.dumps(stamps, separators=(",", ":")).encode("utf-8"))
        self._groups.setdefault(name, stamps)
        self._group_names[id(group)] = (group, name)  # the log kept: its id stays its own
        return name

    def save(self) -> None:
        """Write the cache if anything changed; silently nothing if it cannot be written."""
        if not self._changed:
            return
        # Entries of root files that are gone go with them.
        self._entries = {path: entry for path, entry in self._entries.items()
                         if os.path.isfile(path)}
        used = {name for entry in self._entries.values() if isinstance(entry, dict)
                for name in entry.get("groups", ()) if isinstance(name, str)}
        document = {"format": FORMAT, "key": self.key,
                    "groups": {n: s for n, s in self._groups.items() if n in used},
                    "entries": self._entries, "discovery": self._discovery,
                    "derived": self._derived}
        text = json.dumps(document, separators=(",", ":")).encode("utf-8")
        try:
            if len(text) > MAX_CACHE_BYTES:
                os.remove(self.path)
                return
            _prepare_folder(self.folder)
            _write_atomically(self.path, text)
            _prune(self.folder, keep=self.path)
        except OSError:
            return
        self._changed = False


def _prepare_folder(folder: str) -> None:
    """The cache folder with its ``.gitignore`` (so it is never committed) and a
    ``CACHEDIR.TAG`` (so that backup tools skip it)."""
    os.makedirs(folder, exist_ok=True)
    for name, text in ((".gitignore", _GITIGNORE), ("CACHEDIR.TAG", _CACHEDIR_TAG)):
        path = os.path.join(folder, name)
        if not os.path.exists(path):
            _write_atomically(path, text.encode("utf-8"))


def _write_atomically(path: str, data: bytes) -> None:
    # Imported here: tempfile (with random and shutil) is start-up time for a run that
    # finds its results cached and writes nothing.
    import tempfile

    descriptor, temporary = tempfile.mkstemp(dir=os.path.dirname(path), prefix=".tmp-")
    try:
        with os.fdopen(descriptor, "wb") as handle:
            handle.write(data)
        os.replace(temporary, path)
    except BaseException:
        _remove(temporary)
        raise


def _remove(path: str) -> None:
    with contextlib.suppress(OSError):
        os.remove(path)


def _prune(folder: str, keep: str) -> None:
    """Only the ``MAX_CACHE_FILES`` most recently written cache files stay."""
    found = []
    for entry in os.scandir(folder):
        if entry.name.startswith("results-") and entry.name.endswith(".json") \
                and entry.path != keep:
            found.append((entry.stat().st_mtime_ns, entry.path))
    for _, path in sorted(found, reverse=True)[MAX_CACHE_FILES - 1:]:
        _remove(path)


def results_cache_folder(configured: str | None, configuration_file: str | None) -> str:
    """The cache folder: ``configured`` (relative to the configuration file's folder), else
    ``.launch-linter-cache`` in the configuration file's folder, else in the working one."""
    base = os.path.dirname(os.path.abspath(configuration_file)) if configuration_file \
        else os.getcwd()
    if configured:
        return os.path.normpath(os.path.join(base, os.path.expanduser(configured)))
    return os.path.join(base, CACHE_FOLDER)


def lint_with_cache(
    inputs: Iterable[InputFile], cache: ResultsCache | None,
    lint: Callable[[list[InputFile]], list[tuple[Linted, reads.ReadLog | None]]],
) -> list[Linted]:
    """The results of ``inputs`` in order: from ``cache`` where they hold, else from
    ``lint`` (given the misses, returning each result with the log of its reads)."""
    items = list(inputs)
    if cache is None:
        return [linted for linted, _ in lint(items)]
    cache.refresh()
    found: list[Linted | None] = [cache.get(item) for item in items]
    misses = [item for item, hit in zip(items, found) if hit is None]
    fresh = iter(lint(misses)) if misses else iter(())
    out: list[Linted] = []
    for item, hit in zip(items, found):
        if hit is None:
            linted, log = next(fresh)
            if log is not None:
                cache.put(item, linted, log)
            hit = linted
        out.append(hit)
    return out
