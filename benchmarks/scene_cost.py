"""Model no more than a scene needs: what each scene computes, what its consumers read, what the rest costs.

Run ``python benchmarks/scene_cost.py [--quick] [--out DIR]`` (``--quick``: under 30 s).

Every scene of :mod:`planargeo.scenes` computes a fixed set of quantities, and
its consumers (``planargeo report``, the explorers of :mod:`planargeo.widgets`,
the gallery figures, the notebooks) each read a part of them.  For every
scene and consumer this script times **the scene as it is** against **the
minimal computation that consumer needs**, written out here from the same
package functions (:data:`CASES`), and reports the ratio.  Both are timed
interleaved in one run (:func:`planargeo.bench.time_interleaved`: alternating
blocks, thread CPU time) and the table gives the ratio of the best blocks and
the median of the per-round ratios (:func:`planargeo.bench.ratio_stats`).
``tests/test_scene_cost.py`` checks that every minimal path gives the same
numbers as the full one (agreement, never timing).

The explorers' own choices are measured too (the chain explorer computes the
per-joint T/U split only when it is drawn), together with the qdd-only fast
paths of the forward-dynamics methods against their full workspaces, and,
for scale, the whole explorer update (compute, then the picture the page draws,
``ex.picture()``).

Where an explorer already computes only what it draws (cached models, ``loop_solve``'s
contact columns, the car's ``outlines=False``), its compute step is the minimal side and
the scene the full one.  The one minimal path not applied to the package, the chain
explorer's q̈-plus-Newton–Euler compute step, is a prototype in this file;
``docs/scenes.md`` lists what is applied and what is found.

Writes ``results/scene_cost.md``.
"""
from __future__ import annotations

import argparse
import functools
import itertools
import math
import os
import platform
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

for _v in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):   # as planargeo bench
    os.environ.setdefault(_v, "1")
os.environ.setdefault("MPLBACKEND", "Agg")

import numpy as np  # noqa: E402

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from planargeo import scenes  # noqa: E402
from planargeo.files import atomic_write  # noqa: E402
from planargeo.algorithms.aba import articulated_body, forward_dynamics  # noqa: E402
from planargeo.algorithms.articulated_inertia import articulated_inertia  # noqa: E402
from planargeo.algorithms.articulated_mobility import articulated_mobility  # noqa: E402
from planargeo.algorithms.chain_splitting import forward_dynamics_mobility_split, mobility_split  # noqa: E402
from planargeo.algorithms.projective import forward_dynamics_projective, projective_workspace  # noqa: E402
from planargeo.algorithms.stacked import forward_dynamics_stacked, stacked_solve  # noqa: E402
from bench import _progress as log  # noqa: E402  (one progress-line helper)
from bench import ratio_stats, time_interleaved  # noqa: E402
from planargeo.mechanics.kinematics import kinematics  # noqa: E402
from planargeo.mechanics.model import chain_model  # noqa: E402
from planargeo.scenes import car as car_scene  # noqa: E402
from planargeo.scenes import chain as chain_scene  # noqa: E402
from planargeo.scenes import trees as tree_scene  # noqa: E402
from planargeo.scenes.horizontal_chain import effective_centre, horizontal_chain_model  # noqa: E402
from planargeo.scenes.two_body import two_body_model  # noqa: E402


# =========================================================================== minimal paths
# --------------------------------------------------------------------------- chain (report)
def chain_methods_only(n=10, seed=1):
    """The chain scene's quantities without ``extra["data"]`` (an ABA workspace nothing reads)."""
    model = chain_model(n, 1.0, 1.0, "revolute", gravity=(0.0, -9.81))
    q, qd, tau = np.random.default_rng(seed).normal(size=(3, n))
    qdd = {name: np.asarray(fn(model, q, qd, tau), dtype=float).tolist()
           for name, fn in chain_scene.METHODS.items()}
    vals = [np.asarray(v) for v in qdd.values()]
    return {"qdd": qdd, "max_disagreement": max(float(np.abs(v - vals[0]).max(initial=0.0)) for v in vals)}


# --------------------------------------------------------------------------- car (explorer)
# --------------------------------------------------------------------------- explorers that solve loops or trees
def slider_crank_compute_reads(st) -> dict:
    """The numbers the slider-crank explorer's ``render`` reads from its compute state."""
    sol = st["sol"]
    return {"pose": sol.data.pose, "com": sol.data.com, "v": np.asarray(st["v"]), "a": np.asarray(st["a"]),
            "F3": st["F3"], "qdd": np.asarray(sol.qdd), "tau_drive": np.asarray(sol.tau_drive), "h": st["h"],
            "q": np.asarray(st["q"]), "qd": np.asarray(st["qd"])}


def slider_crank_explorer_reads(res) -> dict:
    """The same numbers from the ``slider-crank`` scene's result."""
    sol, qn = res.extra["solution"], res.quantities
    return {"pose": sol.data.pose, "com": sol.data.com, "v": np.asarray(qn["v"]), "a": np.asarray(qn["a"]),
            "F3": np.asarray(qn["F3"]), "qdd": np.asarray(qn["qdd"]), "tau_drive": np.asarray(qn["tau_drive"]),
            "h": qn["h"], "q": np.asarray(qn["q"]), "qd": np.asarray(qn["qd"])}


def tree_compute_reads(st) -> dict:
    """What the tree explorer's ``render`` reads from its compute state (loops open or closed)."""
    sol = st["sol"]
    out = {"pose": sol.data.pose, "v": sol.data.v, "a": np.asarray(st["a"]), "qdd": np.asarray(st["qdd"])}
    if st["closed"]:
        out.update(F=np.asarray(st["F"]), cond=st["cond"])
    return out


def tree_scene_reads(res) -> dict:
    """The same numbers from the ``tree`` / ``constrained-tree`` scene's result."""
    sol = res.extra["solution"]
    out = {"pose": sol.data.pose, "v": sol.data.v, "a": np.asarray(res.quantities["a"]).reshape(-1, 3),
           "qdd": np.asarray(res.quantities["qdd"])}
    if "F" in res.quantities:
        out.update(F=np.asarray(res.quantities["F"]).reshape(-1, 3), cond=res.quantities["cond"])
    return out


def tree_geometry_only(mass=1.0, length=1.0, g=9.81):
    """What gallery Fig 9.1 reads: the model and the pose (it runs ``kinematics`` itself), no dynamics."""
    model = tree_scene.tree_model(mass, length, g)
    q = tree_scene._default_q()
    return {"model": model, "pose": kinematics(model, q, np.zeros(9)).pose}


def tree_figure_reads(res) -> dict:
    return {"model": res.model, "pose": kinematics(res.model, res.state["q"], np.zeros(res.model.nq)).pose}


# --------------------------------------------------------------------------- chapter 7 chart points
_two_body_model = functools.lru_cache(maxsize=64)(two_body_model)
_horizontal_model = functools.lru_cache(maxsize=64)(horizontal_chain_model)


def two_body_mx(rho=0.5, phi=math.pi / 4, m=1.0, L=1.0):
    """One point of the m_x/m chart (Fig 7.4): ``A_1[0, 0] / m`` on a cached model."""
    return float(articulated_inertia(_two_body_model(m, rho, L), np.array([0.0, phi])).A[0][0, 0] / m)


def horizontal_d(n=4, lam=2.0):
    """One point of the d/L chart (Figs 7.5-7.6): the effective centre of ``A_1`` on a cached model."""
    r = articulated_inertia(_horizontal_model(n, 1.0, 1.0 / lam, 1.0), np.zeros(n))
    return effective_centre(r.A[0])[0]


def mobility_x(rho=0.5, phi=math.pi / 4, m=1.0, L=1.0, tau=1.0):
    """One point of the x/L chart (Fig 7.10): ``a_2 = -Λ_2⁻¹ f_3 + b_2`` on a cached model."""
    r = articulated_mobility(_two_body_model(m, rho, L), np.array([0.0, phi]))
    a2 = -r.Lambda_inv[1] @ np.array([0.0, 0.0, tau]) + r.b[1]
    return float(-a2[1] / (L * a2[2]))


# --------------------------------------------------------------------------- explorers
def chain_explorer(overlays: bool, links: int = 10):
    from planargeo.widgets import ChainExplorer
    from planargeo.widgets.chain import OVERLAYS

    return ChainExplorer(display="agg", links=links, **{k: overlays for k in OVERLAYS})


def chain_explorer_default(links: int = 10):
    """The chain explorer with its default overlays (velocity poles, internal forces)."""
    from planargeo.widgets import ChainExplorer

    return ChainExplorer(display="agg", links=links)


def chain_explorer_values(ex, overlays: bool) -> dict:
    from planargeo.widgets.chain import OVERLAYS

    return dict(ex.values, **{k: overlays for k in OVERLAYS})


def chain_explorer_rnea_compute(ex, v) -> dict:
    """The chain explorer's compute step without the ABA workspace (prototype).

    Unless the articulated inertias or the T/U split are shown, nothing drawn or read
    needs ``A``: q̈ by the compiled kernel (:func:`forward_dynamics`) and one Newton–Euler
    pass (:func:`newton_euler`) give ``v``, ``κ``, ``p``, ``a``, ``f`` and the energies.
    """
    from planargeo.algorithms.rnea import newton_euler
    from planargeo.simulate.integrate import energy

    model, q, qd, tau = ex.initial_state(v)
    w = newton_euler(model, q, qd, forward_dynamics(model, q, qd, tau))
    ke, pe = energy(model, q, qd)
    return {"model": model, "w": w, "t": 0.0, "tau": tau, "ke": float(ke), "pe": float(pe)}


def chain_explorer_drawn(st) -> dict:
    """What the chain explorer draws and reads with its default overlays (velocity poles, internal forces)."""
    w = st["w"]
    return {"qdd": w.qdd, "f": w.f, "a": w.a, "v": w.v, "kappa": w.kappa, "p": w.p, "ke": st["ke"], "pe": st["pe"]}


def chain_explorer_reads(st) -> dict:
    """The numbers of the chain explorer's readout (and the drawn workspace arrays) from a compute state."""
    w = st["w"]
    return {"qdd": w.qdd, "f": w.f, "a": w.a, "v": w.v, "A": w.A, "ke": st["ke"], "pe": st["pe"]}


# --------------------------------------------------------------------------- percussion explorer
# =========================================================================== cases
@dataclass
class Case:
    """One comparison: ``full()`` is what runs now, ``minimal()`` what the consumer needs.

    ``read_full(full())`` and ``read_minimal(minimal())`` give the numbers the
    consumer reads (dicts of arrays / floats); ``exact``: they must agree bitwise
    (the same operations), otherwise to ``rtol``.
    """

    group: str
    scene: str
    consumer: str
    skipped: str
    full: Callable[[], Any]
    minimal: Callable[[], Any]
    read_full: Callable[[Any], dict] = lambda r: r
    read_minimal: Callable[[Any], dict] = lambda r: r
    exact: bool = True
    rtol: float = 1e-12
    note: str = ""
    extra: dict = field(default_factory=dict)


def _chain_report_reads(res):
    return {"qdd": res.quantities["qdd"], "max_disagreement": res.quantities["max_disagreement"]}


def _car_reads(res):
    q, x = res.quantities, res.extra
    out = {k: np.asarray(q[k], dtype=float) for k in ("v", "a", "I", "f_A", "omega_dot", "mu")}
    out.update({k: np.asarray(x[k], dtype=float) for k in ("rear_contact", "front_contact", "cg", "front_rolling",
                                                           "tyre_wrenches", "steer")})
    return out


def cases() -> list:
    """Every comparison, built fresh (explorer instances included)."""
    N = 10
    qn, qdn, taun = np.random.default_rng(3).normal(size=(3, N))
    mn = chain_model(N)
    from planargeo.widgets import SliderCrankExplorer, TreeExplorer
    from planargeo.scenes import impulse as impulse_scene, subspace as subspace_scene
    from planargeo.scenes.articulated import articulated_state, bent_chain_model
    from planargeo.scenes.splitting import splitting_state
    from planargeo.screws.twists import inertia_matrix

    sc_ex, tr_ex = SliderCrankExplorer(display="agg"), TreeExplorer(display="agg")
    v_sc = dict(sc_ex.values, **{"crank angle (deg)": math.degrees(0.7)})
    v_open = dict(tr_ex.values, speed=0.7, gravity=9.81, loops="open (Fig 9.1)")    # the scenes' g
    v_closed = dict(tr_ex.values, speed=0.7, gravity=9.81, loops="closed (Fig 9.2)")
    out = [
        # ---- scenes as their consumers read them
        Case("scene", "chain", "`planargeo report chain`, notebook 08 (n = 10)",
             "the ABA workspace `extra['data']` (read by nothing)",
             lambda: scenes.build("chain", n=10, seed=1), lambda: chain_methods_only(10, 1),
             read_full=_chain_report_reads),
        Case("scene", "car", "car explorer (every control change): `car(..., outlines=False)`",
             "the shapely outlines of the body and tyres, which the report and gallery Fig 6.6 compute "
             "(the default) and the explorer skips",
             lambda: car_scene.car(omega=0.6), lambda: car_scene.car(omega=0.6, outlines=False),
             read_full=_car_reads, read_minimal=_car_reads),
        Case("scene", "subspace", "subspace explorer: its compute step (`subspace_state`) vs the scene",
             "the report's plain lists of every quantity (the explorer keeps the numpy arrays)",
             lambda: scenes.build("subspace", joint="revolute_prismatic", joint_angle_deg=30.0),
             lambda: subspace_scene.subspace_state("revolute_prismatic", (0.0, 0.0),
                                                   subspace_scene.unit_direction(30.0),
                                                   inertia_matrix(2.0, (1.0, 0.0), 0.5), [0.0, 1.0, 1.6]),
             read_full=lambda r: {k: r.quantities[k] for k in ("T", "U", "Q", "mu", "psi", "gamma")},
             read_minimal=lambda st: {k: st[k] for k in ("T", "U", "Q", "mu", "psi", "gamma")}),
        Case("scene", "articulated", "articulated explorer: `articulated_state` vs the scene",
             "plain lists and the 7.26 ratios",
             lambda: scenes.build("articulated", n=4, lam=3.0, phi=0.4),
             lambda: articulated_state(bent_chain_model(4, 1 / 3.0), [0.0, 0.4, 0.4, 0.4], pole=(0.0, -0.6)),
             read_full=lambda r: {"A": np.array(r.quantities["A"])}, read_minimal=lambda st: {"A": st["A"]}),
        Case("scene", "splitting", "splitting explorer: `splitting_state` vs the scene",
             "plain lists and the example 7.5 extras",
             lambda: scenes.build("splitting"),
             lambda: splitting_state(bent_chain_model(2, 0.5), [0.0, math.pi / 4], 1, 1.0),
             read_full=lambda r: {"a": np.array(r.quantities["a"])}, read_minimal=lambda st: {"a": st["a"]}),
        Case("scene", "impulse", "impulse explorer: the scene function vs `scenes.build`",
             "`inspect.signature` of the scene (the explorer calls the function)",
             lambda: scenes.build("impulse", body="door", x=0.3), lambda: impulse_scene.impulse(body="door", x=0.3),
             read_full=lambda r: {k: r.quantities[k] for k in ("dv", "reaction", "apparent_mass")},
             read_minimal=lambda r: {k: r.quantities[k] for k in ("dv", "reaction", "apparent_mass")}),
        Case("scene", "slider-crank", "slider-crank explorer: its compute step vs the scene",
             "the scene's model rebuild and report quantities (the explorer caches the model and calls "
             "`loop_solve`, which forms only the contact columns of Λ⁻¹)",
             lambda: scenes.build("slider-crank", psi=0.7), lambda: sc_ex.compute(v_sc, set()),
             read_full=slider_crank_explorer_reads, read_minimal=slider_crank_compute_reads, exact=False),
        Case("scene", "tree", "tree explorer, loops open: its compute step vs the scene",
             "the direct solution 9.48 (`mobility_recursion`, `qdd_direct`: the report's cross-check), C, Δ⁻¹, "
             "the model rebuild: the explorer runs one stacked solve on a cached model",
             lambda: scenes.build("tree", speed=0.7), lambda: tr_ex.compute(v_open, set()),
             read_full=tree_scene_reads, read_minimal=tree_compute_reads, exact=False, rtol=1e-12),
        Case("scene", "tree", "gallery Fig 9.1 (draws the pose)",
             "all dynamics (the figure calls `kinematics` itself)",
             lambda: scenes.build("tree"), lambda: tree_geometry_only(), read_full=tree_figure_reads,
             read_minimal=lambda r: {"model": r["model"], "pose": r["pose"]}),
        Case("scene", "constrained-tree", "tree explorer, loops closed: its compute step vs the scene",
             "the model rebuild and velocity projection (cached in the explorer)",
             lambda: scenes.build("constrained-tree", speed=0.7), lambda: tr_ex.compute(v_closed, set()),
             read_full=tree_scene_reads, read_minimal=tree_compute_reads, exact=False, rtol=1e-10),
        Case("scene", "two-body", "gallery Fig 7.4 chart, one point (m_x/m)",
             "rebuilding the model; `U2`, `T2`, `s`, `R` and the lists of the report",
             lambda: scenes.build("two-body", rho=0.25, phi=1.0), lambda: two_body_mx(0.25, 1.0),
             read_full=lambda r: {"mx_over_m": r.quantities["mx_over_m"]},
             read_minimal=lambda x: {"mx_over_m": x}),
        Case("scene", "horizontal-chain", "gallery Figs 7.5–7.6 chart, one point (d/L)",
             "rebuilding the model; the other three ratios and `A1` as lists",
             lambda: scenes.build("horizontal-chain", n=4, lam=3.0), lambda: horizontal_d(4, 3.0),
             read_full=lambda r: {"d_over_L": r.quantities["d_over_L"]},
             read_minimal=lambda x: {"d_over_L": x}),
        Case("scene", "mobility-example", "gallery Fig 7.10 chart, one point (x/L)",
             "rebuilding the model; `Λ⁻¹`, `T`, `U` of both bodies as lists",
             lambda: scenes.build("mobility-example", rho=0.25, phi=1.0), lambda: mobility_x(0.25, 1.0),
             read_full=lambda r: {"x_over_L": r.quantities["x_over_L"]},
             read_minimal=lambda x: {"x_over_L": x}),
        Case("scene", "(every scene)", "explorers: `scenes.build(name, ...)` instead of the scene function",
             "`inspect.signature` of the scene on every call (to reject unknown parameters)",
             lambda: scenes.build("car", omega=0.6), lambda: car_scene.car(omega=0.6),
             read_full=_car_reads, read_minimal=_car_reads),
        # ---- qdd-only paths against the full workspaces (one state, N = 10)
        Case("method", "chain (N = 10)", "aba: `forward_dynamics` vs `articulated_body`",
             "the workspace (A, d, a, f, per-joint D, U, u); the plan computes q̈ only",
             lambda: articulated_body(mn, qn, qdn, taun), lambda: forward_dynamics(mn, qn, qdn, taun),
             read_full=lambda w: {"qdd": w.qdd}, read_minimal=lambda x: {"qdd": x}, exact=False),
        Case("method", "chain (N = 10)", "projective: `forward_dynamics_projective` vs `projective_workspace`",
             "reaction bases R, U, γ, μ and the forces f (6.101–6.106)",
             lambda: projective_workspace(mn, qn, qdn, taun), lambda: forward_dynamics_projective(mn, qn, qdn, taun),
             read_full=lambda w: {"qdd": w.qdd}, read_minimal=lambda x: {"qdd": x}, exact=False),
        Case("method", "chain (N = 10)", "mobility split: `forward_dynamics_mobility_split` vs `mobility_split`",
             "the internal forces 7.56",
             lambda: mobility_split(mn, qn, qdn, taun), lambda: forward_dynamics_mobility_split(mn, qn, qdn, taun),
             read_full=lambda w: {"qdd": w.qdd}, read_minimal=lambda x: {"qdd": x}, exact=False),
        Case("method", "chain (N = 10)", "stacked: `forward_dynamics_stacked` vs `stacked_solve`",
             "nothing: there is no q̈-only stacked path (the same solve, forces included)",
             lambda: stacked_solve(mn, qn, qdn, taun), lambda: forward_dynamics_stacked(mn, qn, qdn, taun),
             read_full=lambda s: {"qdd": s.qdd}, read_minimal=lambda x: {"qdd": x}),
    ]
    return out


#: (group, scene, consumer, what the lighter side skips) of :func:`explorer_cases`, in order
EXPLORER_LABELS = (
    ("explorer", "chain", "chain explorer (10 links): compute step with the T/U split drawn vs not",
     "the per-joint T/U split (`tu_split`, `T_of`): derived in `render` only when shown"),
    ("explorer", "chain", "chain explorer (10 links, default overlays): compute step",
     "the ABA workspace (`articulated_body`, vectorised path): q̈ by the compiled kernel and one Newton–Euler "
     "pass give every drawn and read number unless the articulated inertias or the T/U split are shown "
     "(prototype)"),
)


def _compute_with_split(ex, v):
    st = ex.compute(v, set())
    ex.tu_split(st)
    return st


def explorer_cases() -> list:
    """The explorers' compute steps: as they are against what they draw (explorer instances on Agg)."""
    ex = chain_explorer_default()          # compute() reads only the values it is given
    v_dflt = dict(ex.values)
    tu, rnea = EXPLORER_LABELS
    return [
        Case(*tu, lambda: _compute_with_split(ex, v_dflt), lambda: ex.compute(v_dflt, set()),
             read_full=chain_explorer_reads, read_minimal=chain_explorer_reads),
        Case(*rnea, lambda: ex.compute(v_dflt, set()), lambda: chain_explorer_rnea_compute(ex, v_dflt),
             read_full=chain_explorer_drawn, read_minimal=chain_explorer_drawn, exact=False),
    ]


# =========================================================================== timing
def _cycler(ex, control, values):
    """A function that moves ``ex.controls[control]`` to the next of ``values`` (one update per call)."""
    it = itertools.cycle([float(v) for v in values])
    return lambda: setattr(ex.controls[control], "value", next(it))


def _updater(ex, control, values):
    """A whole update as the page sees it: the control's next value (compute), then the picture."""
    step = _cycler(ex, control, values)

    def run():
        step()
        ex.picture()
    return run


def measure(case: Case, budget: float, rounds: int) -> dict:
    t = time_interleaved({"full": case.full, "minimal": case.minimal}, budget=budget, rounds=rounds)
    st = ratio_stats(t, "minimal", "full")
    return {"full_us": 1e6 * min(t["full"]), "minimal_us": 1e6 * min(t["minimal"]), "ratio": st,
            "saved_us": 1e6 * (min(t["full"]) - min(t["minimal"]))}


def measure_updates(budget: float, rounds: int) -> list:
    """Whole explorer updates (compute, then ``ex.picture()``): context for the savings above.

    The explorers run with ``display="agg"`` (nothing shown): a control change computes the
    state and readout; building the picture is what the page's update adds in Python
    (sending it and drawing it in the browser: ``benchmarks/page_latency.py``).
    """
    from planargeo.widgets import CarExplorer, SliderCrankExplorer, TreeExplorer

    rows = []
    log("  update: chain, 10 links, overlays on / off")
    on, off = chain_explorer(True), chain_explorer(False)
    angles = list(np.linspace(-40.0, 0.0, 7))
    t = time_interleaved({"on": _updater(on, "angle", angles), "off": _updater(off, "angle", angles)},
                         budget=budget, rounds=rounds)
    rows.append({"explorer": "chain, 10 links: all overlays (on) vs none (off)", "on_ms": 1e3 * np.median(t["on"]),
                 "off_ms": 1e3 * np.median(t["off"]), "ratio": ratio_stats(t, "off", "on")})
    for label, ex, control, values in (
            ("car", CarExplorer(display="agg"), "speed (m/s)", list(np.linspace(2, 14, 7))),
            ("slider-crank", SliderCrankExplorer(display="agg"), "crank angle (deg)", list(np.linspace(10, 70, 7))),
            ("trees, loops closed", TreeExplorer(display="agg"), "speed", list(np.linspace(0.2, 2.0, 7)))):
        log(f"  update: {label}")
        tt = time_interleaved({"update": _updater(ex, control, values), "draw": ex.picture},
                              budget=budget, rounds=rounds)
        rows.append({"explorer": label, "update_ms": 1e3 * np.median(tt["update"]),
                     "draw_ms": 1e3 * np.median(tt["draw"])})
    return rows


# =========================================================================== report
def _us(x: float) -> str:
    return f"{x:.0f}" if x >= 100 else f"{x:.1f}"


def write_markdown(res: dict, path: Path) -> None:
    m = res["meta"]
    L = ["# Model no more than a scene needs: measured", "",
         f"Generated by `python benchmarks/scene_cost.py{' --quick' if m['quick'] else ''}` on {m['date']}; "
         f"Python {m['python']}, numpy {np.__version__}; {m['runtime_s']:.0f} s. "
         "What each scene computes, who reads what, and why: [`docs/scenes.md`](../../docs/scenes.md).", "",
         "For every scene and consumer: the scene as it runs now (**full**) against the minimal computation that "
         "consumer needs (**minimal**, written out in `benchmarks/scene_cost.py` from the same package functions). "
         f"Timed interleaved in one run ({m['rounds']} rounds of alternating blocks, thread CPU time, BLAS single-"
         "threaded): **minimal / full** is the ratio of the best blocks and the median of the per-round ratios. "
         "`tests/test_scene_cost.py` checks that every minimal path gives the numbers the consumer reads "
         "(bitwise where the operations are the same, else to 1e-12 / 1e-10).", "",
         "## Scenes and their consumers", "",
         "| scene | consumer | minimal path skips | full µs | minimal µs | minimal / full (best) | (median) | saved µs (best) |",
         "|---|---|---|---:|---:|---:|---:|---:|"]
    for r in res["cases"]:
        if r["group"] != "scene":
            continue
        L.append(f"| {r['scene']} | {r['consumer']} | {r['skipped']} | {_us(r['full_us'])} | {_us(r['minimal_us'])} | "
                 f"{r['ratio']['best']:.2f} | {r['ratio']['median']:.2f} | {_us(r['saved_us'])} |")
    L += ["", "## The explorers' own choices", "",
          "| explorer | what the lighter side skips | full µs | lighter µs | lighter / full (best) | (median) |",
          "|---|---|---:|---:|---:|---:|"]
    for r in res["cases"]:
        if r["group"] == "explorer":
            L.append(f"| {r['consumer']} | {r['skipped']} | {_us(r['full_us'])} | {_us(r['minimal_us'])} | "
                     f"{r['ratio']['best']:.2f} | {r['ratio']['median']:.2f} |")
    if res.get("updates"):
        L += ["", "Whole updates for scale (a control change: compute, then the picture, `ex.picture()`; "
              "sending and drawing it in the page: [page_latency.md](page_latency.md)), medians:", "",
              "| explorer | update ms | picture alone ms | |", "|---|---:|---:|---|"]
        for u in res["updates"]:
            if "on_ms" in u:
                L.append(f"| {u['explorer']} | {u['on_ms']:.1f} (on) / {u['off_ms']:.1f} (off) | — | "
                         f"off / on: {u['ratio']['best']:.2f} best, {u['ratio']['median']:.2f} median |")
            else:
                L.append(f"| {u['explorer']} | {u['update_ms']:.1f} | {u['draw_ms']:.1f} | |")
    L += ["", "## q̈-only paths against the full workspaces (one state, chain N = 10)", "",
          "| method | what the q̈-only path skips | workspace µs | q̈ only µs | q̈ only / workspace (best) | (median) |",
          "|---|---|---:|---:|---:|---:|"]
    for r in res["cases"]:
        if r["group"] == "method":
            L.append(f"| {r['consumer']} | {r['skipped']} | {_us(r['full_us'])} | {_us(r['minimal_us'])} | "
                     f"{r['ratio']['best']:.2f} | {r['ratio']['median']:.2f} |")
    L += ["", "## Reading the numbers", ""] + res.get("notes", [])
    atomic_write(path, "\n".join(L) + "\n")


def _notes(res: dict) -> list:
    by = {(r["scene"], r["consumer"]): r for r in res["cases"]}

    def get(scene, start):
        return next(r for (s, c), r in by.items() if s == scene and c.startswith(start))

    sc, tr, ct = (get("slider-crank", "slider-crank explorer"), get("tree", "tree explorer"),
                  get("constrained-tree", "tree explorer"))
    car, chain, build = get("car", "car"), get("chain", "`planargeo"), get("(every scene)", "explorers")
    fig91 = get("tree", "gallery")
    ch_rnea = get("chain", "chain explorer (10 links, default")
    ch_tu = get("chain", "chain explorer (10 links): compute")
    ups = {u["explorer"]: u for u in res.get("updates", [])}
    out = [
        f"* **tree**: the scene runs the direct solution 9.48 (the report's `qdd_direct` cross-check) besides the "
        f"stacked solve; the explorer runs only the stacked solve on a cached model: "
        f"{tr['ratio']['median']:.2f}× the scene's time ({_us(tr['saved_us'])} µs saved per change). Gallery "
        f"Fig 9.1, which only draws the pose, would need {fig91['ratio']['median']:.2f}× the scene's time.",
        f"* **constrained-tree**: the explorer caches the model and the velocity projection: "
        f"{ct['ratio']['median']:.2f}× the scene's time ({_us(ct['saved_us'])} µs per change).",
        f"* **slider-crank**: the explorer caches the model; both call `loop_solve` (contact columns of Λ⁻¹ "
        f"only): {sc['ratio']['median']:.2f}× the scene's time ({_us(sc['saved_us'])} µs per change).",
        f"* **car**: the explorer passes `outlines=False`: {car['ratio']['median']:.2f}× the time of the "
        f"default scene ({_us(car['saved_us'])} µs per change), which computes the shapely outlines for the "
        "report and gallery Fig 6.6.",
        f"* **chain scene**: its ABA workspace `extra['data']` is read by nothing: {chain['ratio']['median']:.2f}× "
        "without it.",
        f"* **chain explorer**: it derives the T/U split only when it is shown (with it, its compute step takes "
        f"{1 / ch_tu['ratio']['median']:.2f}× the time without), but it always builds the full ABA "
        f"workspace; for the default overlays the compiled kernel plus one Newton–Euler pass would do in "
        f"{ch_rnea['ratio']['median']:.2f}× the time ({_us(ch_rnea['saved_us'])} µs per change).",
        f"* **`scenes.build`** checks parameter names with `inspect.signature` on every call: calling the scene "
        f"function directly takes {build['ratio']['median']:.2f}× the time ({_us(build['saved_us'])} µs per change).",
    ]
    if ups:
        u = [x for x in ups.values() if "update_ms" in x]
        if u:
            out.append("* **For scale**, a whole update in an explorer (compute, then the picture) takes "
                       + ", ".join(f"{x['update_ms']:.1f} ms ({x['explorer']})" for x in u)
                       + ". The savings above matter most for sweeps (gallery charts, notebooks, `report` in a "
                       "loop) and for animation.")
        ch = next((x for x in ups.values() if "on_ms" in x), None)
        if ch:
            out.append(f"* **chain explorer, whole update**: switching every overlay off makes an update "
                       f"{ch['ratio']['median']:.2f}× as long ({ch['on_ms']:.0f} ms → {ch['off_ms']:.0f} ms): drawing "
                       "the overlays is the cost, not computing them.")
    return out




def run(out_dir, quick: bool = False) -> dict:
    """Measure every case, write ``scene_cost.md`` in ``out_dir``; returns the results."""
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    t0 = time.time()
    budget, rounds = (0.15, 10) if quick else (1.0, 30)
    res = {"cases": []}
    log("building the scenes and explorers")
    all_cases = cases() + explorer_cases()
    for k, case in enumerate(all_cases):
        log(f"[{k + 1}/{len(all_cases)}] {case.scene}: {case.consumer} (~{rounds} rounds, {budget:g} s) ...")
        row = {"group": case.group, "scene": case.scene, "consumer": case.consumer, "skipped": case.skipped}
        row.update(measure(case, budget, rounds))
        res["cases"].append(row)
        log(f"[{k + 1}/{len(all_cases)}] minimal/full {row['ratio']['best']:.2f} best, "
            f"{row['ratio']['median']:.2f} median")
    log("whole explorer updates (4 explorers) ...")
    res["updates"] = measure_updates(0.6 if quick else 4.0, 5 if quick else 10)
    res["meta"] = {"date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), "python": platform.python_version(),
                   "runtime_s": time.time() - t0, "quick": quick, "rounds": rounds}
    res["notes"] = _notes(res)
    write_markdown(res, out_dir / "scene_cost.md")
    return res


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--quick", action="store_true", help="short budgets (under 30 s)")
    p.add_argument("--out", default=str(HERE / "results"), help="output directory (default: %(default)s)")
    args = p.parse_args(argv)
    res = run(args.out, quick=args.quick)
    print(f"wrote {Path(args.out) / 'scene_cost.md'} in {res['meta']['runtime_s']:.0f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
