"""The one guarded reader for every file camtool reads: regular files only, capped in size, depth and nodes.

A file named on the command line or found in a configuration directory can
be anything: a FIFO that never delivers (``open`` would block forever), a
directory, a symlink loop, a multi-gigabyte file, UTF-16 text, or a YAML
document built to explode (a "billion laughs" alias bomb expands a 1 KB file
to billions of nodes; 30,000 nested brackets overflow the C stack of the
YAML composer). :func:`read_bytes` and :func:`read_text` refuse the first
kinds before reading; :func:`load_yaml` walks the YAML event stream, which
the parser produces without recursion, and refuses a document that is too
deep, expands to too many nodes, repeats a key in one mapping, or holds an
absurdly long number, before anything is built from it.

Every refusal is a :class:`FileProblem`: one line naming the file (and the
line, where there is one).

>>> import os, tempfile
>>> with tempfile.TemporaryDirectory() as d:
...     path = os.path.join(d, "x.yaml")
...     with open(path, "w") as f:
...         _ = f.write("a: 1\\nb: [2, 3]\\na: 4\\n")
...     try:
...         load_yaml(read_text(path), path)
...     except FileProblem as problem:
...         print(os.path.basename(str(problem)))
x.yaml:3: duplicate key 'a' (lines 1 and 3)
"""

from __future__ import annotations

import errno
import os
import re
import stat
from typing import Any

from camtool.core.errors import FileError

MAX_BYTES = 64 * 1024 * 1024
"""Largest file read unless the caller asks for less."""

MAX_NODES = 2_000_000
"""Largest number of YAML nodes a document may expand to through aliases (an alias bomb is refused)."""

MAX_DEPTH = 64
"""Deepest nesting of YAML collections (camtool's own files nest five deep)."""

MAX_NUMBER_CHARS = 100
"""Longest plain scalar that looks like a number (Python refuses to convert integers of 4300 digits and more)."""

_NUMERIC = r"^[-+]?[0-9][0-9_]*(?:\.[0-9_]*)?(?:[eE][-+]?[0-9]+)?$"
"""A plain scalar YAML would read as a number (compiled on first use, by re's cache: no start-up cost)."""


class FileProblem(FileError):
    """A file that cannot be read, or whose content is refused: ``path``, ``problem`` and ``line`` (or None)."""

    def __init__(self, path: str, problem: str, line: int | None = None) -> None:
        self.path = str(path)
        self.problem = " ".join(problem.split())
        self.line = line
        super().__init__(self.path, self.problem, line)

    def __str__(self) -> str:
        where = self.path if self.line is None else f"{self.path}:{self.line}"
        return f"{where}: {self.problem}"


def file_kind(mode: int) -> str:
    """What a file of ``mode`` is, in words, when it is not a regular file (for one-line refusals)."""
    if stat.S_ISDIR(mode):
        return "a directory"
    if stat.S_ISFIFO(mode):
        return "a FIFO (named pipe)"
    if stat.S_ISSOCK(mode):
        return "a socket"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "a device"
    return "not a regular file"


def read_bytes(path: str | os.PathLike[str], max_bytes: int = MAX_BYTES) -> bytes:
    """The content of the regular file ``path``, at most ``max_bytes`` long.

    The file is opened non-blocking, so a FIFO is refused instead of waiting
    for a writer; a symlink loop, a directory, a device or a larger file is a
    :class:`FileProblem`.
    """
    name = os.fspath(path)
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0)
    try:
        fd = os.open(name, flags)
    except OSError as error:
        if error.errno == errno.ELOOP:
            raise FileProblem(name, "cannot read the file: a loop of symbolic links") from None
        raise FileProblem(name, f"cannot read the file: {error.strerror or error}") from None
    try:
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode):
            raise FileProblem(name, f"cannot read the file: it is {file_kind(info.st_mode)}, not a regular file")
        if info.st_size > max_bytes:
            raise FileProblem(name, f"the file is larger than {_size(max_bytes)}")
        chunks, total = [], 0
        while True:
            chunk = os.read(fd, min(1 << 20, max_bytes + 1 - total))
            if not chunk:
                break
            chunks.append(chunk)
            total += len(chunk)
            if total > max_bytes:
                raise FileProblem(name, f"the file is larger than {_size(max_bytes)}")
        return b"".join(chunks)
    except OSError as error:
        raise FileProblem(name, f"cannot read the file: {error.strerror or error}") from None
    finally:
        os.close(fd)


class WriteProblem(FileProblem):
    """A file that cannot be written: ``path`` (``-`` is standard output), ``problem``, and ``index``.

    ``index`` is the place of ``path`` among the targets given to :func:`check_writable` (None from
    :func:`write_bytes`), so a caller that writes several files can name the one refused.
    """

    def __init__(self, path: str, problem: str, index: int | None = None) -> None:
        super().__init__(path, problem)
        self.index = index

    def __str__(self) -> str:
        return f"cannot write to standard output: {self.problem}" if self.path == "-" else super().__str__()


class SameTarget(WriteProblem):
    """Two targets of one :func:`check_writable` call are the same file: ``index`` and the earlier ``other``."""

    def __init__(self, path: str, index: int, other: int) -> None:
        super().__init__(path, "the same file as another target", index)
        self.other = other


def _not_regular(mode: int) -> str:
    kind = file_kind(mode)
    return "it is not a regular file" if kind == "not a regular file" else f"it is {kind}, not a regular file"


def check_writable(targets: list[str | None]) -> None:
    """Refuse at once a target that cannot be written: no such directory, not a regular file, two the same.

    ``None`` and ``-`` (standard output) are passed over. A missing file in an
    existing directory is fine (it will be created); a FIFO, device, socket or
    directory is refused, as is a file named twice (by any path). Raises
    :class:`WriteProblem` (:class:`SameTarget` for the last) carrying the
    target's place in ``targets``.
    """
    files = [(index, target) for index, target in enumerate(targets) if target is not None and target != "-"]
    for index, target in files:
        try:
            info = os.stat(target)
        except FileNotFoundError:
            if not os.path.isdir(os.path.dirname(os.path.realpath(target))):
                raise WriteProblem(target, "cannot write there: no such directory", index) from None
            continue
        except OSError as error:
            raise WriteProblem(target, f"cannot write there: {error.strerror or error}", index) from None
        if not stat.S_ISREG(info.st_mode):
            raise WriteProblem(target, f"cannot write there: {_not_regular(info.st_mode)}", index)
    seen: dict[str, int] = {}
    for index, target in files:
        real = os.path.realpath(target)
        if real in seen:
            raise SameTarget(target, index, seen[real])
        seen[real] = index


def write_bytes(path: str | os.PathLike[str], payload: bytes) -> None:
    """Write ``payload`` to standard output (``-``) or to the regular file ``path``, created if missing.

    The counterpart of :func:`read_bytes`: the file is opened without
    blocking and checked again once open, so a FIFO or device put in its
    place after :func:`check_writable` is refused, not waited on; an
    existing file is replaced whole. A closed standard output, a file that
    is not regular, or a failed write is a :class:`WriteProblem`.
    """
    import sys

    target = os.fspath(path)
    if target == "-":
        stream = getattr(sys.stdout, "buffer", None)
        if stream is None:  # standard output closed (camtool chart ... -o - >&-)
            raise WriteProblem("-", "it is closed")
        try:
            stream.write(payload)
            stream.flush()
        except ValueError:  # the stream was closed under us
            raise WriteProblem("-", "it is closed") from None
        return
    flags = os.O_WRONLY | os.O_CREAT | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0)
    try:
        fd = os.open(target, flags, 0o666)
    except OSError as error:
        raise WriteProblem(target, f"cannot write there: {error.strerror or error}") from None
    try:
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode):
            raise WriteProblem(target, f"cannot write there: {_not_regular(info.st_mode)}")
        os.ftruncate(fd, 0)
        view = memoryview(payload)
        while view:
            view = view[os.write(fd, view):]
    except OSError as error:
        raise WriteProblem(target, f"cannot write there: {error.strerror or error}") from None
    finally:
        os.close(fd)


def _size(n: int) -> str:
    return f"{n // 2**20} MiB" if n >= 2**20 else f"{n // 2**10} KiB" if n >= 2**10 else f"{n} bytes"


def decode(raw: bytes, path: str) -> str:
    """UTF-8 text of ``raw`` (a UTF-8 byte-order mark is dropped); UTF-16 and other encodings are refused."""
    if raw.startswith((b"\xff\xfe", b"\xfe\xff")):
        raise FileProblem(path, "the file is UTF-16 text; save it as UTF-8")
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        line = raw.count(b"\n", 0, error.start) + 1
        raise FileProblem(path, f"not UTF-8 text (byte {error.start}: 0x{raw[error.start]:02x}); save it as UTF-8",
                          line) from None


def read_text(path: str | os.PathLike[str], max_bytes: int = MAX_BYTES) -> str:
    """:func:`read_bytes` decoded as UTF-8 (see :func:`decode`)."""
    name = os.fspath(path)
    return decode(read_bytes(name, max_bytes), name)


def load_yaml(source: str, path: str, max_nodes: int = MAX_NODES, max_depth: int = MAX_DEPTH) -> tuple[Any, Any]:
    """Safely load one YAML document: the Python value and its node tree (for line numbers), or ``(None, None)``.

    Only the safe subset is constructed (no ``!!python/...`` tags). The event
    stream is checked first (see :func:`check_yaml`), so nothing is built from
    a hostile document.
    """
    import yaml

    loader_class = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    try:
        check_yaml(source, path, max_nodes, max_depth)
        loader = loader_class(source)
        try:
            node = loader.get_single_node()
            if node is None:
                return None, None
            return loader.construct_document(node), node
        finally:
            loader.dispose()
    except yaml.MarkedYAMLError as error:
        mark = error.problem_mark or error.context_mark
        line = mark.line + 1 if mark is not None else None
        text = " ".join(str(error.problem or error).split())
        if error.context and "constructor" not in str(error.context):
            text = " ".join(str(error.context).split()) + ": " + text
        raise FileProblem(path, f"YAML error: {text}", line) from None
    except yaml.YAMLError as error:
        raise FileProblem(path, f"YAML error: {error}") from None
    except RecursionError:
        raise FileProblem(path, "YAML error: the document is nested too deeply") from None
    except (ValueError, OverflowError) as error:  # a value the constructor cannot convert
        raise FileProblem(path, f"YAML error: {error}") from None


def check_yaml(source: str, path: str, max_nodes: int = MAX_NODES, max_depth: int = MAX_DEPTH) -> None:
    """Walk the YAML events of ``source`` and raise :class:`FileProblem` on a hostile or ambiguous document.

    Refused: nesting deeper than ``max_depth``; more than ``max_nodes`` nodes
    once every alias is expanded; a key repeated in one mapping (naming both
    lines); a plain number longer than :data:`MAX_NUMBER_CHARS` characters.
    YAML syntax errors propagate as ``yaml.YAMLError``.
    """
    import yaml

    loader_class = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    loader = loader_class(source)
    anchors: dict[str, int] = {}
    # one frame per open collection: [anchor, node count, is mapping, items seen, {key: line}]
    stack: list[list[Any]] = [[None, 0, False, 0, None]]

    def add(count: int, line: int) -> None:
        frame = stack[-1]
        frame[1] += count
        if frame[1] > max_nodes or count > max_nodes:
            raise FileProblem(path, f"YAML error: the document expands to more than {max_nodes:,} nodes "
                                    "(too many nested aliases)", line)
        frame[3] += 1

    try:
        while True:
            event = loader.get_event()
            if event is None or isinstance(event, yaml.StreamEndEvent):
                break
            line = event.start_mark.line + 1
            if isinstance(event, (yaml.MappingStartEvent, yaml.SequenceStartEvent)):
                if len(stack) > max_depth:
                    raise FileProblem(path, f"YAML error: the document is nested more than {max_depth} levels deep",
                                      line)
                stack.append([event.anchor, 1, isinstance(event, yaml.MappingStartEvent), 0, {}])
            elif isinstance(event, (yaml.MappingEndEvent, yaml.SequenceEndEvent)):
                anchor, count = stack.pop()[:2]
                if anchor is not None:
                    anchors[anchor] = count
                add(count, line)
            elif isinstance(event, yaml.ScalarEvent):
                frame = stack[-1]
                if not event.style and len(event.value) > MAX_NUMBER_CHARS and re.match(_NUMERIC, event.value):
                    raise FileProblem(path, f"YAML error: a number of {len(event.value)} characters "
                                            f"(at most {MAX_NUMBER_CHARS})", line)
                if frame[2] and frame[3] % 2 == 0 and event.value != "<<":
                    seen = frame[4]
                    if event.value in seen:
                        raise FileProblem(path, f"duplicate key {event.value!r} (lines {seen[event.value]} and {line})",
                                          line)
                    seen[event.value] = line
                if event.anchor is not None:
                    anchors[event.anchor] = 1
                add(1, line)
            elif isinstance(event, yaml.AliasEvent):
                if any(frame[0] == event.anchor for frame in stack):
                    raise FileProblem(path, "YAML error: an alias refers to the node that contains it", line)
                add(anchors.get(event.anchor or "", 1), line)
    finally:
        loader.dispose()
