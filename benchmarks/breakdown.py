"""Where the forward-dynamics methods break down: accuracy against an extended-precision reference.

Run ``python benchmarks/breakdown.py`` (about a minute).  Sweeps five
conditioning knobs and, at each point, compares the five tree methods (and,
for the slider-crank, the closed-loop solver and the Lagrange-multiplier
solver) with an *independent* reference: the joint-space equations
``H q̈ = τ - C`` written from scratch with world-frame Jacobians and solved in
``np.longdouble`` or in exact rational arithmetic (``reference_system`` in
``tests/test_breakdown.py``: one copy, imported from there).

Knobs
-----
a. chain length N (uniform unit links, revolute);
b. mass ratio: link masses graded geometrically from 1 (base) to 10^-k (tip), and the reverse;
c. slender links (radius of gyration ρ → 0, point masses), and a point-mass tip whose
   centre of mass approaches its joint axis (offset d → 0);
d. slider-crank folding onto its singular configuration (rod length → crank length at ψ = 0,
   and ψ → 0 at rod length = crank length);
e. prismatic chains (parallel sliders, N sweep and mass grading; random sliding directions).

Writes ``results/breakdown.md`` and ``results/breakdown.svg/.png``.
"""
from __future__ import annotations

import importlib.util
import json
import platform
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

_spec = importlib.util.spec_from_file_location("_breakdown_reference", ROOT / "tests" / "test_breakdown.py")
ref = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(ref)

from planargeo.algorithms.loops import SINGULAR_COND, constrained_dynamics_lagrange, loop_solve  # noqa: E402
from planargeo.errors import SingularConfigurationError  # noqa: E402
from planargeo.model import Body, Joint, Model, chain_model, random_model  # noqa: E402

EPS, EPS_LD = ref.EPS, ref.EPS_LD
METHODS = ref.METHODS
MARKERS = {"aba": "o", "projective": "s", "mobility_split": "^", "stacked": "D", "crba": "x",
           "loop_solve": "v", "lagrange": "P"}
COLORS = {"aba": "C0", "projective": "C1", "mobility_split": "C2", "stacked": "C3", "crba": "C4",
          "loop_solve": "C5", "lagrange": "C6"}


# --------------------------------------------------------------------------- one point
def tree_point(model: Model, q, qd, tau, mode: str, **label) -> dict:
    """Every tree method against the reference at one state."""
    H, rhs = ref.reference_system(model, q, qd, tau, mode=mode)
    x = ref._gauss_solve(H, rhs)
    qdd_ref = np.array([float(v) for v in x])
    cond = ref.cond_spd(H)
    row = dict(label, cond=cond, ref=mode, errors={}, raised={})
    if mode == "longdouble":
        # the reference's own error, estimated by eliminating in the reverse order (validated against
        # the exact reference at N = 20: 1.0e-15 estimated, 1.3e-15 actual)
        xr = ref._gauss_solve(H[::-1, ::-1].copy(), rhs[::-1].copy())[::-1]
        row["ref_spread"] = ref.rel_err(np.array([float(v) for v in xr]), qdd_ref)
    if mode == "exact" and model.nq <= 20:
        row["ld_vs_exact"] = ref.rel_err(ref.reference_qdd(model, q, qd, tau), qdd_ref)
    for name, f in METHODS.items():
        try:
            row["errors"][name] = ref.rel_err(f(model, q, qd, tau), qdd_ref)
        except SingularConfigurationError as e:
            row["raised"][name] = float(e.cond)
    return row


def knob_length() -> list:
    rows = []
    for N in (2, 5, 10, 20, 50, 100, 200, 400):
        q, qd, tau = ref.state(N)
        rows.append(tree_point(chain_model(N), q, qd, tau, "exact" if N <= 20 else "longdouble", N=N))
    return rows


def knob_mass_ratio() -> list:
    rows = []
    N = 8
    for reverse in (False, True):
        for k in range(13):
            ratio = 10.0 ** -k
            q, qd, tau = ref.state(N, 1)
            grade = np.geomspace(1, ratio, N)
            tau = tau * (grade[::-1] if reverse else grade)      # torques scaled like the masses they drive
            rows.append(tree_point(ref.graded_chain(N, ratio, reverse=reverse), q, qd, tau, "exact",
                                   k=k, light="base" if reverse else "tip"))
    return rows


def knob_slender() -> list:
    rows = []
    N = 8
    q, qd, tau = ref.state(N, 2)
    for rho in (0.3, 1e-1, 1e-2, 1e-4, 1e-6, 1e-8, 0.0):
        rows.append(tree_point(ref.slender_chain(N, rho), q, qd, tau, "exact", variant="rho", value=rho))
    for j in range(1, 10):
        d = 10.0 ** -j
        bodies = [Body(1.0, (0.5, 0.0), 1 / 12)] * (N - 1) + [Body(1.0, (d, 0.0), 0.0)]
        joints = [Joint("revolute", (0.0 if i == 0 else 1.0, 0.0, 0.0)) for i in range(N)]
        rows.append(tree_point(Model(bodies, joints, list(range(-1, N - 1))), q, qd, tau, "exact",
                               variant="tip offset d", value=d))
    return rows


def knob_prismatic() -> list:
    rows = []
    for N in (2, 5, 10, 20, 50, 100, 200):
        q, qd, tau = ref.state(N, 5)
        rows.append(tree_point(chain_model(N, joint="prismatic"), q, qd, tau,
                               "exact" if N <= 10 else "longdouble", variant="parallel", N=N))
    for N in (5, 20, 50):
        q, qd, tau = ref.state(N, 6)
        rows.append(tree_point(random_model(N, seed=N, kinds=("prismatic",)), q, qd, tau,
                               "exact" if N <= 10 else "longdouble", variant="random directions", N=N))
    N = 8
    for reverse in (False, True):
        for k in range(0, 13, 2):
            ratio = 10.0 ** -k
            q, qd, tau = ref.state(N, 5)
            grade = np.geomspace(1, ratio, N)
            tau = tau * (grade[::-1] if reverse else grade)
            rows.append(tree_point(ref.graded_chain(N, ratio, reverse=reverse, joint="prismatic"), q, qd, tau,
                                   "exact", variant=f"graded, light {'base' if reverse else 'tip'}", N=N, k=k))
    return rows


def knob_slider_crank() -> list:
    rows = []
    for path in ("rod", "psi"):
        for k in range(1, 16):
            delta = 10.0 ** -k
            row = dict(path=path, delta=delta)
            try:
                model, q, qd, r, l = ref.folded_state(delta, path)
            except SingularConfigurationError as e:
                row["state_raised"] = float(e.cond)
                rows.append(row)
                continue
            tau = np.zeros(3)
            x = ref.slider_crank_reference(model, q, qd, tau, r, l, mode="exact")
            row["qdd_scale"] = float(np.max(np.abs(x)))
            row["ld_vs_exact"] = ref.rel_err(ref.slider_crank_reference(model, q, qd, tau, r, l), x)
            lag = constrained_dynamics_lagrange(model, q, qd, tau)["qdd"]
            row["lagrange"] = ref.rel_err(lag, x)
            # the problem's own sensitivity: the reference after moving θ by one ulp
            q2 = q.copy()
            q2[1] = np.nextafter(q2[1], np.inf)
            row["ulp_sensitivity"] = ref.rel_err(ref.slider_crank_reference(model, q2, qd, tau, r, l, mode="exact"), x)
            try:
                sol = loop_solve(model, q, qd, tau)
                row["cond"] = float(sol.cond)
                row["loop_solve"] = ref.rel_err(sol.qdd, x)
                row["loop_vs_lagrange"] = ref.rel_err(sol.qdd, lag)
            except SingularConfigurationError as e:
                row["cond"] = float(e.cond)
                row["loop_raised"] = float(e.cond)
            rows.append(row)
    return rows


# --------------------------------------------------------------------------- report
def _e(x) -> str:
    return "—" if x is None else ("0" if x == 0 else f"{x:.1e}")


def _cells(row) -> list:
    out = []
    for name in METHODS:
        if name in row["raised"]:
            out.append(f"**raises** ({row['raised'][name]:.0e})")
        elif row["errors"][name] < 3 * row.get("ref_spread", 0.0):
            out.append("≲ " + _e(row["errors"][name]))          # not resolved by the reference
        else:
            out.append(_e(row["errors"][name]))
    return out


def _table(rows, keys) -> list:
    keys = [k if len(k) == 3 else (k[0], k[0], k[1]) for k in keys]
    head = [h for h, _, _ in keys] + ["cond(H)", "ε·cond(H)", "ref"] + list(METHODS)
    lines = ["| " + " | ".join(head) + " |", "|" + "---:|" * len(head)]
    for r in rows:
        lab = [fmt(r.get(k)) for _, k, fmt in keys]
        refc = "exact" if r["ref"] == "exact" else f"ld ±{r['ref_spread']:.0e}"
        lines.append("| " + " | ".join(lab + [_e(r["cond"]), _e(EPS * r["cond"]), refc] + _cells(r)) + " |")
    return lines


def _worst(rows, names):
    return max((r["errors"][n] for r in rows for n in names if n in r["errors"]), default=float("nan"))


def write_markdown(res: dict, path: Path) -> None:
    L = ["# Where the methods break down (accuracy study)", "",
         f"Generated by `python benchmarks/breakdown.py` on {res['meta']['date']}; "
         f"Python {res['meta']['python']}, numpy {np.__version__}; {res['meta']['runtime_s']:.0f} s.", "",
         "Error = max|q̈ − q̈_ref| / max|q̈_ref| against an **independent reference**: the joint-space "
         "equations `H q̈ = τ − C` written from scratch with world-frame Jacobians "
         "(`H = Σ J_cᵀ m J_c + J_ωᵀ J J_ω`, bias from `J̇ q̇`), evaluated and solved in exact rational "
         "arithmetic (`exact`: only the sines and cosines are rounded, to 64-bit-mantissa long double) or in "
         f"`np.longdouble` (`ld`, ε_ld = {EPS_LD:.1e}; its own error, `±`, is estimated by solving again with "
         "the elimination order reversed; at N = 20 that estimate, 1.0e-15, matches the actual ld-vs-exact "
         "difference, 1.3e-15). Errors marked `≲` are below 3× that estimate: not resolved. "
         "Code: `reference_system` in `tests/test_breakdown.py`. "
         "cond(H) is the 2-norm condition number (λ_max from `eigvalsh`, λ_min by long-double inverse "
         f"iteration). ε = {EPS:.1e}. **raises (c)**: the method raised `SingularConfigurationError` with "
         "`.cond = c` (its own measure). The chart `breakdown.svg/.png` plots every point against the ε·cond line.",
         "", "![error vs cond](breakdown.png)", ""]

    # (a)
    rows = res["length"]
    L += ["## (a) Chain length", "",
          "Uniform unit links (`chain_model(N)`), random state (`q, q̇, τ ∈ [-1, 1]`).", ""]
    L += _table(rows, [("N", str)])
    big = rows[-1]
    L += ["", f"cond(H) grows roughly like N³ (N = 400: {big['cond']:.1e}), and the dense solve (`crba`) follows "
          f"ε·cond(H) within a factor of about 20 (N = 400: {big['errors']['crba']:.1e} against "
          f"ε·cond = {EPS * big['cond']:.1e}). The recursive methods do better than ε·cond(H) because they never "
          "form or factor H: ABA's error grows far slower (7.7e-13 at N = 100; at N = 200 and 400 it is at or "
          f"below the long-double reference's resolution, ≲ {big['errors']['aba']:.0e}), and the projective, "
          "mobility-split and stacked methods sit in between, 10 to 100 times ABA. Nothing raises: "
          "length alone makes the numbers worse, never singular. What breaks first: the dense solve.", ""]

    # (b)
    rows = res["mass_ratio"]
    tip = [r for r in rows if r["light"] == "tip"]
    base = [r for r in rows if r["light"] == "base"]
    L += ["## (b) Mass ratio", "",
          "N = 8 unit links; link masses (and inertias m/12) graded geometrically from 1 at the base to 10⁻ᵏ at the "
          "tip (**light tip**), or from 10⁻ᵏ at the base to 1 at the tip (**light base**). Torques are scaled like "
          "the masses they drive (otherwise the light links' accelerations swamp the max-norm). Exact reference.", "",
          "Light tip:", ""]
    L += _table(tip, [("k", str)])
    L += ["", "Light base:", ""]
    L += _table(base, [("k", str)])
    L += ["", f"**Light tip: nothing breaks.** cond(H) reaches {tip[-1]['cond']:.0e}, yet every method, the dense "
          f"solve included, stays near 1e-14 (worst over k: {_worst(tip, METHODS):.1e}) and shows no trend with k. The small "
          "eigenvalue belongs to the light links at the end of the matrix; elimination meets them last, after the "
          "heavy part is done, so no large numbers cancel: ill-conditioning from grading is harmless here.", "",
          f"**Light base: the dense solve breaks first.** With light links near the base carrying heavy ones, the "
          "motions of the first few light links that leave the heavy links still are cheap (small eigenvalue), "
          "but every entry of H in those rows is dominated by the heavy links; the solve must cancel heavy "
          f"numbers to find the light ones. At k = 12 the dense solve's error is {base[-1]['errors']['crba']:.1e} "
          f"(ε·cond = {EPS * base[-1]['cond']:.1e}); the stacked method follows at "
          f"{base[-1]['errors']['stacked']:.1e}, projective / mobility-split at ~"
          f"{max(base[-1]['errors']['projective'], base[-1]['errors']['mobility_split']):.0e}, and ABA stays best "
          f"({base[-1]['errors']['aba']:.1e}): its articulated inertias of the light links still subtract projected "
          "heavy inertias, but in 3×3 blocks rather than across the whole matrix. A long-double reference is not "
          "good enough here (ld vs exact up to "
          f"{max(r.get('ld_vs_exact', 0) for r in base):.0e}): the exact reference is needed.", ""]

    # (c)
    rows = res["slender"]
    rho = [r for r in rows if r["variant"] == "rho"]
    tipd = [r for r in rows if r["variant"] != "rho"]
    L += ["## (c) Slender links", "",
          "N = 8 unit masses at mid-link, radius of gyration ρ (ρ = 0: point masses):", ""]
    L += _table(rho, [("ρ", "value", lambda v: f"{v:g}")])
    L += ["", "Point-mass tip link whose centre of mass sits a distance d from its own joint axis "
          "(the other links uniform):", ""]
    L += _table(tipd, [("d", "value", lambda v: f"{v:g}")])
    first_raise = {n: next((r["value"] for r in tipd if n in r["raised"]), None) for n in METHODS}
    L += ["", f"**Slender links alone break nothing**: cond(H) saturates at {rho[-1]['cond']:.1e} as ρ → 0 (a point "
          "mass off the joint axis still has inertia m d² about it) and every error stays at 1e-13 or better.", "",
          "**A point mass approaching its own joint axis** makes that joint's inertia m d² → 0 and cond(H) ~ 1/d². "
          "The dense solve and the projective / mobility-split / stacked methods lose accuracy like ε·cond(H); "
          "the projective, mobility-split and stacked methods then refuse first (raise at d = "
          f"{first_raise['projective']:g}), the dense solve at d = {first_raise['crba']:g}, "
          f"ABA last (d = {first_raise['aba']:g}). ABA's small errors here are partly the max-norm: the tip's "
          "acceleration ~1/d² dominates q̈ and ABA gets that component to full precision (D = m d² is formed "
          "directly from the tip's own inertia).", ""]

    # (d)
    rows = res["slider_crank"]
    L += ["## (d) Slider-crank at its folded singularity", "",
          "Thesis 9.6 slider-crank (r = 2.29, ψ̇ = 20, g = 9.81, no torque). Path **rod**: ψ = 0, rod length "
          "l = r(1 + δ); path **psi**: l = r, crank angle ψ = δ. At δ = 0 the piston pin lies on the crank pivot and "
          "the closure loses rank. Reference: the tree reference above reduced to the one-degree-of-freedom motion "
          "q̇ = n s with the closure's polynomial null vector n = (l sin β, −(r sin ψ + l sin β), r sin ψ), "
          "β = ψ + θ, solved exactly. cond = the loop solver's cond(BᵀGΛ⁻¹GᵀB) (raises above "
          f"{SINGULAR_COND:.0e}).", "",
          "| path | δ | cond | loop_solve | lagrange | loop vs lagrange | ref change for 1 ulp in θ | ld ref vs exact |",
          "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        if "state_raised" in r:
            L.append(f"| {r['path']} | {r['delta']:.0e} | — | state refused (`slider_crank_state` cond "
                     f"{r['state_raised']:.0e}) | — | — | — | — |")
            continue
        loop = f"**raises** ({r['loop_raised']:.0e})" if "loop_raised" in r else _e(r["loop_solve"])
        L.append(f"| {r['path']} | {r['delta']:.0e} | {_e(r['cond'])} | {loop} | {_e(r['lagrange'])} | "
                 f"{_e(r.get('loop_vs_lagrange'))} | {_e(r['ulp_sensitivity'])} | {_e(r['ld_vs_exact'])} |")
    rod = [r for r in rows if r["path"] == "rod" and "cond" in r]
    rod_raise = next((r["delta"] for r in rod if "loop_raised" in r), None)
    rod_ok = [r for r in rod if "loop_solve" in r]
    psi = [r for r in rows if r["path"] == "psi" and "cond" in r]
    psi_raise = next((r["delta"] for r in psi if "loop_raised" in r), None)
    L += ["", f"**The loop solver breaks first.** Along the rod path its error grows with its cond "
          f"(δ = {rod_ok[-1]['delta']:.0e}: cond {rod_ok[-1]['cond']:.1e}, error {rod_ok[-1]['loop_solve']:.1e}) "
          f"and it raises from δ = {rod_raise:.0e} on, while the Lagrange solver (maximal coordinates, dense KKT) "
          f"stays at ~1e-16 down to δ = 1e-14 and only fails at δ = 1e-15, when l is a few ulps from r. The loop "
          "solver's cond(BᵀGΛ⁻¹GᵀB) grows like 1/δ: it inverts the reaction-space matrix, whose rank drops at the fold; "
          "the Lagrange solver solves one KKT system in maximal coordinates and, measured, does not lose accuracy "
          "until the fold is a few ulps away (why its KKT system degrades so much later was not analysed here). "
          "The loop solver's loss is its own, not the problem's: at δ = 1e-10 moving θ by one ulp changes the exact "
          "answer by only 3e-11, against the loop solver's 1.9e-8.", "",
          "Along the psi path (ψ → 0 at l = r) both solvers lose accuracy together and agree with each other far "
          "better than with the reference: the question itself is ill-conditioned there. Moving θ by one ulp "
          "changes the exact answer by as much as the solvers' deviation (column 'ref change for 1 ulp'), so the "
          "float64 state cannot pin q̈ down better; no method can do better than that. The loop solver raises from "
          f"ψ = {psi_raise:.0e} on; from ψ ≈ 1e-8 `slider_crank_state` refuses to build the state because cos ψ "
          "rounds to 1 and the rod lands exactly on the singular fold.", ""]

    # (e)
    rows = res["prismatic"]
    L += ["## (e) Prismatic chains", "",
          "Parallel sliders along x (`chain_model(N, joint='prismatic')`), random sliding directions "
          "(`random_model(N, kinds=('prismatic',))`), and parallel sliders with graded masses (N = 8):", ""]
    L += _table(rows, [("variant", str), ("N", str), ("k", lambda v: "—" if v is None else str(v))])
    gb = [r for r in rows if r["variant"] == "graded, light base"]
    first = next((r for r in gb if r["raised"]), None)
    L += ["", "**Uniform prismatic chains are benign**: H is the matrix of masses carried, cond(H) ~ N², and the "
          "recursive methods are exact to rounding; only the dense solve follows ε·cond(H).", "",
          "**A light slider carrying heavy ones (light base)** is the prismatic analogue of (b): moving the light base "
          "slider with the next one counter-sliding leaves the heavy ones still, so H has a tiny eigenvalue hidden "
          "under heavy entries. The dense solve loses ε·cond(H) "
          f"(k = 8: {next(r for r in gb if r['k'] == 8)['errors']['crba']:.1e}), the recursive methods stay at "
          "1e-16 (the articulated inertia of a slider is its own mass plus what the children pass on, no cancellation). "
          + (f"From k = {first['k']} every method raises (`.cond` ≈ {min(first['raised'].values()):.0e}) although "
             "the recursive ones could still compute the answer: their singularity test compares sᵀAs with trace(A), "
             "and a 1e-12 slider under an 8-unit body fails it. That is the threshold being conservative, not a loss "
             "of accuracy." if first else ""), ""]

    L += ["## Summary: what breaks first", "",
          "| knob | breaks first | how |", "|---|---|---|",
          "| chain length | dense solve (crba) | error ≈ ε·cond(H), cond ~ N⁴; recursive methods well below |",
          "| light tip | nothing | graded H is harmless when the light links come last |",
          "| light base | dense solve, then stacked | heavy entries cancel to find light motions; ABA best |",
          "| slender links | nothing | point masses off the axis keep H regular |",
          "| tip mass → its joint axis | projective / mobility-split / stacked raise first | cond(H) ~ 1/d², errors ≈ ε·cond |",
          "| folded slider-crank | loop solver (9.5) | cond(BᵀGΛ⁻¹GᵀB) ~ 1/δ; Lagrange KKT survives longer |",
          "| light base slider | dense solve; then all raise by threshold | recursive methods exact until the test refuses |",
          ""]
    path.write_text("\n".join(L), encoding="utf-8")


def plot(res: dict, out_dir: Path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax, bx) = plt.subplots(1, 2, figsize=(12, 5.2), gridspec_kw={"width_ratios": [2, 1]})
    floor = 1e-20
    tree_rows = res["length"] + res["mass_ratio"] + res["slender"] + res["prismatic"]
    for name in METHODS:
        xs = [r["cond"] for r in tree_rows if name in r["errors"]]
        ys = [max(r["errors"][name], floor) for r in tree_rows if name in r["errors"]]
        ax.scatter(xs, ys, marker=MARKERS[name], s=22, label=name, color=COLORS[name],
                   facecolors="none" if MARKERS[name] not in ("x", "P") else None, alpha=0.8)
        xr = [r["cond"] for r in tree_rows if name in r["raised"]]
        if xr:
            ax.scatter(xr, [3e-2] * len(xr), marker=MARKERS[name], s=22, color=COLORS[name], alpha=0.8)
    c = np.geomspace(1, 1e22, 50)
    for a in (ax, bx):
        a.plot(c, EPS * c, "k--", lw=1, label="ε·cond")
        a.axhline(3e-2, color="0.7", lw=0.8)
        a.set_xscale("log")
        a.set_yscale("log")
        a.set_ylim(floor / 2, 1)
        a.grid(True, which="major", alpha=0.3)
    for a in (ax, bx):
        a.text(1.5, 4.5e-2, "raised SingularConfigurationError", fontsize=8, color="0.4")
    ax.set_xlim(1, 1e22)
    ax.set_xlabel("cond(H)")
    ax.set_ylabel(r"relative error of $\ddot q$ vs extended-precision reference")
    ax.text(1.5, 2e-20, "exact zeros plotted at 1e-20", fontsize=8, color="0.4")
    ax.set_title("tree methods (all knobs a, b, c, e)")
    ax.legend(fontsize=8, loc="lower right")
    for path, cols in (("rod", ("C5", "C6")), ("psi", ("C8", "C9"))):
        sc = [r for r in res["slider_crank"] if "cond" in r and r["path"] == path]
        for name, col in zip(("loop_solve", "lagrange"), cols):
            xs = [r["cond"] for r in sc if name in r]
            ys = [max(r[name], floor) for r in sc if name in r]
            bx.scatter(xs, ys, marker=MARKERS[name], color=col, s=26, label=f"{name} ({path} path)",
                       facecolors="none" if name == "loop_solve" else None)
        xr = [r["cond"] for r in sc if "loop_raised" in r]
        bx.scatter(xr, [3e-2] * len(xr), marker=MARKERS["loop_solve"], color=cols[0], s=26)
    bx.axvline(SINGULAR_COND, color="C5", lw=0.8, ls=":")
    bx.set_xlim(1, 1e16)
    bx.set_xlabel("loop solver cond(BᵀGΛ⁻¹GᵀB)")
    bx.set_title("folded slider-crank (knob d)")
    bx.legend(fontsize=7, loc="lower right", ncol=2, handletextpad=0.2, columnspacing=0.6)
    fig.tight_layout()
    for ext in ("svg", "png"):
        fig.savefig(out_dir / f"breakdown.{ext}", dpi=110)
    plt.close(fig)


def run(out_dir) -> dict:
    """Run every sweep, write ``breakdown.md``, ``breakdown.svg`` and ``breakdown.png`` in ``out_dir``."""
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    t0 = time.time()
    res = {}
    for key, fn in (("length", knob_length), ("mass_ratio", knob_mass_ratio), ("slender", knob_slender),
                    ("slider_crank", knob_slider_crank), ("prismatic", knob_prismatic)):
        t = time.time()
        res[key] = fn()
        print(f"{key}: {time.time() - t:.1f} s", flush=True)
    res["meta"] = {"date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), "python": platform.python_version(),
                   "runtime_s": time.time() - t0}
    write_markdown(res, out_dir / "breakdown.md")
    plot(res, out_dir)
    return res


if __name__ == "__main__":
    out = run(HERE / "results")
    print(json.dumps(out["meta"]))
