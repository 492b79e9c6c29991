"""On-disk caches that are never trusted: one envelope, checked on every read, for every cache camtool keeps.

camtool keeps two caches under ``$XDG_CACHE_HOME/camtool`` (default
``~/.cache/camtool``): the validated records of each preset file
(``presets/``) and the aberration calibration of each prescription
(``aberrations/``). Both store their entries through this module, in one
format::

    {"format":1,"kind":"...","version":"0.1.0","source":"<sha256>","length":N,"mac":"<hex>"}\\n
    <N bytes of payload>

- ``format`` is :data:`FORMAT`, ``version`` the camtool that wrote the entry
  and ``kind`` the cache it belongs to; an entry of another format, version or
  cache is ignored.
- ``source`` is the SHA-256 of what the entry was derived from (a preset
  file's bytes, a prescription's content), recomputed by the caller on every
  read: an entry for another file or another content is never used.
- ``mac`` is a keyed BLAKE2b-256 of the header fields and the payload, keyed by
  a random per-user key (``$XDG_CACHE_HOME/camtool/cache.key``, created with
  mode 0600, used only when it is a regular file of the current user that no
  one else may read or write). A truncated, edited or bit-flipped entry fails
  it, and so does an entry written by anyone who cannot read the key: another
  user sharing the cache directory, a file copied from another account.
- An entry is read only from a regular file of at most the size the caller
  allows (through :func:`camtool.core.files.read_bytes`: non-blocking, so a
  FIFO, a device, a symbolic link to a device, a directory or an oversized file
  is refused at once, without reading it).

What this does not defend against: a process running as the same user can
read the key and forge any entry, but it can equally edit the user's preset
files or camtool itself. The callers re-check the values of every entry they
use (the same checks as freshly computed ones), so even a forged entry can
only give values a fresh computation could have given.

Any entry that fails a check is ignored (:func:`read` returns None) and the
caller writes a fresh one over it; writing is atomic (a temporary file in the
same directory, renamed over the entry) and the temporary file is removed on
any failure. ``CAMTOOL_NO_CACHE`` set to any non-empty value turns every cache
off, reading and writing (:func:`enabled`).

Only the paths that use a cache hash anything, and they take SHA-256 and
BLAKE2b from CPython's own small modules when it has them (the same
algorithms :mod:`hashlib` offers, without loading OpenSSL's, which costs a
few milliseconds of a command's start-up).
"""

from __future__ import annotations

import contextlib
import json
import os
import stat
import sys
import time
from typing import Any

from camtool.core.files import FileProblem, read_bytes

FORMAT = 1
"""The envelope's format number; bumped when the header layout changes."""

KEY_NAME = "cache.key"
_KEY_BYTES = 32
_MAC_BYTES = 32
_HEADER_MAX = 1024
_HEADER_KEYS = frozenset({"format", "kind", "version", "source", "length", "mac"})


def enabled() -> bool:
    """False when ``CAMTOOL_NO_CACHE`` is set to anything non-empty."""
    return not os.environ.get("CAMTOOL_NO_CACHE")


def root() -> str:
    """``$XDG_CACHE_HOME/camtool``; a relative or empty ``XDG_CACHE_HOME`` means ``~/.cache``."""
    base = os.environ.get("XDG_CACHE_HOME", "")
    base = base if base and os.path.isabs(base) else os.path.join(os.path.expanduser("~"), ".cache")
    return os.path.join(base, "camtool")


_constructors: dict[str, Any] = {}


def _hash(name: str, modules: tuple[str, ...]) -> Any:
    """The constructor ``name`` from the first of ``modules`` that has it (:mod:`hashlib` last), found once.

    A module that is not there is searched for on the whole path each time it
    is imported, so the constructor found is remembered.
    """
    found = _constructors.get(name)
    if found is not None:
        return found
    for module in (*modules, "hashlib"):
        try:
            found = _constructors[name] = getattr(__import__(module), name)
            return found
        except (ImportError, AttributeError):
            continue
    raise ImportError(name)


_SHA256_MODULES = ("_sha2",) if sys.version_info >= (3, 12) else ("_sha256",)
"""Where CPython keeps its own SHA-256 (a module looked for and missing costs a search of the whole path)."""


def _sha256(data: bytes) -> Any:
    return _hash("sha256", _SHA256_MODULES)(data)


def _blake2b(data: bytes, key: bytes) -> Any:
    return _hash("blake2b", ("_blake2",))(data, key=key, digest_size=_MAC_BYTES)


def source_digest(data: bytes) -> str:
    """The SHA-256 (hex) that binds an entry to the bytes it was derived from.

    >>> import hashlib
    >>> source_digest(b"camtool") == hashlib.sha256(b"camtool").hexdigest()
    True
    """
    return str(_sha256(data).hexdigest())


def _version() -> str:
    """The running camtool's version (the package root is loaded before any of its modules; importing it from
    here would close an import cycle)."""
    return str(getattr(sys.modules.get("camtool"), "__version__", "unknown"))


def _signed(kind: str, source: str, payload: bytes) -> bytes:
    """The bytes the MAC covers: the header fields (canonical JSON) and the payload."""
    fields = json.dumps([FORMAT, kind, _version(), source, len(payload)], separators=(",", ":"))
    return fields.encode("utf-8") + b"\n" + payload


def _mac(key: bytes, kind: str, source: str, payload: bytes) -> str:
    return str(_blake2b(_signed(kind, source, payload), key).hexdigest())


def _read_key(path: str) -> bytes | None:
    """The key in ``path`` if it is a regular file of this user, private to it and of the right length."""
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0) | getattr(os, "O_NOFOLLOW", 0)
    try:
        fd = os.open(path, flags)
    except OSError:
        return None
    try:
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode) or info.st_size != _KEY_BYTES or info.st_mode & 0o077:
            return None
        if hasattr(os, "geteuid") and info.st_uid != os.geteuid():
            return None
        key = os.read(fd, _KEY_BYTES + 1)
        return key if len(key) == _KEY_BYTES else None
    except OSError:
        return None
    finally:
        os.close(fd)


def _key(create: bool) -> bytes | None:
    """This user's cache key (created when ``create`` and missing), or None when there is no usable one."""
    directory = root()
    path = os.path.join(directory, KEY_NAME)
    key = _read_key(path)
    if key is None and create and not os.path.lexists(path):
        _publish(path, os.urandom(_KEY_BYTES), replace=False)  # never replaces a key another process made first
        key = _read_key(path)
    return key


def read(path: str, kind: str, source: str, max_bytes: int) -> bytes | None:
    """The payload of the entry at ``path`` when every check passes, else None (never raises, never blocks).

    ``kind`` names the cache, ``source`` is the :func:`source_digest` of what
    the entry must have been derived from, and ``max_bytes`` the largest
    entry read (header included).
    """
    if not enabled():
        return None
    try:
        raw = read_bytes(path, max_bytes)
    except FileProblem:
        return None
    end = raw.find(b"\n", 0, _HEADER_MAX)
    if end < 0:
        return None
    try:
        header = json.loads(raw[:end])
    except (ValueError, RecursionError):
        return None
    if not isinstance(header, dict) or set(header) != _HEADER_KEYS:
        return None
    payload = raw[end + 1:]
    if (header["format"] != FORMAT or type(header["format"]) is not int or header["kind"] != kind
            or header["version"] != _version() or header["source"] != source
            or header["length"] != len(payload) or type(header["length"]) is not int
            or not isinstance(header["mac"], str)):
        return None
    key = _key(create=False)
    if key is None:
        return None
    if header["mac"] != _mac(key, kind, source, payload):
        return None
    return payload


def write(path: str, kind: str, source: str, payload: bytes) -> bool:
    """Store ``payload`` as the entry at ``path``, atomically; False (and nothing left behind) when it cannot be.

    The entry is written to a temporary file in the same directory and
    renamed over ``path``; on any failure the temporary file is removed
    (an interrupt is re-raised after the clean-up).
    """
    if not enabled():
        return False
    key = _key(create=True)
    if key is None:
        return False
    header = json.dumps({"format": FORMAT, "kind": kind, "version": _version(), "source": source,
                         "length": len(payload), "mac": _mac(key, kind, source, payload)},
                        separators=(",", ":"), sort_keys=True).encode("utf-8")
    return _publish(path, header + b"\n" + payload, replace=True)


def _publish(path: str, data: bytes, *, replace: bool) -> bool:
    """Write ``data`` to a private temporary file beside ``path``, then put it there; False when it cannot be.

    ``replace``: over whatever is there (:func:`os.replace`); otherwise by a
    hard link, which fails rather than replace a file another process made
    first. The temporary file is removed on every path, an interrupt too.
    """
    directory = os.path.dirname(path)
    temporary = None
    try:
        os.makedirs(directory, mode=0o700, exist_ok=True)
        temporary = os.path.join(directory, f".{os.path.basename(path)}.{os.getpid()}.{os.urandom(4).hex()}.tmp")
        fd = os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_CLOEXEC", 0), 0o600)
        try:
            _write_all(fd, data)
        finally:
            os.close(fd)
        if replace:
            os.replace(temporary, path)
            temporary = None
        else:
            os.link(temporary, path)
        return True
    except OSError:
        return False
    finally:
        if temporary is not None:
            _remove(temporary)


def _write_all(fd: int, data: bytes) -> None:
    view = memoryview(data)
    while view:
        written = os.write(fd, view)
        view = view[written:]


def _remove(path: str) -> None:
    with contextlib.suppress(OSError):
        os.unlink(path)


def dumps(value: Any) -> bytes:
    """Canonical JSON of a payload (no NaN or infinity: ValueError)."""
    return json.dumps(value, separators=(",", ":"), allow_nan=False).encode("utf-8")


_SETTLED_NS = 2_000_000_000
"""A file changed less than this long ago may change again within its clock tick: its digest is not remembered."""


def _stat_key(path: str) -> list[int] | None:
    """What a rewrite of the regular file at ``path`` changes: size, modification and change times, inode, device."""
    try:
        st = os.stat(path)
    except (OSError, ValueError):
        return None
    if not stat.S_ISREG(st.st_mode):
        return None
    return [st.st_size, st.st_mtime_ns, st.st_ctime_ns, st.st_ino, st.st_dev]


class FileDigests:
    """The SHA-256 of each of a fixed list of files, remembered in one cache entry against the files' ``stat``.

    A command that binds data to a file's bytes (the shipped preset records
    to the YAML they were made from) would otherwise read and hash every such
    file on every run. The entry's ``source`` is the digest of every file's
    path, size, modification time, change time (which no program can set),
    inode and device, so any rewrite of any file, or another file in its
    place, finds no entry; the entry's digests are then used without reading
    the files. A digest is remembered only when the file's times were more
    than two seconds old when it was looked at (a file rewritten within the
    same clock tick would keep its times), and the entry is written only when
    every file's digest is known. The entry goes through :func:`read` and
    :func:`write` like every other, and a bad one is only a miss.
    """

    KIND = "file-digests"

    def __init__(self, entry: str, paths: list[str]) -> None:
        self.entry = entry
        self.paths = list(paths)
        self._stats = {path: _stat_key(path) for path in self.paths}
        now = time.time_ns()
        self._settled = {path: key is not None and now - max(key[1], key[2]) > _SETTLED_NS
                         for path, key in self._stats.items()}
        listing = json.dumps([[path, self._stats[path]] for path in self.paths], separators=(",", ":"))
        self._source = source_digest(listing.encode("utf-8", "surrogateescape"))
        self.known: dict[str, str] = {}
        if self.paths and all(self._settled.values()):
            payload = read(entry, self.KIND, self._source, 1024 + 80 * len(self.paths))
            try:
                digests = json.loads(payload) if payload is not None else None
            except (ValueError, RecursionError):
                digests = None
            if (isinstance(digests, list) and len(digests) == len(self.paths)
                    and all(isinstance(d, str) and len(d) == 64 and d.strip("0123456789abcdef") == "" for d in digests)):
                self.known = dict(zip(self.paths, digests, strict=True))

    def get(self, path: str) -> str | None:
        """The remembered digest of ``path`` while it still has the ``stat`` the entry was bound to (None: not one
        of the files, not known or changed since; hash its bytes)."""
        digest = self.known.get(path)
        return digest if digest is not None and _stat_key(path) == self._stats[path] else None

    def put(self, path: str, data: bytes) -> str:
        """The digest of ``data``, the bytes just read from ``path``; remembered when ``path`` is one of the files,
        had settled and still has the ``stat`` it had when first looked at (the entry written once every file's
        digest is known)."""
        digest = source_digest(data)
        key = self._stats.get(path)
        if (key is not None and self._settled[path] and key[0] == len(data) and self.known.get(path) != digest
                and _stat_key(path) == key):
            self.known[path] = digest
            if len(self.known) == len(self.paths):
                write(self.entry, self.KIND, self._source, dumps([self.known[p] for p in self.paths]))
        return digest
