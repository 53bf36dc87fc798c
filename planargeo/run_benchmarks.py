"""``planargeo bench``: run the benchmark suite of a source checkout into a results folder.

The suite (``benchmarks/`` of a source checkout, or ``--suite``) is not part of the installed
package: this command runs its ``run.py`` in a fresh process, writing into a hidden folder inside
``--out`` (default: a new temporary folder), never into the committed results (``make bench``
rewrites those).  ``--out`` must be new, empty, or made by ``planargeo bench`` (it keeps the
manifest :data:`MANIFEST`, :mod:`planargeo.files`); files are moved in only over files that still
hold what it wrote, unless ``--force``.  Nothing is ever deleted; Ctrl-C keeps what was written.
"""
from __future__ import annotations

import argparse
import math
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

from planargeo.errors import InputError, NonFiniteError, OutputError, SizeLimitError
from planargeo.files import atomic_write_many, digest, make_folder, manifest_bytes, owned_files, read_manifest

__all__ = ["add_arguments", "main", "find_suite", "out_folder", "parse_sizes", "MANIFEST", "MAX_SIZE",
           "MAX_SIZE_COUNT"]

#: The manifest ``planargeo bench`` keeps in its ``--out`` folder (SHA-256 and name of each file written).
MANIFEST = ".planargeo-bench"
_MANIFEST_HEAD = ("# files written by `planargeo bench` (SHA-256, name); it replaces only these, and only "
                  "while they still hold what it wrote")
#: The largest chain size ``N`` of ``--sizes`` without ``--large``: the dense methods' single-state
#: timings grow like ``N³`` (``N = 200``, the default's largest, takes seconds; ``N = 500`` about a minute).
MAX_SIZE = 500
#: At most this many ``--sizes``.
MAX_SIZE_COUNT = 32
_STAGE = ".planargeo-bench-run-"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Add ``planargeo bench``'s options to ``parser``.

    Parameters
    ----------
    parser : argparse.ArgumentParser
        The subcommand's parser.
    """
    parser.add_argument("--suite", default=None,
                        help="the benchmarks folder (default: ./benchmarks, else the one beside the package)")
    parser.add_argument("--out", default=None,
                        help="output folder: new, empty, or an earlier result of planargeo bench "
                             "(default: a new temporary folder)")
    parser.add_argument("--quick", action="store_true", help="fewer sizes and repeats (under a minute)")
    parser.add_argument("--only", action="append", default=None,
                        help="run only this group (repeatable): dynamics, breakdown, widgets, integrators, scenes, "
                             "truncated, browser")
    parser.add_argument("--no-charts", action="store_true", help="tables only")
    parser.add_argument("--sizes", default=None, metavar="N,N,...",
                        help=f"chain sizes N of the single-state tables, each from 1 to {MAX_SIZE} "
                             f"(--large: to 10000), at most {MAX_SIZE_COUNT} of them")
    parser.add_argument("--large", action="store_true",
                        help=f"allow --sizes past {MAX_SIZE} (a deliberate long run: timings grow like N³)")
    parser.add_argument("--force", action="store_true",
                        help="write into an --out folder that planargeo bench did not make, replacing files "
                             "of the same name as its results (nothing is ever deleted)")


def parse_sizes(text: str, large: bool = False) -> tuple[int, ...]:
    """The chain sizes of ``--sizes``: comma-separated whole numbers, each within the limit.

    Parameters
    ----------
    text : str
        E.g. ``"1,10,50"``; ``1e3`` is read as 1000.
    large : bool, optional
        Lift the limit from :data:`MAX_SIZE` to the model builders' ``MAX_BODIES`` (``--large``).

    Returns
    -------
    tuple of int

    Raises
    ------
    NonFiniteError
        A size is ``inf`` or ``nan``.
    SizeLimitError
        A size past the limit, or more than :data:`MAX_SIZE_COUNT` sizes.
    InputError
        A size that is not a positive whole number, or no size at all.

    Examples
    --------
    >>> parse_sizes("1e6")
    Traceback (most recent call last):
    ...
    planargeo.errors.SizeLimitError: --sizes: N = 1e6 is past the limit of 500 bodies (single-state timings grow like N³); pass --large for a deliberate long run (up to 10000)
    """
    from planargeo.mechanics.model import MAX_BODIES

    parts = [s.strip() for s in str(text).split(",")]
    if not any(parts):
        raise InputError(f"--sizes names no size, got {text!r}")
    if len(parts) > MAX_SIZE_COUNT:
        raise SizeLimitError(f"--sizes: {len(parts)} sizes, past the limit of {MAX_SIZE_COUNT}; "
                             "run the benchmark again for more")
    sizes = []
    for s in parts:
        try:
            v = float(s)
        except ValueError:
            raise InputError(f"--sizes: N must be a positive whole number, got {s!r}") from None
        if not math.isfinite(v):
            raise NonFiniteError(f"--sizes: N must be finite, got {s}")
        if not (v >= 1 and v == int(v)):
            raise InputError(f"--sizes: N must be a positive whole number, got {s}")
        if v > MAX_SIZE and not large:
            raise SizeLimitError(f"--sizes: N = {s} is past the limit of {MAX_SIZE} bodies (single-state timings "
                                 f"grow like N³); pass --large for a deliberate long run (up to {MAX_BODIES})")
        if v > MAX_BODIES:
            raise SizeLimitError(f"--sizes: N = {s} is past {MAX_BODIES} bodies, the model builders' limit "
                                 "(MAX_BODIES), even with --large")
        sizes.append(int(v))
    return tuple(sizes)


def find_suite(suite: str | None = None) -> Path:
    """The folder holding ``run.py`` of the benchmark suite.

    Parameters
    ----------
    suite : str, optional
        An explicit folder; by default ``./benchmarks``, then the folder beside the package.

    Returns
    -------
    pathlib.Path

    Raises
    ------
    InputError
        No folder with a ``run.py`` (an installed package without its checkout).
    """
    candidates = [Path(suite)] if suite else [Path.cwd() / "benchmarks",
                                              Path(__file__).resolve().parents[1] / "benchmarks"]
    for c in candidates:
        if (c / "run.py").is_file():
            return c.resolve()
    raise InputError(f"suite: no benchmarks/run.py found in {', '.join(map(str, candidates))} "
                     "(the benchmarks ship with the source checkout, not the installed package)")


def _prepare(out: str | None, force: bool) -> tuple[Path, bool]:
    """``(folder, created)``: the ``--out`` folder, checked and created if new (see :func:`out_folder`)."""
    if out is None:
        try:
            return Path(tempfile.mkdtemp(prefix="planargeo-bench-")), True
        except OSError as e:
            raise OutputError(f"cannot create a temporary folder: {e.strerror or e}") from e
    p = Path(out)
    if make_folder(p):
        return p, True
    try:
        foreign = read_manifest(p / MANIFEST) is None and any(p.iterdir())
    except OutputError as e:              # cannot read the manifest
        raise OutputError(f"--out {p}: {e}") from e
    except OSError as e:                  # no permission to look...
        raise OutputError(f"--out {p}: {e.strerror or e}") from e
    if foreign and not force:
        raise OutputError(f"--out {p} holds files that are not a benchmark result of planargeo bench "
                          f"(it has no {MANIFEST} manifest): choose another folder, or pass --force "
                          "to write there anyway (nothing is deleted)")
    return p, False


def _stage(out: Path, created: bool) -> Path:
    """A fresh hidden folder inside ``out`` for the suite to write into (proves ``out`` writable)."""
    try:
        return Path(tempfile.mkdtemp(dir=out, prefix=_STAGE))
    except OSError as e:
        if created:
            shutil.rmtree(out, ignore_errors=True)
        raise OutputError(f"--out {out}: cannot write in the folder: {e.strerror or e}") from e


def out_folder(out: str | None, force: bool = False) -> Path:
    """The folder the results go to: ``out`` (checked, created if new) or a new temporary folder.

    Parameters
    ----------
    out : str or None
        The ``--out`` folder, or None for a new temporary folder.
    force : bool, optional
        Accept a folder holding files that are not a result of ``planargeo bench``.

    Returns
    -------
    pathlib.Path
        The folder; it exists and files can be created in it.

    Raises
    ------
    OutputError
        ``out`` has no parent, is a file, cannot be created or written into, or holds files and no
        manifest of ``planargeo bench`` while ``force`` is not given.

    Examples
    --------
    >>> out_folder("/dev/full")
    Traceback (most recent call last):
    ...
    planargeo.errors.OutputError: --out /dev/full is a file, not a folder
    """
    p, created = _prepare(out, force)
    shutil.rmtree(_stage(p, created))
    return p


def _move_in(stage: Path, out: Path, force: bool) -> tuple[list[str], list[str]]:
    """Move the files into ``out`` over ones still as written (or ``force``): ``written, left``."""
    try:
        new = {p.relative_to(stage).as_posix(): p.read_bytes()          # the regular files staged
               for p in sorted(stage.rglob("*")) if p.is_file() and not p.is_symlink()}
        own, _changed = owned_files(out, read_manifest(out / MANIFEST) or {})
        taken = {n for n in new if (out / n).exists() or (out / n).is_symlink()}
    except OSError as e:
        raise OutputError(f"--out {out}: {e.strerror or e}") from e
    left = sorted(n for n in taken - set(own) if not force)
    write = {n: d for n, d in new.items() if n not in left}
    entries = {**own, **{n: digest(d) for n, d in write.items()}}
    files = {out / n: d for n, d in write.items()}
    files[out / MANIFEST] = manifest_bytes(_MANIFEST_HEAD, entries)
    atomic_write_many(files)
    return sorted(write), left


def _run(cmd: list[str], cwd: str) -> tuple[int, bool]:
    """``(exit status, interrupted)`` of the suite; on Ctrl-C it is given time to stop by itself."""
    proc = subprocess.Popen(cmd, cwd=cwd)
    try:
        return proc.wait(), False
    except KeyboardInterrupt:
        try:
            proc.wait(timeout=10)
        except (subprocess.TimeoutExpired, KeyboardInterrupt):
            proc.kill()
            proc.wait()
        return 130, True


def main(args: argparse.Namespace) -> int:
    """Run ``planargeo bench``: the benchmark suite in a subprocess, results into ``--out``.

    Parameters
    ----------
    args : argparse.Namespace
        Parsed options of :func:`add_arguments`.

    Returns
    -------
    int
        0; the suite's status when it fails; 1 when a file of the user's kept a result out; 2 when
        no suite is found; 130 after Ctrl-C.

    Raises
    ------
    InputError
        ``--sizes`` out of bounds (:func:`parse_sizes`).
    OutputError
        ``--out`` cannot be used (:func:`out_folder`).
    """
    sizes = None if args.sizes is None else parse_sizes(args.sizes, args.large)
    try:
        suite = find_suite(args.suite)
    except InputError as e:
        print(f"planargeo bench: error: {e}", file=sys.stderr)
        return 2
    out, created = _prepare(args.out, args.force)
    stage = _stage(out, created)
    try:
        cmd = [sys.executable, str(suite / "run.py"), "--out", str(stage.resolve()),
               "--summary", str(stage.resolve() / "RESULTS.md"), "--gallery", ""]
        cmd += [flag for flag, on in (("--quick", args.quick), ("--no-charts", args.no_charts)) if on]
        cmd += ["--sizes", ",".join(map(str, sizes))] if sizes else []
        cmd += [word for group in args.only or () for word in ("--only", group)]
        rc, interrupted = _run(cmd, str(suite.parent))
        written, left = _move_in(stage, out, args.force)
    finally:
        shutil.rmtree(stage, ignore_errors=True)
    if interrupted:
        print(f"planargeo bench: interrupted; the {len(written)} result files written so far are in {out}",
              file=sys.stderr)
        return 130
    if left:
        print(f"planargeo bench: error: left {', '.join(left)} in {out} as {'it is' if len(left) == 1 else 'they are'}"
              f" (not what planargeo bench wrote there, so yours); pass --force to replace "
              f"{'it' if len(left) == 1 else 'them'}", file=sys.stderr)
        return rc or 1
    if rc:
        print(f"planargeo bench: error: the benchmark suite failed (exit status {rc}); "
              f"{len(written)} result files are in {out}", file=sys.stderr)
        return rc
    print(f"planargeo bench: results in {out}")
    return 0
