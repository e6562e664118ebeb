"""Records: the contract types as plain classes whose methods are written in the source.

The contract types were frozen dataclasses. ``dataclasses`` writes each class's methods as
source text and compiles it when the module is imported (six ``exec`` calls per frozen
class): for the 46 types on the way of a one-file ``check`` that was a third of the
linter's start-up. A record keeps the dataclass's behaviour exactly (fields in order,
defaults, equality and hash over the compared fields, ``repr``, immutability, pickling for
``--jobs``) with the methods here, shared by every record, and an ``__init__`` written in
each class; ``tests/test_records.py`` checks each type against the contract it had as a
dataclass.

A record class lists its fields in ``__slots__`` (in the dataclass's field order) and, where
some are left out of equality or are worked out later, names the compared ones in
``_compared`` and the non-field slots in ``_private``.
"""

from __future__ import annotations

from operator import attrgetter

TYPE_CHECKING = False  # typing is not imported at run time: start-up (docs/performance.md)
if TYPE_CHECKING:
    from typing import Any, Callable, ClassVar, TypeVar

    T = TypeVar("T")

_set = object.__setattr__
"""Sets a slot of a frozen record (its own ``__setattr__`` refuses): for ``__init__``."""


class FrozenInstanceError(AttributeError):
    """Assigning to or deleting a field of a frozen record (like ``dataclasses``')."""


def _key_of(names: tuple[str, ...]) -> Callable[[Any], tuple[Any, ...]]:
    """A function giving the tuple of ``names`` of an instance (a tuple even for one)."""
    if not names:
        return lambda _: ()
    if len(names) == 1:
        single = attrgetter(names[0])
        return lambda record: (single(record),)
    return attrgetter(*names)


class Record:
    """Equality, hash, ``repr``, ordering, pickling and immutability over ``_fields``."""

    __slots__ = ()
    _fields: ClassVar[tuple[str, ...]] = ()
    """The fields in order: the ``__init__`` parameters, the ``repr``, pickling."""
    _compared: ClassVar[tuple[str, ...]] = ()
    """The fields equality, hash and ordering compare (all of them unless a class says)."""
    _private: ClassVar[tuple[str, ...]] = ()
    """Slots that are not fields (a value worked out once, kept in the instance)."""
    # Called with the instance: ``...`` because they are kept as static methods.
    _key: ClassVar[Callable[..., tuple[Any, ...]]]
    _values: ClassVar[Callable[..., tuple[Any, ...]]]

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        if "_sealed_as" in cls.__dict__:
            return  # an open twin (see ``_open``): its class's fields, never seen outside
        private = cls.__dict__.get("_private", ())
        cls._fields = tuple(n for n in cls.__dict__.get("__slots__", ()) if n not in private)
        compared = cls.__dict__.get("_compared", cls._fields)
        cls._compared = compared
        cls._key = staticmethod(_key_of(compared))
        cls._values = staticmethod(_key_of(cls._fields))

    def __repr__(self) -> str:
        inner = ", ".join(f"{name}={getattr(self, name)!r}" for name in self._fields)
        return f"{type(self).__qualname__}({inner})"

    def __eq__(self, other: object) -> bool:
        if other.__class__ is self.__class__:
            return bool(self._key(self) == self._key(other))
        return NotImplemented

    def __hash__(self) -> int:
        return hash(self._key(self))

    def __setattr__(self, name: str, value: object) -> None:
        raise FrozenInstanceError(f"cannot assign to field {name!r}")

    def __delattr__(self, name: str) -> None:
        raise FrozenInstanceError(f"cannot delete field {name!r}")

    def __reduce__(self) -> tuple[type[Record], tuple[Any, ...]]:
        # Rebuilt through ``__init__`` (a frozen record refuses the slot-by-slot default).
        return (type(self), self._values(self))


class MutableRecord(Record):
    """A record whose fields may be assigned (a dataclass without ``frozen``): equal by
    value, so unhashable, as such a dataclass is."""

    __slots__ = ()
    __hash__ = None  # type: ignore[assignment]
    # object's own (in C): a record's refusals undone.
    __setattr__ = object.__setattr__  # type: ignore[assignment]
    __delattr__ = object.__delattr__


class OrderedRecord(Record):
    """A record that also sorts, by its compared fields in order (``order=True``)."""

    __slots__ = ()

    def __lt__(self, other: object) -> bool:
        if other.__class__ is self.__class__:
            return bool(self._key(self) < self._key(other))
        return NotImplemented

    def __le__(self, other: object) -> bool:
        if other.__class__ is self.__class__:
            return bool(self._key(self) <= self._key(other))
        return NotImplemented

    def __gt__(self, other: object) -> bool:
        if other.__class__ is self.__class__:
            return bool(self._key(self) > self._key(other))
        return NotImplemented

    def __ge__(self, other: object) -> bool:
        if other.__class__ is self.__class__:
            return bool(self._key(self) >= self._key(other))
        return NotImplemented


def _open(record: Record) -> None:
    """Lets ``__init__`` assign the fields of a frozen record as plain attributes, until
    :func:`_seal`: the record is meanwhile an instance of its class's open twin (the same
    slots, ``object``'s ``__setattr__``).

    For the records made by the thousand per file (a node, a static transform): thirteen
    or twenty-six ``_set`` calls (each a call of ``object.__setattr__``) cost three to five
    times what two changes of class and plain assignments do."""
    cls = type(record)
    twin = _TWINS.get(cls)  # a dict, not ``cls.__dict__``: no mapping proxy made per record
    if twin is None:
        twin = _TWINS[cls] = type(cls.__name__, (cls,), {
            "__slots__": (), "__module__": cls.__module__, "__qualname__": cls.__qualname__,
            "__setattr__": object.__setattr__, "__delattr__": object.__delattr__,
            "_sealed_as": cls,
        })
    _set(record, "__class__", twin)


_TWINS: dict[type, type] = {}
"""Each record class opened so far -> its open twin (see :func:`_open`)."""


def _seal(record: Record) -> None:
    """Gives back to a record opened by :func:`_open` its own (frozen) class."""
    record.__class__ = record._sealed_as  # type: ignore[attr-defined]


def replace(record: T, **changes: Any) -> T:
    """A copy of ``record`` with ``changes``: ``dataclasses.replace`` for records, and for
    the dataclasses that are not on the start-up path."""
    if not isinstance(record, Record):
        import dataclasses  # only for a dataclass: the records never need the module

        return dataclasses.replace(record, **changes)  # type: ignore[type-var]
    values = dict(zip(record._fields, record._values(record)))
    unknown = set(changes).difference(values)
    if unknown:
        raise TypeError(f"{type(record).__qualname__} has no field {sorted(unknown)[0]!r}")
    values.update(changes)
    return type(record)(**values)


def fields(record: Record | type[Record]) -> tuple[str, ...]:
    """The names of the fields, in order (``dataclasses.fields`` for records)."""
    return record._fields


def compared_fields(record: Record | type[Record]) -> tuple[str, ...]:
    """The names of the fields equality and hash compare."""
    return record._compared
