"""``planargeo bench``: run the benchmark suite of a source checkout, side by side in one run.

The suite (``benchmarks/`` beside the package in a source checkout, or ``--suite``) is not part
of the installed package: this command only finds it and runs ``benchmarks/run.py`` in a fresh
process.  Results go to ``--out`` (default: a new temporary folder, printed at the end), never
to the committed ``benchmarks/results``, ``benchmarks/RESULTS.md`` or ``gallery/`` files:
only ``make bench`` rewrites those.  An ``--out`` folder must be new, empty or an earlier
result (it holds ``RESULTS.md``); a folder of other files is refused unless ``--force``, so a
run never overwrites files it did not write.
"""
from __future__ import annotations

import argparse
import subprocess
import sys
import tempfile
from pathlib import Path

from planargeo.errors import InputError, OutputError

__all__ = ["add_arguments", "main", "find_suite", "out_folder"]


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Add ``planargeo bench``'s options (``--suite``, ``--out``, ``--quick``, ``--only``, ``--no-charts``, ``--force``) to ``parser``.

    Parameters
    ----------
    parser : argparse.ArgumentParser
        The subcommand's parser.
    """
    parser.add_argument("--suite", default=None,
                        help="the benchmarks folder (default: ./benchmarks, else the one beside the package)")
    parser.add_argument("--out", default=None,
                        help="output folder (default: a new temporary folder)")
    parser.add_argument("--quick", action="store_true", help="fewer sizes and repeats (under a minute)")
    parser.add_argument("--only", action="append", default=None,
                        help="run only this group (repeatable): dynamics, breakdown, widgets, integrators, scenes, "
                             "truncated, browser")
    parser.add_argument("--no-charts", action="store_true", help="tables only")
    parser.add_argument("--force", action="store_true",
                        help="write into an --out folder that holds files other than an earlier result")


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
        If no folder with a ``run.py`` is found (an installed package without its checkout).
    """
    candidates = [Path(suite)] if suite else [Path.cwd() / "benchmarks",
                                              Path(__file__).resolve().parents[1] / "benchmarks"]
    for c in candidates:
        if (c / "run.py").is_file():
            return c.resolve()
    raise InputError(f"suite: no benchmarks/run.py found in {', '.join(map(str, candidates))} "
                     "(the benchmarks ship with the source checkout, not the installed package)")


def out_folder(out: str | None, force: bool = False) -> Path:
    """The folder the results go to: ``out`` (checked) or a new temporary folder.

    Parameters
    ----------
    out : str or None
        The ``--out`` folder, or None for a new temporary folder.
    force : bool, optional
        Accept a folder holding other files.

    Returns
    -------
    pathlib.Path
        The folder (created if needed).

    Raises
    ------
    OutputError
        ``out`` has no existing parent, is a file, or holds files that are not an earlier result
        (no ``RESULTS.md``) and ``force`` is not given.

    Examples
    --------
    >>> out_folder("/dev/full")
    Traceback (most recent call last):
    ...
    planargeo.errors.OutputError: --out /dev/full is not a folder
    """
    if out is None:
        return Path(tempfile.mkdtemp(prefix="planargeo-bench-"))
    p = Path(out)
    try:
        if not p.parent.is_dir():
            raise OutputError(f"--out {p}: the parent folder {p.parent} does not exist")
        if p.exists() and not p.is_dir():
            raise OutputError(f"--out {p} is not a folder")
        if p.is_dir() and any(p.iterdir()) and not (p / "RESULTS.md").is_file() and not force:
            raise OutputError(f"--out {p} holds files that are not a benchmark result: choose another folder, "
                              "or pass --force to write there anyway")
    except OutputError:
        raise
    except OSError as e:
        raise OutputError(f"--out {p}: {e.strerror or e}") from e
    return p


def main(args: argparse.Namespace) -> int:
    """Run ``planargeo bench``: the benchmark suite in a subprocess, results into ``--out``.

    Parameters
    ----------
    args : argparse.Namespace
        Parsed options of :func:`add_arguments`.

    Returns
    -------
    int
        Exit status: the suite's, or 2 when no suite is found.
    """
    try:
        suite = find_suite(args.suite)
    except InputError as e:
        print(f"planargeo bench: error: {e}", file=sys.stderr)
        return 2
    out = out_folder(args.out, args.force)
    cmd = [sys.executable, str(suite / "run.py"), "--out", str(out.resolve()),
           "--summary", str(out.resolve() / "RESULTS.md"), "--gallery", ""]
    if args.quick:
        cmd.append("--quick")
    if args.no_charts:
        cmd.append("--no-charts")
    for group in args.only or ():
        cmd += ["--only", group]
    rc = subprocess.call(cmd, cwd=str(suite.parent))
    print(f"planargeo bench: results in {out}")
    return rc
