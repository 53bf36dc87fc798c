"""Widget latency: time from a control change to the redrawn figure, per explorer.

For each explorer (drawn off-screen on an Agg canvas, ``display="agg"``) a
control is moved through a list of values; each change runs the explorer's
update (recompute, set the artists in place, ``canvas.draw()``).  It is
compared with a *bare redraw*: ``fig.canvas.draw()`` of the same figure with
nothing changed.  The two are measured interleaved (change, bare, change,
bare...) so that machine load affects both alike; medians are reported.

Goal: for the 10-link chain with every overlay on, the update should cost at
most 1.3 bare redraws (the explorer's own work is small next to drawing).

A second table times the display-only controls (overlay checkboxes, the
percussion explorer's ``α``): they re-render the last computed state without
calling the explorer's ``compute`` (the *computes* column counts the calls
during the measurement; it must be 0 there).

Run::

    MPLBACKEND=Agg .venv/bin/python benchmarks/widget_latency.py [--repeat 15] [--out benchmarks/results]
"""
from __future__ import annotations

import argparse
import datetime
import json
import os
import platform
import statistics
import time
from pathlib import Path

import numpy as np

from planargeo.files import atomic_write_many

ALL_CHAIN_OVERLAYS = {k: True for k in ("velocity poles", "acceleration poles", "bias terms",
                                          "internal forces", "T/U split", "articulated inertias")}


def cases():
    """(label, factory, control, values) for every explorer."""
    from planargeo.widgets import (CarExplorer, ChainExplorer, PercussionExplorer,
                                   ProjectiveExplorer, ScrewSumExplorer, SliderCrankExplorer,
                                   TreeExplorer)

    return [
        ("projective playground (ellipse, construction)", lambda: ProjectiveExplorer(display="agg"),
         "P x", list(np.linspace(1.8, 3.0, 6)) + list(np.linspace(0.1, 0.6, 6))),
        ("inertia and percussion (bat)", lambda: PercussionExplorer(display="agg"),
         "pole x", list(np.linspace(-0.8, -0.1, 12))),
        ("twist addition", lambda: ScrewSumExplorer(display="agg"),
         "x2", list(np.linspace(0.5, 2.5, 12))),
        ("wrench addition", lambda: ScrewSumExplorer(display="agg", add="wrenches"),
         "angle2", list(np.linspace(60, 120, 12))),
        ("chain, 4 links, default overlays", lambda: ChainExplorer(display="agg"),
         "angle", list(np.linspace(-60, 0, 12))),
        ("chain, 10 links, all overlays", lambda: ChainExplorer(display="agg", links=10, **ALL_CHAIN_OVERLAYS),
         "angle", list(np.linspace(-60, 0, 12))),
        ("chain, 20 links, all overlays", lambda: ChainExplorer(display="agg", links=20, **ALL_CHAIN_OVERLAYS),
         "angle", list(np.linspace(-60, 0, 12))),
        ("car cornering", lambda: CarExplorer(display="agg"),
         "speed (m/s)", list(np.linspace(2, 14, 12))),
        ("slider-crank", lambda: SliderCrankExplorer(display="agg"),
         "crank angle (deg)", list(np.linspace(10, 70, 12))),
        ("trees and loops (Fig 9.2)", lambda: TreeExplorer(display="agg"),
         "speed", list(np.linspace(0.2, 2.0, 12))),
    ]


def toggle_cases():
    """(label, factory, control, values): display-only controls, switched back and forth."""
    from planargeo.widgets import (ChainExplorer, PercussionExplorer, ProjectiveExplorer,
                                   SliderCrankExplorer, TreeExplorer)

    flip = [False, True] * 6
    return [
        ("projective playground: construction", lambda: ProjectiveExplorer(display="agg"),
         "construction", flip),
        ("inertia and percussion: α (readout only)", lambda: PercussionExplorer(display="agg"),
         "angular accel. α", list(np.linspace(-20, 20, 12))),
        ("chain, 10 links, all overlays: T/U split",
         lambda: ChainExplorer(display="agg", links=10, **ALL_CHAIN_OVERLAYS), "T/U split", flip),
        ("chain, 10 links, all overlays: articulated inertias",
         lambda: ChainExplorer(display="agg", links=10, **ALL_CHAIN_OVERLAYS), "articulated inertias", flip),
        ("slider-crank: velocity poles", lambda: SliderCrankExplorer(display="agg"),
         "velocity poles", [True, False] * 6),
        ("trees and loops: reaction forces", lambda: TreeExplorer(display="agg"),
         "reaction forces", flip),
    ]


def measure(factory, control, values, repeat):
    ex = factory()
    fig = ex.fig
    fig.canvas.draw()
    n0 = ex.n_computes
    upd, bare = [], []
    for _ in range(repeat):
        for v in values:
            v = v if isinstance(v, (bool, str)) else float(v)
            t0 = time.perf_counter()
            ex.controls[control].value = v
            t1 = time.perf_counter()
            fig.canvas.draw()
            t2 = time.perf_counter()
            upd.append(t1 - t0)
            bare.append(t2 - t1)
    if ex.message:
        raise RuntimeError(f"explorer reported a message during the benchmark: {ex.message}")
    return statistics.median(upd), statistics.median(bare), ex.n_updates, ex.n_computes - n0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3, help="passes over each value list")
    ap.add_argument("--out", default=str(Path(__file__).parent / "results"))
    args = ap.parse_args(argv)
    import matplotlib

    matplotlib.use("Agg")
    rows, toggles = [], []
    for table, make in ((rows, cases), (toggles, toggle_cases)):
        for label, factory, control, values in make():
            u, b, n, nc = measure(factory, control, values, args.repeat)
            table.append({"explorer": label, "control": control, "update_ms": 1e3 * u,
                          "bare_ms": 1e3 * b, "ratio": u / b, "updates": n, "computes": nc})
            print(f"{label:56s} update {1e3 * u:7.1f} ms  bare {1e3 * b:7.1f} ms  ratio {u / b:5.2f}"
                  f"  computes {nc}")
    out = Path(args.out)
    goal = next(r for r in rows if r["explorer"].startswith("chain, 10 links"))
    meta = {"date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
            "python": platform.python_version(), "machine": platform.machine(),
            "cpus": os.cpu_count(), "load": os.getloadavg()[0] if hasattr(os, "getloadavg") else None,
            "matplotlib": matplotlib.__version__, "repeat": args.repeat}
    lines = [
        "# Widget latency",
        "",
        "Median time from a control change to the redrawn figure (Agg canvas, off-screen), and its",
        "ratio to a bare redraw (`fig.canvas.draw()` of the same figure with nothing changed),",
        "measured interleaved. Generated by `benchmarks/widget_latency.py`.",
        "",
        f"Machine: {meta['machine']}, {meta['cpus']} CPUs, load average {meta['load']:.1f} at the start; "
        f"Python {meta['python']}, matplotlib {meta['matplotlib']}; {meta['date']}.",
        "",
        f"Medians of {args.repeat} passes over each value list (12 changes per pass); the machine is "
        "shared, so the ratios (measured interleaved) matter more than the milliseconds.",
        "",
        "| explorer | control | update (ms) | bare redraw (ms) | ratio | computes |",
        "|---|---|---:|---:|---:|---:|",
    ]
    for r in rows:
        lines.append(f"| {r['explorer']} | `{r['control']}` | {r['update_ms']:.1f} | {r['bare_ms']:.1f} "
                     f"| {r['ratio']:.2f} | {r['computes']} |")
    lines += ["", "Display-only controls (no `compute`, the last state re-rendered and redrawn):", "",
              "| explorer | control | update (ms) | bare redraw (ms) | ratio | computes |",
              "|---|---|---:|---:|---:|---:|"]
    for r in toggles:
        lines.append(f"| {r['explorer']} | `{r['control']}` | {r['update_ms']:.1f} | {r['bare_ms']:.1f} "
                     f"| {r['ratio']:.2f} | {r['computes']} |")
    ok = goal["ratio"] <= 1.3
    quiet = all(r["computes"] == 0 for r in toggles)
    lines += ["", f"Display-only controls called `compute`: **{'never' if quiet else 'YES (a bug)'}**."]
    lines += ["", f"Goal (10-link chain, all overlays, ratio <= 1.3): **{'met' if ok else 'NOT met'}** "
                  f"({goal['ratio']:.2f}).", ""]
    atomic_write_many({out / "widget_latency.json": json.dumps({"meta": meta, "rows": rows,
                                                                "display_only": toggles}, indent=1),
                       out / "widget_latency.md": "\n".join(lines)})
    print(f"wrote {out / 'widget_latency.md'}")
    return 0 if ok and quiet else 1


if __name__ == "__main__":
    raise SystemExit(main())
