"""camtool.core.record: the frozen value classes of the presets behave as frozen dataclasses of the same fields do."""

from __future__ import annotations

import copy
import dataclasses
import pickle
from typing import Any

import pytest

from camtool.core.record import Record, field, fields, replace
from camtool.presets.schema import Camera, Lens, Sensor


class Point(Record):
    x: float
    y: float = 0.0
    tag: Any = field(default=None, compare=False, repr=False)


@dataclasses.dataclass(frozen=True)
class PointDataclass:
    x: float
    y: float = 0.0
    tag: Any = dataclasses.field(default=None, compare=False, repr=False)


@pytest.mark.parametrize(("args", "kwargs"), [((1.0,), {}), ((1.0, 2.0), {}), ((), {"x": 3.0, "tag": "t"}),
                                              ((1.0,), {"y": 5.0, "tag": [1]})])
def test_construction_equality_hash_and_repr_are_a_frozen_dataclass_s(args, kwargs):
    record, reference = Point(*args, **kwargs), PointDataclass(*args, **kwargs)
    assert repr(record) == repr(reference).replace("PointDataclass", "Point")
    assert [getattr(record, f.name) for f in fields(record)] == [getattr(reference, f.name)
                                                                for f in dataclasses.fields(reference)]
    other = Point(record.x, record.y, tag="another")  # a field left out of the comparison
    assert record == other and hash(record) == hash(other)
    assert record != Point(record.x + 1.0, record.y) and record != reference


@pytest.mark.parametrize(("args", "kwargs", "message"), [
    ((), {}, "missing argument 'x'"), ((1.0, 2.0, 3.0, 4.0), {}, "takes 3 arguments, 4 given"),
    ((1.0,), {"x": 2.0}, "a second argument 'x'"), ((), {"x": 1.0, "z": 2.0}, "an unexpected argument 'z'")])
def test_bad_arguments_are_type_errors(args, kwargs, message):
    with pytest.raises(TypeError, match=message):
        Point(*args, **kwargs)
    with pytest.raises(TypeError):
        PointDataclass(*args, **kwargs)


def test_frozen():
    point = Point(1.0)
    with pytest.raises(AttributeError):
        point.x = 2.0  # type: ignore[misc]
    with pytest.raises(AttributeError):
        del point.y  # type: ignore[misc]
    assert point == Point(1.0)


def test_a_field_without_a_default_after_one_with_is_refused_when_the_class_is_made():
    with pytest.raises(TypeError, match="'b' without a default follows one with a default"):
        class Bad(Record):
            a: int = 0
            b: int


def test_presets_copy_and_pickle_as_values():
    sensor = Sensor("s", "S", 36.0, 24.0, aliases=("full",))
    camera = Camera("c", "C", sensor, 6000, 4000)
    lens = Lens("z", "Z", 24.0, 70.0, 2.8, 22.0, close_focus=((24.0, 380.0, None),))
    for preset in (sensor, camera, lens):
        for twin in (copy.copy(preset), copy.deepcopy(preset), pickle.loads(pickle.dumps(preset))):
            assert twin == preset and hash(twin) == hash(preset) and repr(twin) == repr(preset)
    assert {lens: 1}[Lens("z", "Z", 24.0, 70.0, 2.8, 22.0, close_focus=((24.0, 380.0, None),))] == 1


def test_a_lens_compares_without_its_prescription_and_members():
    # fields declared compare=False (as their dataclass declared them) are left out of equality and the hash
    plain = Lens("p", "P", 50.0, 50.0, 1.8)
    assert plain == Lens("p", "P", 50.0, 50.0, 1.8, prescription=object(), members=(plain,))
    assert " prescription=" not in repr(plain) and " members=" not in repr(plain)


@pytest.mark.parametrize("changes", [{}, {"y": 7.0}, {"x": -1.0, "tag": "t"}])
def test_replace_is_dataclasses_replace(changes):
    record, reference = Point(1.0, 2.0, tag="a"), PointDataclass(1.0, 2.0, tag="a")
    copied, expected = replace(record, **changes), dataclasses.replace(reference, **changes)
    assert [getattr(copied, f.name) for f in fields(copied)] == [getattr(expected, f.name)
                                                                for f in dataclasses.fields(expected)]
    assert record == Point(1.0, 2.0)  # the original is untouched
    with pytest.raises(TypeError):
        replace(record, z=1.0)


def test_the_optics_classes_are_records():
    # the prescription path imports no dataclasses: its three value classes are records
    from camtool.optics.paraxial import FirstOrder
    from camtool.optics.prescription import Prescription, Surface

    surface = Surface(50.0, 5.0, 1.5)
    lens = Prescription((surface, replace(surface, radius_mm=-50.0, stop=True)))
    assert lens == Prescription((Surface(50.0, 5.0, 1.5), Surface(-50.0, 5.0, 1.5, stop=True)))
    assert hash(lens) == hash(Prescription((Surface(50.0, 5.0, 1.5), Surface(-50.0, 5.0, 1.5, stop=True))))
    assert all(issubclass(cls, Record) for cls in (FirstOrder, Prescription, Surface))
