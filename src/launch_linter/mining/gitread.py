"""Commit count and HEAD of a corpus repository, without running any of its code.

A repository's own ``.git/config`` can name programs that git runs (``core.fsmonitor``,
``core.hooksPath``, ``core.pager``, ``core.sshCommand``, filters, aliases...), and git
always reads that file. So git is never pointed at a corpus repository: HEAD is read here
from the files (a ref, loose or packed, or a detached SHA), and ``git rev-list --count``
runs in a throw-away repository of our own whose only link to the corpus one is an
``objects/info/alternates`` entry (object files are data, never code). Every other config
source is neutralised too: no system or global config, no pager, no prompts, an empty
HOME, a fixed PATH lookup of ``git`` itself.

What git does follow of the corpus repository is its object store: the object and pack
files, ``objects/info/alternates`` (recursively) and the commit-graph files. Before git
runs, the store is walked (bounded): every entry must be a folder or a regular file (a
FIFO would block git until its timeout, a device would be read for ever), alternates must
be small regular files naming folders, and the store's size is capped. Files read here
(``.git`` files, ``commondir``, ``HEAD``, refs, ``packed-refs``, ``shallow``) are opened as
regular files only, without blocking, size-capped.
"""

from __future__ import annotations

import os
import re
import shutil
import stat
import subprocess
import tempfile

from launch_linter.resolve.xml_safe import read_file_within

GIT_TIMEOUT_S = 120
MAX_REF_BYTES = 4096
MAX_PACKED_REFS_BYTES = 64 * 1024 * 1024
MAX_OBJECT_ENTRIES = 2_000_000
"""Entries of an object store (loose objects, packs, folders, alternates' too) walked
before git is trusted with it: far above a real repository's, linear to check."""
MAX_ALTERNATES = 5
"""git's own depth limit for alternates of alternates."""
_SHA = re.compile(r"[0-9a-f]{40}(?:[0-9a-f]{24})?\Z")
_REF = re.compile(r"refs/[A-Za-z0-9._/+-]{1,400}\Z")
# Command-line settings win over every file git reads: these switch off what could run.
_SAFE_CONFIG = (
    "core.fsmonitor=false", "core.hooksPath=/dev/null", "core.pager=cat", "core.editor=false",
    "core.sshCommand=false", "core.askPass=", "credential.helper=", "diff.external=",
    "protocol.allow=never", "gc.auto=0", "maintenance.auto=false", "core.untrackedCache=false",
)


def _read_small(path: str, limit: int = MAX_REF_BYTES) -> str | None:
    """A small regular file's text, or None (a FIFO or device is never waited on: it is
    opened without blocking and its type checked on the open descriptor)."""
    try:
        data = read_file_within(path, limit)
    except (OSError, ValueError):  # FileTooLarge included
        return None
    return data.decode("utf-8", "replace")


def object_store_problem(objects: str) -> str | None:
    """Why git must not be pointed at the object folder ``objects`` (None when it may):
    an entry that is neither a folder nor a regular file, an alternates file that is not
    a small regular file or names something other than a folder, alternates deeper than
    git follows them, or more than ``MAX_OBJECT_ENTRIES`` entries. Walked iteratively,
    each folder once by identity (a loop of links cannot keep it going)."""
    pending = [(objects, 0)]
    seen: set[tuple[int, int]] = set()
    entries = 0
    while pending:
        store, depth = pending.pop()
        try:
            status = os.stat(store)
        except OSError:
            return f"{store}: cannot be read"
        if not stat.S_ISDIR(status.st_mode):
            return f"{store}: not a folder"
        folders = [(store, status)]
        while folders:
            folder, status = folders.pop()
            if (status.st_dev, status.st_ino) in seen:
                continue
            seen.add((status.st_dev, status.st_ino))
            try:
                listing = list(os.scandir(folder))
            except OSError:
                return f"{folder}: cannot be listed"
            entries += len(listing)
            if entries > MAX_OBJECT_ENTRIES:
                return f"{objects}: more than {MAX_OBJECT_ENTRIES:,} entries"
            for entry in listing:
                try:
                    found = entry.stat(follow_symlinks=True)
                except OSError:
                    return f"{entry.path}: a link that leads nowhere"
                if stat.S_ISDIR(found.st_mode):
                    folders.append((entry.path, found))
                elif not stat.S_ISREG(found.st_mode):
                    return f"{entry.path}: not a regular file"
        alternates = os.path.join(store, "info", "alternates")
        if not os.path.lexists(alternates):
            continue
        text = _read_small(alternates)
        if text is None:
            return f"{alternates}: not a small regular file"
        for line in text.splitlines():
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            if depth + 1 > MAX_ALTERNATES:
                return f"{alternates}: alternates nested more than {MAX_ALTERNATES} deep"
            pending.append((os.path.join(store, line.strip('"')), depth + 1))
    return None


def git_dir(folder: str) -> str | None:
    """The repository's git folder (``.git``, or where a ``.git`` file points)."""
    dot_git = os.path.join(folder, ".git")
    if os.path.isdir(dot_git):
        return dot_git
    text = _read_small(dot_git)
    if text is None or not text.startswith("gitdir:"):
        return None
    target = text[len("gitdir:"):].strip()
    target = target if os.path.isabs(target) else os.path.join(folder, target)
    return target if os.path.isdir(target) else None


def _common_dir(gitdir: str) -> str:
    text = _read_small(os.path.join(gitdir, "commondir"))
    if text is None:
        return gitdir
    common = text.strip()
    common = common if os.path.isabs(common) else os.path.join(gitdir, common)
    return common if os.path.isdir(common) else gitdir


def _packed_refs(common: str) -> dict[str, str]:
    text = _read_small(os.path.join(common, "packed-refs"), MAX_PACKED_REFS_BYTES)
    refs: dict[str, str] = {}
    for line in (text or "").splitlines():
        sha, _, name = line.partition(" ")
        if _SHA.match(sha) and name:
            refs[name.strip()] = sha
    return refs


def head_sha(gitdir: str) -> str | None:
    """HEAD's commit SHA, following symbolic refs (at most a few levels)."""
    common = _common_dir(gitdir)
    text = _read_small(os.path.join(gitdir, "HEAD"))
    for _ in range(5):
        if text is None:
            return None
        text = text.strip()
        if _SHA.match(text):
            return text
        if not text.startswith("ref:"):
            return None
        ref = text[4:].strip()
        if not _REF.match(ref) or ".." in ref:
            return None
        loose = _read_small(os.path.join(gitdir, ref)) or _read_small(os.path.join(common, ref))
        text = loose if loose is not None else _packed_refs(common).get(ref)
    return None


def safe_environment(home: str) -> dict[str, str]:
    """An environment in which git reads no configuration file but ours."""
    return {
        "PATH": os.environ.get("PATH", os.defpath),
        "HOME": home,
        "XDG_CONFIG_HOME": home,
        "GIT_CONFIG_NOSYSTEM": "1",
        "GIT_CONFIG_GLOBAL": os.devnull,
        "GIT_CONFIG_SYSTEM": os.devnull,
        "GIT_TERMINAL_PROMPT": "0",
        "GIT_PAGER": "cat",
        "PAGER": "cat",
        "GIT_ASKPASS": "",
        "SSH_ASKPASS": "",
        "GIT_OPTIONAL_LOCKS": "0",
        "GIT_NO_REPLACE_OBJECTS": "1",
        "LC_ALL": "C",
    }


def commit_count(folder: str) -> tuple[int | None, str]:
    """(number of commits reachable from HEAD, HEAD's SHA); (None, "") when unknown."""
    gitdir = git_dir(folder)
    if gitdir is None:
        return None, ""
    head = head_sha(gitdir)
    common = _common_dir(gitdir)
    objects = os.path.join(common, "objects")
    # object_store_problem also refuses a missing ``objects`` or one that is no folder.
    if head is None or object_store_problem(objects):
        return None, ""
    git = shutil.which("git")
    if git is None:
        return None, ""
    with tempfile.TemporaryDirectory(prefix="launch-linter-git-") as scratch:
        # Our own bare repository: its config is ours, its objects are the corpus's.
        home = os.path.join(scratch, "home")
        own = os.path.join(scratch, "repo.git")
        for sub in ("home", "repo.git/objects/info", "repo.git/refs", "repo.git/hooks"):
            os.makedirs(os.path.join(scratch, sub))
        with open(os.path.join(own, "HEAD"), "w", encoding="ascii") as handle:
            handle.write(head + "\n")
        with open(os.path.join(own, "config"), "w", encoding="ascii") as handle:
            handle.write("[core]\n\trepositoryformatversion = 0\n\tbare = true\n")
        with open(os.path.join(own, "objects", "info", "alternates"), "w",
                  encoding="utf-8", errors="surrogateescape") as handle:
            handle.write(os.path.abspath(objects) + "\n")
        shallow = _read_small(os.path.join(common, "shallow"), 16 * 1024 * 1024)
        if shallow is not None:
            with open(os.path.join(own, "shallow"), "w", encoding="ascii",
                      errors="replace") as handle:
                handle.write(shallow)
        command = [git, "--no-pager", "--git-dir", own]
        for setting in _SAFE_CONFIG:
            command += ["-c", setting]
        try:
            done = subprocess.run(
                [*command, "rev-list", "--count", head], capture_output=True, text=True,
                timeout=GIT_TIMEOUT_S, check=False, env=safe_environment(home), cwd=scratch,
                stdin=subprocess.DEVNULL,
            )
        except (OSError, subprocess.TimeoutExpired):
            return None, ""
    count = done.stdout.strip()
    if done.returncode != 0 or not count.isdigit():
        return None, ""
    return int(count), head
