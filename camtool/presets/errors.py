"""The two errors of the preset database: a name that is not there, and a file that is wrong."""

from __future__ import annotations

from collections.abc import Sequence

from camtool.core.errors import CamtoolError, FileError


class PresetNotFound(CamtoolError, LookupError):
    """No preset of ``kind`` answers to ``name``.

    ``suggestions`` holds the ids of the closest names (possibly empty); the
    message is one line and ends with "did you mean ...?" when there are any.

    >>> str(PresetNotFound("lens", "canon 5O", ["canon-ef-50mm-f1.8-stm"]))
    "unknown lens 'canon 5O'; did you mean canon-ef-50mm-f1.8-stm?"
    """

    def __init__(self, kind: str, name: str, suggestions: Sequence[str] = ()) -> None:
        self.kind = kind
        self.name = name
        self.suggestions = list(suggestions)
        self.param = kind  # the input that named it (a lens's own sensor is named by the lens)
        super().__init__(kind, name)

    def __str__(self) -> str:
        text = f"unknown {self.kind} {self.name!r}"
        if self.suggestions:
            text += f"; did you mean {', '.join(self.suggestions)}?"
        else:
            text += f" (camtool presets list --kind {self.kind} shows the known ones)"
        return text


class PresetFileError(FileError):
    """A preset file cannot be read or holds an invalid preset.

    Every part that is known is kept as an attribute and appears in the
    one-line message: ``path``, ``line`` (1-based, where the YAML parser or
    the file's structure gives one), ``kind`` and ``preset_id`` of the entry,
    the ``key`` and the ``problem``.

    >>> str(PresetFileError("my.yaml", "must be > 0 mm, got -3", line=7, kind="sensor",
    ...                     preset_id="tiny", key="width_mm"))
    "my.yaml:7: sensor 'tiny': width_mm: must be > 0 mm, got -3"
    """

    def __init__(
        self,
        path: str,
        problem: str,
        *,
        line: int | None = None,
        kind: str | None = None,
        preset_id: str | None = None,
        key: str | None = None,
    ) -> None:
        self.path = str(path)
        self.problem = problem
        self.line = line
        self.kind = kind
        self.preset_id = preset_id
        self.key = key
        super().__init__(self.path, problem)

    def __str__(self) -> str:
        where = self.path if self.line is None else f"{self.path}:{self.line}"
        parts = [where]
        if self.preset_id is not None:
            parts.append(f"{self.kind or 'preset'} {self.preset_id!r}")
        elif self.kind is not None:
            parts.append(self.kind)
        if self.key is not None:
            parts.append(self.key)
        return ": ".join(parts) + ": " + " ".join(self.problem.split())
