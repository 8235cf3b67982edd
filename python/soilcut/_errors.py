"""The exceptions of soilcut."""

from __future__ import annotations


class CaseError(ValueError):
    """A case that cannot be read or is out of range.

    The message is the command line's (``soilcut check``): it names the key
    and the allowed range, e.g. ``blade.depth: must be a finite number > 0
    (got -1)``. ``key`` is that dotted key, or None when the message is about
    the whole text (a TOML syntax error) or a study's argument.
    """

    def __init__(self, message: str, key: str | None = None) -> None:
        super().__init__(message)
        self.key = key

    def __reduce__(self):  # keeps `key` across processes (executors)
        return (type(self), (str(self), self.key))


class StepError(ValueError):
    """An increment that cannot be made: none has an admissible mechanism
    (every candidate violates β > 0 and β + φ + φw < 90°), so the case
    cannot be simulated further, or a step was asked for after the case's
    travel had been reached (``Simulation.advance_to`` goes beyond it; the
    message says which). The command line reports the first as bad input
    too (exit code 2).

    ``steps`` holds the records of the increments made before the one that
    failed, by the call that raised (:meth:`soilcut.Simulation.advance_to`
    makes several); the simulation stands after the last of them. They
    are not pickled with the error (a record is a native object of this
    process).

    ``result``, from :func:`soilcut.run`, is the run of those increments (a
    :class:`soilcut.RunResult` whose ``summary["stopped"]`` says where and
    why it stopped; ``save`` writes its folder as ``soilcut run`` keeps
    it), or None when no increment was made or from another call.
    """

    def __init__(self, message: str, key: str | None = None, steps: list | None = None) -> None:
        super().__init__(message)
        self.key = key
        self.steps = [] if steps is None else steps
        self.result = None

    def __reduce__(self):
        return (type(self), (str(self), self.key))


class SnapshotError(ValueError):
    """Bytes that :meth:`soilcut.Simulation.from_snapshot` cannot restore:
    not a snapshot, a snapshot of another version of soilcut (the model's
    numbers may differ between versions, so only its own are restored),
    truncated, corrupt (its checksum does not match) or holding a state no
    run reaches. The message names which, and where."""

    def __init__(self, message: str, key: str | None = None) -> None:
        super().__init__(message)
        self.key = key

    def __reduce__(self):
        return (type(self), (str(self), self.key))


class AccuracyWarning(UserWarning):
    """A case that runs where the model is known to cost accuracy: a blade
    narrower than a sixth of its depth, which fails the soil sideways below
    a critical depth that the side crescents do not describe
    (``docs/model.md`` §16.4). ``soilcut run`` prints the same message on
    stderr."""


class CaseFormWarning(FutureWarning):
    """A case file with a key in the form of an earlier version, which
    still runs (``run.vertex_spacing = 0`` for the node grid, now
    ``run.ground = "nodes"``): the message says what to write instead.
    ``soilcut run`` prints the same message on stderr as a notice."""
