"""Atomic file output: a reader sees the old file or the new one, never half of one.

Every file planargeo writes (gallery SVGs, exported views, benchmark results, docs) goes through
:func:`atomic_write`: the bytes go to a temporary file in the same folder, which then replaces
the target with :func:`os.replace` (atomic on POSIX and Windows).  A set of files that belong
together goes through :func:`atomic_write_many`: all are written to temporary files first and
only then moved in, so a failure leaves the old set intact.  Files get the usual permissions
(``0o666`` less the process umask), not the ``0o600`` of :func:`tempfile.mkstemp`.
"""
from __future__ import annotations

import os
import tempfile
from pathlib import Path

from planargeo.errors import InputError, OutputError

__all__ = ["atomic_write", "atomic_write_many"]


def _umask_mode() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return 0o666 & ~mask


def _stage(path: Path, data: bytes, mode: int) -> str:
    """Write ``data`` to a new temporary file beside ``path``; return its name."""
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())
        os.chmod(tmp, mode)
    except BaseException:
        os.unlink(tmp)
        raise
    return tmp


def atomic_write(path, data) -> Path:
    """Write ``data`` (bytes or str, UTF-8) to ``path`` atomically; return the path.

    Parameters
    ----------
    path : str or os.PathLike
        The target file; its folder is created if missing.
    data : bytes or str
        The file's whole content (text is written as UTF-8).

    Returns
    -------
    pathlib.Path

    Raises
    ------
    OutputError
        If the folder cannot be created or the file cannot be written (full device, no
        permission, the path is a folder or a device such as ``/dev/full``, which is never
        replaced); the previous file, if any, is unchanged.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> d = pathlib.Path(tempfile.mkdtemp())
    >>> atomic_write(d / "a.txt", "hello").read_text()
    'hello'
    """
    return atomic_write_many({path: data})[0]


def atomic_write_many(files) -> list[Path]:
    """Write several files so that either all are replaced or none is.

    Parameters
    ----------
    files : mapping of path -> bytes or str
        ``{path: data}``: every file of the batch and its content.

    Returns
    -------
    list of pathlib.Path
        The paths written, in the order given.

    Raises
    ------
    InputError
        A path that names no file (empty, a NUL byte) or data that is not bytes or str.
    OutputError
        If any file cannot be staged (see :func:`atomic_write`); then no target has been touched.
    """
    mode = _umask_mode()
    staged: list[tuple[str, Path]] = []
    try:
        for path, data in dict(files).items():
            path, data = _checked(path, data)
            try:
                path.parent.mkdir(parents=True, exist_ok=True)
                if path.exists() and not path.is_file():   # a folder, a device (/dev/full), a pipe
                    raise IsADirectoryError(0, "it exists and is not a regular file")
                staged.append((_stage(path, data, mode), path))
            except OSError as e:
                raise OutputError(f"cannot write {path}: {e.strerror or e}") from e
        for tmp, path in staged:
            os.replace(tmp, path)
        done, staged = [p for _, p in staged], []
        return done
    finally:
        for tmp, _ in staged:
            if os.path.exists(tmp):
                os.unlink(tmp)


def _checked(path, data) -> tuple[Path, bytes]:
    """``(Path(path), bytes)``, or :class:`InputError` naming what is wrong."""
    if isinstance(data, str):
        data = data.encode("utf-8")
    if not isinstance(data, (bytes, bytearray, memoryview)):
        raise InputError(f"data for {path!r} must be bytes or str, got {type(data).__name__}")
    try:
        path = Path(path)
    except TypeError:
        raise InputError(f"path must be a str or os.PathLike, got {path!r}") from None
    if "\0" in str(path) or not path.name:
        raise InputError(f"path must name a file, got {str(path)!r}")
    return path, bytes(data)
