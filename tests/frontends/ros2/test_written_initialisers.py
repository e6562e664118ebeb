"""The frozen dataclasses of the ROS 2 front-end whose ``__init__`` is written by hand
(for speed: docs/performance.md, "Per file, fifth pass") keep the dataclass's contract:
the same parameters in the same order with the same defaults, every field set, still
frozen, equal to an instance made field by field. A field added to the class but not to
its ``__init__`` fails here."""

from __future__ import annotations

import dataclasses
import inspect

import pytest

from launch_linter.decode_ros2 import Ros2Decoded
from launch_linter.frontends.ros2_actions import DeclareArg, Params, RunNode, Where
from launch_linter.frontends.ros2_python.values import (
    BoundMethod,
    Builtin,
    LazyStr,
    ModuleVal,
    SubsVal,
    Unknown,
)
from launch_linter.model.transform import ArgForm
from launch_linter.resolve.ros2_substitution import Call, Text

WRITTEN = (RunNode, Call, Params, DeclareArg, Ros2Decoded, Unknown, LazyStr, SubsVal,
           ModuleVal, BoundMethod, Builtin, Where, Text)


def _default_of(field: dataclasses.Field[object]) -> object:
    if field.default is not dataclasses.MISSING:
        return field.default
    if field.default_factory is not dataclasses.MISSING:
        return field.default_factory()
    return inspect.Parameter.empty


@pytest.mark.parametrize("cls", WRITTEN, ids=lambda cls: cls.__name__)
def test_the_written_init_takes_the_fields_in_order_with_their_defaults(cls: type) -> None:
    assert "__init__" in cls.__dict__, "the class no longer writes its __init__"
    fields = [f for f in dataclasses.fields(cls) if f.init]
    parameters = list(inspect.signature(cls.__dict__["__init__"]).parameters.values())[1:]
    assert [p.name for p in parameters] == [f.name for f in fields]
    for parameter, field in zip(parameters, fields):
        if field.default_factory is not dataclasses.MISSING:
            # Written as None and made per instance (a shared mutable default is not).
            assert parameter.default is None
        else:
            assert parameter.default == _default_of(field), field.name


@pytest.mark.parametrize("cls", WRITTEN, ids=lambda cls: cls.__name__)
def test_every_field_given_is_kept_and_the_instance_stays_frozen(cls: type) -> None:
    fields = dataclasses.fields(cls)
    given = {f.name: object() for f in fields}
    made = cls(**given)
    # In the instance itself: a field the __init__ forgets would fall back to the
    # class's default silently.
    assert vars(made) == given
    assert made == cls(**given)
    assert dataclasses.replace(made) == made
    with pytest.raises(dataclasses.FrozenInstanceError):
        setattr(made, fields[0].name, None)


@pytest.mark.parametrize("cls", WRITTEN, ids=lambda cls: cls.__name__)
def test_fields_left_out_take_their_defaults(cls: type) -> None:
    fields = dataclasses.fields(cls)
    required = {f.name: object() for f in fields if _default_of(f) is inspect.Parameter.empty}
    made = cls(**required)
    assert set(vars(made)) == {f.name for f in fields}
    for field in fields:
        assert getattr(made, field.name) == required.get(field.name, _default_of(field))


def test_a_default_factory_gives_each_instance_its_own_value() -> None:
    def made() -> Ros2Decoded:
        return Ros2Decoded(ArgForm.INVALID, None, None, None, None, None, (), ())

    first, second = made(), made()
    assert first.sources == {} and first.sources is not second.sources
