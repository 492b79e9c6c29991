"""Reading a depth image and writing a blur map, every problem one :class:`~camtool.core.files.FileProblem`.

A depth image is an OpenEXR file with a ``Z`` (or ``depth.Z``, ``depth``, ``Depth``) channel, or a one-channel
16-bit PNG or TIFF (or a 32-bit float TIFF) whose code values are multiplied by a stated depth unit. The OpenEXR
standard attributes of the lens state (OpenEXR, "Standard Attributes": ``focus`` in metres, ``aperture`` the
f-number, ``tStop``, ``effectiveFocalLength``, ``pinholeFocalLength`` and ``nominalFocalLength`` in mm,
``entrancePupilOffset``, the axial distance from the image plane to the entrance pupil in mm) are read when
present, as plain floats; the plan range-checks them like the options they stand for.

A blur map is written as OpenEXR (float32 channels ``coc_mm`` and ``radius_px``, no compression), 16-bit PNG
(the radius in hundredths of a pixel, clipped at 65535: 655.35 px) or ``.npy`` (float32, shape 2 × H × W: the
CoC in mm, then the radius in pixels).
"""

from __future__ import annotations

import os
import stat
from typing import Any

from camtool.core.files import FileProblem, file_kind
from camtool.core.record import NamedTuple

EXR_CHANNELS = ("Z", "depth.Z", "depth", "Depth", "z")
"""The depth channels looked for, in order, when none is named."""

LENS_ATTRIBUTES = ("focus", "aperture", "tStop", "effectiveFocalLength", "pinholeFocalLength", "nominalFocalLength",
                   "entrancePupilOffset")
"""The OpenEXR standard attributes of the lens state that a CoC map can use."""

PNG_RADIUS_SCALE = 100.0
"""A 16-bit PNG blur map holds the radius in pixels × 100 (steps of 0.01 px, up to 655.35 px)."""

FORMATS = ("exr", "png", "tif", "tiff", "npy")


class DepthImage(NamedTuple):
    """A depth image: the values as float32 (H × W), whether they were integer code values, and the header's
    lens attributes (name -> float; only those present)."""

    values: Any
    integer: bool
    attributes: dict[str, float]
    channel: str


def _regular(path: str) -> None:
    try:
        info = os.stat(path)
    except OSError as error:
        raise FileProblem(path, f"cannot read the file: {error.strerror or error}") from None
    if not stat.S_ISREG(info.st_mode):
        raise FileProblem(path, f"cannot read the file: it is {file_kind(info.st_mode)}, not a regular file")


def _kind(path: str) -> str:
    ext = os.path.splitext(path)[1].lower().lstrip(".")
    if ext not in FORMATS:
        raise FileProblem(path, f"unknown image type {('.' + ext) if ext else '(no extension)'}: "
                                "give .exr, .png, .tif or .tiff (and .npy for a map)")
    return ext


def _optional(module: str, path: str) -> Any:
    import importlib

    try:
        return importlib.import_module(module)
    except ImportError:
        raise FileProblem(path, f"this file type needs the Python package {module}: "
                                "pip install 'camtool[depth]'") from None


def read_depth(path: str, channel: str | None = None) -> DepthImage:
    """The depth image at ``path`` (a regular file), its values as float32."""
    _regular(path)
    kind = _kind(path)
    if kind == "npy":
        raise FileProblem(path, "a depth image is .exr, .png, .tif or .tiff (.npy is for the map written)")
    if kind == "exr":
        return _read_exr(path, channel)
    import numpy as np

    if channel is not None:
        raise FileProblem(path, f"a {kind.upper()} file has no named channels (--channel {channel})")
    try:
        if kind == "png":
            array = _optional("imageio.v3", path).imread(path)
        else:
            array = _optional("tifffile", path).imread(path)
    except FileProblem:
        raise
    except Exception as error:  # the decoders raise many types for a damaged file
        raise FileProblem(path, f"cannot read it as {kind.upper()}: {_reason(error)}") from None
    if array.ndim != 2:
        raise FileProblem(path, f"a depth image has one channel; this one is {array.shape} (height, width, channels)")
    if array.dtype == np.uint8:
        raise FileProblem(path, "an 8-bit image holds too few depths: give a 16-bit PNG or TIFF")
    if array.dtype == np.uint16:
        return DepthImage(array.astype(np.float32), True, {}, "grey")
    if array.dtype in (np.float32, np.float64):
        return DepthImage(array.astype(np.float32, copy=False), False, {}, "grey")
    raise FileProblem(path, f"samples of type {array.dtype} are not a depth: give 16-bit integers or 32-bit floats")


def _reason(error: BaseException) -> str:
    text = " ".join(str(error).split()) or type(error).__name__
    return text[:200]


def _read_exr(path: str, channel: str | None) -> DepthImage:
    import numpy as np

    openexr = _optional("OpenEXR", path)
    try:
        with _quiet():
            image = openexr.File(path)
            header = image.header()
            channels = image.channels()
    except Exception as error:  # a truncated or damaged file
        raise FileProblem(path, f"cannot read it as OpenEXR: {_reason(error)}") from None
    names = list(channels)
    wanted = [channel] if channel is not None else [c for c in EXR_CHANNELS if c in channels]
    if not wanted or wanted[0] not in channels:
        shown = ", ".join(names[:12]) + (", …" if len(names) > 12 else "")
        what = f"no channel {channel!r}" if channel is not None else "no Z or depth channel"
        raise FileProblem(path, f"{what} (its channels: {shown or 'none'})")
    try:
        with _quiet():
            pixels = channels[wanted[0]].pixels
    except Exception as error:
        raise FileProblem(path, f"cannot read channel {wanted[0]}: {_reason(error)}") from None
    if pixels is None or getattr(pixels, "ndim", 0) != 2:
        raise FileProblem(path, f"channel {wanted[0]} is not one value per pixel")
    if pixels.dtype.kind not in "fu":
        raise FileProblem(path, f"channel {wanted[0]} holds {pixels.dtype}, not depths")
    attributes = {}
    for name in LENS_ATTRIBUTES:
        value = header.get(name)
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            attributes[name] = float(value)
    return DepthImage(pixels.astype(np.float32, copy=False), pixels.dtype.kind == "u", attributes, wanted[0])


class _quiet:
    """Silence what the OpenEXR library prints about a damaged file (to Python's streams and to file descriptor 2):
    the problem is reported once, as the file's one line."""

    def __enter__(self) -> None:
        import contextlib
        import io
        import sys

        self._stack = contextlib.ExitStack()
        self._stack.enter_context(contextlib.redirect_stdout(io.StringIO()))
        self._stack.enter_context(contextlib.redirect_stderr(io.StringIO()))
        self._saved = None
        try:
            sys.__stderr__.flush() if sys.__stderr__ else None
            self._saved = os.dup(2)
            null = os.open(os.devnull, os.O_WRONLY)
            os.dup2(null, 2)
            os.close(null)
        except OSError:
            self._saved = None

    def __exit__(self, *exc: object) -> None:
        if self._saved is not None:
            os.dup2(self._saved, 2)
            os.close(self._saved)
        self._stack.close()


def map_bytes(kind: str, coc_mm: Any, radius_px: Any) -> bytes:
    """A blur map as the bytes of a PNG16 or ``.npy`` file (EXR is written by :func:`write_map`)."""
    import io

    import numpy as np

    if kind == "npy":
        buffer = io.BytesIO()
        np.save(buffer, np.stack([coc_mm, radius_px]).astype(np.float32, copy=False))
        return buffer.getvalue()
    codes = np.rint(np.minimum(radius_px * PNG_RADIUS_SCALE, 65535.0)).astype(np.uint16)
    return bytes(_optional("imageio.v3", "-").imwrite("<bytes>", codes, extension=".png"))


def write_map(path: str, coc_mm: Any, radius_px: Any, attributes: dict[str, float] | None = None) -> None:
    """Write a blur map to ``path`` (its extension picks the format); ``-`` is refused (the map is binary)."""
    from camtool.core.files import WriteProblem, check_writable, write_bytes

    if path == "-":
        raise WriteProblem("-", "a map is binary: give a file name ending .exr, .png or .npy")
    kind = _kind(path)
    if kind in ("tif", "tiff"):
        raise WriteProblem(path, "a map is written as .exr, .png or .npy")
    check_writable([path])
    if kind != "exr":
        write_bytes(path, map_bytes(kind, coc_mm, radius_px))
        return
    openexr = _optional("OpenEXR", path)
    header = {"compression": openexr.NO_COMPRESSION, "type": openexr.scanlineimage, **(attributes or {})}
    try:
        openexr.File(header, {"coc_mm": coc_mm, "radius_px": radius_px}).write(path)
    except Exception as error:
        raise WriteProblem(path, f"cannot write there: {_reason(error)}") from None


def frames(pattern: str) -> list[str]:
    """The frames of a sequence: the files of a folder (sorted, depth images only), or a printf pattern such as
    ``shot.%04d.exr`` matched against the files beside it (sorted by frame number)."""
    import re

    if os.path.isdir(pattern):
        names = sorted(n for n in os.listdir(pattern) if os.path.splitext(n)[1].lower().lstrip(".") in FORMATS[:4])
        return [os.path.join(pattern, n) for n in names]
    match = re.search(r"%0?(\d*)d", pattern)
    if match is None:
        return [pattern]
    folder, name = os.path.split(pattern)
    start = name.find(match.group(0))
    head, tail = name[:start], name[start + len(match.group(0)):]
    width = match.group(1)
    digits = rf"\d{{{int(width)}}}" if width else r"\d+"
    rule = re.compile(re.escape(head) + f"({digits})" + re.escape(tail) + "$")
    try:
        listing = os.listdir(folder or ".")
    except OSError as error:
        raise FileProblem(pattern, f"cannot list the frames: {error.strerror or error}") from None
    found = sorted((int(m.group(1)), n) for n in listing if (m := rule.match(n)))
    return [os.path.join(folder, n) for _, n in found]
