"""SliderCrankExplorer (#14 item 4): pin and bearing forces at their joints against a hand Newton–Euler
reference, Play through simulate_loops against a one-coordinate integration, dead centres by name,
drags (refused ones keep the last good state), units, round-off as 0, legibility of every state visited."""
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import _slider_crank_reference as ref
from picture_checks import elements, overlapping_labels, parts, shown_labels, undescribed
from planargeo.widgets.slider_crank import SliderCrankExplorer

G = 9.81


def legible(ex):
    """Every state a test visits must be legible (issue #13): no two labels overlap, every element described."""
    pic = ex.picture()
    problems = overlapping_labels(pic) + undescribed(pic)
    assert problems == [], problems
    return ex


def kx(pic) -> float:
    """Pixels per metre of a picture."""
    x0, x1, _y0, _y1 = pic["box"]
    return (pic["size"][0] - pic["margin"][0] - pic["margin"][1]) / (x1 - x0)


def drawn_force(ex, sym):
    """``(force, foot, tol)`` as drawn: the arrow's vector read back at the picture's scale (the largest force
    of the readout is FORCE_LENGTH m long), the arrow's middle, and the force of 0.015 px (pixels are kept to
    0.01)."""
    from planargeo.draw.pictures.slider_crank import FORCE_LENGTH

    pic = ex.picture()
    (a,) = parts(elements(pic)[sym], "arrow")
    fmax = max(ex.readout_values[k] for k in ("|f₁| crank pivot", "|f₂| crank pin", "|f₃| wrist pin",
                                               "|F₃| slider bearing"))
    vec = np.array([a["dx"], a["dy"]]) / kx(pic)
    return (vec * fmax / FORCE_LENGTH, np.array([a["x"], a["y"]]) + vec / 2,
            0.015 / kx(pic) * fmax / FORCE_LENGTH)


def banner(ex) -> str:
    el = elements(ex.picture()).get("banner")
    return "" if el is None else el["parts"][0]["text"]


@pytest.fixture
def ex():
    return legible(SliderCrankExplorer(display="agg"))


def hand_reactions(psi, psidot, drive="free"):
    """Pin forces f₁, f₂, f₃ and the bearing force by Newton–Euler on each body, from the piston inwards.

    The accelerations come from the reference's own multiplier solve (plain trigonometry); the bearing's
    force is its multiplier ξ (9.90): ``-F₃ = -B₃ ξ`` acts on the piston, so ``f₃ = m₃ (c̈₃ - g) + F₃``,
    ``f₂ = f₃ + m₂ (c̈₂ - g)``, ``f₁ = f₂ + m₁ (c̈₁ - g)`` (forces only)."""
    r = ref.reference(psi, psidot, drive=drive)
    q, qd, qdd = r["q"], r["qd"], r["qdd"]
    segs = ref._segments(ref.R, ref.L, ref.T)
    cdd = []
    for key in ("c1", "c2", "c3"):
        Jc = ref.complex_step_jacobian(lambda x: ref._point(segs[key], x), q)
        cdd.append(Jc @ qdd + ref._point_bias(segs[key], q, qd))
    g = np.array([0.0, -G])
    F3 = r["F3"][:2]
    f3 = ref.M[2] * (cdd[2] - g) + F3
    f2 = f3 + ref.M[1] * (cdd[1] - g)
    f1 = f2 + ref.M[0] * (cdd[0] - g)
    return {"f_1": f1, "f_2": f2, "f_3": f3, "F_1": -F3}, r


def readout_matches_hand(ex, psi, psidot, drive="free"):
    hand, r = hand_reactions(psi, psidot, drive)
    scale = max(np.abs(v).max() for v in hand.values())
    for sym, key in (("f_1", "|f₁| crank pivot"), ("f_2", "|f₂| crank pin"), ("f_3", "|f₃| wrist pin"),
                     ("F_1", "|F₃| slider bearing")):
        assert ex.readout_values[key] == pytest.approx(np.hypot(*hand[sym]), abs=1e-10 * scale), key
        # the drawn arrow is that force, at its joint
        drawn, _foot, tol = drawn_force(ex, {"f_1": "f₁", "f_2": "f₂", "f_3": "f₃", "F_1": "F₃"}[sym])
        np.testing.assert_allclose(drawn, hand[sym], rtol=0, atol=tol, err_msg=sym)
    assert ex.readout_values["drive torque Q₁"] == pytest.approx(r["tau_drive"][0], abs=1e-10 * scale)
    return scale


@pytest.mark.parametrize("deg, speed, drive", [(math.degrees(0.4), 20.0, "free"), (-60.0, 12.0, "free"),
                                               (135.0, -8.0, "constant-speed"), (10.0, 30.0, "constant-speed")])
def test_pin_and_bearing_forces_match_hand_newton_euler(ex, deg, speed, drive):
    legible(ex.set(**{"crank angle (deg)": deg, "crank speed": speed, "drive": drive}))
    readout_matches_hand(ex, math.radians(deg), speed, drive)


def test_every_force_is_labelled_with_its_thesis_symbol_and_drawn_at_its_joint(ex):
    texts = [t for _id, t in shown_labels(ex.picture())]
    for sym in ("f₁", "f₂", "f₃", "F₃"):
        assert sym in texts, sym
    sol = ex.state["sol"]
    pose = sol.data.pose
    # free pins: the line of action passes through the pin, the arrow sits on it
    for sym, P in (("f₁", (0.0, 0.0)), ("f₂", pose[1, :2]), ("f₃", pose[2, :2])):
        np.testing.assert_allclose(drawn_force(ex, sym)[1], P, atol=1e-4)
    # the bearing carries a couple: its line is offset from the contact point by couple / force, and a
    # dotted lever arm joins them
    F = sol.reaction("F_1")
    _f, foot, _tol = drawn_force(ex, "F₃")
    lever = np.array(parts(elements(ex.picture())["F₃ lever"], "path")[0]["xy"])
    np.testing.assert_allclose(lever[1], foot, atol=1e-4)
    assert np.hypot(*(lever[1] - lever[0])) == pytest.approx(abs(F.moment) / F.force, abs=1e-4)
    assert ex.readout_values["bearing couple"] == pytest.approx(F.moment)
    for lab in ("1", "2", "3", "ψ", "θ", "φ"):
        assert lab in texts, lab
    ex.set(**{"reaction forces": False})
    assert not set(elements(ex.picture())) & {"f₁", "f₂", "f₃", "F₃"}
    legible(ex)


def test_units_on_every_readout_value(ex):
    assert set(ex.readout_values) <= set(ex.units)
    assert ex.readout_strings["piston height h"].endswith(" m")
    assert ex.readout_strings["|f₂| crank pin"].endswith(" N")


def _reference_psi(psi0, psidot0, t_end):
    """ψ(t) of the free crank by the reference's one-coordinate dynamics (the multiplier solve), tight tolerances."""
    def rhs(_t, y):
        return [y[1], ref.reference(y[0], y[1])["qdd"][0]]

    sol = solve_ivp(rhs, (0.0, t_end), [psi0, psidot0], method="DOP853", rtol=1e-11, atol=1e-12)
    return sol.y[0, -1], sol.y[1, -1]


def test_play_free_crank_follows_the_reference_and_keeps_energy(ex):
    n = 12
    ex.advance(n)
    legible(ex)
    t = ex.readout_values["t"]
    assert t == pytest.approx(n * ex.play_dt) and ex.play_dt == pytest.approx(ex.time_scale / ex.play_fps)
    psi, psidot = _reference_psi(math.radians(23.0), 20.0, t)
    shown = math.radians(ex.readout_values["crank angle ψ"])
    assert math.remainder(shown - psi, 2 * math.pi) == pytest.approx(0.0, abs=1e-6)
    assert ex.readout_values["crank speed ψ̇"] == pytest.approx(psidot, abs=1e-5)
    assert abs(ex.readout_values["energy drift ΔE/E₀"]) < 1e-7
    assert ex.readout_values["closure drift"] < 1e-9
    assert ex.readout_strings["closure drift"] == "0 m"           # round-off shown as 0
    # and the forces of the frame shown are the hand Newton–Euler forces of that state
    readout_matches_hand(ex, shown, ex.readout_values["crank speed ψ̇"])


def test_play_names_the_dead_centres_as_the_crank_passes(ex):
    ex.set(**{"crank angle (deg)": 85.0, "crank speed": 40.0})
    assert ex.readout_values["last dead centre passed"] == "none yet"
    seen, banners = [], set()
    for _ in range(60):
        ex.advance(1)
        seen.append(ex.readout_values["last dead centre passed"])
        banners.add(banner(ex))
        legible(ex)
        if seen[-1].startswith("bottom"):
            break
    names = [s.split(" at ")[0] for s in seen if s != "none yet"]
    assert names[0] == "top dead centre" and names[-1] == "bottom dead centre"
    assert "passing top dead centre" in banners and "passing bottom dead centre" in banners
    assert ex.message == ""                          # passing is reported, not an error


def test_dead_centre_shown_at_rest_by_name(ex):
    ex.set(**{"crank angle (deg)": -90.0})
    assert ex.readout_values["configuration"] == "bottom dead centre"
    assert banner(ex) == "at bottom dead centre" and "bottom dead centre" in ex.message


def test_play_driven_crank_keeps_its_speed_and_reports_the_drive(ex):
    ex.set(drive="constant-speed", **{"crank speed": 15.0})
    ex.advance(8)
    legible(ex)
    assert ex.readout_values["crank speed ψ̇"] == pytest.approx(15.0, abs=1e-9)
    assert ex.readout_values["ψ̈ crank"] == 0.0
    assert "drive does work" in ex.readout_values["energy drift ΔE/E₀"]
    readout_matches_hand(ex, math.radians(ex.readout_values["crank angle ψ"]), 15.0, "constant-speed")


def test_drag_the_crank_pin(ex):
    start = tuple(ex.state["sol"].data.pose[1, :2])
    ex.drag("crank pin", start, (-1.0, 2.0), steps=6)
    legible(ex)
    assert ex.message == ""
    assert ex.values["crank angle (deg)"] == pytest.approx(math.degrees(math.atan2(2.0, -1.0)))
    assert ex.readout_values["t"] == 0.0                               # a new initial state
    readout_matches_hand(ex, math.atan2(2.0, -1.0), 20.0)


def test_drag_the_piston_and_a_refused_drag(ex):
    wrist = tuple(ex.state["sol"].data.pose[2, :2])
    ex.drag("piston", wrist, (0.0, 4.0), steps=4)
    legible(ex)
    pin = ex.state["sol"].data.pose[1, :2]
    assert ex.state["sol"].data.pose[2, 1] == pytest.approx(4.0, abs=1e-9)
    assert np.hypot(*pin) == pytest.approx(ref.R) and pin[0] > 0          # the crank kept its side
    shown = dict(ex.values)
    ex.drag("piston", (0.0, 4.0), (0.0, 8.5), steps=1)                      # beyond l + r = 7.29
    legible(ex)
    assert "cannot reach height" in ex.message and "drag of piston refused" in ex.message
    assert ex.values == shown and ex.state["sol"].data.pose[2, 1] == pytest.approx(4.0, abs=1e-9)


def test_a_short_rod_is_refused_and_the_last_state_kept(ex):
    ex.set(**{"rod length": 1.5, "crank angle (deg)": 80.0})
    legible(ex)
    assert ex.message == ""
    shown = dict(ex.values)
    ex.drag("crank pin", tuple(ex.state["sol"].data.pose[1, :2]), (2.29, 0.0), steps=1)
    assert "rod too short" in ex.message and ex.values == shown
    legible(ex)
    # a drag that gets there in steps keeps the last step that could be assembled: controls, figure and
    # readout show that one state
    ex.drag("crank pin", tuple(ex.state["sol"].data.pose[1, :2]), (2.29, 0.0), steps=4)
    assert "rod too short" in ex.message
    psi = math.radians(ex.values["crank angle (deg)"])
    assert ex.values == ex.shown_values and ref.R * math.cos(psi) <= 1.5
    assert ex.readout_values["crank angle ψ"] == pytest.approx(ex.values["crank angle (deg)"])
    crank = parts(elements(ex.picture())["crank"], "path")[0]["xy"]
    np.testing.assert_allclose(crank[1], ref.R * np.array([math.cos(psi), math.sin(psi)]), atol=1e-4)
    legible(ex)


def test_play_with_every_overlay_stays_legible(ex):
    ex.set(**{"velocity poles": True, "acceleration poles": True, "key": True})
    for _ in range(6):
        legible(ex.advance(2))
    els = elements(ex.picture())
    assert all(f"{k}{i}" in els for k in "va" for i in "₁₂₃")


def test_the_key_leaves_the_piston_uncovered():
    # the key goes to the corner where least is drawn, a body's area counting (not only its outline):
    # the piston stands in the middle of the upper half, where a key half the figure wide covered it
    pic = SliderCrankExplorer(display="agg", key=True).picture()
    by_id = {e["id"]: e for e in pic["elements"]}

    def box(el):
        xy = np.concatenate([np.asarray(q["xy"], float) for q in el["parts"] if "xy" in q])
        return xy.min(0), xy.max(0)

    if "below" in pic:      # no corner has room: the key is under the plot, outside it, the piston named
        assert "key panel" not in by_id and any("piston" in b["text"] for b in pic["below"])
        return
    (k0, k1), (p0, p1) = box(by_id["key panel"]), box(by_id["piston"])
    assert (p1 < k0).any() or (k1 < p0).any(), "the key panel covers the piston"
