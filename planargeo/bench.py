"""``planargeo bench``: forward dynamics benchmarks, measured side by side in one run.

Three tables (Markdown) and charts (SVG + PNG) are written to ``--out``
(default ``benchmarks/results``):

``single_state``
    One state of a uniform chain of ``N`` links: time per call of our ABA
    (thesis 3.6), Pinocchio's ``pin.aba`` (C++), our dense CRBA solve and the
    other forward dynamics methods available; the headline is the *ratio* to
    Pinocchio, which is robust to machine speed and load.
``batch``
    Throughput for 1, 100 and 10000 states (N = 10): our vectorised ABA (one
    call), our ABA called state by state, ``pin.aba`` in a Python loop, and
    the batched dense CRBA.
``accuracy``
    Speed against accuracy: largest relative error of each method against the
    dense CRBA solve and against Pinocchio, with its time per call.

All timings are the best of several repeats of the mean over many calls
(``timeit``) in *thread CPU time* (``time.thread_time``: time the process
spends descheduled on a busy machine does not count), so they estimate the cost
without the noise of other processes.  The headline ratio ``aba / pin.aba`` is
measured by interleaving: the two calls alternate in short blocks over many
rounds, and the table gives the ratio of the best blocks and the median of the
per-round ratios (both see the same machine state);
BLAS runs single-threaded (as Pinocchio does): the command re-runs itself in a
fresh process with ``OPENBLAS_NUM_THREADS=1`` (and OMP/MKL) if needed.
This module imports matplotlib (charts); the math modules never do.
"""
from __future__ import annotations

import argparse
import datetime as _dt
import importlib
import os
import platform
import sys
import time
import timeit
from pathlib import Path

import numpy as np

from .model import chain_model

__all__ = ["add_arguments", "main", "time_call", "time_interleaved", "to_pinocchio"]

SINGLE_SIZES = (2, 5, 10, 20, 50, 100)
BATCH_SIZES = (1, 100, 10000)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--out", default="benchmarks/results", help="output directory (default: %(default)s)")
    parser.add_argument("--quick", action="store_true", help="fewer repeats and smaller batches (smoke test)")
    parser.add_argument("--no-charts", action="store_true", help="tables only")
    parser.add_argument("--sizes", default=",".join(map(str, SINGLE_SIZES)),
                        help="chain sizes N for the single-state table (default: %(default)s)")
    parser.add_argument("--only", choices=("dynamics", "breakdown", "widgets"), action="append",
                        help="run only these groups (repeatable; default: all). 'breakdown' is the "
                             "accuracy study benchmarks/breakdown.py, 'widgets' the explorer latencies "
                             "benchmarks/widget_latency.py (both need a source checkout)")


def _calls_for(fn, seconds: float, timer) -> int:
    """How many calls of ``fn`` take about ``seconds``."""
    fn()
    n, t = 1, 0.0
    while True:
        t = timeit.Timer(fn, timer=timer).timeit(number=n)
        if t > seconds / 10 or n > 1e6:
            break
        n *= 4 if t < seconds / 100 else 2
    return max(1, int(n * seconds / max(t, 1e-9)))


def time_call(fn, *, budget: float = 0.2, repeat: int = 5, timer=time.thread_time) -> float:
    """Seconds per call of ``fn()``: best over ``repeat`` runs of the mean over ~``budget`` seconds (thread CPU time)."""
    n = _calls_for(fn, budget / repeat, timer)
    return min(timeit.Timer(fn, timer=timer).repeat(number=n, repeat=repeat)) / n


def time_interleaved(fns: dict, *, budget: float = 0.5, rounds: int = 25, timer=time.thread_time) -> dict:
    """Seconds per call of each ``fns[name]()``, measured in alternating blocks: ``{name: [per round]}``.

    Every round times one block of each function in turn, so the functions see
    the same machine state; ratios of the best blocks or medians of per-round
    ratios are robust to load.
    """
    per = budget / (rounds * len(fns))
    timers = {k: (timeit.Timer(f, timer=timer), _calls_for(f, per, timer)) for k, f in fns.items()}
    out = {k: [] for k in fns}
    for _ in range(rounds):
        for k, (t, n) in timers.items():
            out[k].append(t.timeit(number=n) / n)
    return out


def ratio_stats(times: dict, num: str, den: str) -> dict:
    """``{"best": min(num)/min(den), "median": median of per-round num/den}`` from :func:`time_interleaved`."""
    a, b = np.array(times[num]), np.array(times[den])
    return {"best": float(a.min() / b.min()), "median": float(np.median(a / b))}


def to_pinocchio(model):
    """The same revolute/prismatic mechanism as a Pinocchio model (None if pinocchio is missing)."""
    try:
        import pinocchio as pin
    except ImportError:  # pragma: no cover
        return None
    pm = pin.Model()
    ids = []
    for i, (b, j, p) in enumerate(zip(model.bodies, model.joints, model.parents)):
        px, py, th = j.placement
        R = np.array([[np.cos(th), -np.sin(th), 0.0], [np.sin(th), np.cos(th), 0.0], [0.0, 0.0, 1.0]])
        jm = {"revolute": pin.JointModelRZ, "prismatic": pin.JointModelPX}[j.kind]()
        jid = pm.addJoint(0 if p < 0 else ids[p], jm, pin.SE3(R, np.array([px, py, 0.0])), f"joint{i}")
        I3 = np.diag([1.0, 1.0, b.inertia])
        pm.appendBodyToJoint(jid, pin.Inertia(b.mass, np.array([b.com[0], b.com[1], 0.0]), I3), pin.SE3.Identity())
        ids.append(jid)
    pm.gravity = pin.Motion(np.array([model.gravity[0], model.gravity[1], 0.0, 0.0, 0.0, 0.0]))
    return pm


def _methods() -> dict:
    from .scenes.chain import available_methods

    return available_methods()


def _state(N, seed=0, batch=()):
    rng = np.random.default_rng(seed)
    return rng.normal(size=(3,) + batch + (N,))


def _fmt_us(t):
    return "—" if t is None or not np.isfinite(t) else (f"{t * 1e6:.1f}" if t < 1e-2 else f"{t * 1e6:.0f}")


def _interleaved_ratio(m, budget, seed):
    """aba and pin.aba on one model, interleaved: (best aba s, best pin s, ratio stats) or None without Pinocchio."""
    from .algorithms.aba import forward_dynamics

    pm = to_pinocchio(m)
    if pm is None:
        return None
    import pinocchio as pin

    pd = pm.createData()
    q, qd, tau = _state(m.nq, seed=seed)
    t = time_interleaved({"aba": lambda: forward_dynamics(m, q, qd, tau), "pin": lambda: pin.aba(pm, pd, q, qd, tau)},
                         budget=3 * budget, rounds=40)
    return min(t["aba"]), min(t["pin"]), ratio_stats(t, "aba", "pin")


def run_single(sizes, budget):
    """Time per call (s) of every method and pin.aba for each N; and their errors.

    ``aba`` and ``pinocchio`` are timed interleaved (:func:`time_interleaved`);
    ``ratio`` holds their best and median ratios on ``chain_model(N)``, and
    ``ratio_random`` on ``random_model(N)`` (no zero placements or offsets).
    """
    from .model import random_model

    methods = _methods()
    rows = []
    for N in sizes:
        m = chain_model(N)
        q, qd, tau = _state(N, seed=N)
        ref = methods["crba"](m, q, qd, tau)
        pm = to_pinocchio(m)
        row = {"N": N, "times": {}, "err_crba": {}, "err_pin": {}}
        pin_ref = None
        if pm is not None:
            import pinocchio as pin

            pd = pm.createData()
            pin_ref = pin.aba(pm, pd, q, qd, tau).copy()
            row["err_crba"]["pinocchio"] = float(np.abs(pin_ref - ref).max() / np.abs(ref).max())
            t_aba, t_pin, row["ratio"] = _interleaved_ratio(m, budget, N)
            row["times"]["pinocchio"] = t_pin
            row["ratio_random"] = _interleaved_ratio(random_model(N, seed=N), budget, N)[2]
        for name, fn in methods.items():
            try:
                out = np.asarray(fn(m, q, qd, tau))
            except Exception as exc:  # report, don't die
                row["times"][name] = float("nan")
                row["err_crba"][name] = f"{type(exc).__name__}"
                continue
            if name == "aba" and "ratio" in row:
                row["times"][name] = t_aba
            else:
                row["times"][name] = time_call(lambda: fn(m, q, qd, tau), budget=budget)
            row["err_crba"][name] = float(np.abs(out - ref).max() / np.abs(ref).max())
            if pin_ref is not None:
                row["err_pin"][name] = float(np.abs(out - pin_ref).max() / np.abs(pin_ref).max())
        rows.append(row)
    return rows


def run_batch(batch_sizes, budget, N=10):
    from .algorithms.aba import forward_dynamics
    from .algorithms.crba import forward_dynamics_crba

    m = chain_model(N)
    pm = to_pinocchio(m)
    rows = []
    for B in batch_sizes:
        q, qd, tau = _state(N, seed=B, batch=(B,))
        row = {"B": B, "times": {}}
        row["times"]["aba (vectorised)"] = time_call(lambda: forward_dynamics(m, q, qd, tau), budget=budget, repeat=3)

        def loop_ours():
            for k in range(B):
                forward_dynamics(m, q[k], qd[k], tau[k])

        row["times"]["aba (state by state)"] = time_call(loop_ours, budget=budget, repeat=3)
        row["times"]["crba (vectorised)"] = time_call(lambda: forward_dynamics_crba(m, q, qd, tau), budget=budget,
                                                      repeat=3)
        if pm is not None:
            import pinocchio as pin

            pd = pm.createData()

            def loop_pin():
                for k in range(B):
                    pin.aba(pm, pd, q[k], qd[k], tau[k])

            row["times"]["pinocchio (loop)"] = time_call(loop_pin, budget=budget, repeat=3)
        # agreement of the vectorised call with the dense reference
        a, b = forward_dynamics(m, q, qd, tau), forward_dynamics_crba(m, q, qd, tau)
        row["err"] = float(np.abs(a - b).max() / np.abs(b).max())
        rows.append(row)
    return rows


def _header(title):
    now = _dt.datetime.now(_dt.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    try:
        import pinocchio as pin

        pv = pin.__version__
    except ImportError:  # pragma: no cover
        pv = "not installed"
    return (f"# {title}\n\nGenerated by `planargeo bench` on {now}; Python {platform.python_version()}, "
            f"numpy {np.__version__}, Pinocchio {pv}, {os.cpu_count()} CPU(s), {platform.machine()}.\n"
            "Times are per call (µs), best of repeats in thread CPU time; **ratios are the headline** (absolute times depend "
            "on the machine and its load).\n\n")


def write_single(rows, out: Path) -> str:
    names = [n for n in rows[0]["times"] if n != "pinocchio"]
    has_pin = "pinocchio" in rows[0]["times"]
    lines = [_header("Single-state forward dynamics, uniform chain of N links"),
             "Model: `chain_model(N)` (unit links, revolute joints, gravity -9.81 y), random q, q̇, τ.\n"]
    if "ratio" in rows[0]:
        lines += ["## Headline: ABA / pin.aba, measured interleaved\n",
                  "`aba` (`planargeo.algorithms.aba.forward_dynamics`, one state as float64 arrays: the compiled "
                  "plan) and `pin.aba` alternate in short blocks over 40 rounds (thread CPU time). *best*: ratio "
                  "of the best blocks; *median*: median of the per-round ratios. `chain_model` has zero placement "
                  "angles and y offsets, folded out of the plan; `random_model(N)` (random placements, coms, "
                  "revolute and prismatic joints) has none.\n",
                  "| N | pin.aba µs | aba µs | chain: best | chain: median | random_model: best | "
                  "random_model: median |", "|---:|---:|---:|---:|---:|---:|---:|"]
        for r in rows:
            a, b = r["ratio"], r["ratio_random"]
            lines.append(f"| {r['N']} | {_fmt_us(r['times']['pinocchio'])} | {_fmt_us(r['times']['aba'])} | "
                         f"{a['best']:.1f}× | {a['median']:.1f}× | {b['best']:.1f}× | {b['median']:.1f}× |")
        lines += ["", "## All methods\n"]
    cols = ["N"] + (["pin.aba µs"] if has_pin else []) + [f"{n} µs" for n in names]
    cols += [f"{n} / pin" for n in names] if has_pin else []
    lines.append("| " + " | ".join(cols) + " |")
    lines.append("|" + "---:|" * len(cols))
    for r in rows:
        t = r["times"]
        cells = [str(r["N"])] + ([_fmt_us(t["pinocchio"])] if has_pin else []) + [_fmt_us(t[n]) for n in names]
        if has_pin:
            cells += [f"{t[n] / t['pinocchio']:.1f}×" if np.isfinite(t[n]) else "—" for n in names]
        lines.append("| " + " | ".join(cells) + " |")
    text = "\n".join(lines) + "\n"
    (out / "single_state.md").write_text(text)
    return text


def write_accuracy(rows, out: Path) -> str:
    names = list(rows[0]["err_crba"])
    lines = [_header("Speed against accuracy"),
             "Largest relative error max|q̈ − q̈_ref| / max|q̈_ref| against the dense CRBA solve "
             "(`H q̈ = τ − C`) and against Pinocchio's `pin.aba`, with the time per call. "
             "For large N the dense solve is itself the least accurate (its error grows with cond(H)), "
             "so the column against Pinocchio is the sharper one.\n",
             "| N | method | µs per call | error vs CRBA | error vs Pinocchio |", "|---:|---|---:|---:|---:|"]
    for r in rows:
        for n in names:
            e1 = r["err_crba"].get(n)
            e2 = r["err_pin"].get(n)
            f1 = e1 if isinstance(e1, str) else f"{e1:.1e}"
            f2 = "—" if e2 is None else f"{e2:.1e}"
            lines.append(f"| {r['N']} | {n} | {_fmt_us(r['times'].get(n))} | {f1} | {f2} |")
    text = "\n".join(lines) + "\n"
    (out / "accuracy.md").write_text(text)
    return text


def write_batch(rows, out: Path) -> str:
    names = list(rows[0]["times"])
    lines = [_header("Batch throughput, chain of N = 10 links"),
             "Time per state (µs) for a batch of B states; `aba (vectorised)` is one call of "
             "`forward_dynamics` on arrays of shape (B, 10).\n"]
    cols = ["B"] + [f"{n} µs/state" for n in names] + ["vectorised / pin loop", "error vs CRBA"]
    lines.append("| " + " | ".join(cols) + " |")
    lines.append("|" + "---:|" * len(cols))
    for r in rows:
        t = r["times"]
        ratio = (f"{t['aba (vectorised)'] / t['pinocchio (loop)']:.2f}×" if "pinocchio (loop)" in t else "—")
        lines.append("| " + " | ".join([str(r["B"])] + [_fmt_us(t[n] / r["B"]) for n in names]
                                       + [ratio, f"{r['err']:.1e}"]) + " |")
    text = "\n".join(lines) + "\n"
    (out / "batch.md").write_text(text)
    return text


def write_charts(single, batch, out: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    Ns = [r["N"] for r in single]
    cycle = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    colour = {n: cycle[k % len(cycle)] for k, n in enumerate(single[0]["times"])}
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    for n in single[0]["times"]:
        ts = np.array([r["times"][n] for r in single]) * 1e6
        ax[0].loglog(Ns, ts, "o-", label=n, color=colour[n])
        if "pinocchio" in single[0]["times"] and n != "pinocchio":
            ax[1].semilogx(Ns, ts / (np.array([r["times"]["pinocchio"] for r in single]) * 1e6), "o-", label=n,
                           color=colour[n])
    ax[0].set(xlabel="N (links)", ylabel="µs per call", title="Single state: time per call")
    ax[1].set(xlabel="N (links)", ylabel="time / pin.aba", title="Single state: ratio to Pinocchio")
    ax[1].set_yscale("log")
    for a in ax:
        a.grid(True, which="both", alpha=0.3)
        a.legend(fontsize=8)
    fig.tight_layout()
    for ext in ("svg", "png"):
        fig.savefig(out / f"single_state.{ext}", dpi=110)
    plt.close(fig)

    Bs = [r["B"] for r in batch]
    fig, ax = plt.subplots(figsize=(6, 4.2))
    for n in batch[0]["times"]:
        ax.loglog(Bs, [r["times"][n] / r["B"] * 1e6 for r in batch], "o-", label=n)
    ax.set(xlabel="batch size B (states)", ylabel="µs per state", title="Batch throughput, N = 10")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    for ext in ("svg", "png"):
        fig.savefig(out / f"batch.{ext}", dpi=110)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(6, 4.2))
    for n in single[0]["err_crba"]:
        pts = [(r["times"][n] * 1e6, r["err_crba"][n]) for r in single
               if not isinstance(r["err_crba"][n], str) and np.isfinite(r["times"][n])]
        if pts:
            x, y = zip(*pts)
            ax.loglog(x, np.maximum(y, 1e-17), "o-", label=n, color=colour[n])
    ax.set(xlabel="µs per call (N = " + ", ".join(map(str, Ns)) + ")", ylabel="relative error vs CRBA",
           title="Speed against accuracy")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    for ext in ("svg", "png"):
        fig.savefig(out / f"speed_accuracy.{ext}", dpi=110)
    plt.close(fig)


_THREAD_VARS = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")


def _single_threaded_argv(args):
    """argv to re-run this benchmark with single-threaded BLAS, or None if it already is."""
    if all(os.environ.get(v) == "1" for v in _THREAD_VARS):
        return None
    argv = [sys.executable, "-m", "planargeo.bench", "--out", str(args.out), "--sizes", str(args.sizes)]
    argv += ["--quick"] * bool(args.quick) + ["--no-charts"] * bool(args.no_charts)
    for group in getattr(args, "only", None) or ():
        argv += ["--only", group]
    return argv


def main(args) -> int:
    # Pinocchio is single-threaded; multi-threaded BLAS on a busy machine makes small dense solves
    # (CRBA) erratic, so every method runs with one BLAS thread: re-run in a fresh process if needed.
    argv = _single_threaded_argv(args)
    if argv is not None:
        import subprocess

        env = dict(os.environ, **{v: "1" for v in _THREAD_VARS})
        return subprocess.call(argv, env=env)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    sizes = tuple(int(s) for s in str(args.sizes).split(",") if s.strip())
    groups = set(getattr(args, "only", None) or ("dynamics", "breakdown", "widgets"))
    rc = 0
    if "dynamics" in groups:
        budget = 0.05 if args.quick else 0.3
        batches = (1, 100, 1000) if args.quick else BATCH_SIZES
        single = run_single(sizes, budget)
        print(write_single(single, out))
        print(write_accuracy(single, out))
        batch = run_batch(batches, budget)
        print(write_batch(batch, out))
        if not args.no_charts:
            write_charts(single, batch, out)
            print(f"charts written to {out}/single_state.svg, batch.svg, speed_accuracy.svg (+ .png)")
    scripts = Path(__file__).resolve().parents[1] / "benchmarks"
    for group, script in (("breakdown", "breakdown.py"), ("widgets", "widget_latency.py")):
        if group not in groups:
            continue
        path = scripts / script
        if not path.exists():
            print(f"skipping {group}: {path} not found (run from a source checkout)")
            continue
        import subprocess

        print(f"running {path.name} ...", flush=True)
        rc |= subprocess.call([sys.executable, str(path)], cwd=str(scripts.parent))
    return rc


if __name__ == "__main__":  # pragma: no cover
    p = argparse.ArgumentParser()
    add_arguments(p)
    raise SystemExit(main(p.parse_args()))
