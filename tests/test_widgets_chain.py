"""ChainExplorer: controls drive readouts and the picture; errors become messages.

The picture is read as the page and the exports get it (``ex.picture()``: elements
found by id, e.g. ``v1``, ``f3``, ``TQ2``, ``links``); its coordinates are rounded to
1e-5 of the view, hence the drawn-position tolerances.
"""
import math

import numpy as np
import pytest

from planargeo.draw.geometry import conic_geometry, point_xy
from planargeo.errors import SingularConfigurationError
from planargeo.widgets.chain import ChainExplorer

G = 9.81
#: tolerance of a drawn coordinate (the picture's rounding)
DRAWN = 2e-4


def els(ex) -> dict:
    """``{id: element}`` of the shown picture."""
    return {e["id"]: e for e in ex.picture()["elements"]}


def chain_xy(ex) -> np.ndarray:
    """The drawn links: base, then each joint and the link's far end."""
    return np.asarray(els(ex)["links"]["parts"][0]["xy"], float)


def mark(el):
    """``(x, y)`` of an element's marker, or None (a pole drawn at the edge of the view)."""
    m = next((p for p in el["parts"] if p["p"] == "mark"), None)
    return None if m is None else np.array([m["x"], m["y"]])


def on_drawn_line(el, xy, tol=DRAWN) -> bool:
    """True when the point ``xy`` lies on the line drawn by the element (its clipped segment)."""
    a, b = (np.asarray(q, float) for q in next(p for p in el["parts"] if p["p"] == "path")["xy"])
    d = (b - a) / np.linalg.norm(b - a)
    r = np.asarray(xy, float) - a
    return abs(d[0] * r[1] - d[1] * r[0]) <= tol * (1 + np.abs(r).max())


def ids_with(ex, prefix: str) -> list[str]:
    """Ids of the picture's elements ``prefix1``, ``prefix2``... (one layer of overlays)."""
    return sorted(k for k in els(ex) if k.startswith(prefix) and k[len(prefix):].isdigit())


@pytest.fixture
def ex():
    return ChainExplorer(display="agg", links=1, speed=0.0, torque=0.0, angle=0.0)


def test_single_pendulum_matches_closed_form(ex):
    # uniform rod (m=1, L=1) pinned at one end: J_pivot = mL²/3
    for deg in (0.0, -30.0, 45.0):
        ex.controls["angle"].value = deg
        th = math.radians(deg)
        assert ex.message == ""
        assert ex.readout_values["q̈₁"] == pytest.approx(-1.5 * G * math.cos(th), rel=1e-9)
        assert ex.readout_values["potential energy (J)"] == pytest.approx(G * 0.5 * math.sin(th), abs=1e-12)
        # the tip of the drawn link is at (cos, sin)
        assert tuple(chain_xy(ex)[-1]) == pytest.approx((math.cos(th), math.sin(th)), abs=DRAWN)


def test_speed_sets_kinetic_energy_and_velocity_pole(ex):
    ex.controls["speed"].value = 2.0
    assert ex.readout_values["kinetic energy (J)"] == pytest.approx(0.5 * (1 / 3) * 4.0)
    # rotation about the pivot (0, 0) at 2 rad/s: the pole at the pivot, its rate described
    v1 = els(ex)["v1"]
    assert tuple(mark(v1)) == pytest.approx((0.0, 0.0), abs=DRAWN)
    assert "rate 2 rad/s" in v1["desc"] and "(4.5)" in v1["desc"]
    assert ids_with(ex, "v") == ["v1"]


def test_torque_enters_the_acceleration(ex):
    ex.controls["angle"].value = -90.0       # hanging: gravity gives no torque
    ex.controls["torque"].value = 2.0
    assert ex.readout_values["q̈₁"] == pytest.approx(2.0 / (1 / 3), rel=1e-9)


def test_links_and_overlays(ex):
    with ex.hold():
        ex.controls["links"].value = 6
        for k in ("acceleration poles", "bias terms", "T/U split", "articulated inertias"):
            ex.controls[k].value = True
    assert ex.readout_values["links"] == 6 and "q̈₆" in ex.readout_values
    assert ids_with(ex, "A") == [f"A{i}" for i in range(1, 7)]
    assert ids_with(ex, "f") == [f"f{i}" for i in range(1, 7)]
    # the active + reaction parts add up to the joint force (6.38)
    w, split = ex.state["w"], ex.tu_split(ex.state)
    assert split["active"] + split["reaction"] == pytest.approx(w.f, abs=1e-9)
    # the reaction part passes through its revolute joint: incidence (5.24), algebraically
    # and as drawn
    e = els(ex)
    for i in range(6):
        x, y = w.origin[i]
        r = split["reaction"][i]
        assert np.dot([y, -x, 1.0], r) == pytest.approx(0.0, abs=1e-9 * (1 + np.abs(r).max()))
        if any(p["p"] == "path" for p in e[f"Rμ{i + 1}"]["parts"]):
            assert on_drawn_line(e[f"Rμ{i + 1}"], (x, y))
    ex.controls["links"].value = 2
    assert ids_with(ex, "A") == ["A1", "A2"]
    ex.controls["articulated inertias"].value = False
    assert ids_with(ex, "A") == []


def test_joint_sets(ex):
    for js in ("prismatic", "alternating", "revolute"):
        ex.set(joints=js, links=5)
        assert ex.message == ""
        assert len([k for k in ex.readout_values if k.startswith("q̈")]) == 2


def test_error_keeps_last_drawing(ex, monkeypatch):
    ex.controls["angle"].value = 10.0
    before = chain_xy(ex)
    good = dict(ex.readout_values)

    def boom(*a, **k):
        raise SingularConfigurationError("joint 0: singular on purpose", 1e17)

    monkeypatch.setattr(ex, "compute", boom)
    ex.controls["angle"].value = 20.0            # must not raise
    assert "singular on purpose" in ex.message
    assert ex.readout_values == good
    assert np.array_equal(chain_xy(ex), before)
    monkeypatch.undo()
    ex.controls["angle"].value = 30.0            # and it keeps working
    assert ex.message == ""
    assert ex.readout_values["q̈₁"] == pytest.approx(-1.5 * G * math.cos(math.radians(30)))


def test_simulation_conserves_energy_and_animates():
    ex = ChainExplorer(display="agg", links=3, speed=0.5, torque=0.0, fps=20)
    e0 = ex.readout_values["total energy (J)"]
    assert ex.simulate(0.5) == pytest.approx(0.5)
    assert ex.message == ""
    ex.controls["time (s)"].value = 0.5
    assert ex.readout_values["t (s)"] == pytest.approx(0.5)
    assert ex.readout_values["energy drift (J)"] == pytest.approx(0.0, abs=1e-6 * max(1.0, abs(e0)))
    assert ex.readout_values["total energy (J)"] == pytest.approx(e0, abs=1e-6 * max(1.0, abs(e0)))
    # changing the initial state starts again at t = 0
    ex.controls["speed"].value = 0.0
    assert ex.values["time (s)"] == 0.0 and ex.readout_values["t (s)"] == 0.0


def test_reset_and_export(tmp_path):
    ex = ChainExplorer(display="agg", export_dir=tmp_path)
    ex.set(links=7, angle=50.0)
    ex.reset()
    assert ex.values == ex.defaults and ex.readout_values["links"] == 4
    p = ex.export_svg()
    assert p.exists() and p.read_text().lstrip().startswith("<?xml")
    ex._export_clicked()
    assert "saved" in ex.export_label.value


def test_image_mode_updates_png():
    ex = ChainExplorer(display="image", links=2)
    a = ex.image.value
    ex.controls["angle"].value = 60.0
    assert ex.image.value[:8] == b"\x89PNG\r\n\x1a\n" and ex.image.value != a


def test_active_part_hidden_without_torque_shown_with_it():
    ex = ChainExplorer(display="agg", links=3, torque=0.0, **{"T/U split": True})
    # no joint torque: Q = sᵀf = τ = 0, the joint force is pure reaction
    assert ids_with(ex, "TQ") == []
    assert ids_with(ex, "Rμ") == ["Rμ1", "Rμ2", "Rμ3"]
    ex.controls["torque"].value = 5.0
    assert ids_with(ex, "TQ") == ["TQ1", "TQ2", "TQ3"]
    # the active part lies on the percussion axis: its moment about the joint is Q = τ
    w, split = ex.state["w"], ex.tu_split(ex.state)
    for i in range(3):
        x, y = w.origin[i]
        assert np.dot([y, -x, 1.0], split["active"][i]) == pytest.approx(5.0)
        assert "(6.38)" in els(ex)[f"TQ{i + 1}"]["desc"]


def test_torque_on_one_joint_only():
    ex = ChainExplorer(display="agg", links=3, speed=0.0, torque=0.0, gravity=False)
    assert ex.readout_values["q̈₁"] == pytest.approx(0.0, abs=1e-12)
    ex.set(torque=2.0, **{"torque on": "last joint"})
    # only the tip joint is driven; at rest without gravity the only external load is the
    # base pin, which carries no moment about the origin (τ1 = 0): Σ (I_i a_i)_z = 0
    w = ex.state["w"]
    assert np.array(w.tau) == pytest.approx([0.0, 0.0, 2.0])
    assert ex.readout_values["q̈₃"] > 0
    moment = sum((w.I[i] @ w.a[i])[2] for i in range(3))
    assert moment == pytest.approx(0.0, abs=1e-9)
    ex.controls["torque on"].value = "first joint"
    assert np.array(ex.state["w"].tau) == pytest.approx([2.0, 0.0, 0.0])


def test_per_joint_lists_override_the_patterns():
    ex = ChainExplorer(display="agg", links=2, gravity=False, speed=0.0, torque=0.0)
    ex.set(**{"joint values (deg / m)": "90, -90", "joint speeds": "0, 0", "joint torques": "0, 1"})
    w = ex.state["w"]
    assert w.q == pytest.approx([math.pi / 2, -math.pi / 2])
    # the tip of link 2 is at (1, 1): link 1 points up, link 2 turns back to +x
    assert tuple(chain_xy(ex)[-1]) == pytest.approx((1.0, 1.0), abs=DRAWN)
    assert np.array(w.tau) == pytest.approx([0.0, 1.0])
    good = dict(ex.readout_values)
    ex.controls["joint torques"].value = "0, one"
    assert "joint torques must be numbers" in ex.message and ex.readout_values == good
    ex.controls["joint torques"].value = ""
    assert ex.message == "" and np.array(ex.state["w"].tau) == pytest.approx([0.0, 0.0])


# ----------------------------------------------------------------- T/U split of the accelerations
def _hand_two_link(q, qd, tau, g=G):
    """Two uniform unit links (m = 1, L = 1, J = 1/12) on revolute joints, by hand.

    Returns joint points p_i, unit twists s_i = [p_y, -p_x, 1], body accelerations
    a_i = Σ_{j≤i} (s_j q̈_j + ṡ_j q̇_j) from the double pendulum's Lagrange equations
    H q̈ + h + G = τ (derived by hand below), and the spatial inertias at the origin
    I = [[m, 0, -m c_y], [0, m, m c_x], [-m c_y, m c_x, J + m|c|²]].
    """
    th1, th2 = q[0], q[0] + q[1]
    p = [np.zeros(2), np.array([math.cos(th1), math.sin(th1)])]
    c = [0.5 * p[1], p[1] + 0.5 * np.array([math.cos(th2), math.sin(th2)])]
    pdot = [np.zeros(2), qd[0] * np.array([-math.sin(th1), math.cos(th1)])]
    s = [np.array([pi[1], -pi[0], 1.0]) for pi in p]
    sdot = [np.array([pd[1], -pd[0], 0.0]) for pd in pdot]
    # Lagrange, links of length L = 1, centre c = 1/2, I_o = J + m c² = 1/3 about their joints:
    # T = ½ I_o q̇1² + ½ [I_o (q̇1 + q̇2)² + m L² q̇1² + 2 m L c cos q2 q̇1 (q̇1 + q̇2)],
    # V = m g (c sin th1) + m g (L sin th1 + c sin th2)
    Io, mLc = 1 / 12 + 0.25, 0.5
    c2, s2 = math.cos(q[1]), math.sin(q[1])
    H = np.array([[2 * Io + 1.0 + 2 * mLc * c2, Io + mLc * c2], [Io + mLc * c2, Io]])
    h = np.array([-mLc * s2 * (2 * qd[0] * qd[1] + qd[1] ** 2), mLc * s2 * qd[0] ** 2])
    G = g * np.array([1.5 * math.cos(th1) + 0.5 * math.cos(th2), 0.5 * math.cos(th2)])
    qdd = np.linalg.solve(H, np.asarray(tau, float) - h - G)
    a1 = s[0] * qdd[0] + sdot[0] * qd[0]
    a2 = a1 + s[1] * qdd[1] + sdot[1] * qd[1]
    I = [np.array([[1.0, 0.0, -ci[1]], [0.0, 1.0, ci[0]], [-ci[1], ci[0], 1 / 12 + ci @ ci]]) for ci in c]
    return p, s, [a1, a2], I, qdd


def test_acceleration_split_matches_hand_formulas():
    q, qd, tau = np.array([0.4, -0.9]), np.array([1.3, -0.6]), np.array([2.0, -1.0])
    ex = ChainExplorer(display="agg", links=2, gravity=True,
                       **{"joint values (deg / m)": f"{math.degrees(q[0])}, {math.degrees(q[1])}",
                          "joint speeds": "1.3, -0.6", "joint torques": "2, -1", "T/U split": True})
    assert ex.message == ""
    p, s, a, I, qdd = _hand_two_link(q, qd, tau)
    assert ex.readout_values["q̈₁"] == pytest.approx(qdd[0], rel=1e-9)
    # articulated inertias (3.38): the last body is rigid; the first adds the second projected
    A2 = I[1]
    A1 = I[0] + A2 - np.outer(A2 @ s[1], A2 @ s[1]) / (s[1] @ A2 @ s[1])
    for i, A in enumerate((A1, A2)):
        T = A @ s[i] / (s[i] @ A @ s[i])                                        # (6.36)
        R = np.array([[1.0, 0.0], [0.0, 1.0], [-p[i][1], p[i][0]]])            # forces through p_i
        Ainv_R = np.linalg.solve(A, R)
        U = Ainv_R @ np.linalg.inv(R.T @ Ainv_R)                                 # (6.37), (6.45)
        psi, gamma = T @ a[i], R.T @ a[i]                                        # (6.100), (6.101)
        split = ex.tu_split(ex.state)
        motion, reactive = split["motion"][i], split["reactive"][i]
        assert {f"sψ{i + 1}", f"Uγ{i + 1}"} <= set(els(ex))
        drawn = mark(els(ex)[f"sψ{i + 1}"])        # the motion part's pole, where drawn: at the joint
        if drawn is not None:
            assert tuple(drawn) == pytest.approx(tuple(p[i]), abs=DRAWN)
        assert motion == pytest.approx(s[i] * psi, abs=1e-9)
        assert reactive == pytest.approx(U @ gamma, abs=1e-9)
        assert motion + reactive == pytest.approx(a[i], abs=1e-9)               # (6.44)
        # the motion part is a rotation about the joint; the reactive part has no ψ (Tᵀ U = 0)
        assert T @ reactive == pytest.approx(0.0, abs=1e-9)
        # the force split: sᵀ (T Q) = Q is the joint torque (6.49)
        assert s[i] @ split["active"][i] == pytest.approx(tau[i], rel=1e-9)
    assert ids_with(ex, "sψ") == ["sψ1", "sψ2"] and ids_with(ex, "Uγ") == ["Uγ1", "Uγ2"]


def test_split_is_hidden_when_off_and_derived_once():
    ex = ChainExplorer(display="agg", links=3, torque=1.0)
    assert not any(ids_with(ex, k) for k in ("TQ", "Rμ", "sψ", "Uγ"))
    assert "split" not in ex.state
    n = ex.n_computes
    ex.controls["T/U split"].value = True                      # drawing only: no recompute
    assert len(ids_with(ex, "sψ")) == 3 and len(ids_with(ex, "Rμ")) == 3   # drawn (agg: when asked)
    assert ex.n_computes == n and "split" in ex.state
    split = ex.state["split"]
    ex.controls["T/U split"].value = False
    ex.controls["T/U split"].value = True
    ids_with(ex, "sψ")
    assert ex.state["split"] is split and ex.n_computes == n
    ex.controls["angle"].value = 10.0                          # physics: recomputed
    ids_with(ex, "sψ")
    assert ex.n_computes == n + 1 and ex.state["split"] is not split


@pytest.mark.parametrize("overlay", ["velocity poles", "acceleration poles", "bias terms",
                                     "internal forces", "articulated inertias"])
def test_overlay_toggles_do_not_recompute_and_draw_the_state(overlay):
    ex = ChainExplorer(display="agg", links=3, speed=1.0, torque=0.5,
                       **{k: False for k in ("velocity poles", "internal forces")})
    calls = []
    real = ex.compute
    ex.compute = lambda v, changed: calls.append(changed) or real(v, changed)
    ex.controls[overlay].value = True
    assert calls == []
    w = ex.state["w"]
    prefix, data = {"velocity poles": ("v", w.v), "acceleration poles": ("a", w.a),
                    "bias terms": ("p", w.p), "internal forces": ("f", w.f),
                    "articulated inertias": ("A", w.A)}[overlay]
    assert ids_with(ex, prefix) == [f"{prefix}{i}" for i in (1, 2, 3)]
    e = els(ex)
    for i in range(3):      # each drawn where the state's own value puts it
        el = e[f"{prefix}{i + 1}"]
        if overlay.endswith("poles"):
            xy = point_xy(data[i])
            if mark(el) is not None:
                assert tuple(mark(el)) == pytest.approx(tuple(xy), abs=DRAWN)
        elif overlay == "articulated inertias":
            ell = next(p for p in el["parts"] if p["p"] == "ellipse")
            A = conic_geometry(data[i])["affine"]
            assert [ell["x"], ell["y"]] == pytest.approx(list(A[:2, 2]), abs=DRAWN)
            assert ell["m"] == pytest.approx([A[0, 0], A[0, 1], A[1, 0], A[1, 1]], abs=DRAWN)
        else:
            fx, fy, tz = data[i]
            foot = np.array([fy * tz, -fx * tz]) / (fx * fx + fy * fy)   # the line's point nearest 0
            assert on_drawn_line(el, foot)


def test_play_drives_the_time():
    ex = ChainExplorer(display="agg", links=2, speed=1.0, torque=0.0, fps=10)
    qs = []
    for k in range(5):                       # what Play does while it runs: the time 0.1 s further
        if k:
            ex.advance(1)
        assert ex.values["time (s)"] == pytest.approx(0.1 * k)
        assert ex.readout_values["t (s)"] == pytest.approx(0.1 * k)
        qs.append(chain_xy(ex))
    assert not np.allclose(qs[0], qs[-1])                      # the links moved
    ex.player.value = 0.2                                      # the slider: the same state as Play's
    np.testing.assert_allclose(chain_xy(ex), qs[2], rtol=0, atol=1e-12)
    ex.controls["speed"].value = 0.0                         # a new initial state: back to t = 0
    assert ex.player.value == 0
