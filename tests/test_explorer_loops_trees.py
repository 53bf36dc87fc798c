"""TreeExplorer (#14 item 4): every pin force of Fig 9.2 at its joint against the Lagrange multipliers of
maximal coordinates (closed) and Pinocchio's joint forces (open), Play through simulate_loops against an
integration of the maximal-coordinate reference, focus, drags (refused ones keep the last good state),
legibility of every state visited."""
import numpy as np
import pytest
from scipy.integrate import solve_ivp

from planargeo.algorithms.loops import constrained_dynamics_lagrange
from picture_checks import drawn_arrow, elements, overlapping_labels, parts, shown_labels, undescribed
from planargeo.simulate.loops import closure_residual
from planargeo.widgets.trees import TreeExplorer


SUB = "₁₂₃₄₅₆₇₈₉"


def legible(ex):
    """No two labels overlap; every element has its symbol and a description with its value."""
    pic = ex.picture()
    problems = overlapping_labels(pic) + undescribed(pic)
    assert problems == [], problems
    return ex


def drawn_wrench_matches(ex, eid, w, tol):
    """The drawn arrow of ``eid`` is the force of the wrench ``w`` (the largest force of the picture drawn
    0.9 m long) and sits on its line of action."""
    fmax = max(np.hypot(*x.wrench[:2]) for x in ex.state["reactions"])
    vec, foot = drawn_arrow(ex.picture(), eid)
    np.testing.assert_allclose(vec * fmax / 0.9, w[:2], rtol=0, atol=tol, err_msg=eid)
    assert np.dot([foot[1], -foot[0], 1.0], w) == pytest.approx(0.0, abs=1e-4 * max(1.0, np.abs(w).max())), eid
    return foot


@pytest.fixture
def ex():
    return legible(TreeExplorer(display="agg"))


def _lagrange_joint_wrenches(model, q, qd):
    """Each revolute joint's constraint force on its body (Φ_iᵀ λ_i of the maximal-coordinate KKT solve),
    as a wrench at the origin; and the contact forces F."""
    r = constrained_dynamics_lagrange(model, q, qd, np.zeros(9))
    Phi, lam = r["Phi"], r["lambda"]
    from planargeo.mechanics.kinematics import kinematics

    com = kinematics(model, q).com
    out = []
    for i in range(9):                      # two rows (point coincidence) per revolute joint, in joint order
        gen = Phi[2 * i:2 * i + 2].T @ lam[2 * i:2 * i + 2]
        fx, fy, mc = gen[3 * i:3 * i + 3]
        out.append([fx, fy, mc + com[i, 0] * fy - com[i, 1] * fx])
    return np.array(out), np.asarray(r["F"]).reshape(-1, 3)


def check_drawn_forces(ex):
    q, qd = ex.state["q"], ex.state["qd"]
    f, F = _lagrange_joint_wrenches(ex.state["model"], q, qd)
    scale = max(1.0, np.abs(f).max())
    for i in range(9):
        drawn_wrench_matches(ex, f"f{SUB[i]}", f[i], 1e-5 * scale)
    for k in range(2):
        drawn_wrench_matches(ex, f"F{SUB[k]}", -F[k], 1e-5 * scale)
    assert ex.readout_values["largest pin force"] == pytest.approx(np.hypot(f[:, 0], f[:, 1]).max(), rel=1e-9)
    return scale


def test_every_pin_force_drawn_labelled_and_equal_to_the_multipliers(ex):
    texts = [t for _id, t in shown_labels(ex.picture())]
    for sym in ["f₁", "f₂", "f₃", "f₄", "f₅", "f₆", "f₇", "f₈", "f₉", "F₁", "F₂"] + [str(i) for i in range(1, 10)]:
        assert sym in texts, sym
    check_drawn_forces(ex)
    # free pins: every joint's arrow sits at its joint (no joint torques here)
    pose = ex.state["sol"].data.pose
    for i in range(9):
        np.testing.assert_allclose(drawn_arrow(ex.picture(), f"f{SUB[i]}")[1], pose[i, :2], atol=1e-4)
    assert set(ex.readout_values) <= set(ex.units) | {k for k in ex.readout_values if "(N)" in k or k == "loops"}


def test_open_tree_pin_forces_match_pinocchio(ex):
    pin = pytest.importorskip("pinocchio")
    from bench import to_pinocchio

    ex.set(loops="open (Fig 9.1)", speed=1.2, mass=1.5)
    legible(ex)
    model, q, qd = ex.state["model"], ex.state["q"], ex.state["qd"]
    pm = to_pinocchio(model)
    pd = pm.createData()
    pin.rnea(pm, pd, q, qd, ex.state["qdd"])
    pin.forwardKinematics(pm, pd, q, qd, ex.state["qdd"])
    scale = max(np.hypot(*x.wrench[:2]) for x in ex.state["reactions"])
    for i in range(9):
        fi, oMi = pd.f[i + 1], pd.oMi[i + 1]
        F = oMi.rotation @ fi.linear
        p = oMi.translation
        tz = (oMi.rotation @ fi.angular)[2] + p[0] * F[1] - p[1] * F[0]
        np.testing.assert_allclose(ex.state["reactions"][i].wrench, [F[0], F[1], tz], atol=1e-10 * max(1.0, scale))
        drawn_wrench_matches(ex, f"f{SUB[i]}", np.array([F[0], F[1], tz]), 1e-5 * scale)
    assert not {"F₁", "F₂"} & set(elements(ex.picture()))


def _reference_run(model, q0, qd0, t_end):
    """q(t_end) by integrating the maximal-coordinate Lagrange reference (q̈ of the dense KKT solve)."""
    def rhs(_t, y):
        return np.concatenate([y[9:], constrained_dynamics_lagrange(model, y[:9], y[9:], np.zeros(9))["qdd"]])

    sol = solve_ivp(rhs, (0.0, t_end), np.concatenate([q0, qd0]), method="DOP853", rtol=1e-10, atol=1e-12)
    return sol.y[:9, -1]


def test_play_follows_the_reference_keeps_energy_and_the_loops(ex):
    q0, qd0 = ex.state["q"].copy(), ex.state["qd"].copy()
    ex.advance(6)
    legible(ex)
    t = ex.readout_values["t"]
    assert t == pytest.approx(6 * ex.play_dt)
    q_ref = _reference_run(ex.state["model"], q0, qd0, t)
    np.testing.assert_allclose(ex.state["q"], q_ref, atol=2e-6)
    assert abs(ex.readout_values["energy drift ΔE/E₀"]) < 1e-7
    assert ex.readout_values["closure drift |φ|"] < 1e-9
    assert np.abs(closure_residual(ex.state["model"], ex.state["q"])).max() < 1e-9
    check_drawn_forces(ex)                   # the overlays are those of the frame shown


def test_play_overlays_with_poles_stay_legible(ex):
    ex.set(**{"velocity poles": True, "acceleration poles": True})
    for _ in range(3):
        ex.advance(1)
        legible(ex)
    ex.set(key=True)                         # the key covers the upper left: labels keep clear of it
    for _ in range(3):
        legible(ex.advance(2))


def test_focus_on_one_reaction(ex):
    assert ex.controls["focus"].options[:2] == ("all", "f₁")
    box = ex.picture()["box"]
    ex.set(focus="f₅")
    legible(ex)
    pic = ex.picture()
    els = elements(pic)
    forces = [f"f{s}" for s in SUB] + ["F₁", "F₂"]
    assert [i for i, _t in shown_labels(pic) if i in forces] == ["f₅"]         # only the focus labelled
    assert els["f₅"].get("opacity", 1.0) == 1.0 and els["f₅"]["width"] > els["f₄"]["width"]   # bold
    assert all(els[k]["opacity"] < 1 for k in forces if k != "f₅")             # the rest faded
    x = ex.state["reactions"][4]
    assert ex.readout_values["|f₅|"] == pytest.approx(np.hypot(*x.wrench[:2]))
    assert f"{ex.readout_values['|f₅|']:.4g} N" in els["f₅"]["desc"]
    assert ex.picture()["box"] == pytest.approx(box, abs=1e-12)          # the focus keeps the view
    ex.set(focus="all")
    assert ex.picture()["box"] == pytest.approx(box, abs=1e-12)
    legible(ex)


def test_drag_the_tip_of_body_2_closes_the_loops_again(ex):
    ex.advance(2)
    start = tuple(ex.state["tips"][1])
    base = ex.state["tips"][0]
    target = (base[0] - 0.2, base[1] + 0.95)
    ex.drag("tip of body 2", start, target, steps=5)
    legible(ex)
    assert ex.message == ""
    assert ex.values["t (s)"] == "0" and ex.readout_values["t"] == 0.0       # a new initial state
    a2 = np.degrees(np.arctan2(target[1] - base[1], target[0] - base[0]))
    assert ex.state["sol"].data.pose[1, 2] == pytest.approx(np.radians(a2))
    assert np.abs(closure_residual(ex.state["model"], ex.state["q"])).max() < 1e-9
    check_drawn_forces(ex)


def test_a_long_drag_step_shows_the_pose_of_its_angles_and_a_drag_onto_the_joint_is_refused(ex):
    """One pose per pair of angles (issue 23 item 6): a jump in one step shows the pose a fresh explorer shows."""
    base = ex.state["tips"][0]
    ex.drag("tip of body 2", tuple(ex.state["tips"][1]), (base[0] + 0.3, base[1] - 1.0), steps=1)
    legible(ex)
    assert ex.message == ""
    fresh = TreeExplorer(display="agg", **ex.values)
    np.testing.assert_array_equal(fresh.state["q"], ex.state["q"])
    assert np.abs(closure_residual(ex.state["model"], ex.state["q"])).max() < 1e-9
    check_drawn_forces(ex)
    shown = dict(ex.values)
    ex.drag("tip of body 2", tuple(ex.state["tips"][1]), tuple(ex.state["tips"][0]), steps=1)
    assert "cannot be dragged onto its joint" in ex.message and ex.values == shown
    legible(ex)


def test_drag_the_tip_of_body_1_turns_the_pivot(ex):
    ex.drag("tip of body 1", tuple(ex.state["tips"][0]), (-0.5, 0.8), steps=8)
    legible(ex)
    assert ex.message == ""
    assert ex.values["body 1 angle (deg)"] == pytest.approx(np.degrees(np.arctan2(0.8, -0.5)))
    check_drawn_forces(ex)
