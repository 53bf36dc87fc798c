"""Where the forward-dynamics methods break down: accuracy against an extended-precision reference.

Run ``python benchmarks/breakdown.py [--quick] [--out DIR]`` (about a minute;
``--quick``: chains up to N = 100, fewer geometry samples, about 15 s).  Sweeps seven
conditioning knobs and, at each point, compares the five tree methods (and,
for the slider-crank, the closed-loop solver and the Lagrange-multiplier
solver) with an *independent* reference: the joint-space equations
``H q̈ = τ - C`` written from scratch with world-frame Jacobians and solved in
``np.longdouble`` or in exact rational arithmetic (``reference_system`` in
``planargeo/_reference.py``: one copy, shared with ``tests/test_breakdown.py`` and
``planargeo.bench``).  ``join`` and ``meet``
are measured without their condition-number limit (``cond_limit=inf``) so that the error
can be charted past it; the tables say which samples the default call refuses.

Knobs
-----
a. chain length N (uniform unit links, revolute);
b. mass ratio: link masses graded geometrically from 1 (base) to 10^-k (tip), and the reverse;
c. slender links (radius of gyration ρ → 0, point masses), and a point-mass tip whose
   centre of mass approaches its joint axis (offset d → 0);
d. slider-crank folding onto its singular configuration (rod length → crank length at ψ = 0,
   and ψ → 0 at rod length = crank length);
e. prismatic chains (parallel sliders, N sweep and mass grading; random sliding directions);
f. the geometry layer: the meet of near-coincident and of near-parallel lines, the join of
   nearly coincident points, the axis of percussion (polar) as its pole approaches the centre of
   mass or goes to infinity, the percussion pole (pole) as its line approaches the line at
   infinity or the centre of mass, and the pole for an inertia conic degenerating to a point
   mass; each against exact rational arithmetic on the same float inputs (``cross_exact``,
   ``matvec_exact``, ``solve_exact`` in ``planargeo/_reference.py``);
g. long chains (N = 20, 50, 200) with tiny and huge masses mixed: masses alternating 10^(k/2) and
   10^(-k/2), condition numbers of H to 1e12 and beyond.

Writes ``results/breakdown.md`` and ``results/breakdown.svg/.png``.
"""
from __future__ import annotations

import json
import platform
import sys
import time
import warnings
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

import reference as ref  # noqa: E402  (the study's reference, one copy: also tests and planargeo.bench)
from planargeo.algorithms.loops import SINGULAR_COND, constrained_dynamics_lagrange, loop_solve  # noqa: E402
from bench import _progress as log  # noqa: E402  (one progress-line helper)
from planargeo.geometry.conics import pole  # noqa: E402
from planargeo.errors import DegenerateGeometryError, SingularConfigurationError, SingularInertiaError  # noqa: E402
from planargeo.screws.inertia import percussion_axis, percussion_pole  # noqa: E402
from planargeo.mechanics.model import Body, Joint, Model, chain_model, random_model  # noqa: E402
from planargeo.errors import COND_LIMIT  # noqa: E402
from planargeo.geometry.projective import from_xy, join, meet, signed_distance, to_xy  # noqa: E402
from planargeo.scenes.chain import METHODS  # noqa: E402  (method name -> forward dynamics, one table)

EPS, EPS_LD = ref.EPS, ref.EPS_LD

MARKERS = {"aba": "o", "projective": "s", "mobility_split": "^", "stacked": "D", "crba": "x",
           "loop_solve": "v", "lagrange": "P"}
COLORS = {"aba": "C0", "projective": "C1", "mobility_split": "C2", "stacked": "C3", "crba": "C4",
          "loop_solve": "C5", "lagrange": "C6"}


# --------------------------------------------------------------------------- one point
def tree_point(model: Model, q, qd, tau, mode: str, **label) -> dict:
    """Every tree method against the reference at one state."""
    qdd_ref, spread, cond = ref.reference_with_info(model, q, qd, tau, mode=mode)
    row = dict(label, cond=cond, ref=mode, errors={}, raised={})
    if mode == "longdouble":
        # the reference's own error, estimated by eliminating in the reverse order
        row["ref_spread"] = spread
    if mode == "exact" and model.nq <= 20:
        row["ld_vs_exact"] = ref.rel_err(ref.reference_qdd(model, q, qd, tau), qdd_ref)
    for name, f in METHODS.items():
        try:
            row["errors"][name] = ref.rel_err(f(model, q, qd, tau), qdd_ref)
        except SingularConfigurationError as e:
            row["raised"][name] = float(e.cond)
        except np.linalg.LinAlgError as e:          # not a planargeo error: a bare numpy failure
            row.setdefault("unnamed", {})[name] = f"{type(e).__name__}: {e}"
    return row


LENGTHS = (2, 5, 10, 20, 50, 100, 200, 400)


def knob_length(lengths=LENGTHS) -> list:
    rows = []
    for N in lengths:
        log(f"(a) chain length N = {N}")
        q, qd, tau = ref.state(N)
        rows.append(tree_point(chain_model(N), q, qd, tau, "exact" if N <= 20 else "longdouble", N=N))
    return rows


def knob_mass_ratio() -> list:
    rows = []
    N = 8
    for reverse in (False, True):
        log(f"(b) mass ratio, light {'base' if reverse else 'tip'}: 13 ratios")
        for k in range(13):
            ratio = 10.0 ** -k
            q, qd, tau = ref.state(N, 1)
            grade = np.geomspace(1, ratio, N)
            tau = tau * (grade[::-1] if reverse else grade)      # torques scaled like the masses they drive
            rows.append(tree_point(ref.graded_chain(N, ratio, reverse=reverse), q, qd, tau, "exact",
                                   k=k, light="base" if reverse else "tip"))
    return rows


MIXED = ((20, (7, 16)), (50, (0, 2, 4, 6, 7, 8, 10, 12, 16)), (200, (0, 6, 7)))


def knob_mixed_masses(cases=MIXED) -> list:
    """Long chains with tiny and huge masses mixed: masses alternate 10^(k/2), 10^(-k/2) (ratio 10^k)."""
    rows = []
    for N, ks in cases:
        log(f"(g) mixed masses, N = {N}: k = {', '.join(map(str, ks))}")
        for k in ks:
            q, qd, tau = ref.state(N, 3)
            rows.append(tree_point(ref.alternating_chain(N, k), q, qd, tau, "exact" if N <= 20 else "longdouble",
                                   N=N, k=k))
    return rows


def knob_slender() -> list:
    rows = []
    N = 8
    q, qd, tau = ref.state(N, 2)
    log("(c) slender links and a point-mass tip near its joint")
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
        log(f"(e) parallel sliders N = {N}")
        q, qd, tau = ref.state(N, 5)
        rows.append(tree_point(chain_model(N, joint="prismatic"), q, qd, tau,
                               "exact" if N <= 10 else "longdouble", variant="parallel", N=N))
    log("(e) random sliding directions, graded sliders")
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
        log(f"(d) slider-crank folding, {path} path: 15 steps")
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


# --------------------------------------------------------------------------- knob f: geometry layer
GEO_SAMPLES = 16          # random configurations per sweep value


def _silently(fn, *args):
    """``fn(*args)`` with every warning turned into an error (ideal elements must pass silently)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return fn(*args)


def _sweep(values, make, measure, seed, n=None) -> list:
    """One row per value: ``n`` random configurations, each measured against the exact reference.

    ``measure(*make(value, rng))`` returns a dict of numbers; a named error is counted in
    ``raised`` (with the largest ``.cond`` it carried, if any).
    """
    rows = []
    n = GEO_SAMPLES if n is None else n
    for k, v in enumerate(values):
        rng = np.random.default_rng(seed + k)
        row = dict(value=v, samples=[], raised=0, raised_cond=None, raised_as=None)
        for _ in range(n):
            inputs = make(v, rng)
            try:
                row["samples"].append(measure(*inputs))
            except (DegenerateGeometryError, SingularInertiaError) as e:
                row["raised"] += 1
                row["raised_as"] = type(e).__name__
                if getattr(e, "cond", None) is not None:
                    row["raised_cond"] = max(row["raised_cond"] or 0.0, float(e.cond))
        rows.append(row)
    return rows


def _point_reading(p, exact, kappa) -> dict:
    """Homogeneous error of a point and of its Euclidean reading ``(x, y)``."""
    out = {"kappa": kappa, "err": ref.hom_err(p, exact)}
    if exact[2] == 0:                   # an ideal point: its Euclidean reading is its direction
        out["ideal"] = True
        out["ideal_exact"] = bool(p[2] == 0)
        return out
    out["kappa_e"] = ref.euclid_cond(kappa, exact, exact[2])
    out["err_e"] = ref.euclid_err(p, exact)
    return out


def _refusal(fn, a, b) -> dict:
    """Whether ``fn(a, b)`` at the default :data:`COND_LIMIT` refuses, and the ``.cond`` it reports."""
    try:
        _silently(fn, a, b)
    except DegenerateGeometryError as e:
        return {"refused": True, "refused_cond": float(e.cond)}
    return {"refused": False}


def _meet(l, m) -> dict:
    # the bare cross product (cond_limit=inf: only an exactly zero l × m raises), so the error can be
    # charted past the threshold; whether the default call refuses is recorded alongside
    p = _silently(meet, l, m, np.inf)
    exact = ref.cross_exact(l, m)
    out = _point_reading(p, exact, ref.cross_cond(l, m, exact))
    out.update(_refusal(meet, l, m))
    if "err_e" in out:
        # the problem's own sensitivity: the largest change of the exact meet when one coefficient
        # of m moves by one ulp (what the float inputs can pin down at all)
        X = [-exact[1] / exact[2], exact[0] / exact[2]]
        sens = 0.0
        for j in range(3):
            m2 = np.array(m, dtype=float)
            m2[j] = np.nextafter(m2[j], np.inf)
            e2 = ref.cross_exact(l, m2)
            if e2[2] == 0:
                sens = float("inf")
                continue
            X2 = [-e2[1] / e2[2], e2[0] / e2[2]]
            sens = max(sens, ref.norm_exact([a - b for a, b in zip(X2, X)]) / ref.norm_exact(X))
        out["ulp_sensitivity"] = sens
    return out


def _join(p, q) -> dict:
    l = _silently(join, p, q, np.inf)
    exact = ref.cross_exact(p, q)
    out = {"kappa": ref.cross_cond(p, q, exact), "err": ref.hom_err(l, exact)}
    out.update(_refusal(join, p, q))
    # how far the returned line passes from the first point (which lies on the exact line)
    P = to_xy(p)
    dist = ref.distance_exact(ref.fr(l), P)
    out["miss"] = float(abs(dist))
    out["separation"] = float(np.hypot(*(to_xy(q) - P)))
    return out


def _axis(I, a) -> dict:
    f = _silently(percussion_axis, I, a)
    exact = ref.matvec_exact(I, a)
    kappa = ref.matvec_cond(I, a, exact)
    out = {"kappa": kappa, "err": ref.hom_err(f, exact)}
    r_float = float(_silently(signed_distance, from_xy(ref.GEO_COM), f))
    out["at_infinity"] = bool(f[0] == 0 and f[1] == 0)
    # Euclidean reading: the axis's distance r from the centre of mass (r = ρ²/d, thesis 5.68)
    r = ref.distance_exact(exact, ref.GEO_COM)
    out["r"], out["r_float"] = float(r), r_float
    out["kappa_e"] = ref.distance_cond(kappa, exact, ref.GEO_COM)
    out["err_e"] = ref.decimal_err(r_float, r) if np.isfinite(r_float) else float("inf")
    return out


def _ppole(fn, I, f) -> dict:
    p = _silently(fn, I, f)
    exact = ref.solve_exact(I, f)
    return _point_reading(p, exact, float(np.linalg.cond(I)))


def knob_geometry() -> dict:
    I = ref.geo_inertia()
    res = {}
    log(f"(f) geometry layer: {GEO_SAMPLES} samples per row")
    ks = list(range(0, 18))
    res["meet_pencil"] = _sweep([10.0 ** -k for k in ks], lambda t, rng: ref.pencil_pair(t, rng), _meet, 100)
    res["meet_strip"] = _sweep([10.0 ** -k for k in ks] + [0.0], lambda t, rng: ref.strip_pair(t, rng), _meet, 200)
    res["join"] = []
    for R, seed in ((1.0, 300), (1e3, 400)):
        rows = _sweep([R * 10.0 ** -k for k in range(0, 20)], lambda d, rng, R=R: ref.near_points(d, R, rng),
                      _join, seed)
        for r in rows:
            r["R"] = R
        res["join"] += rows
    res["axis_near_com"] = _sweep([10.0 ** -k for k in range(0, 17)] + [0.0],
                                  lambda d, rng: (I, ref.pole_near_com(d, rng)), _axis, 500)
    res["axis_far"] = _sweep([10.0 ** k for k in range(0, 17)] + [np.inf],
                             lambda R, rng: (I, ref.pole_far(R, rng) if np.isfinite(R) else
                                             np.append(rng.normal(size=2), 0.0)), _axis, 600)
    res["pole_near_infinity"] = _sweep([10.0 ** -k for k in range(0, 17)] + [0.0],
                                       lambda e, rng: (I, ref.line_near_infinity(e, rng)),
                                       lambda I_, f: _ppole(percussion_pole, I_, f), 700)
    res["pole_near_com"] = _sweep([10.0 ** -k for k in range(0, 17)],
                                  lambda e, rng: (I, ref.line_near_com(e, rng)),
                                  lambda I_, f: _ppole(percussion_pole, I_, f), 800)
    # an inertia conic degenerating to a point mass: ρ → 0, a random line's pole by both routes
    rhos = [10.0 ** -k for k in range(0, 10)]
    res["degenerate_pole"] = _sweep(rhos, lambda rho, rng: (ref.geo_inertia(rho), rng.normal(size=3)),
                                    lambda I_, f: _ppole(pole, I_, f), 900)
    res["degenerate_percussion_pole"] = _sweep(rhos, lambda rho, rng: (ref.geo_inertia(rho), rng.normal(size=3)),
                                               lambda I_, f: _ppole(percussion_pole, I_, f), 900)
    # two copies of one line, one of them scaled (rounded): the same line to the eye, not to meet()
    rng = np.random.default_rng(1000)
    # [exact zero, a point from the bare cross product, a point at the default COND_LIMIT]
    same = {"identical": [0, 0, 0], "scaled by 2": [0, 0, 0], "scaled by 3": [0, 0, 0], "normalised": [0, 0, 0]}
    from planargeo.geometry.projective import normalize_line
    for _ in range(200):
        l = rng.normal(size=3)
        for name, m in (("identical", l.copy()), ("scaled by 2", 2 * l), ("scaled by 3", 3 * l),
                        ("normalised", normalize_line(l))):
            try:
                meet(l, m, np.inf)                    # the bare cross product: raises only for an exact zero
                same[name][1] += 1
            except DegenerateGeometryError:
                same[name][0] += 1
            try:
                meet(l, m)
                same[name][2] += 1
            except DegenerateGeometryError:
                pass
    res["same_line"] = same
    return res


# --------------------------------------------------------------------------- report
def _e(x) -> str:
    return "—" if x is None else ("0" if x == 0 else f"{x:.1e}")


def _cells(row) -> list:
    out = []
    for name in METHODS:
        if name in row.get("unnamed", {}):
            out.append("**numpy LinAlgError**")
        elif name in row["raised"]:
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


def _gstats(row, key):
    """Largest finite value of ``key`` over a row's samples (``inf`` if any is infinite; None if none)."""
    v = [s[key] for s in row["samples"] if s.get(key) is not None]
    return max(v) if v else None


def _gmed(row, key):
    v = [s[key] for s in row["samples"] if s.get(key) is not None and np.isfinite(s[key])]
    return float(np.median(v)) if v else None


def _ge(x) -> str:
    if x is None:
        return "—"
    if not np.isfinite(x):
        return "∞"
    return _e(x)


def _raised(row) -> str:
    if not row["raised"]:
        return "0"
    c = "" if row["raised_cond"] is None else f", cond {row['raised_cond']:.0e}"
    return f"**{row['raised']}/{row['raised'] + len(row['samples'])}** ({row['raised_as']}{c})"


def _refused(row) -> str:
    """Samples the default ``join``/``meet`` refuses: exactly zero (``raised``) plus κ > COND_LIMIT."""
    k = row["raised"] + sum(1 for s in row["samples"] if s.get("refused"))
    n = row["raised"] + len(row["samples"])
    if not k:
        return "0"
    conds = [s["refused_cond"] for s in row["samples"] if s.get("refused")]
    c = f", `.cond` ≥ {min(conds):.0e}" if conds else ", exactly zero"
    return f"**{k}/{n}**{c}"


def _accepted(rows):
    """Rows in which the default ``join``/``meet`` answered every sample."""
    return [r for r in rows if r["samples"] and not r["raised"] and not any(s.get("refused") for s in r["samples"])]


def _gv(v) -> str:
    return "∞" if not np.isfinite(v) else ("0" if v == 0 else f"{v:.0e}")


def _n_samples(g: dict) -> int:
    r = g["meet_pencil"][0]
    return r["raised"] + len(r["samples"])


def geometry_markdown(g: dict) -> list:
    L = ["## (f) Geometry layer: near-parallel lines, points near infinity", "",
         "The projective layer (`planargeo.geometry.projective`, `conics`, `inertia`) against **exact rational arithmetic on "
         "the same float inputs** (`cross_exact`, `matvec_exact`, `solve_exact` in `planargeo/_reference.py`): the "
         "reference answers the question for the numbers given, so any difference is the package's rounding. "
         f"{_n_samples(g)} random configurations per row (random positions and orientations; masses and coordinates "
         "that are not powers of two); the tables give the median condition number and the largest error. "
         "**hom. error** = |x − x_ref| / |x_ref| of the unnormalised homogeneous result (`p × q`, `I a`, `I⁻¹ f`: "
         "the reference's scale); **Eucl. error** = relative error of the Euclidean position read off it "
         "(`to_xy` of a point; the signed distance of the centre of mass from a line). Condition numbers: "
         "κ = |a| |b| / |a × b| for join and meet (one over the sine of the angle between the two 3-vectors), "
         "κ = ‖ |I| |a| ‖ / ‖ I a ‖ for an axis of percussion (polar), cond₂(I) for a percussion pole (pole); "
         "the Euclidean reading divides by the weight and has κ_E = κ |x| / |w| (a point), "
         "κ (|c| |f| / |c·f| + |f| / |(fx, fy)|) (distance of c from the line f). "
         "Every result passes with warnings turned into errors: ideal points and the line at infinity are "
         "ordinary values. The chart (bottom row of `breakdown.svg/.png`) plots every sample against ε·κ.", ""]
    # meet: near-coincident (pencil)
    rows = g["meet_pencil"]
    L += ["### Meet of two lines", "",
          "**Near-coincident lines**: both through one point of [−1, 1]², at angles a and a + θ (`pencil_pair`). "
          "The meet is that point; as θ → 0 the two lines become one line.", "",
          "Errors are those of the bare cross product (`meet(l, m, cond_limit=inf)`); **refused** counts the "
          f"samples the default `meet(l, m)` answers with `DegenerateGeometryError` (κ > COND_LIMIT = "
          f"{COND_LIMIT:.0e}, or l × m exactly zero).", "",
          "| θ | κ | hom. error | κ_E | Eucl. error | exact answer's change for 1 ulp in m | refused |",
          "|---:|---:|---:|---:|---:|---:|---|"]
    for r in rows:
        L.append(f"| {_gv(r['value'])} | {_ge(_gmed(r, 'kappa'))} | {_ge(_gstats(r, 'err'))} | "
                 f"{_ge(_gmed(r, 'kappa_e'))} | {_ge(_gstats(r, 'err_e'))} | {_ge(_gstats(r, 'ulp_sensitivity'))} | "
                 f"{_refused(r)} |")
    last = _accepted(rows)[-1]
    past = [r for r in rows if r["samples"] and r["value"] < last["value"]]
    L += ["", f"The error follows ε·κ with κ ≈ 1/θ all the way down, and it is never larger "
          "than what one ulp in a coefficient of the input does to the exact answer (last-but-one column): the float "
          f"lines do not determine their common point any better. `meet` answers while κ ≤ {COND_LIMIT:.0e} "
          f"(θ = {last['value']:.0e}: up to {_gstats(last, 'err'):.1e} homogeneous, {_gstats(last, 'err_e'):.1e} "
          "Euclidean) and refuses past it with `DegenerateGeometryError` carrying `.cond`"
          + (f"; the bare cross product would have returned points with up to "
             f"{max(_gstats(r, 'err_e') for r in past):.0%} Euclidean error there." if past else ".") + "", ""]
    # strip
    rows = g["meet_strip"]
    par = rows[-1]
    n_ideal = sum(1 for s in par["samples"] if s.get("ideal_exact"))
    L += ["**Near-parallel lines**: one unit apart, at angles a and a + θ (`strip_pair`): they meet about 1/θ "
          "away; θ = 0 is exactly parallel (the same direction floats).", "",
          "| θ | κ | hom. error | κ_E | Eucl. error | exact answer's change for 1 ulp in m |",
          "|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        L.append(f"| {_gv(r['value'])} | {_ge(_gmed(r, 'kappa'))} | {_ge(_gstats(r, 'err'))} | "
                 f"{_ge(_gmed(r, 'kappa_e'))} | {_ge(_gstats(r, 'err_e'))} | {_ge(_gstats(r, 'ulp_sensitivity'))} |")
    worst_h = max(_gstats(r, "err") for r in rows)
    kmax = max(_gstats(r, "kappa") for r in rows)
    L += ["", f"**The homogeneous meet of near-parallel lines does not degrade**: κ stays below {kmax:.0f} and the "
          f"error below {worst_h:.1e} for every θ, because the lines are far from coincident; the point simply "
          "moves towards infinity, which the homogeneous form represents as well as any other point. Only its "
          "Euclidean reading degrades, like ε·κ_E ≈ ε/θ, and that is again the input's own limit: one ulp in the "
          "direction of m moves the exact far point by as much (last column). At θ = 0 the meet is an ideal point "
          f"with weight exactly 0 ({n_ideal} of {len(par['samples'])}), no warning, `to_xy` gives NaN silently and "
          "`direction` the common direction. Between them (θ ≲ 1e-16) the direction floats of the two lines "
          "may round to the same numbers and give an ideal point too: the honest answer for those floats.", ""]
    sl = g["same_line"]
    L += [f"**The same line written twice.** `l × l` and `l × 2 l` are exactly zero; `l × 3 l` is not in "
          f"{sl['scaled by 3'][1]} of {sum(sl['scaled by 3'][:2])} random lines, nor `l × normalize_line(l)` in "
          f"{sl['normalised'][1]} of {sum(sl['normalised'][:2])}: rounding makes the copies distinct lines with "
          "κ ~ 1/ε, whose \"meet\" would be an arbitrary point of the line. The default `meet` returns a point "
          f"for {sl['scaled by 3'][2] + sl['normalised'][2]} of them (κ > COND_LIMIT refuses the rest).", ""]
    # join
    L += ["### Join of nearly coincident points", "",
          "Two points δ apart, the first at distance between R/2 and R from the origin (`near_points`). "
          "**misses by**: distance of the first point from the line of the bare cross product "
          "(`join(p, q, cond_limit=inf)`; the exact line passes through it). **refused**: as for `meet`.",
          "", "| R | δ | κ | hom. error | misses by | refused |", "|---:|---:|---:|---:|---:|---|"]
    for r in g["join"]:
        L.append(f"| {r['R']:g} | {_gv(r['value'])} | {_ge(_gmed(r, 'kappa'))} | {_ge(_gstats(r, 'err'))} | "
                 f"{_ge(_gstats(r, 'miss'))} | {_refused(r)} |")
    far = [r for r in g["join"] if r["R"] > 1]
    lastj = [r for r in far if r["samples"] and not r["raised"]][-1]     # bare cross product, last non-zero
    acc_j = _accepted(far)[-1]
    L += ["", "The direction of the join (x₂ − x₁, y₂ − y₁) is exact (the differences of nearby floats are exact), "
          "the moment x₁y₂ − x₂y₁ is not: it cancels, so the error is ε·κ with κ ≈ R/δ (R ≥ 1), and the line misses "
          "the given points by about ε R²/δ. At R ≈ 1e3 and δ = " f"{lastj['value']:.0e} (about one ulp) the bare "
          f"cross product returns lines with relative error up to {_gstats(lastj, 'err'):.1f} that pass up to "
          f"{_gstats(lastj, 'miss'):.0f} units away from the points they were asked to join; the default `join` "
          f"refuses them (κ > {COND_LIMIT:.0e}). The last δ it answers at R ≈ 1e3 is {acc_j['value']:.0e}: error "
          f"≤ {_gstats(acc_j, 'err'):.0e}, the line within {_gstats(acc_j, 'miss'):.0e} of the points.", ""]
    # percussion axis
    L += ["### Axis of percussion (the polar of the acceleration pole, thesis 5.64–5.68)", "",
          f"Body m = {ref.GEO_MASS}, centre of mass c = ({ref.GEO_COM[0]}, {ref.GEO_COM[1]}), ρ = {ref.GEO_RHO}. "
          "`percussion_axis(I, a) = I a`; its Euclidean reading is the axis's signed distance r from c "
          "(r = ρ²/d for a pole at distance d from c). Pole at distance d from c (axis → the line at infinity), "
          "and pole R away, given as `from_xy(c + R u) / R` (axis → a line through c; R = ∞: the ideal point "
          "`[u, 0]`):", "",
          "| pole | κ | hom. error | r (exact) | κ_E | error of r |", "|---:|---:|---:|---:|---:|---:|"]
    for r in g["axis_near_com"]:
        L.append(f"| d = {_gv(r['value'])} | {_ge(_gmed(r, 'kappa'))} | {_ge(_gstats(r, 'err'))} | "
                 f"{_ge(_gmed(r, 'r') if r['value'] else None)} | {_ge(_gmed(r, 'kappa_e'))} | {_ge(_gstats(r, 'err_e'))} |")
    for r in g["axis_far"]:
        rr = [abs(s["r"]) for s in r["samples"]]
        L.append(f"| R = {_gv(r['value'])} | {_ge(_gmed(r, 'kappa'))} | {_ge(_gstats(r, 'err'))} | "
                 f"{_ge(float(np.median(rr)))} | {_ge(_gmed(r, 'kappa_e'))} | {_ge(_gstats(r, 'err_e'))} |")
    at_c = g["axis_near_com"][-1]
    n_inf = sum(1 for s in at_c["samples"] if s["at_infinity"])
    ideal = g["axis_far"][-1]
    rf = max(abs(s["r_float"]) for s in ideal["samples"])
    axis_rows = g["axis_near_com"] + g["axis_far"]
    axis_err = max(_gstats(r, "err") for r in axis_rows)
    L += ["", f"**The homogeneous axis never degrades** (κ ≤ {max(_gstats(r, 'kappa') for r in axis_rows):.0f}, "
          f"error ≤ {axis_err:.1e} in both limits): "
          "`I a` is a product, not a solve, and its pieces do not cancel. Its Euclidean reading r loses ε·κ_E: "
          "near the centre the axis runs off to infinity (r = ρ²/d, relative error ~ ε/d); far away the axis "
          "passes through c and r → 0 is found as a small difference with an absolute error of about ε |c|. "
          f"With the pole exactly at c the float product cancels exactly and gives the line at infinity "
          f"[0, 0, J] ({n_inf} of {len(at_c['samples'])}; the exact product of the rounded inertia entries is a line "
          f"~1e16 away: within ε·κ_E); an ideal pole gives a line through c (|r| ≤ {rf:.0e}). No warning, "
          "no error: neither limit is degenerate.", ""]
    # percussion pole
    L += ["### Percussion pole (the pole of a line, `I⁻¹ f`)", "",
          "A line `[e fx, e fy, 1]` approaching the line at infinity (a pure couple: the pole → c), and a line "
          "passing e from c (the pole → infinity, the body translates):", "",
          "| line | κ = cond₂(I) | hom. error | κ_E | Eucl. error |", "|---:|---:|---:|---:|---:|"]
    for name, rows in (("→ ∞", g["pole_near_infinity"]), ("→ c", g["pole_near_com"])):
        for r in rows:
            L.append(f"| {name}, e = {_gv(r['value'])} | {_ge(_gmed(r, 'kappa'))} | {_ge(_gstats(r, 'err'))} | "
                     f"{_ge(_gmed(r, 'kappa_e'))} | {_ge(_gstats(r, 'err_e'))} |")
    L += ["", "The same picture from the other side: the solve is as accurate as cond₂(I) ≈ 12 allows in both "
          "limits; the pole's Euclidean position is exact to rounding as it approaches c and loses ε·κ_E ≈ ε/e as it "
          "runs to infinity (∞: the float solve returned weight exactly 0, an ideal point, for a point ~1e16 away).",
          ""]
    # degenerate inertia
    dp, dpp = g["degenerate_pole"], g["degenerate_percussion_pole"]
    L += ["### An inertia conic degenerating to a point mass", "",
          "The same body with ρ → 0 (a point mass has a singular inertia): the pole of a random line by "
          "`conics.pole` (raises `DegenerateGeometryError` when cond₂(C) > 1/rtol = 1e13) and by "
          "`percussion_pole` (raises `SingularInertiaError` when λ_min ≤ 1e-12 λ_max):", "",
          "| ρ | cond₂(I) | `pole`: hom. error | `pole`: Eucl. error | `percussion_pole`: hom. error |",
          "|---:|---:|---:|---:|---:|"]
    for a, b in zip(dp, dpp):
        ca = f"**raises** ({a['raised_cond']:.0e})" if a["raised"] else _ge(_gstats(a, "err"))
        cb = f"**raises** ({b['raised_cond']:.0e})" if b["raised"] else _ge(_gstats(b, "err"))
        kap = _gmed(a, "kappa") if a["samples"] else (a["raised_cond"] if a["raised"] else None)
        L.append(f"| {a['value']:.0e} | {_ge(kap)} | {ca} | {_ge(_gstats(a, 'err_e'))} | {cb} |")
    lp = [r for r in dpp if r["samples"]][-1]
    lc = [r for r in dp if r["samples"]][-1]
    worst = max(s_["err"] / (EPS * s_["kappa"]) for r in dp + dpp for s_ in r["samples"])
    L += ["", "Here the package does refuse on a condition number. The pole loses ε·cond(I) (at most "
          f"{worst:.2f} ε·cond measured) in the homogeneous result, i.e. in the size of the acceleration, while its position stays "
          "exact to rounding: the error lies along the pole itself (a point mass spins about itself at any rate). "
          f"`percussion_pole` refuses first (ρ = {dpp[[r['raised'] > 0 for r in dpp].index(True)]['value']:.0e}, "
          f"cond ≈ {dpp[[r['raised'] > 0 for r in dpp].index(True)]['raised_cond']:.0e}; last answer "
          f"{_gstats(lp, 'err'):.1e} at cond {_gmed(lp, 'kappa'):.0e}), `conics.pole` a decade later "
          f"(last answer {_gstats(lc, 'err'):.1e} at cond {_gmed(lc, 'kappa'):.0e}).", ""]
    L += ["### Where the geometry layer reports a named error", "",
          "| operation | named error | rule | largest error returned before it (measured above) |",
          "|---|---|---|---|",
          f"| `meet(l, m)`, `join(p, q)` | `DegenerateGeometryError` (`.cond`) | κ = |a| |b| / |a × b| > "
          f"COND_LIMIT = {COND_LIMIT:.0e} (or a × b exactly zero) | near-coincident lines "
          f"{_gstats(last, 'err_e'):.0e} (Euclidean); nearly coincident points at R ≈ 1e3: "
          f"{_gstats(acc_j, 'err'):.0e} |",
          "| `percussion_axis(I, a)`, `polar(C, p)` | none for a positive semi-definite I | a product needs no "
          f"inversion; both limits (line at infinity, line through c) are ordinary values | ≤ {axis_err:.0e} "
          "homogeneous |",
          f"| `percussion_pole(I, f)` | `SingularInertiaError` (`.cond`) | λ_min ≤ 1e-12 λ_max | "
          f"{_gstats(lp, 'err'):.0e} at cond {_gmed(lp, 'kappa'):.0e} |",
          f"| `pole(C, l)` | `DegenerateGeometryError` (`.cond`) | cond₂(C) > 1/rtol = 1e13 | "
          f"{_gstats(lc, 'err'):.0e} at cond {_gmed(lc, 'kappa'):.0e} |", "",
          "**Finding.** `meet` and `join` refuse on the condition number κ = |a| |b| / |a × b| (three norms), past "
          "the package's one limit `COND_LIMIT` = 1e12 (`pole` at 1e13): near-*parallel* lines and points and lines "
          f"near infinity keep κ small (≤ {kmax:.0f} above) and are answered at full accuracy, ideal results included, "
          "while near-*coincident* lines and nearly coincident points (κ ≈ 1/θ, R/δ) are answered to about "
          "ε·κ ≤ 2e-4 and refused beyond, "
          "instead of returning answers with no correct digit.", ""]
    return L


def write_markdown(res: dict, path: Path) -> None:
    L = ["# Where the methods break down (accuracy study)", "",
         f"Generated by `python benchmarks/breakdown.py{' --quick' if res['meta'].get('quick') else ''}` on "
         f"{res['meta']['date']}; "
         + ("**quick mode: chains up to N = 100 and fewer geometry samples; the text is written for the full "
            "run.** " if res["meta"].get("quick") else "") +
         f"Python {res['meta']['python']}, numpy {np.__version__}; {res['meta']['runtime_s']:.0f} s.", "",
         "Error = max|q̈ − q̈_ref| / max|q̈_ref| against an **independent reference**: the joint-space "
         "equations `H q̈ = τ − C` written from scratch with world-frame Jacobians "
         "(`H = Σ J_cᵀ m J_c + J_ωᵀ J J_ω`, bias from `J̇ q̇`), evaluated and solved in exact rational "
         "arithmetic (`exact`: only the sines and cosines are rounded, to 64-bit-mantissa long double) or in "
         f"`np.longdouble` (`ld`, ε_ld = {EPS_LD:.1e}; its own error, `±`, is estimated by solving again with "
         "the elimination order reversed; at N = 20 that estimate, 1.0e-15, matches the actual ld-vs-exact "
         "difference, 1.3e-15). Errors marked `≲` are below 3× that estimate: not resolved. "
         "Code: `reference_system` in `planargeo/_reference.py`. "
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
    n100 = next((r for r in rows if r["N"] == 100), big)
    slope = float(np.polyfit(np.log([r["N"] for r in rows]), np.log([r["cond"] for r in rows]), 1)[0])
    L += ["", f"cond(H) grows roughly like N^{slope:.1f} (least-squares slope over these N; the random states make "
          f"it irregular; N = {big['N']}: {big['cond']:.1e}), and the dense solve (`crba`) "
          f"follows ε·cond(H) within a factor of about 20 (N = {big['N']}: {big['errors']['crba']:.1e} against "
          f"ε·cond = {EPS * big['cond']:.1e}). The recursive methods do better than ε·cond(H) because they never "
          f"form or factor H: ABA's error grows far slower ({n100['errors']['aba']:.1e} at N = 100; at N = 200 and "
          f"400 it is at or below the long-double reference's resolution, ≲ {big['errors']['aba']:.0e}), and the "
          "projective, "
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

    if "geometry" in res:
        L += geometry_markdown(res["geometry"])

    # (g)
    if res.get("mixed_masses"):
        rows = res["mixed_masses"]
        L += ["## (g) Long chains, tiny and huge masses mixed", "",
              "Unit links whose masses alternate between 10^(k/2) and 10^(−k/2) along the chain (ratio 10ᵏ; inertias "
              "m/12; `alternating_chain` in `planargeo/_reference.py`), random state; exact reference at N = 20, "
              "long-double beyond (at N = 20 the long-double reference agrees with the exact one to "
              + _e(max((r.get("ld_vs_exact", 0.0) for r in rows), default=0.0))
              + " even at k = 16: heavy-first alternation makes no cancellation). **numpy LinAlgError**: the method failed with a bare `numpy.linalg.LinAlgError`, not a "
              "planargeo error.", ""]
        L += _table(rows, [("N", str), ("k", str)])
        near = next((r for r in rows if r["N"] == 50 and r["cond"] >= 1e12), rows[-1])
        rec = [n for n in METHODS if n != "crba"]
        worst_rec = {n: max((r["errors"][n] for r in rows if n in r["errors"]), default=float("nan")) for n in rec}
        crba_first = min((r for r in rows if "crba" in r["raised"]), key=lambda r: r["cond"], default=None)
        unnamed = {}
        for r in rows:
            for n in r.get("unnamed", {}):
                unnamed.setdefault(n, []).append(f"N = {r['N']}, k = {r['k']}")
        r50 = [r for r in rows if r["N"] == 50] or rows
        L += ["", f"cond(H) grows like the mass ratio (N = 50: from {r50[0]['cond']:.0e} at k = 0, ×~10 per unit of k) "
              f"and passes 1e12 at k = {near['k']} (N = {near['N']}: cond {near['cond']:.1e}). There ABA's error is "
              f"{near['errors'].get('aba', float('nan')):.1e}, projective {near['errors'].get('projective', float('nan')):.1e}, "
              f"stacked {near['errors'].get('stacked', float('nan')):.1e}, mobility-split "
              f"{near['errors'].get('mobility_split', float('nan')):.1e} and the dense solve "
              + (f"{near['errors']['crba']:.1e}" if "crba" in near["errors"] else "raises")
              + f" (ε·cond = {EPS * near['cond']:.1e}). Worst over the sweep (`≲`: at the reference's own floor): "
              + ", ".join(f"{n} {v:.0e}" for n, v in worst_rec.items()) + ". "
              + (f"The dense solve refuses first (k = {crba_first['k']}, N = {crba_first['N']}, `.cond` "
                 f"{crba_first['raised']['crba']:.0e}). " if crba_first else "")
              + "ABA is the most accurate throughout; mobility splitting loses the most digits among the recursive "
              "methods" + (" (though never more than ε·cond(H))." if all(
                  r["errors"]["mobility_split"] <= EPS * r["cond"] for r in rows if "mobility_split" in r["errors"])
                  else ", in places more than ε·cond(H).")
              + "".join(f" **`{n}` raised a bare numpy `LinAlgError`** ({'; '.join(w)}) instead of a named "
                        "`SingularConfigurationError`: an unnamed failure, to be fixed in the method."
                        for n, w in unnamed.items()), ""]


    L += ["## Summary: what breaks first", "",
          "| knob | breaks first | how |", "|---|---|---|",
          f"| chain length | dense solve (crba) | error ≈ ε·cond(H), cond ~ N^{slope:.1f}; recursive methods well "
          "below |",
          "| light tip | nothing | graded H is harmless when the light links come last |",
          "| light base | dense solve, then stacked | heavy entries cancel to find light motions; ABA best |",
          "| slender links | nothing | point masses off the axis keep H regular |",
          "| tip mass → its joint axis | projective / mobility-split / stacked raise first | cond(H) ~ 1/d², errors ≈ ε·cond |",
          "| folded slider-crank | loop solver (9.5) | cond(BᵀGΛ⁻¹GᵀB) ~ 1/δ; Lagrange KKT survives longer |",
          "| light base slider | dense solve; then all raise by threshold | recursive methods exact until the test refuses |",
          "| tiny and huge masses mixed, long chains | dense solve refuses (cond ~1e13); mobility split least accurate "
          "of the recursive methods | ABA stays near ε at cond 1e12 |",
          f"| near-coincident lines / points (meet, join) | refuse past κ = {COND_LIMIT:.0e} (`.cond`) | error ≈ ε·κ "
          "≤ 2e-3 before that, κ ~ 1/θ, R/δ |",
          "| near-parallel lines, elements near infinity | nothing, in homogeneous form | Euclidean readings lose ε·κ_E, "
          "the input's own limit |",
          "| inertia conic → point mass (pole) | `percussion_pole` raises first (cond 1e12), `pole` at 1e13 | "
          "the acceleration's size loses ε·cond(I), its position does not |",
          ""]
    path.write_text("\n".join(L), encoding="utf-8")


def plot(res: dict, out_dir: Path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    geo = "geometry" in res
    fig, axes = plt.subplots(2 if geo else 1, 2, figsize=(12, 10.4 if geo else 5.2),
                             gridspec_kw={"width_ratios": [2, 1] if not geo else [1.4, 1]}, squeeze=False)
    (ax, bx) = axes[0]
    floor = 1e-20
    tree_rows = res["length"] + res["mass_ratio"] + res.get("mixed_masses", []) + res["slender"] + res["prismatic"]
    for name in METHODS:
        xs = [r["cond"] for r in tree_rows if name in r["errors"]]
        ys = [max(r["errors"][name], floor) for r in tree_rows if name in r["errors"]]
        ax.scatter(xs, ys, marker=MARKERS[name], s=22, label=name, color=COLORS[name],
                   facecolors="none" if MARKERS[name] not in ("x", "P") else None, alpha=0.8, rasterized=True)
        xr = [r["cond"] for r in tree_rows if name in r["raised"]]
        if xr:
            ax.scatter(xr, [3e-2] * len(xr), marker=MARKERS[name], s=22, color=COLORS[name], alpha=0.8,
                       rasterized=True)
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
    ax.set_title("tree methods (knobs a, b, c, e, g)")
    ax.legend(fontsize=8, loc="lower right")
    for path, cols in (("rod", ("C5", "C6")), ("psi", ("C8", "C9"))):
        sc = [r for r in res["slider_crank"] if "cond" in r and r["path"] == path]
        for name, col in zip(("loop_solve", "lagrange"), cols):
            xs = [r["cond"] for r in sc if name in r]
            ys = [max(r[name], floor) for r in sc if name in r]
            bx.scatter(xs, ys, marker=MARKERS[name], color=col, s=26, label=f"{name} ({path} path)",
                       facecolors="none" if name == "loop_solve" else None, rasterized=True)
        xr = [r["cond"] for r in sc if "loop_raised" in r]
        bx.scatter(xr, [3e-2] * len(xr), marker=MARKERS["loop_solve"], color=cols[0], s=26, rasterized=True)
    bx.axvline(SINGULAR_COND, color="C5", lw=0.8, ls=":")
    bx.set_xlim(1, 1e16)
    bx.set_xlabel("loop solver cond(BᵀGΛ⁻¹GᵀB)")
    bx.set_title("folded slider-crank (knob d)")
    bx.legend(fontsize=7, loc="lower right", ncol=2, handletextpad=0.2, columnspacing=0.6)
    if geo:
        plot_geometry(res["geometry"], axes[1][0], axes[1][1])
    fig.tight_layout()
    # the dense scatter layers are rasterized (in the SVG too, at 110 dpi): the geometry panels alone hold
    # thousands of markers; axes, guides and text stay vector.  No date and a fixed hash salt: a rerun with
    # the same numbers writes the same bytes
    with plt.rc_context({"svg.hashsalt": "planargeo"}):
        fig.savefig(out_dir / "breakdown.svg", dpi=110, metadata={"Date": None})
    fig.savefig(out_dir / "breakdown.png", dpi=110)
    plt.close(fig)



GEO_SERIES = (  # key, label, marker, colour
    ("meet_pencil", "meet, near-coincident lines", "o", "C0"),
    ("meet_strip", "meet, near-parallel lines", "s", "C1"),
    ("join", "join, nearly coincident points", "^", "C2"),
    ("axis_near_com", "axis of percussion, pole → c", "D", "C3"),
    ("axis_far", "axis of percussion, pole → ∞", "v", "C4"),
    ("pole_near_infinity", "percussion pole, line → ∞", "<", "C5"),
    ("pole_near_com", "percussion pole, line → c", ">", "C6"),
    ("degenerate_pole", "pole, inertia → point mass", "x", "C7"),
    ("degenerate_percussion_pole", "percussion_pole, inertia → point mass", "+", "C8"),
)


def plot_geometry(g: dict, ax, bx) -> None:
    """Bottom row: every geometry sample, homogeneous error vs κ (left), Euclidean reading vs κ_E (right)."""
    floor, top, band = 1e-18, 1e3, 1e2
    for key, label, mk, col in GEO_SERIES:
        rows = g[key]
        for a, kk, ek in ((ax, "kappa", "err"), (bx, "kappa_e", "err_e")):
            pts = [(s[kk], s[ek]) for r in rows for s in r["samples"]
                   if s.get(kk) is not None and s.get(ek) is not None and np.isfinite(s[kk])]
            if not pts:
                continue
            x, y = np.array(pts).T
            y = np.where(np.isfinite(y), np.maximum(y, floor), band)
            a.scatter(x, np.minimum(y, band), marker=mk, s=14, color=col, alpha=0.6, label=label,
                      facecolors="none" if mk in "osD^v<>" else None, linewidths=0.8, rasterized=True)
        xr = [r["raised_cond"] for r in rows if r["raised"] and r["raised_cond"] is not None
              and np.isfinite(r["raised_cond"])]
        if xr:
            ax.scatter(xr, [band] * len(xr), marker=mk, s=30, color=col, rasterized=True)
    c = np.geomspace(1, 1e19, 50)
    for a in (ax, bx):
        a.plot(c, EPS * c, "k--", lw=1, label="ε·κ")
        a.axhline(band, color="0.7", lw=0.8)
        a.set_xscale("log")
        a.set_yscale("log")
        a.set_xlim(1, 1e19)
        a.set_ylim(floor / 2, top)
        a.grid(True, which="major", alpha=0.3)
    ax.axvline(COND_LIMIT, color="C8", lw=0.8, ls=":")
    ax.axvline(1e13, color="C7", lw=0.8, ls=":")
    ax.text(1.5, 1.4 * band, "raised, at their cond (dotted: join, meet, percussion_pole refuse past κ = 1e12, "
            "pole past 1e13); join / meet shown without the limit",
            fontsize=7, color="0.4")
    bx.text(1.5, 1.4 * band, "Euclidean reading lost (returned at infinity)", fontsize=7, color="0.4")
    ax.set_xlabel("κ (join / meet: |a||b|/|a×b|; axis: ‖|I||a|‖/‖Ia‖; pole: cond₂)")
    ax.set_ylabel("relative error vs exact rational reference")
    ax.set_title("geometry layer (knob f): homogeneous results")
    ax.legend(fontsize=6.5, loc="lower right", ncol=2, handletextpad=0.2, columnspacing=0.6)
    bx.set_xlabel("κ_E = κ |x| / |weight| (distance of c from a line: see text)")
    bx.set_title("their Euclidean readings")

def run(out_dir, quick: bool = False) -> dict:
    """Run every sweep, write ``breakdown.md``, ``breakdown.svg`` and ``breakdown.png`` in ``out_dir``.

    ``quick``: chains up to N = 100 only and 4 geometry samples per row (about 10 s); the
    prose of the report is written for the full run.
    """
    global GEO_SAMPLES
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    t0 = time.time()
    res = {}
    samples = GEO_SAMPLES
    if quick:
        GEO_SAMPLES = 4
    try:
        for key, fn in (("length", lambda: knob_length(tuple(N for N in LENGTHS if N <= 100) if quick else LENGTHS)),
                        ("mass_ratio", knob_mass_ratio), ("mixed_masses", knob_mixed_masses),
                        ("slender", knob_slender),
                        ("slider_crank", knob_slider_crank), ("prismatic", knob_prismatic),
                        ("geometry", knob_geometry)):
            t = time.time()
            res[key] = fn()
            log(f"{key}: done in {time.time() - t:.1f} s")
    finally:
        GEO_SAMPLES = samples
    res["meta"] = {"date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), "python": platform.python_version(),
                   "runtime_s": time.time() - t0, "quick": quick}
    log(f"writing {out_dir / 'breakdown.md'} and the charts")
    write_markdown(res, out_dir / "breakdown.md")
    plot(res, out_dir)
    return res


def main(argv=None) -> int:
    import argparse

    p = argparse.ArgumentParser(description="Where the methods break down: accuracy against an exact reference.")
    p.add_argument("--quick", action="store_true", help="chains up to N = 100, fewer geometry samples (~10 s)")
    p.add_argument("--out", default=str(HERE / "results"), help="output directory (default: %(default)s)")
    args = p.parse_args(argv)
    out = run(args.out, quick=args.quick)
    print(json.dumps(out["meta"]))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
