"""Execute every notebook deterministically and store its outputs in place (``make notebooks``).

The lessons are committed *with* their outputs, so that they show their figures on GitHub, in a
file browser and in the documentation site without being run.  This script is the one way those
outputs are made, and ``tests/test_notebook_outputs.py`` re-runs the notebooks the same way and
compares the fresh outputs with the stored ones.

What makes a run deterministic:

* each notebook runs in a fresh kernel (``python3``, the interpreter running this script) in the
  ``notebooks/`` folder, with ``PYTHONHASHSEED=0`` and ``SOURCE_DATE_EPOCH=0``;
* figures are inline PNG: ``MPLBACKEND`` is removed from the kernel's environment, so IPython's
  inline backend is used; an explorer's output keeps, beside its widget, a static PNG of its
  picture drawn by matplotlib (``Explorer._repr_mimebundle_``), which GitHub and the docs show
  without a kernel; before the first cell a silent set-up (not stored in the notebook, not in the
  history) marks ``ipympl`` unavailable, as in a reader's kernel; the notebooks seed every random
  generator they use;
* no timings, dates or widget state are stored: ``record_timing`` is off, widget state is not
  saved, the kernelspec metadata is fixed.

Cells tagged ``needs-merge`` use an explorer that another branch adds (its name is in the cell's
``metadata["planargeo"]["needs"]``).  When ``planargeo.widgets`` does not have it yet, the cell is
not executed (its outputs are cleared) and the script says which; once the class exists the cell
runs like any other.  Cells tagged ``output-varies`` (live timings) run, but their outputs are not
compared by the test.

Usage::

    python notebooks/run_all.py              # every notebook, outputs stored in place
    python notebooks/run_all.py 03 05        # only notebooks whose names start with these
    python notebooks/run_all.py --check      # run, compare with the stored outputs, write nothing
    python notebooks/run_all.py -j 2         # two notebooks at a time (each in its own kernel)
"""
from __future__ import annotations

import argparse
import base64
import concurrent.futures
import copy
import importlib
import io
import json
import os
import re
import resource
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
NEEDS_TAG = "needs-merge"
VARIES_TAG = "output-varies"
KERNELSPEC = {"display_name": "Python 3 (ipykernel)", "language": "python", "name": "python3"}
TIMEOUT = 300
#: run silently before the first cell of a recording (see the module docstring): no widget front end
RECORDING_SETUP = "import sys\nsys.modules['ipympl'] = None\ndel sys"


def notebook_paths(prefixes=()) -> list[Path]:
    """The notebooks of ``notebooks/`` in course order, optionally only those starting with a prefix.

    Parameters
    ----------
    prefixes : sequence of str, optional
        Keep only notebooks whose file name starts with one of these.

    Returns
    -------
    list of pathlib.Path
    """
    paths = sorted(HERE.glob("*.ipynb"))
    if prefixes:
        paths = [p for p in paths if any(p.name.startswith(x) for x in prefixes)]
    return paths


def missing_names(nb) -> dict[int, str]:
    """Cells tagged ``needs-merge`` whose explorer ``planargeo.widgets`` does not provide yet.

    Parameters
    ----------
    nb : nbformat.NotebookNode

    Returns
    -------
    dict
        cell index -> the missing name.
    """
    widgets = importlib.import_module("planargeo.widgets")
    out = {}
    for i, cell in enumerate(nb.cells):
        if NEEDS_TAG in cell.get("metadata", {}).get("tags", []):
            name = cell["metadata"].get("planargeo", {}).get("needs", "")
            try:
                present = bool(name) and hasattr(widgets, name)
            except Exception:   # noqa: BLE001 - a lazy import that fails means "not there"
                present = False
            if not present:
                out[i] = name or "?"
    return out


def kernel_environment() -> dict[str, str]:
    """The environment the notebooks' kernels run in (see the module docstring).

    Returns
    -------
    dict
    """
    env = dict(os.environ)
    env.pop("MPLBACKEND", None)
    env.update(PYTHONHASHSEED="0", SOURCE_DATE_EPOCH="0", PLANARGEO_WIDGET_BACKEND="image")
    root = str(HERE.parent)
    paths = env.get("PYTHONPATH", "").split(os.pathsep)
    if root not in paths:                                 # this checkout's planargeo, not another
        env["PYTHONPATH"] = os.pathsep.join([root] + [p for p in paths if p])
    return env


def execute(path: Path, timeout: int = TIMEOUT):
    """Run one notebook in a fresh kernel and return it with its new outputs.

    Parameters
    ----------
    path : pathlib.Path
        The notebook.
    timeout : int, optional
        Seconds allowed per cell.

    Returns
    -------
    nb : nbformat.NotebookNode
        The executed notebook (the file is not written).
    seconds : float
        Wall time of the run, kernel start included (see :func:`kernel_cpu_seconds` for the CPU time,
        which does not depend on how busy the machine is).
    skipped : dict
        cell index -> name of the missing explorer, for cells not executed.
    """
    import nbformat
    from nbclient import NotebookClient

    nb = nbformat.read(path, as_version=4)
    skipped = missing_names(nb)
    t0 = time.perf_counter()
    client = NotebookClient(nb, timeout=timeout, kernel_name="python3", record_timing=False,
                            store_widget_state=False, allow_errors=False,
                            resources={"metadata": {"path": str(path.parent)}})
    with client.setup_kernel(env=kernel_environment()):   # the kernel's own environment (thread-safe)
        nb.cells.append(nbformat.v4.new_code_cell(RECORDING_SETUP))   # run, then removed again
        try:
            client.execute_cell(nb.cells[-1], len(nb.cells) - 1, store_history=False)
        finally:
            nb.cells.pop()
        for index, cell in enumerate(nb.cells):
            if cell.cell_type != "code":
                continue
            if index in skipped:
                cell.outputs, cell.execution_count = [], None
                continue
            client.execute_cell(cell, index)
    seconds = time.perf_counter() - t0
    nb.metadata.pop("widgets", None)
    nb.metadata["kernelspec"] = dict(KERNELSPEC)
    for cell in nb.cells:
        cell.get("metadata", {}).pop("execution", None)
        if cell.cell_type == "code":
            cell.outputs = coalesce_streams(cell.outputs)
    return nb, seconds, skipped


def coalesce_streams(outputs) -> list:
    """Merge consecutive stream outputs of the same stream (how the kernel chunks them varies).

    Parameters
    ----------
    outputs : list
        A code cell's outputs.

    Returns
    -------
    list
        The outputs with each run of ``stdout`` (or ``stderr``) pieces joined into one.
    """
    out = []
    for o in outputs:
        if (o.get("output_type") == "stream" and out and out[-1].get("output_type") == "stream"
                and out[-1].get("name") == o.get("name")):
            prev = out[-1]
            prev["text"] = "".join(prev["text"]) + "".join(o["text"])
        else:
            out.append(o)
    return out


def kernel_cpu_seconds() -> float:
    """CPU time (user + system) of the finished child processes so far: the kernels this process ran.

    Returns
    -------
    float
    """
    ru = resource.getrusage(resource.RUSAGE_CHILDREN)
    return ru.ru_utime + ru.ru_stime


# ------------------------------------------------------------------------------- normalised outputs
_ADDRESS = re.compile(r"0x[0-9a-fA-F]{6,}")
_MODEL_ID = re.compile(r"[0-9a-f]{32}")


def _text(value) -> str:
    text = "".join(value) if isinstance(value, list) else str(value)
    return _MODEL_ID.sub("<id>", _ADDRESS.sub("0x…", text))


def png_pixels(data: str):
    """Decode an inline PNG (base64 text) to an RGBA float array.

    Parameters
    ----------
    data : str
        The ``image/png`` value of a notebook output.

    Returns
    -------
    numpy.ndarray
        Shape (height, width, channels), values in [0, 1].
    """
    import matplotlib.image as mpimg

    return mpimg.imread(io.BytesIO(base64.b64decode(data)), format="png")


def normalised(cell) -> list:
    """A code cell's outputs in a comparable form.

    Execution counts and widget model ids are dropped, memory addresses masked, images decoded to
    pixels (PNG) or kept as text (SVG, with ids masked); cells tagged ``output-varies`` keep only
    the kinds of their outputs.

    Parameters
    ----------
    cell : nbformat.NotebookNode
        A code cell.

    Returns
    -------
    list
        One entry per output: ``(kind, payload)``.
    """
    varies = VARIES_TAG in cell.get("metadata", {}).get("tags", [])
    out = []
    for o in coalesce_streams(copy.deepcopy(cell.get("outputs", []))):
        kind = o["output_type"]
        if kind == "stream":
            out.append((kind, o["name"], None if varies else _text(o["text"])))
            continue
        if kind == "error":
            out.append((kind, o["ename"], _text(o["evalue"])))
            continue
        data = {}
        for mime, value in sorted(o.get("data", {}).items()):
            if varies:
                data[mime] = None
            elif mime == "image/png":
                data[mime] = png_pixels("".join(value) if isinstance(value, list) else value)
            elif mime == "application/vnd.jupyter.widget-view+json":
                data[mime] = {k: v for k, v in value.items() if k != "model_id"}
            elif isinstance(value, (dict, list)) and not isinstance(value, str) and mime.endswith("json"):
                data[mime] = json.dumps(value, sort_keys=True)
            else:
                data[mime] = _text(value)
        out.append(("display", data))
    return out


def differences(stored, fresh, *, pixel_tol: float = 2e-3) -> list[str]:
    """Where two runs of one notebook differ, as readable lines ([] when they agree).

    Parameters
    ----------
    stored, fresh : nbformat.NotebookNode
        The committed notebook and a fresh run of it.
    pixel_tol : float, optional
        Largest root-mean-square difference of two PNG images (pixel values in [0, 1]) counted
        as the same picture (anti-aliasing may differ by a few levels between font builds).

    Returns
    -------
    list of str
    """
    import numpy as np

    problems = []
    if len(stored.cells) != len(fresh.cells):
        return [f"{len(stored.cells)} stored cells, {len(fresh.cells)} fresh"]
    for i, (a, b) in enumerate(zip(stored.cells, fresh.cells)):
        if (a.cell_type, a.source) != (b.cell_type, b.source):
            problems.append(f"cell {i}: the cell itself differs (a run must not change the notebook's cells)")
            continue
        if a.cell_type != "code":
            continue
        na, nb_ = normalised(a), normalised(b)
        if len(na) != len(nb_):
            problems.append(f"cell {i}: {len(na)} stored outputs, {len(nb_)} fresh")
            continue
        for k, (x, y) in enumerate(zip(na, nb_)):
            if x[0] != y[0]:
                problems.append(f"cell {i} output {k}: {x[0]} stored, {y[0]} fresh")
            elif x[0] != "display":
                if x != y:
                    problems.append(f"cell {i} output {k}: {x[-1]!r:.200} stored, {y[-1]!r:.200} fresh")
            elif set(x[1]) != set(y[1]):
                problems.append(f"cell {i} output {k}: kinds {sorted(x[1])} stored, {sorted(y[1])} fresh")
            else:
                for mime, va in x[1].items():
                    vb = y[1][mime]
                    if mime == "image/png" and va is not None:
                        if va.shape != vb.shape:
                            problems.append(f"cell {i} output {k}: image {va.shape} stored, {vb.shape} fresh")
                        elif float(np.sqrt(np.mean((va - vb) ** 2))) > pixel_tol:
                            rms = float(np.sqrt(np.mean((va - vb) ** 2)))
                            problems.append(f"cell {i} output {k}: image differs (rms {rms:.2g})")
                    elif va != vb:
                        problems.append(f"cell {i} output {k} {mime}: {va!r:.200} stored, {vb!r:.200} fresh")
    return problems


def write(nb, path: Path) -> None:
    """Store an executed notebook atomically.

    Parameters
    ----------
    nb : nbformat.NotebookNode
    path : pathlib.Path
    """
    import nbformat
    from planargeo.files import atomic_write

    atomic_write(path, nbformat.writes(nb) + "\n")


def main(argv=None) -> int:
    """Command line: run (and store, or check) the notebooks; print the time of each.

    Parameters
    ----------
    argv : list of str, optional

    Returns
    -------
    int
        Exit status: 0, or 1 when ``--check`` found a difference.
    """
    import nbformat

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("prefixes", nargs="*", help="only notebooks whose names start with these")
    ap.add_argument("--check", action="store_true", help="compare with the stored outputs, write nothing")
    ap.add_argument("--jobs", "-j", type=int, default=1, help="notebooks run at once (default 1)")
    args = ap.parse_args(argv)
    total, total_cpu, status = 0.0, 0.0, 0
    paths = notebook_paths(args.prefixes)
    cpu_start, wall_start = kernel_cpu_seconds(), time.perf_counter()
    with concurrent.futures.ThreadPoolExecutor(max(1, args.jobs)) as pool:
        runs = pool.map(execute, paths)
        for path, (nb, seconds, skipped) in zip(paths, runs):
            cpu = kernel_cpu_seconds() - cpu_start - total_cpu if args.jobs == 1 else float("nan")
            total += seconds
            total_cpu += 0.0 if cpu != cpu else cpu
            note = "".join(f"; cell {i} not run ({name} missing)" for i, name in skipped.items())
            if args.check:
                diff = differences(nbformat.read(path, as_version=4), nb)
                status |= bool(diff)
                note += "".join(f"\n    {d}" for d in diff) or "; outputs as stored"
            else:
                write(nb, path)
            cpu_text = f"{cpu:6.1f} s CPU" if cpu == cpu else "     (CPU: see total)"
            print(f"{path.name:48s} {seconds:6.1f} s wall {cpu_text}{note}", flush=True)
    total_cpu = kernel_cpu_seconds() - cpu_start
    print(f"{'total (sum of the runs)':48s} {total:6.1f} s wall {total_cpu:6.1f} s CPU (kernels); "
          f"elapsed {time.perf_counter() - wall_start:.1f} s with {args.jobs} job(s)")
    return status


if __name__ == "__main__":
    sys.exit(main())
