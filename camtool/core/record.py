"""Frozen value classes declared by annotations, at no cost when their module is imported.

A preset (:mod:`camtool.presets.schema`) is a frozen value: fields with
defaults, equality and a hash over the fields that are compared, a readable
``repr``. :func:`dataclasses.dataclass` makes exactly that, but it writes and
compiles each class's methods when the class is created, and importing
:mod:`dataclasses` imports :mod:`inspect`; on a command that names one lens
preset the two were about a quarter of ``python -c "import click"``. A
:class:`Record` subclass gets the same behaviour from methods written once
here, reading the field list its class body declares.

>>> class Point(Record):
...     x: float
...     y: float = 0.0
...     label: str | None = field(default=None, compare=False)
>>> p = Point(1.0, label="a")
>>> p, p == Point(1.0, 0.0, "b"), hash(p) == hash(Point(1.0))
(Point(x=1.0, y=0.0, label='a'), True, True)
>>> p.x = 2.0
Traceback (most recent call last):
...
AttributeError: cannot assign to field 'x' of a frozen Point
>>> Point()
Traceback (most recent call last):
...
TypeError: Point() missing argument 'x'
>>> [f.name for f in fields(p)]
['x', 'y', 'label']
>>> replace(p, y=2.0)
Point(x=1.0, y=2.0, label='a')

:class:`NamedTuple` is :class:`typing.NamedTuple` (type checkers see that one)
at a third of its cost when a class is created: ``typing`` turns each string
annotation into a ``ForwardRef``, compiling it, which took about 55 µs of each
of the 35 named tuples a ``dof`` command creates. The class made is the same
:func:`collections.namedtuple` with the body's methods and annotations.

>>> class Pair(NamedTuple):
...     near: float
...     far: float = float("inf")
...     def total(self) -> float:
...         return self.far - self.near
>>> Pair(1.0), Pair(1.0, 3.0).total(), Pair._fields, Pair.__annotations__["far"]
(Pair(near=1.0, far=inf), 2.0, ('near', 'far'), 'float')
"""

from __future__ import annotations

import collections
import itertools
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # how type checkers learn the constructor; nothing at run time (typing has it from 3.11 only)
    from typing import NamedTuple as NamedTuple

    from typing_extensions import dataclass_transform
else:
    def dataclass_transform(**_options: Any) -> Any:
        return lambda cls: cls

__all__ = ["Field", "NamedTuple", "Record", "field", "fields", "replace"]

_MISSING: Any = object()


class Field:
    """One declared field: its name, its default (or none) and whether it is compared, hashed and shown."""

    __slots__ = ("compare", "default", "hash", "name", "repr")

    def __init__(self, name: str, default: Any = _MISSING, compare: bool = True, hash: bool = True,
                 repr: bool = True) -> None:
        self.name, self.default, self.compare, self.hash, self.repr = name, default, compare, hash, repr

    def named(self, name: str) -> Field:
        return Field(name, self.default, self.compare, self.hash, self.repr)


def field(*, default: Any = _MISSING, compare: bool = True, hash: bool | None = None, repr: bool = True) -> Any:
    """A field's options, as :func:`dataclasses.field` takes them (``hash`` follows ``compare`` unless given)."""
    return Field("", default, compare, compare if hash is None else hash, repr)


@dataclass_transform(frozen_default=True, field_specifiers=(field,))
class Record:
    """A frozen value class: the annotated names of its body are its fields, in order (see the module)."""

    # the values live in the instance __dict__; a computed hash in a slot of its own, never pickled or copied
    __slots__ = ("__dict__", "__weakref__", "_record_hash")

    __fields__: tuple[Field, ...] = ()
    __names__: frozenset[str] = frozenset()
    _record_order: tuple[str, ...] = ()
    _record_defaults: dict[str, Any] = {}  # noqa: RUF012 - each class's own, set once when it is created
    _record_all_compared = True

    def __init_subclass__(cls, **kwargs: Any) -> None:
        super().__init_subclass__(**kwargs)
        declared: list[Field] = []
        # the class body's own annotations; inspect.get_annotations would import inspect, what this module avoids
        for name, annotation in cls.__dict__.get("__annotations__", {}).items():  # noqa: RUF063
            if str(annotation).startswith(("ClassVar", "typing.ClassVar")):
                continue
            value = cls.__dict__.get(name, _MISSING)
            spec = value.named(name) if isinstance(value, Field) else Field(name, value)
            if spec.default is _MISSING and declared and declared[-1].default is not _MISSING:
                raise TypeError(f"{cls.__name__}: field {name!r} without a default follows one with a default")
            if value is not _MISSING:
                delattr(cls, name)
            declared.append(spec)
        cls.__fields__ = tuple(declared)
        cls.__names__ = frozenset(spec.name for spec in declared)
        cls._record_order = tuple(spec.name for spec in declared)
        cls._record_defaults = {spec.name: spec.default for spec in declared if spec.default is not _MISSING}
        cls._record_all_compared = all(spec.compare for spec in declared)

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        order = self._record_order
        values = dict(self._record_defaults)
        if args:
            if len(args) > len(order):
                raise TypeError(f"{type(self).__name__}() takes {len(order)} arguments, {len(args)} given")
            values.update(zip(order, args))
        if kwargs:
            if not self.__names__.issuperset(kwargs) or (args and not kwargs.keys().isdisjoint(order[:len(args)])):
                name = next(n for n in kwargs if n not in self.__names__ or n in order[:len(args)])
                raise TypeError(f"{type(self).__name__}() got "
                                f"{'an unexpected' if name not in self.__names__ else 'a second'} argument {name!r}")
            values.update(kwargs)
        if len(values) < len(order):
            missing = next(name for name in order if name not in values)
            raise TypeError(f"{type(self).__name__}() missing argument {missing!r}")
        object.__setattr__(self, "__dict__", values)

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError(f"cannot assign to field {name!r} of a frozen {type(self).__name__}")

    def __delattr__(self, name: str) -> None:
        raise AttributeError(f"cannot delete field {name!r} of a frozen {type(self).__name__}")

    def _compared(self) -> tuple[Any, ...]:
        return tuple(self.__dict__[spec.name] for spec in self.__fields__ if spec.compare)

    def __eq__(self, other: object) -> bool:
        if other.__class__ is not self.__class__:
            return NotImplemented
        assert isinstance(other, Record)
        if self._record_all_compared:  # the values dict holds exactly the fields: one comparison in C
            return self.__dict__ == other.__dict__
        return self._compared() == other._compared()

    def __hash__(self) -> int:
        # computed once: a prescription is a key of several caches, hashed on every call of a rung
        try:
            return self._record_hash  # type: ignore[attr-defined]
        except AttributeError:
            pass
        value = hash(tuple(self.__dict__[spec.name] for spec in self.__fields__ if spec.hash))
        object.__setattr__(self, "_record_hash", value)
        return value

    def __getstate__(self) -> dict[str, Any]:
        return self.__dict__  # the values only: a hash depends on the process (string hashing is salted)

    def __setstate__(self, state: dict[str, Any]) -> None:
        object.__setattr__(self, "__dict__", dict(state))

    def __repr__(self) -> str:
        shown = ", ".join(f"{spec.name}={self.__dict__[spec.name]!r}" for spec in self.__fields__ if spec.repr)
        return f"{type(self).__name__}({shown})"


def fields(record: Record | type[Record]) -> tuple[Field, ...]:
    """The fields of a record (or a record class), in declaration order."""
    return record.__fields__


def replace(record: Any, /, **changes: Any) -> Any:
    """A copy of ``record`` with the fields ``changes`` names set anew (:func:`dataclasses.replace`'s contract)."""
    return type(record)(**{**record.__dict__, **changes})


if not TYPE_CHECKING:
    # what typing.NamedTuple's metaclass refuses or leaves to namedtuple (as of CPython 3.11 to 3.13)
    _PROHIBITED = frozenset({"__new__", "__init__", "__slots__", "__getnewargs__", "_fields", "_field_defaults",
                             "_make", "_replace", "_asdict", "_source"})
    _SPECIAL = frozenset({"__module__", "__name__", "__annotations__", "__qualname__", "__classcell__",
                          "__static_attributes__", "__firstlineno__"})

    class _NamedTupleMeta(type):
        def __new__(mcs, typename: str, bases: tuple[type, ...], namespace: dict[str, Any]) -> Any:
            annotations = namespace.get("__annotations__", {})
            names = list(annotations)
            defaults = [namespace[name] for name in names if name in namespace]
            for before, name in itertools.pairwise(names):
                if before in namespace and name not in namespace:
                    raise TypeError(f"Non-default namedtuple field {name} cannot follow default field {before}")
            made = collections.namedtuple(typename, names, defaults=defaults, module=namespace["__module__"])
            made.__annotations__ = made.__new__.__annotations__ = dict(annotations)
            made.__qualname__ = namespace.get("__qualname__", typename)
            for key, value in namespace.items():
                if key in _PROHIBITED:
                    raise AttributeError(f"cannot overwrite NamedTuple attribute {key}")
                if key not in _SPECIAL and key not in made._fields:
                    setattr(made, key, value)
            return made

    # the base a class body names: its subclasses are made by the metaclass (the class form only)
    NamedTuple = type.__new__(_NamedTupleMeta, "NamedTuple", (), {})
