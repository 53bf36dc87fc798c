"""Atomic file output: a reader sees the old file or the new one, never half of one.

Every file planargeo writes goes through :func:`atomic_write` (a temporary file in the same
folder, then :func:`os.replace`) or, for a set that belongs together, :func:`atomic_write_many`
(all staged first, then moved in).  Files get ``0o666`` less the umask.  A command writing into
a folder the user names keeps a *manifest* there (``sha256sum`` format) and later replaces or
deletes only files that still hold what it wrote (:func:`owned_files`).
"""
from __future__ import annotations

import functools
import hashlib
import os
import re
import tempfile
from pathlib import Path

from planargeo.errors import InputError, OutputError

__all__ = ["package_words", "WORDS_FILE", "atomic_write", "atomic_write_many", "digest", "read_manifest", "manifest_bytes", "owned_files",
           "make_folder"]


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
        The file's whole content.

    Returns
    -------
    pathlib.Path

    Raises
    ------
    OutputError
        The folder cannot be created or the file written (full device, no permission, a folder or
        device in the way); the previous file is unchanged.

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
        Every file of the batch and its content.

    Returns
    -------
    list of pathlib.Path
        The paths written, in the order given.

    Raises
    ------
    InputError
        A path that names no file (empty, a NUL byte) or data that is not bytes or str.
    OutputError
        A file cannot be staged (see :func:`atomic_write`); then no target has been touched.
    """
    mask = os.umask(0)                  # read the umask (setting it is the only way)
    os.umask(mask)
    mode = 0o666 & ~mask
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


# --------------------------------------------------------------------------- manifests
_LINE = re.compile(r"^([0-9a-f]{64})  (.+)$")


def digest(data) -> str:
    """The SHA-256 of ``data`` (bytes or str, UTF-8) as 64 hexadecimal digits.

    Parameters
    ----------
    data : bytes or str

    Returns
    -------
    str

    Examples
    --------
    >>> digest(b"abc")[:16]
    'ba7816bf8f01cfea'
    """
    if isinstance(data, str):
        data = data.encode("utf-8")
    return hashlib.sha256(data).hexdigest()


def _file_digest(path: Path) -> str | None:
    """The SHA-256 of the regular file ``path``; None if there is none (or it cannot be read)."""
    try:
        if not path.is_file():
            return None
        with open(path, "rb") as fh:
            return hashlib.file_digest(fh, "sha256").hexdigest()
    except OSError:
        return None


def _safe_name(name: str) -> bool:
    """A relative name inside the folder: not absolute, no ``..``, no empty part, no NUL."""
    parts = name.split("/")
    return bool(name) and "\0" not in name and not name.startswith("/") and all(p not in ("", ".", "..") for p in parts)


def read_manifest(path) -> dict[str, str | None] | None:
    """The entries of the manifest file ``path``: ``{name: sha256}``, None if there is no such file.

    Lines are ``<sha256>  <name>``; a bare name (an old manifest) gives ``{name: None}``.  Comments
    (``#``) and names that leave the folder are ignored.

    Parameters
    ----------
    path : str or os.PathLike
        The manifest file.

    Returns
    -------
    dict or None

    Raises
    ------
    OutputError
        The manifest exists but cannot be read (a folder, no permission, not UTF-8).

    Examples
    --------
    >>> import tempfile, pathlib
    >>> m = pathlib.Path(tempfile.mkdtemp()) / "manifest"
    >>> _ = m.write_bytes(manifest_bytes("# head", {"a.svg": digest(b"a")}) + b"old.svg\\n")
    >>> sorted(read_manifest(m).items())[1]
    ('old.svg', None)
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        return None
    except (OSError, UnicodeError) as e:
        raise OutputError(f"cannot read the manifest {path}: {getattr(e, 'strerror', None) or e}") from e
    entries: dict[str, str | None] = {}
    for line in text.splitlines():
        if not line.strip() or line.startswith("#"):
            continue
        m = _LINE.match(line)
        name, h = (m.group(2), m.group(1)) if m else (line, None)
        if _safe_name(name) and name != path.name:
            entries[name] = h
    return entries


def manifest_bytes(head: str, entries) -> bytes:
    """The manifest's content: the comment ``head``, then one ``<sha256>  <name>`` line per file, sorted.

    Parameters
    ----------
    head : str
        A comment (``# ...``) saying which command wrote the files.
    entries : mapping of str -> str or None
        ``{name: sha256}``; None keeps an old entry without a hash.

    Returns
    -------
    bytes

    Examples
    --------
    >>> manifest_bytes("# mine", {"b": "0" * 64}).decode().splitlines()[1][62:]
    '00  b'
    """
    head = head.rstrip("\n") + "\n"
    return (head + "".join(f"{h}  {n}\n" if h else f"{n}\n"
                           for n, h in sorted(dict(entries).items()))).encode("utf-8")


def owned_files(folder, entries, new=None) -> tuple[dict[str, str], list[str]]:
    """Which files a manifest lists are still the package's own: ``(own, changed)``.

    A listed file is the package's if its SHA-256 equals the recorded one (for an entry without a
    hash: if its bytes equal ``new[name]``); any other listed file that exists is the user's.

    Parameters
    ----------
    folder : str or os.PathLike
        The folder the manifest describes.
    entries : mapping of str -> str or None
        From :func:`read_manifest`.
    new : mapping of str -> bytes, optional
        What is about to be written, by name.

    Returns
    -------
    own : dict of str -> str
        ``{name: sha256}`` of the files that may be overwritten or deleted.
    changed : list of str
        Listed files that are now the user's, sorted.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> d = pathlib.Path(tempfile.mkdtemp())
    >>> _ = (d / "a.svg").write_bytes(b"mine")
    >>> owned_files(d, {"a.svg": digest(b"what was written")})
    ({}, ['a.svg'])
    """
    folder = Path(folder)
    new = dict(new or {})
    own: dict[str, str] = {}
    changed: list[str] = []
    for name, recorded in dict(entries).items():
        path = folder / name
        if not (path.exists() or path.is_symlink()):
            continue
        now = None if path.is_symlink() else _file_digest(path)
        if recorded is None and name in new:
            recorded = digest(new[name])
        if now is not None and now == recorded:
            own[name] = now
        else:
            changed.append(name)
    return own, sorted(changed)


def make_folder(path, what: str = "--out") -> bool:
    """Make sure ``path`` is a folder, creating it (not its parents) if new; True if this call created it.

    Parameters
    ----------
    path : str or os.PathLike
        The folder.
    what : str, optional
        How the messages name it (the command's option).

    Returns
    -------
    bool

    Raises
    ------
    OutputError
        One line naming the folder: a file in the way, a missing parent, a folder that cannot be
        created or looked at.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> new = pathlib.Path(tempfile.mkdtemp()) / "gallery"
    >>> make_folder(new), make_folder(new)
    (True, False)
    """
    path = Path(path)
    try:
        if path.exists() or path.is_symlink():
            if not path.is_dir():
                raise OutputError(f"{what} {path} is a file, not a folder")
            return False
        if not path.parent.is_dir():
            raise OutputError(f"{what} {path}: the parent folder {path.parent} does not exist")
        try:
            path.mkdir()
        except OSError as e:
            raise OutputError(f"{what} {path}: cannot create the folder: {e.strerror or e}") from e
        return True
    except OutputError:
        raise
    except OSError as e:                    # a name too long, no permission to look...
        raise OutputError(f"{what} {path}: {e.strerror or e}") from e


#: The package's words kept as data: the reported quantities (``[scene.*]``) and the explorers'
#: readout rows and symbols (``[explorer.*]``).
WORDS_FILE = "data/quantities.toml"


@functools.cache
def package_words(part: str) -> dict:
    """One part of the package's words kept as data (:data:`WORDS_FILE`), read once.

    Parameters
    ----------
    part : {"scene", "explorer"}
        What ``planargeo report`` prints for each scene, or each explorer's readout rows and symbols.

    Returns
    -------
    dict
        The part's tables by scene or explorer name (shared: do not modify).

    Raises
    ------
    InputError
        If ``part`` is neither ``"scene"`` nor ``"explorer"``: the data file has no other part.

    Examples
    --------
    >>> package_words("scene")["car"]["omega_dot"]["unit"]
    'rad/s²'
    >>> package_words("explorer")["impulse"]["rows"]["mass m"]
    ['kg', 'mass of the body']
    """
    import tomllib
    from importlib.resources import files

    data = tomllib.loads((files("planargeo") / WORDS_FILE).read_text(encoding="utf-8"))
    if part not in data:
        raise InputError(f"part must be one of {sorted(data)}, got {part!r}")
    return data[part]
