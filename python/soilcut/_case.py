"""Cases: the case file of ``soilcut run`` as a Python value."""

from __future__ import annotations

import os
from collections.abc import Iterable, Mapping
from typing import Any, Union

from . import _soilcut

PathLike = Union[str, "os.PathLike[str]"]


class Case:
    """One case: the blade, the soil and the run, as a case file gives them.

    Make one with :meth:`from_file`, :meth:`from_toml` or :meth:`from_dict`;
    change keys with :meth:`set` (a new case is returned; a case never
    changes). Every case is validated when it is made, exactly as
    ``soilcut run`` validates its case file: a bad type, a NaN, an unknown
    key or a value out of range raises :class:`soilcut.CaseError` with the
    command line's message.

    A case is parsed once, when it is made: it holds the native case (the
    case file's table and the model's case), which every function of the
    package takes as it is.

    Units are those of the case file (see the README's table of keys):
    lengths in any consistent unit (the paper's cases use mm), angles in
    degrees, the unit weight in force per length³ of the same unit.
    """

    __slots__ = ("_native",)

    def __init__(self, text: str) -> None:
        """The case of a case file's TOML ``text`` (same as :meth:`from_toml`)."""
        if not isinstance(text, str):
            raise TypeError(
                f"Case(text) takes the TOML text of a case file, not {type(text).__name__}; "
                "use Case.from_dict or Case.from_file"
            )
        self._native = _soilcut.NativeCase.from_toml(text)

    @classmethod
    def _from_native(cls, native: _soilcut.NativeCase) -> Case:
        case = cls.__new__(cls)
        case._native = native
        return case

    @classmethod
    def from_toml(cls, text: str) -> Case:
        """The case of a case file's TOML text."""
        return cls(text)

    @classmethod
    def from_file(cls, path: PathLike) -> Case:
        """Reads a case file (TOML, UTF-8). Raises ``OSError`` if it cannot be
        read and :class:`soilcut.CaseError`, its message starting with the
        path, if it is not a valid case."""
        if not isinstance(path, (str, os.PathLike)):
            raise TypeError(
                f"Case.from_file takes a path (str or os.PathLike), not {type(path).__name__}"
            )
        return cls._from_native(_soilcut.NativeCase.from_file(path))

    @classmethod
    def from_dict(cls, d: Mapping[str, Any]) -> Case:
        """The case of nested dicts shaped like the case file, e.g.
        ``{"name": "a", "model": "original", "blade": {"depth": 20, ...}, ...}``."""
        return cls._from_native(_soilcut.NativeCase.from_dict(dict(d)))

    def set(self, key: str, value: Any) -> Case:
        """A new case with the dotted ``key`` set to ``value``, as
        ``soilcut run --set key=value`` sets it (any key of the case file;
        tables as dicts): ``case.set("soil.friction.peak", 36)``."""
        return self.update({key: value})

    def update(self, changes: Mapping[str, Any] | Iterable[tuple[str, Any]]) -> Case:
        """A new case with several dotted keys set, in order:
        ``case.update({"run.increment": 0.2, "run.travel": 40})``."""
        pairs = list(changes.items() if isinstance(changes, Mapping) else changes)
        for pair in pairs:
            if not (isinstance(pair, tuple) and len(pair) == 2 and isinstance(pair[0], str)):
                raise TypeError(
                    "update: changes must be a mapping of dotted keys to values or "
                    f"(key, value) pairs, got the item {pair!r}"
                )
        return Case._from_native(self._native.set_keys(pairs))

    def to_toml(self) -> str:
        """The case file's text: as given, or rewritten after :meth:`set`
        (only the keys given)."""
        return self._native.to_toml()

    def to_dict(self) -> dict[str, Any]:
        """The case file as nested dicts (only the keys given)."""
        return self._native.to_dict()

    def resolved(self) -> Case:
        """The same case with every default filled in: the case of the
        ``case.resolved.toml`` that ``soilcut run`` writes."""
        return Case._from_native(self._native.resolved())

    def resolved_toml(self) -> str:
        """The ``case.resolved.toml`` text that ``soilcut run`` writes."""
        return self._native.resolved_toml()

    def __getitem__(self, key: str) -> Any:
        """The value of a dotted key of the resolved case:
        ``case["soil.repose"]`` (a default filled in if not given)."""
        value = self._native.get(key)
        if value is None:
            raise KeyError(
                f"{key}: not in this case as resolved (no such key, or one that it"
                " does not use, as run.vertex_spacing on the node grid; the keys"
                " are in docs/guide/case-keys.md)"
            )
        return value

    @property
    def name(self) -> str:
        """The case's name (it names the output folder ``out/<name>``)."""
        return self._native.names()[0]

    @property
    def title(self) -> str:
        """The case's title (its name if none is given)."""
        return self._native.names()[1]

    @property
    def model(self) -> str:
        """``"original"`` (slip line, softening) or ``"refined"`` (shear band)."""
        return self._native.names()[2]

    def __eq__(self, other: object) -> bool:
        """Two cases are equal when their resolved case files are."""
        return isinstance(other, Case) and self._native == other._native

    def __hash__(self) -> int:
        return hash(self._native)

    def __repr__(self) -> str:
        return f"Case(name={self.name!r}, model={self.model!r})"

    def __reduce__(self):
        return (Case, (self.to_toml(),))


def case_of(case: Case | PathLike) -> Case:
    """A :class:`Case` itself, or the case of a case file's path or text (a
    path: ``os.PathLike``, or one line ending in ``.toml``, naming a file or
    without ``=``, so that a mistyped path is a ``FileNotFoundError``)."""
    if isinstance(case, Case):
        return case
    return Case._from_native(_soilcut.NativeCase.of(case))


def native_of(case: Case | PathLike) -> _soilcut.NativeCase:
    """The native handle of :func:`case_of`'s case."""
    return case_of(case)._native
