"""The car-cornering example (thesis 6.9): closed forms and an independent solve.

References:
* the thesis's printed closed forms T (6.125), U (6.127), ω̇ (6.131), μ (6.133),
  typed in here from the thesis;
* an independent Newton–Euler solve at the centre of gravity with ordinary
  vectors (no screws, no inertia matrix): unknowns a_G, α and the two lateral
  tyre multipliers, the non-holonomic no-slip constraints n_j · v_Pj = 0
  differentiated in time (ṅ_j = ω ẑ × n_j), solved densely with numpy;
* a 1-dof Lagrange check: ω̇ = (moment of F_A about the ICR) / (inertia about the ICR).
"""
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from planargeo import errors, scenes
from planargeo.scenes.car import car

PARAM_SETS = [
    dict(),                                                                 # defaults
    dict(m=1.0, rho=0.5, L=1.0, d=2.0, eps=0.5, omega=1.0, F_A=1.0),
    dict(m=1500.0, rho=1.4, L=2.9, d=25.0, eps=0.35, omega=0.8, F_A=-3000.0),   # braking
    dict(m=800.0, rho=0.9, L=2.2, d=-6.0, eps=0.6, omega=-0.7, F_A=1500.0),     # right turn
    dict(m=2.0, rho=0.3, L=1.5, d=0.4, eps=1.2, omega=3.0, F_A=0.0),            # CG behind the rear axle
]


def _params(kw):
    p = dict(m=1200.0, rho=1.2, L=2.6, d=8.0, eps=0.45, omega=0.5, F_A=2000.0)
    p.update(kw)
    return p


def thesis_closed_forms(m, rho, L, d, eps, omega, F_A):
    """(6.125), (6.127), (6.131), (6.133) exactly as printed."""
    D = rho ** 2 + d ** 2 + (1 - eps) ** 2 * L ** 2
    h = np.sqrt(d ** 2 + L ** 2)
    T = np.array([-(1 - eps) * L / D, d / D, 1.0])
    U = np.array([[1.0, 0.0],
                  [-d / L, h / L],
                  [(d ** 2 + (1 - eps) * L ** 2) / (L * D), -d * h / (L * D)]])
    omega_dot = F_A / m * h / D
    mu = np.array([-(eps * (1 - eps) * L ** 2 - rho ** 2) / D * h / L * F_A - eps * d * m * omega ** 2,
                   (eps * (2 - eps) * L ** 2 - rho ** 2) / D * d / L * F_A - m * omega ** 2 * (1 - eps) * h])
    return T, U, omega_dot, mu


def _cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def _zcross(w, r):
    """ω ẑ × r."""
    return w * np.array([-r[1], r[0]])


def newton_euler_reference(m, rho, L, d, eps, omega, F_A):
    """Independent solve at the CG: returns (α, λ_rear, λ_front, a_G)."""
    G = np.array([d, (1 - eps) * L])
    P = [np.array([d, 0.0]), np.array([d, L])]                     # rear, front contact
    h = np.hypot(d, L)
    n = [np.array([1.0, 0.0]), np.array([d, L]) / h]               # lateral (axle) directions
    e_drive = np.array([-L, d]) / h
    J = m * rho ** 2
    v_G = _zcross(omega, G)                                       # rotating about the ICR
    # unknowns x = [aGx, aGy, alpha, lam_r, lam_f]
    K = np.zeros((5, 5))
    b = np.zeros(5)
    # m a_G - λ_r n_r - λ_f n_f = F_A e
    K[0:2, 0:2] = m * np.eye(2)
    K[0:2, 3] = -n[0]
    K[0:2, 4] = -n[1]
    b[0:2] = F_A * e_drive
    # J α - Σ (P_j - G) × λ_j n_j = (P_f - G) × F_A e
    K[2, 2] = J
    K[2, 3] = -_cross(P[0] - G, n[0])
    K[2, 4] = -_cross(P[1] - G, n[1])
    b[2] = _cross(P[1] - G, F_A * e_drive)
    # d/dt (n_j · v_Pj) = 0:  n_j · (a_G + α ẑ×r_j − ω² r_j) + (ω ẑ×n_j) · v_Pj = 0
    for row, (Pj, nj) in zip((3, 4), zip(P, n)):
        r = Pj - G
        v_P = v_G + _zcross(omega, r)
        K[row, 0:2] = nj
        K[row, 2] = nj @ _zcross(1.0, r)
        b[row] = omega ** 2 * (nj @ r) - _zcross(omega, nj) @ v_P
    x = np.linalg.solve(K, b)
    return x[2], x[3], x[4], x[0:2]


@pytest.mark.parametrize("kw", PARAM_SETS)
def test_scene_matches_thesis_closed_forms(kw):
    p = _params(kw)
    q = car(**p).quantities
    T, U, omega_dot, mu = thesis_closed_forms(**p)
    scale = 1 + abs(p["F_A"]) + p["m"] * p["omega"] ** 2 * (abs(p["d"]) + p["L"])
    np.testing.assert_allclose(q["T"], T, rtol=1e-12, atol=1e-14)                # (6.125)
    np.testing.assert_allclose(q["U"], U, rtol=1e-12, atol=1e-14 * np.abs(U).max())              # (6.127)
    assert np.isclose(q["omega_dot"], omega_dot, rtol=1e-12, atol=1e-14)        # (6.131)
    np.testing.assert_allclose(q["mu"], mu, rtol=1e-11, atol=1e-12 * scale)      # (6.133)


@pytest.mark.parametrize("kw", PARAM_SETS)
def test_closed_forms_against_independent_newton_euler(kw):
    """The thesis's closed forms themselves, checked against an independent CG-frame solve."""
    p = _params(kw)
    T, U, omega_dot, mu = thesis_closed_forms(**p)
    alpha, lam_r, lam_f, a_G = newton_euler_reference(**p)
    scale = 1 + abs(p["F_A"]) + p["m"] * p["omega"] ** 2 * (abs(p["d"]) + p["L"])
    assert np.isclose(alpha, omega_dot, rtol=1e-10, atol=1e-14)
    np.testing.assert_allclose([lam_r, lam_f], mu, rtol=1e-10, atol=1e-11 * scale)
    # the ICR stays put: a_G is the acceleration of a body point rotating about a fixed centre
    G = np.array([p["d"], (1 - p["eps"]) * p["L"]])
    np.testing.assert_allclose(a_G, _zcross(alpha, G) - p["omega"] ** 2 * G, rtol=1e-10, atol=1e-12 * scale)
    # 1-dof Lagrange: ω̇ = moment of F_A about the ICR / inertia about the ICR
    h = np.hypot(p["d"], p["L"])
    J_icr = p["m"] * (p["rho"] ** 2 + G @ G)
    assert np.isclose(omega_dot, h * p["F_A"] / J_icr, rtol=1e-12, atol=1e-14)


@given(st.floats(0.1, 1e4), st.floats(0.05, 3), st.floats(0.5, 5), st.floats(-50, 50),
       st.floats(-0.5, 1.5), st.floats(-3, 3), st.floats(-1e4, 1e4))
def test_scene_against_newton_euler_property(m, rho, L, d, eps, omega, F_A):
    q = car(m=m, rho=rho, L=L, d=d, eps=eps, omega=omega, F_A=F_A).quantities
    alpha, lam_r, lam_f, _ = newton_euler_reference(m, rho, L, d, eps, omega, F_A)
    scale = 1 + abs(F_A) + m * omega ** 2 * (abs(d) + L)
    assert np.isclose(q["omega_dot"], alpha, rtol=1e-9, atol=1e-12 * scale / m)
    np.testing.assert_allclose(q["mu"], [lam_r, lam_f], rtol=1e-9, atol=1e-10 * scale)


@pytest.mark.parametrize("kw", PARAM_SETS)
def test_scene_consistency(kw):
    """Equations of motion (6.121), κ = γ = 0 (6.116, 6.129), p (6.119), f_A (6.120) by hand."""
    p = _params(kw)
    res = car(**p)
    q = res.quantities
    m, L, d, eps, om, F = p["m"], p["L"], p["d"], p["eps"], p["omega"], p["F_A"]
    h = np.hypot(d, L)
    I, a, f = np.array(q["I"]), np.array(q["a"]), np.array(q["f"])
    np.testing.assert_allclose(q["p"], [-m * d * om ** 2, -m * (1 - eps) * L * om ** 2, 0.0], rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(q["f_A"], [-L / h * F, d / h * F, h * F], rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(q["kappa"], 0.0)
    np.testing.assert_allclose(q["gamma"], 0.0)
    np.testing.assert_allclose(a, [0.0, 0.0, q["omega_dot"]], atol=1e-12 * (1 + abs(q["omega_dot"])))
    np.testing.assert_allclose(f + np.array(q["f_A"]), I @ a + np.array(q["p"]),
                               atol=1e-9 * (1 + np.abs(f).max()))                # (6.121)
    np.testing.assert_allclose(q["R"], [[1.0, d / h], [0.0, L / h], [0.0, 0.0]], atol=1e-15)  # (6.114)
    assert q["V"] == pytest.approx(om * d)
    # drawing geometry
    ex = res.extra
    np.testing.assert_allclose(ex["rear_contact"], [d, 0.0])
    np.testing.assert_allclose(ex["front_contact"], [d, L])
    np.testing.assert_allclose(ex["cg"], [d, (1 - eps) * L])
    np.testing.assert_allclose(ex["tyre_wrenches"].sum(axis=1), f, atol=1e-9 * (1 + np.abs(f).max()))
    # each tyre force acts at its contact: its line passes through the contact point
    for j, P in enumerate((ex["rear_contact"], ex["front_contact"])):
        w = np.array(q["R"])[:, j]
        assert abs(w[2] - (P[0] * w[1] - P[1] * w[0])) < 1e-12


def test_thesis_remark_signs_at_defaults():
    """"In general both are negative": tyre forces point towards the ICR at the default state."""
    mu = car().quantities["mu"]
    assert mu[0] < 0 and mu[1] < 0


def test_registry_and_plain_outputs():
    assert "car" in scenes.names()
    assert scenes.parameters("car") == dict(m=1200.0, rho=1.2, L=2.6, d=8.0, eps=0.45, omega=0.5, F_A=2000.0,
                                            outlines=True)
    res = scenes.build("car", omega=1.0)
    assert res.name == "car" and res.params["omega"] == 1.0
    for key, value in res.quantities.items():
        assert isinstance(value, (float, list)), key
    assert np.array(res.quantities["U"]).shape == (3, 2)
    with pytest.raises(errors.SceneError, match="scene 'car' has no parameter 'mass'"):
        scenes.build("car", mass=3.0)


@pytest.mark.parametrize("kw,err,msg", [
    (dict(m=0.0), errors.SceneError, "m must be positive, got 0.0"),
    (dict(rho=-1.0), errors.SceneError, "rho must be positive, got -1.0"),
    (dict(L=0.0), errors.SceneError, "L must be positive, got 0.0"),
    (dict(d=np.nan), errors.NonFiniteError, "d must be finite"),
    (dict(F_A=[1.0, 2.0]), errors.ShapeError, "F_A must be a scalar"),
    (dict(omega="fast"), errors.InputError, "omega must be numeric"),
    (dict(outlines="no"), errors.SceneError, "^outlines must be True or False, got 'no'$"),
    (dict(outlines=1), errors.SceneError, "^outlines must be True or False, got 1$"),
])
def test_bad_parameters(kw, err, msg):
    with pytest.raises(err, match=msg):
        car(**kw)


@pytest.mark.parametrize("kw", PARAM_SETS)
def test_model_forward_dynamics_reproduces_omega_dot(kw):
    """The scene's Model through Pinocchio (an independent dynamics code, not the subspaces)."""
    from test_articulated_reference import pinocchio_qdd

    res = car(**_params(kw))
    st_ = res.state
    qdd = pinocchio_qdd(res.model, st_["q"], st_["qd"], st_["tau"], st_["f_ext"])
    assert np.isclose(qdd[0], res.quantities["omega_dot"], rtol=1e-10, atol=1e-14)


def test_drawing_geometry():
    res = car(d=8.0, L=2.6)
    ex = res.extra
    rear, front = ex["tyres"]
    assert res.model.bodies[0].shape.contains(_point(ex["cg"]))
    assert rear.centroid.distance(_point(ex["rear_contact"])) < 1e-12
    assert front.centroid.distance(_point(ex["front_contact"])) < 1e-12
    # the front tyre's long side is along the rolling direction (-L, d)/√(d²+L²)
    xs, ys = front.exterior.coords.xy
    edges = [np.array([xs[i + 1] - xs[i], ys[i + 1] - ys[i]]) for i in range(4)]
    longest = max(edges, key=np.linalg.norm)
    assert abs(abs(longest @ ex["front_rolling"]) - np.linalg.norm(longest)) < 1e-12
    assert np.isclose(np.tan(ex["steer"]), 2.6 / 8.0)


def _point(xy):
    from shapely.geometry import Point
    return Point(*xy)


# --------------------------------------------------------------------------- outlines=False
def _has_shapely(x):
    from shapely.geometry.base import BaseGeometry
    if isinstance(x, BaseGeometry):
        return True
    if isinstance(x, (list, tuple)):
        return any(_has_shapely(y) for y in x)
    if isinstance(x, dict):
        return any(_has_shapely(y) for y in x.values())
    return False


@pytest.mark.parametrize("kw", PARAM_SETS)
def test_outlines_false_same_outputs_no_outlines(kw):
    full = car(**_params(kw))
    assert _has_shapely(full.extra["tyres"])
    assert _has_shapely([b.shape for b in full.model.bodies])
    bare = car(**_params(kw), outlines=False)               # no shapely outline anywhere (below)
    # every quantity bit for bit (the report's numbers)
    assert bare.quantities == full.quantities
    assert bare.params == full.params and bare.state == full.state and bare.name == full.name
    # the drawing data minus the outlines, arrays exactly equal
    assert set(bare.extra) == set(full.extra) - {"tyres"}
    for k, v in bare.extra.items():
        if isinstance(v, np.ndarray):
            assert np.array_equal(v, full.extra[k]), k
        elif isinstance(v, float):
            assert v == full.extra[k], k
    assert not _has_shapely(bare.extra)
    # the model: same mass properties and joint, no shape
    (b0,), (f0,) = bare.model.bodies, full.model.bodies
    assert b0.shape is None
    assert (b0.mass, tuple(b0.com), b0.inertia, b0.name) == (f0.mass, tuple(f0.com), f0.inertia, f0.name)
    assert bare.model.joints == full.model.joints and bare.model.parents == full.model.parents
    # ω̇ through the bare model still matches the thesis closed form 6.131
    from test_articulated_reference import pinocchio_qdd
    p = _params(kw)
    _T, _U, omega_dot, mu = thesis_closed_forms(**p)
    st_ = bare.state
    qdd = pinocchio_qdd(bare.model, st_["q"], st_["qd"], st_["tau"], st_["f_ext"])
    assert np.isclose(qdd[0], omega_dot, rtol=1e-10, atol=1e-14)
    np.testing.assert_allclose(bare.quantities["mu"], mu, rtol=1e-10, atol=1e-9)


def test_car_explorer_skips_the_outlines():
    """CarExplorer asks for outlines=False (it draws its own outline): no shapely work per change."""
    import sys

    from planargeo.widgets.car import CarExplorer

    calls = []                    # shapely calls, observed by a profiler (nothing is patched)

    def profile(frame, event, arg):
        if event == "call" and frame.f_globals.get("__name__", "").startswith("shapely"):
            calls.append(frame.f_code.co_name)

    ex = CarExplorer(display="agg")
    sys.setprofile(profile)
    try:
        ex.set(**{"speed (m/s)": 9.0, "turn radius (m)": 20.0, "drive force (N)": -1000.0})
    finally:
        sys.setprofile(None)
    assert ex.message == ""
    assert ex.n_computes >= 2                                # the scene did run, several times
    assert calls == []                                       # ... never building an outline
    sys.setprofile(profile)                                  # (the observer sees the scene's own outlines)
    try:
        car(d=20.0)
    finally:
        sys.setprofile(None)
    assert calls
    # what it shows is still the thesis's closed form (6.131, 6.133)
    v = ex.values
    _T, _U, omega_dot, mu = thesis_closed_forms(m=v["mass (kg)"], rho=v["radius of gyration (m)"], L=2.6,
                                                d=20.0, eps=v["centre of mass ε (× L)"], omega=9.0 / 20.0,
                                                F_A=-1000.0)
    r = ex.readout_values
    assert r["yaw acceleration ω̇"] == pytest.approx(omega_dot, rel=1e-10)
    assert [r["rear tyre force μ₁"], r["front tyre force μ₂"]] == pytest.approx(mu, rel=1e-10)
