"""Evaluate a mined database: lint its file versions with its own beliefs, and write the
table, the chart and the history.

The database says which files there are, their versions, their repository's maturity and
the mined beliefs; it does not keep file contents, so each version is read again from the
corpus folder the database was mined from (its ``corpus`` entry), through the miner's own
corpus reader, and checked against the SHA-256 the database recorded.
"""

from __future__ import annotations

import hashlib
import json
import os
from collections import Counter
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from launch_linter.beliefs_files import BeliefsNotFound, load_beliefs
from launch_linter.engine import LintOptions
from launch_linter.evaluation.chart import chart_available, write_chart
from launch_linter.evaluation.history import History, follow_history, render_history
from launch_linter.evaluation.lint import Linted, LintOutcome, Version, lint_bytes
from launch_linter.evaluation.study import STUDY_FILES
from launch_linter.evaluation.table import FaultTable, fault_table, is_fault_rule, render_csv
from launch_linter.evaluation.table import render_markdown as render_table
from launch_linter.mining.ingest import MANIFEST, CorpusEntry, CorpusError, read_corpus
from launch_linter.mining.store import Store, StoredVersion, StoreError
from launch_linter.model.beliefs import BELIEF_CLASSES, BeliefSet
from launch_linter.resolve.xml_safe import read_launch_bytes
from launch_linter.rules import rules_for_profile

OUTPUTS = ("table.md", "table.csv", "rules.png", "history.md")
CHART = "rules.png"

STUDY = "study"
"""Table IV reproduces the study: its checks and severities (docs/severity.md)."""


class EvaluationError(Exception):
    """The database or its corpus cannot be evaluated."""


@dataclass(frozen=True)
class Scope:
    """What was evaluated, for the outputs' preambles."""

    corpus: str
    p0: float
    mature_commits: int
    min_z: float
    beliefs: BeliefSet
    immature_repos: int
    versions: int
    not_linted: tuple[tuple[str, str], ...]
    """(repo:path@version, reason) of stored versions that could not be linted."""
    strongest: float | None
    """The highest z of any belief mined into the database (None when there is none)."""


@dataclass(frozen=True)
class Evaluation:
    scope: Scope
    table: FaultTable
    history: History


def _manifest_head_paths(root: str) -> dict[tuple[str, str, str], tuple[str, ...]]:
    """(repo, path, sha256) → ``head_paths`` of a manifest corpus.

    The store keeps each version under the path it had then; the manifest also says which
    HEAD files' histories hold a version whose file was renamed or copied since, which the
    history needs to compare it with the right latest file.
    """
    out: dict[tuple[str, str, str], tuple[str, ...]] = {}
    path = os.path.join(root, MANIFEST)
    if not os.path.isfile(path):
        return out
    try:
        with open(path, encoding="utf-8") as handle:
            for line in handle:
                try:
                    row = json.loads(line)
                except json.JSONDecodeError:
                    continue
                heads = row.get("head_paths") if isinstance(row, dict) else None
                if isinstance(heads, list) and all(isinstance(h, str) for h in heads):
                    key = (str(row.get("repo")), str(row.get("path")), str(row.get("sha256")))
                    out[key] = tuple(heads)
    except (OSError, UnicodeDecodeError) as exc:
        raise EvaluationError(f"cannot read {path}: {exc}") from None
    return out


def _read(entry: CorpusEntry, sha256: str) -> bytes | str:
    """The bytes of ``entry``, or why they cannot be used."""
    try:
        data = read_launch_bytes(entry.source)
    except OSError as exc:
        return f"cannot read {entry.source}: {exc.strerror or exc}"
    if hashlib.sha256(data).hexdigest() != sha256:
        return f"{entry.source} changed since it was mined"
    return data


def lint_versions(
    stored: Sequence[StoredVersion],
    entries: Mapping[tuple[str, str, str], CorpusEntry],
    head_paths: Mapping[tuple[str, str, str], tuple[str, ...]],
    options: LintOptions,
) -> tuple[list[Linted], list[tuple[str, str]]]:
    """Lint every stored version whose content is in the corpus; each distinct content once
    per name and package roots (what the front-end's reading can depend on)."""
    linted: list[Linted] = []
    skipped: list[tuple[str, str]] = []
    cache: dict[tuple[str, str, tuple[str, ...]], LintOutcome] = {}
    for row in stored:
        where = f"{row.repo}:{row.path}@{row.version}"
        if row.sha256 is None:
            skipped.append((where, "unreadable when mined"))
            continue
        entry = entries.get((row.repo, row.path, row.version))
        if entry is None:
            skipped.append((where, "not in the corpus folder any more"))
            continue
        key = (row.sha256, entry.parse_path, entry.package_roots)
        result = cache.get(key)
        if result is None:
            data = _read(entry, row.sha256)
            if isinstance(data, str):
                skipped.append((where, data))
                continue
            result = cache[key] = lint_bytes(data, entry.parse_path, entry.package_roots, options)
        status, transforms, diagnostics = result
        version = Version(
            row.repo, row.path, row.version, row.latest, row.mature,
            head_paths.get((row.repo, row.path, row.sha256), ()),
        )
        linted.append(Linted(version, status, transforms, diagnostics))
    return linted, skipped


def _corpus_entries(root: str) -> tuple[dict[tuple[str, str, str], CorpusEntry], str, str]:
    """(entries by (repo, path, version), corpus kind, absolute root) of the mined corpus."""
    if not root or not os.path.isdir(root):
        raise EvaluationError(
            f"the database was mined from the corpus folder {root!r}, which is not a folder "
            "here (run from the folder 'launch-linter mine' ran in, or mine again)"
        )
    try:
        corpus = read_corpus(root)
    except CorpusError as exc:
        raise EvaluationError(str(exc)) from None
    entries = {(e.ref.repo, e.ref.path, e.ref.version): e for e in corpus.entries}
    return entries, corpus.kind, corpus.root


def evaluate(db: str, min_z: float, beliefs_spec: str | None = None) -> Evaluation:
    """Lint the versions stored in ``db`` with the beliefs mined into it at ``min_z`` (or
    those of ``beliefs_spec``, as ``check --beliefs`` reads it), and count."""
    try:
        with Store(db, create=False) as store:
            meta = store.meta()
            if "p0" not in meta:
                raise EvaluationError(f"{db}: nothing mined yet (run 'launch-linter mine')")
            stored = store.file_versions()
            every = store.beliefs()
    except StoreError as exc:
        raise EvaluationError(str(exc)) from None
    p0 = float(meta["p0"])
    if beliefs_spec is None:
        beliefs = BeliefSet("database", min_z, tuple(b for b in every if b.z >= min_z), p0)
    else:
        try:
            beliefs = load_beliefs(beliefs_spec, min_z)
        except BeliefsNotFound as exc:
            raise EvaluationError(str(exc)) from None
    entries, kind, root = _corpus_entries(meta.get("corpus", ""))
    heads = _manifest_head_paths(root) if kind == "manifest" else {}
    options = LintOptions(beliefs=beliefs, profile=STUDY)
    linted, skipped = lint_versions(stored, entries, heads, options)
    evaluated = [i for i in linted if i.version.latest and not i.version.mature]
    scope = Scope(
        corpus=meta.get("corpus", ""),
        p0=p0,
        mature_commits=int(meta.get("mature_commits", 30)),
        min_z=min_z,
        beliefs=beliefs,
        immature_repos=len({r.repo for r in stored if not r.mature}),
        versions=len(stored),
        not_linted=tuple(skipped),
        strongest=max((b.z for b in every), default=None),
    )
    rules = rules_for_profile(STUDY)
    history = follow_history(linted, [r.id for r in rules if is_fault_rule(r)])
    return Evaluation(scope, fault_table(evaluated, rules), history)


def _belief_counts(beliefs: BeliefSet) -> str:
    counts = Counter(b.cls for b in beliefs.beliefs)
    return ", ".join(f"{cls} {counts[cls]}" for cls in BELIEF_CLASSES)


def preamble(scope: Scope, table: FaultTable) -> list[str]:
    """Lines that say what was linted and with which beliefs."""
    source = (
        f"mined into the same database from its mature repositories (p0 = {scope.p0:g})"
        if scope.beliefs.source == "database"
        else f"read from `{scope.beliefs.source}`"
    )
    lines = [
        f"- Corpus: `{scope.corpus}`, {scope.versions} stored file versions; a repository "
        f"is mature with at least {scope.mature_commits} commits.",
        f"- Linted: the latest version of each file of the immature repositories: "
        f"{table.files} files of {table.repos} repositories "
        f"({scope.immature_repos} immature repositories in the database).",
        f"- Beliefs: {len(scope.beliefs.beliefs)} with z ≥ {scope.min_z:g}, {source} "
        f"({_belief_counts(scope.beliefs)}).",
    ]
    if scope.not_linted:
        reasons = Counter(reason for _, reason in scope.not_linted)
        lines.append(
            f"- Not linted: {len(scope.not_linted)} stored versions ("
            + "; ".join(f"{count}: {reason}" for reason, count in reasons.most_common(3))
            + ")."
        )
    return lines


def write_outputs(evaluation: Evaluation, out: str) -> list[str]:
    """Write table.md, table.csv, rules.png and history.md into ``out``; their paths.

    rules.png only with matplotlib (the ``plot`` extra): without it the other files are
    written and rules.png is not among the paths."""
    os.makedirs(out, exist_ok=True)
    lines = preamble(evaluation.scope, evaluation.table)
    with_chart = chart_available()
    paths = [os.path.join(out, n) for n in OUTPUTS if with_chart or n != CHART]
    texts = {
        "table.md": render_table(evaluation.table, lines),
        "table.csv": render_csv(evaluation.table),
        "history.md": render_history(evaluation.history, lines),
    }
    for name, text in texts.items():
        with open(os.path.join(out, name), "w", encoding="utf-8") as handle:
            handle.write(text)
    if not with_chart:
        return paths
    write_chart(
        evaluation.table,
        os.path.join(out, CHART),
        f"Files with each fault: {evaluation.table.files} latest files of immature "
        f"repositories (z ≥ {evaluation.scope.min_z:g}) vs the study's {STUDY_FILES}",
    )
    return paths
