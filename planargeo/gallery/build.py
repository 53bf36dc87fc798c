"""``planargeo gallery``: regenerate (or ``--check``) the SVG gallery.

Each registered figure (see :mod:`planargeo.gallery.figures`) is rendered to
``<out>/<name>.svg`` inside the package's fixed style (fonts, sizes,
``svg.hashsalt``, no date metadata), so two runs give identical bytes, and
``<out>/README.md`` indexes the figures with their captions.  ``--check`` renders
into a temporary folder and exits 1 listing stale, missing or extra files.

A run never loses a file it did not write.  ``<out>/.planargeo-gallery`` (the
manifest) lists the files the gallery wrote there, each with the SHA-256 of the
bytes written; a run deletes or overwrites only those that still hold those
bytes (:func:`planargeo.files.owned_files`).  A listed file that has changed
since, or that the user has put there under the same name, is the user's: a run
leaves it and says so in one line.  A manifest from before hashes were kept
lists bare names; such a file counts as the gallery's only if it is identical
to what would be written now.  A run refuses a non-empty folder without a
manifest, and a user's file of the same name as one of its figures, unless
given ``--force`` (which overwrites such files but still deletes nothing it did
not write).  All files of a run are written together by
:func:`planargeo.files.atomic_write_many` (each staged beside its target, then
moved in), with the usual permissions, so a failure (a full device, a file-size
limit) leaves the previous gallery intact.  The folder itself may be created
(before anything is rendered); its parent must exist.  Problems (a missing
parent, a file in the way, a folder that cannot be created or written, a
read-only file system) raise :class:`~planargeo.errors.OutputError`, which
``planargeo gallery`` prints as one line (exit status 1).

The README also indexes the benchmark charts that ``planargeo bench`` copies
into ``<out>/benchmarks/`` (one line each, from :data:`BENCHMARK_CAPTIONS`);
those SVGs are measurements, not rendered here, so ``--check`` compares the
README against the charts present in the checked folder.
"""
from __future__ import annotations

import io
import os
import sys
import tempfile
from pathlib import Path

from planargeo.errors import InputError, OutputError
from planargeo.files import atomic_write_many, digest, make_folder, manifest_bytes, owned_files, read_manifest

DEFAULT_OUT = Path(__file__).resolve().parents[2] / "gallery"

#: One-line captions of the charts ``planargeo bench`` copies to ``gallery/benchmarks/``.
BENCHMARK_CAPTIONS = {
    "single_state": "time per call for one state of an N-link chain, every planargeo method against "
                    "pin.aba and mj_forward (ratios to Pinocchio and MuJoCo are the headline)",
    "work_precision": "work–precision: error against an independent exact / long-double reference "
                      "versus time per call, one panel per N",
    "speed_accuracy": "speed–accuracy: each method's (time, error) as a line through N",
    "batch": "throughput for 1, 100 and 10000 states (N = 10): vectorised ABA, state-by-state ABA, "
             "batched CRBA, pin.aba and mj_forward loops",
    "scaling": "time per call against N on log axes with O(N) and O(N³) guides",
    "breakdown": "where methods break down: error as chains grow, masses become extreme, centres of "
                 "mass approach joint axes and the slider-crank folds",
    "integrators": "integrators' work–precision on the simulation scenes",
    "integrators_drift": "integrators' energy and constraint drift over long runs",
}


def add_arguments(parser):
    """Add ``planargeo gallery``'s options (``--out``, ``--check``, ``--only``, ``--force``) to ``parser``.

    Parameters
    ----------
    parser : argparse.ArgumentParser
        The subcommand's parser.
    """
    parser.add_argument("--out", default=str(DEFAULT_OUT),
                        help="output folder (default: the repository's gallery/)")
    parser.add_argument("--check", action="store_true",
                        help="render to a temporary folder and fail if OUT differs")
    parser.add_argument("--only", nargs="*", default=None, metavar="NAME",
                        help="render only these figures (no README, no extra-file check)")
    parser.add_argument("--force", action="store_true",
                        help="write into a folder holding files the gallery did not write, overwriting "
                             "those with a figure's name (nothing is ever deleted but the gallery's own files)")


def render_svg(spec) -> bytes:
    """Render one figure spec to SVG bytes (deterministic).

    Parameters
    ----------
    spec : FigureSpec
        A registered figure.

    Returns
    -------
    bytes
        The SVG file's content, the same on every run.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from planargeo.draw.style import rc_context

    with rc_context():
        fig = spec.build()
        buf = io.BytesIO()
        try:
            fig.savefig(buf, format="svg", metadata={"Date": None, "Creator": None})
        finally:
            plt.close(fig)
    return buf.getvalue()


def benchmark_charts(folder) -> list[str]:
    """Sorted stems of the SVG charts in ``folder`` (empty if it does not exist).

    Parameters
    ----------
    folder : str or pathlib.Path
        The gallery's ``benchmarks/`` folder.

    Returns
    -------
    list of str
        File stems, sorted.
    """
    folder = Path(folder)
    if not folder.is_dir():
        return []
    return sorted(p.stem for p in folder.glob("*.svg"))


def readme(specs, benchmarks=()) -> str:
    """The gallery's ``README.md``: every figure with its caption, then the benchmark charts.

    Parameters
    ----------
    specs : dict of str to FigureSpec
        The registered figures, in gallery order (:func:`planargeo.gallery.figures.load_all`).
    benchmarks : sequence of str, optional
        Stems of the benchmark charts to index (:func:`benchmark_charts`).

    Returns
    -------
    str
        The Markdown text.
    """
    lines = [
        "# planargeo gallery",
        "",
        "Generated by `planargeo gallery` from computed quantities (do not edit by hand;",
        "`planargeo gallery --check` verifies these files are current).",
        "Colours: twists/velocity poles blue, accelerations vermillion, wrenches orange,",
        "reactions green, momenta/active parts purple, inertias dashed black circles",
        "(radius of gyration about the centre of mass), constructions grey dashed",
        "(see `extra_style_key`).  Every figure is computed from planargeo's math modules and",
        "scenes; captions name the thesis figure and equations, and say where a printed result",
        "was corrected (details in docs/errata.md).  Not drawn: the spatial (3-D) figures",
        "8.1-8.4.",
        "",
        f"{len(specs)} figures: "
        + ", ".join(f"[{n}](#{n.lower()})" for n in specs) + ".",
        "",
    ]
    for s in specs.values():
        lines += [f"## {s.name}", "", s.caption, "", f"![{s.name}]({s.name}.svg)", ""]
    if benchmarks:
        lines += ["## Benchmark charts", "",
                  "Copied here by `planargeo bench` (measurements, not regenerated by "
                  "`planargeo gallery`; details in benchmarks/README.md and benchmarks/RESULTS.md).", ""]
        for b in benchmarks:
            cap = BENCHMARK_CAPTIONS.get(b, "benchmark chart (see benchmarks/README.md)")
            lines += [f"### benchmarks/{b}", "", f"{b}: {cap}.", "",
                      f"![{b}](benchmarks/{b}.svg)", ""]
    return "\n".join(lines)


#: The manifest: the SHA-256 and name of each file the gallery wrote into its folder, one a line.
MANIFEST = ".planargeo-gallery"
_MANIFEST_HEAD = ("# files written by `planargeo gallery` (SHA-256, name); it overwrites or deletes only these,\n"
                  "# and only while they still hold what it wrote")


def _say(line: str) -> None:
    print(f"planargeo gallery: {line}", file=sys.stderr)


def _folder(out: Path) -> bool:
    """Make sure ``out`` is a folder the gallery can write into; return True if this call created it.

    Raises :class:`OutputError` (one line naming the folder and the problem) for a missing
    parent, a file in the way, a folder that cannot be created or written into.
    """
    created = make_folder(out)
    try:                                 # root may write anywhere but a read-only file system or /proc
        fd, probe = tempfile.mkstemp(dir=out, prefix=".planargeo-probe-")
        os.close(fd)
        os.unlink(probe)
    except OSError as e:
        if created:
            out.rmdir()
        raise OutputError(f"--out {out}: cannot write in the folder: {e.strerror or e}") from e
    return created


def _claim(out: Path, names, force: bool, new=None) -> tuple[dict, dict, list]:
    """Check that writing ``names`` into ``out`` loses no file the gallery did not write.

    ``new`` (``{name: bytes}``, once rendered) settles the entries of an old manifest without
    hashes; before that they are left undecided.  Returns ``(own, undecided, changed)``: the
    files still holding what the gallery wrote (``{name: sha256}``, which it may overwrite or
    delete), the old entries not yet settled (``{name: None}``), and the listed files that are
    the user's now.  Raises :class:`OutputError` for a folder holding other files and no
    manifest, or a user's file named like one to be written (unless ``force``).
    """
    try:
        entries = read_manifest(out / MANIFEST)
        listed = {n: h for n, h in (entries or {}).items() if "/" not in n}
        own, changed = owned_files(out, listed, new)
        undecided = {n: None for n in changed if listed[n] is None and new is None}
        changed = [n for n in changed if n not in undecided]
        others = {p.name for p in out.iterdir()} - set(own) - set(undecided) - {MANIFEST, "benchmarks"}
    except OutputError as e:
        raise OutputError(f"--out {out}: {e}") from e
    except OSError as e:                    # no permission to look...
        raise OutputError(f"--out {out}: {e.strerror or e}") from e
    clash = sorted(others & set(names))
    if not force and (clash or (entries is None and others)):
        what = (f"files the gallery did not write, or that changed since it wrote them "
                f"({', '.join(clash[:3])}{', ...' if len(clash) > 3 else ''})") if clash else \
            f"no {MANIFEST} manifest and is not empty"
        raise OutputError(f"--out {out} holds {what}: choose another folder, or pass --force to write "
                          "there anyway (nothing but the gallery's own files is ever deleted)")
    return own, undecided, changed


def generate(out, only=None, *, benchmarks=None, force: bool = False, say=_say) -> dict[str, bytes]:
    """Render the gallery into ``out``; return ``{filename: bytes}`` written.

    Parameters
    ----------
    out : str or os.PathLike
        The gallery folder (created if missing; its parent must exist).
    only : list of str, optional
        Render only these figures (no README; no stale file removed).
    benchmarks : path, optional
        The folder whose benchmark charts the README indexes (default ``out/benchmarks``).
    force : bool
        Write into a folder holding files the gallery did not write (module docstring).
    say : callable, optional
        Receives the one-line note about files the gallery wrote once but leaves because they
        have changed since (default: printed on stderr).

    Returns
    -------
    dict
        ``{filename: bytes}`` of every file written, the manifest included.

    Raises
    ------
    InputError
        ``only`` names an unknown figure.
    OutputError
        ``out`` cannot be written, or holds files the gallery did not write
        (without ``force``); nothing has been changed then.
    """
    from planargeo.gallery.figures import load_all

    specs = load_all()
    if only:
        unknown = sorted(set(only) - set(specs))
        if unknown:
            raise InputError(f"only names unknown figures: {unknown}")
        specs = {k: v for k, v in specs.items() if k in only}
    out = Path(out)
    names = [f"{name}.svg" for name in specs] + ([] if only else ["README.md"])
    created = _folder(out)
    try:
        _claim(out, names, force)                       # refuse early, before the slow rendering
        files = {f"{name}.svg": render_svg(spec) for name, spec in specs.items()}
        if not only:
            bench = out / "benchmarks" if benchmarks is None else Path(benchmarks)
            files["README.md"] = readme(specs, benchmark_charts(bench)).encode()
        own, _, changed = _claim(out, names, force, new=files)
        if only:       # the entries of the figures not rendered now stay as they were (an old one: undecided)
            _, undecided, _ = _claim(out, names, force)
            keep = {**{n: h for n, h in own.items() if n not in files}, **undecided}
        else:
            keep = {}
        files[MANIFEST] = manifest_bytes(_MANIFEST_HEAD, {**keep, **{n: digest(d) for n, d in files.items()}})
        atomic_write_many({out / fname: data for fname, data in files.items()})
    except BaseException:
        if created and not any(out.iterdir()):
            out.rmdir()
        raise
    if not only:  # a full run also removes the figures it wrote before that are no longer in the registry
        for fname in sorted(set(own) - set(files)):
            (out / fname).unlink(missing_ok=True)
        left = [n for n in changed if n not in files]
        if left and say is not None:
            say(f"left {', '.join(left)} in {out}: no longer what the gallery wrote there, so yours (not deleted)")
    return files


def _managed(folder: Path) -> set[str]:
    if not folder.is_dir():
        return set()
    return {p.name for p in folder.iterdir() if p.suffix == ".svg" or p.name in ("README.md", MANIFEST)}


def check(out) -> list[str]:
    """Problems of ``out`` against a fresh render (empty list: up to date).

    Parameters
    ----------
    out : str or pathlib.Path
        The gallery folder to verify.

    Returns
    -------
    list of str
        ``"missing: …"``, ``"stale: …"`` or ``"extra: …"`` lines.  The manifest, which holds
        the other files' hashes, is reported stale only when they are all current.
    """
    out = Path(out)
    with tempfile.TemporaryDirectory() as tmp:
        fresh = generate(tmp, benchmarks=out / "benchmarks")
    have = _managed(out)
    problems = []
    for fname, data in sorted(fresh.items()):
        if fname not in have:
            problems.append(f"missing: {fname}")
        elif (out / fname).read_bytes() != data:
            problems.append(f"stale: {fname}")
    for fname in sorted(have - set(fresh)):
        problems.append(f"extra: {fname}")
    if any(not p.endswith(f": {MANIFEST}") for p in problems):     # its hashes follow the other files:
        problems = [p for p in problems if p != f"stale: {MANIFEST}"]   # stale whenever one of them is
    return problems


def main(args) -> int:
    """Run ``planargeo gallery``: regenerate the gallery, or with ``--check`` verify it.

    Parameters
    ----------
    args : argparse.Namespace
        ``out``, ``only``, ``force`` and ``check``, as :func:`add_arguments` reads them.

    Returns
    -------
    int
        Exit status: 0, or 1 when ``--check`` found problems.
    """
    if args.check:
        problems = check(args.out)
        for p in problems:
            print(p, file=sys.stderr)
        if problems:
            print(f"gallery in {args.out} is out of date ({len(problems)} problems); "
                  "run `planargeo gallery`", file=sys.stderr)
            return 1
        print(f"gallery in {args.out} is up to date")
        return 0
    files = generate(args.out, args.only, force=args.force)
    print(f"wrote {len(files)} files to {args.out}")
    return 0
