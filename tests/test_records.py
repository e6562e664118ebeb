"""The contract types are records (model/record.py) that behave as the frozen dataclasses
they replaced: ``fixtures/record_contracts.json`` is what each dataclass was (its fields in
order, defaults, which fields are compared and shown), written from the dataclasses before
they were replaced. Each record is checked against a dataclass built from that contract
here: the same ``repr``, equality, hash and ordering, immutability and pickling."""

from __future__ import annotations

import dataclasses
import importlib
import inspect
import json
import pickle
import re
from pathlib import Path
from typing import Any

import pytest

from launch_linter.model import record
from launch_linter.model.record import FrozenInstanceError, Record, _set

CONTRACTS = json.loads(
    (Path(__file__).parent / "fixtures" / "record_contracts.json").read_text(encoding="utf-8"))


def load(qualified: str) -> type[Record]:
    module, _, name = qualified.rpartition(".")
    cls = getattr(importlib.import_module(module), name)
    assert isinstance(cls, type)
    return cls


def reference(cls: type, contract: dict[str, Any]) -> type:
    """The frozen dataclass the contract describes (same name, so the same ``repr``)."""
    specs = []
    for spec in contract["fields"]:
        if spec.get("init", True):
            options = {"compare": spec.get("compare", True), "repr": spec.get("repr", True)}
            specs.append((spec["name"], object, dataclasses.field(**options)))
    made = dataclasses.make_dataclass(cls.__name__, specs, frozen=contract["frozen"],
                                      order=contract["order"])
    made.__qualname__ = cls.__qualname__
    return made


def sample_values(contract: dict[str, Any], tag: str) -> dict[str, Any]:
    """A value for every field of ``__init__``: distinct, hashable, comparable, picklable."""
    return {spec["name"]: f"{tag}{index}"
            for index, spec in enumerate(contract["fields"]) if spec.get("init", True)}


def shown(value: object) -> str:
    """``repr(value)`` without an address; an object without its own ``repr`` by type."""
    text = repr(value)
    if " object at 0x" in text:
        return f"<{type(value).__module__}.{type(value).__qualname__}>"
    return re.sub(r" at 0x[0-9a-f]+>", ">", text)


def violations(cls: type, contract: dict[str, Any]) -> list[str]:
    """How ``cls`` departs from ``contract`` (empty when it keeps it)."""
    found: list[str] = []
    init_fields = [s["name"] for s in contract["fields"] if s.get("init", True)]
    if not issubclass(cls, Record):
        return [f"{cls.__qualname__} is not a record"]
    if list(record.fields(cls)) != init_fields:
        found.append(f"fields {record.fields(cls)} != {init_fields}")
    # The class's own annotations (inspect.get_annotations is 3.10+).
    declared = [n for n in vars(cls).get("__annotations__", {}) if n not in cls._private]
    if declared != init_fields:
        found.append(f"annotated fields {declared} != {init_fields}")
    parameters = list(inspect.signature(cls).parameters.values())
    if [p.name for p in parameters] != init_fields:
        found.append(f"__init__ takes {[p.name for p in parameters]}, not {init_fields}")
        return found
    required = {}
    for parameter, spec in zip(parameters, (s for s in contract["fields"]
                                            if s.get("init", True))):
        if "default" in spec and shown(parameter.default) != spec["default"]:
            found.append(f"{spec['name']} defaults to {parameter.default!r}, not "
                         f"{spec['default']}")
        elif "default" not in spec and "factory" not in spec:
            if parameter.default is not inspect.Parameter.empty:
                found.append(f"{spec['name']} has a default, the contract none")
            required[spec["name"]] = f"required-{spec['name']}"
    defaults = cls(**required)
    for spec in contract["fields"]:
        if "factory" in spec and spec.get("init", True):
            made = getattr(defaults, spec["name"])
            if shown(made) != spec["factory"]:
                found.append(f"{spec['name']} is made as {made!r}, not {spec['factory']}")
    values, others = sample_values(contract, "a"), sample_values(contract, "b")
    made = reference(cls, contract)
    ours, theirs = cls(**values), made(**values)
    if repr(ours) != repr(theirs):
        found.append(f"repr {ours!r} != {theirs!r}")
    if ours != cls(**values):
        found.append("equal values: not equal")
    if contract["frozen"] and hash(ours) != hash(theirs):
        found.append("a hash other than the dataclass's")
    if not contract["frozen"] and getattr(cls, "__hash__", None) is not None:
        found.append("hashable, as a mutable dataclass is not")
    for name in init_fields:
        changed = cls(**dict(values, **{name: others[name]}))
        their_changed = made(**dict(values, **{name: others[name]}))
        if (ours == changed) != (theirs == their_changed):
            found.append(f"equality over {name} is not the dataclass's")
        if contract["order"] and (ours < changed) != (theirs < their_changed):
            found.append(f"ordering over {name} is not the dataclass's")
    if ours.__eq__(theirs) is not NotImplemented:
        found.append("compares equal to another class")
    attempts = [lambda: setattr(ours, "new", 1)]
    if contract["frozen"]:
        attempts += [lambda: setattr(ours, init_fields[0], "x"),
                     lambda: delattr(ours, init_fields[0])]
    for attempt in attempts:
        try:
            attempt()
            found.append("assignment or deletion allowed: not frozen, or a new attribute")
        except AttributeError:
            pass
    if not contract["frozen"]:
        changed = cls(**values)
        setattr(changed, init_fields[0], others[init_fields[0]])
        if getattr(changed, init_fields[0]) != others[init_fields[0]]:
            found.append("a field of a mutable record cannot be assigned")
    for protocol in range(2, pickle.HIGHEST_PROTOCOL + 1):
        again = pickle.loads(pickle.dumps(ours, protocol))
        if type(again) is not cls or again != ours or repr(again) != repr(ours):
            found.append(f"pickle protocol {protocol} does not round-trip")
    return found


@pytest.mark.parametrize("contract", CONTRACTS, ids=[c["class"] for c in CONTRACTS])
def test_record_keeps_its_dataclass_contract(contract: dict[str, Any]) -> None:
    assert violations(load(contract["class"]), contract) == []


class Swapped(Record):
    """Its ``__init__`` and ``repr`` take the fields in the wrong order."""

    line: int
    path: str

    __slots__ = ("line", "path")

    def __init__(self, line: int, path: str = "") -> None:
        _set(self, "line", line)
        _set(self, "path", path)


class Grown(Record):
    path: str
    line: int  # added as a dataclass field would be, without a slot or a parameter

    __slots__ = ("path",)

    def __init__(self, path: str) -> None:
        _set(self, "path", path)


def test_the_check_finds_a_record_that_breaks_its_contract() -> None:
    contract = {"class": "Swapped", "frozen": True, "order": False,
                "fields": [{"name": "path"}, {"name": "line", "default": "0"}]}
    found = violations(Swapped, contract)
    assert any("fields" in v for v in found)
    assert any("__init__ takes" in v for v in found)


def test_a_field_annotated_but_not_slotted_is_caught() -> None:
    contract = {"class": "Grown", "frozen": True, "order": False, "fields": [{"name": "path"}]}
    assert any("annotated fields" in v for v in violations(Grown, contract))


def test_every_record_of_the_source_is_under_contract() -> None:
    """A new record needs its contract in the fixture (and its meta-test above)."""
    source = Path(record.__file__).parents[1]
    named = {c["class"].rpartition(".")[2] for c in CONTRACTS}
    declared = set()
    for path in source.rglob("*.py"):  # the package's records (not this file's examples)
        if path.name == "record.py":
            continue
        for line in path.read_text(encoding="utf-8").splitlines():
            if line.startswith("class ") and line.endswith(
                    ("(Record):", "(OrderedRecord):", "(MutableRecord):")):
                declared.add(line[len("class "):].split("(")[0])
    assert declared == named


def test_replace_copies_with_changes_and_refuses_unknown_fields() -> None:
    from launch_linter.model.diagnostic import Location

    here = Location("a.launch", 3, 4)
    assert record.replace(here, line=5) == Location("a.launch", 5, 4)
    assert here.line == 3
    with pytest.raises(TypeError):
        record.replace(here, row=5)
    with pytest.raises(FrozenInstanceError):
        here.line = 6  # type: ignore[misc]


def test_replace_still_copies_a_dataclass() -> None:
    @dataclasses.dataclass(frozen=True)
    class Plain:
        a: int
        b: int = 0

    assert record.replace(Plain(1), b=2) == Plain(1, 2)


def test_a_private_slot_is_neither_compared_nor_pickled() -> None:
    from launch_linter.model.beliefs import BeliefSet

    empty = BeliefSet.empty()
    assert "_index" not in record.fields(empty)
    assert pickle.loads(pickle.dumps(empty)) == empty
