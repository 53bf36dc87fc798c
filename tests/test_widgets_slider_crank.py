"""SliderCrankExplorer against closed forms of the slider-crank (thesis 9.6 geometry)."""
import math

import numpy as np
import pytest

from picture_checks import elements, overlapping_labels, parts, undescribed
from planargeo.widgets.slider_crank import SliderCrankExplorer


def figure_message(ex) -> str:
    """The refusal said on the picture ("" for none)."""
    el = elements(ex.picture()).get("figure message")
    return "" if el is None else " ".join(q["text"] for q in el["parts"] if q["p"] == "text")


def arrow_direction(ex, sym):
    """The pixel direction of an edge arrow (a pole at infinity) or None."""
    arrows = parts(elements(ex.picture())[sym], "arrow")
    return None if not arrows else np.array([arrows[0]["dx"], arrows[0]["dy"]])

R, T = 2.29, 0.5
M = (0.40, 0.15, 0.30)
J = (0.1464 * 0.40 * R * R, None, 0.666 * 0.30 * T * T)


def height(psi, l):
    return R * math.sin(psi) + math.sqrt(l * l - (R * math.cos(psi)) ** 2) + T


def gen_mass(psi, l, h=1e-5):
    """Generalised mass M(ψ) = Σ m |dc/dψ|² + J (dθ/dψ)² from closed-form positions."""
    def coms(p):
        pin = np.array([R * math.cos(p), R * math.sin(p)])
        wrist = np.array([0.0, height(p, l) - T])
        beta = math.atan2(*(wrist - pin)[::-1])
        return [0.25 * pin, 0.5 * (pin + wrist), wrist + [0.0, T]], [p, beta, math.pi / 2]

    (c0, a0), (c1, a1) = coms(psi - h), coms(psi + h)
    dc = [(b - a) / (2 * h) for a, b in zip(c0, c1)]
    da = [(b - a) / (2 * h) for a, b in zip(a0, a1)]
    Jrod = 0.0866 * M[1] * l * l
    return sum(m * d @ d for m, d in zip(M, dc)) + J[0] * da[0] ** 2 + Jrod * da[1] ** 2


@pytest.fixture
def ex():
    """The explorer; the state each test leaves it in must be legible (issue #13)."""
    e = SliderCrankExplorer(display="agg")
    yield e
    pic = e.picture()
    assert overlapping_labels(pic) + undescribed(pic) == []


def test_thesis_state(ex):
    ex.set(**{"crank angle (deg)": math.degrees(0.4)})            # the thesis state (9.80, 9.86)
    r = ex.readout_values
    assert r["piston height h"] == pytest.approx(height(0.4, 5.0), rel=1e-9)
    assert r["piston height h"] == pytest.approx(5.925, abs=1e-3)        # thesis 9.86
    assert r["piston speed"] == pytest.approx(50.483, abs=1e-3)           # thesis 9.80


@pytest.mark.parametrize("deg", [-60.0, 10.0, 135.0])
def test_constant_speed_kinematics(ex, deg):
    ex.set(**{"crank angle (deg)": deg, "drive": "constant-speed", "crank speed": 12.0})
    psi, w, e = math.radians(deg), 12.0, 1e-4
    hp = (height(psi + e, 5.0) - height(psi - e, 5.0)) / (2 * e)
    hpp = (height(psi + e, 5.0) - 2 * height(psi, 5.0) + height(psi - e, 5.0)) / e ** 2
    r = ex.readout_values
    assert r["ψ̈ crank"] == pytest.approx(0.0, abs=1e-9)
    assert r["piston speed"] == pytest.approx(hp * w, rel=1e-6)
    assert r["piston acceleration"] == pytest.approx(hpp * w * w, rel=1e-4)
    # the piston only slides: its acceleration is a pure vertical translation (ideal point)
    a3 = ex.state["a"][2]
    assert a3[0] == pytest.approx(0.0, abs=1e-9) and a3[2] == pytest.approx(0.0, abs=1e-9)
    ex.set(**{"acceleration poles": True})                # drawn as an arrow at the edge, along y
    d = arrow_direction(ex, "a₃")
    assert abs(d[0]) < 1e-9 * abs(d[1]) and "at ∞" in parts(elements(ex.picture())["a₃"], "text")[0]["text"]


def test_free_crank_matches_lagrange(ex):
    ex.set(gravity=0.0, **{"crank angle (deg)": math.degrees(0.4)})
    psi, w, e = 0.4, 20.0, 1e-4
    Mp = (gen_mass(psi + e, 5.0) - gen_mass(psi - e, 5.0)) / (2 * e)
    expected = -0.5 * Mp / gen_mass(psi, 5.0) * w * w
    assert ex.readout_values["ψ̈ crank"] == pytest.approx(expected, rel=1e-5)


def test_contact_force_line_is_drawn(ex):
    F = ex.state["reactions"]["F_1"].wrench            # -F₃ on the piston (9.61)
    assert F[1] == pytest.approx(0.0, abs=1e-12)      # the slider only pushes sideways
    assert ex.readout_values["|F₃| slider bearing"] == pytest.approx(abs(F[0]))
    el = elements(ex.picture())["F₃"]
    (a,) = parts(el, "arrow")                         # drawn sideways, with its sense
    assert abs(a["dy"]) < 1e-9 and np.sign(a["dx"]) == np.sign(F[0])
    assert parts(el, "text")[0]["text"] == "F₃" and "bearing force" in el["desc"]


def test_dead_centre_and_impossible_configurations(ex):
    ex.controls["crank angle (deg)"].value = 90.0
    assert "dead centre" in ex.message and ex.readout_values["configuration"] == "top dead centre"
    assert "dead centre" in figure_message(ex)
    ex.set(**{"rod length": 2.29, "crank angle (deg)": 0.0})   # rod along the horizontal
    assert "singular" in ex.message
    assert "piston pin on the crank pivot" in ex.message       # folded: l = r at ψ = 0
    assert ex.values == ex.shown_values                        # refused: both back to the shown state
    ex.controls["crank angle (deg)"].value = 0.0
    good = dict(ex.readout_values)
    ex.controls["rod length"].value = 2.0                      # rod cannot reach
    assert "rod too short" in ex.message and "rod too short" in figure_message(ex)
    assert ex.readout_values == good and ex.values["rod length"] == 5.0
    ex.controls["rod length"].value = 4.0
    assert ex.message == ""
    assert ex.readout_values["piston height h"] == pytest.approx(height(0.0, 4.0))


def test_crank_moves_reuse_the_model_and_pole_toggles_only_redraw(ex):
    model = ex.model_for(5.0, 9.81)
    ex.controls["crank angle (deg)"].value = 40.0
    assert ex.model_for(5.0, 9.81) is model and len(ex._models) == 1
    n = ex.n_computes
    ex.controls["velocity poles"].value = True
    assert ex.n_computes == n
    # the drawn velocity poles are the link twists of the current state: the crank turns about
    # the origin at the crank speed, the piston only slides (an ideal point) at h'(ψ) ψ̇
    psi, w, e = math.radians(40.0), 20.0, 1e-5
    assert ex.state["v"][0] == pytest.approx([0.0, 0.0, w], abs=1e-12)
    els = elements(ex.picture())
    assert parts(els["v₁"], "mark")[0]["x"] == 0.0 and parts(els["v₁"], "mark")[0]["y"] == 0.0
    v3 = ex.state["v"][2]
    hp = (height(psi + e, 5.0) - height(psi - e, 5.0)) / (2 * e)
    assert v3 == pytest.approx([0.0, hp * w, 0.0], abs=1e-6)
    ex.controls["acceleration poles"].value = False
    assert ex.n_computes == n and not {"a₁", "a₂", "a₃"} & set(elements(ex.picture()))
    ex.controls["rod length"].value = 4.0                       # a new model
    assert ex.n_computes == n + 1 and len(ex._models) == 2
    assert ex.readout_values["piston height h"] == pytest.approx(height(psi, 4.0), rel=1e-9)


def test_crank_changes_build_no_model(ex, monkeypatch):
    import planargeo.widgets.slider_crank as mod

    built = []
    real = mod.slider_crank_model
    monkeypatch.setattr(mod, "slider_crank_model", lambda **k: built.append(k) or real(**k))
    for deg in (10.0, 20.0, 30.0):
        ex.controls["crank angle (deg)"].value = deg
    ex.controls["crank speed"].value = 5.0
    ex.controls["drive"].value = "constant-speed"
    assert built == []
    ex.controls["gravity"].value = 3.0
    assert len(built) == 1 and built[0]["g"] == 3.0 and built[0]["l"] == 5.0


def test_folded_dead_centre_reports_the_contact_matrix(ex):
    """l = r at ψ = 180°: the rod folds back onto the crank, the piston pin sits on the crank pivot
    (pin at (-r, 0), rod of length r along +x), so the slider's contact matrix is singular; the widget
    reports what the scene reports, with the condition of that matrix (beyond COND_LIMIT = 1e12)."""
    import re

    from planargeo import scenes
    from planargeo.errors import SingularConfigurationError

    ex.set(**{"rod length": 2.29, "crank angle (deg)": 180.0})
    assert "dead centre with the piston pin on the crank pivot" in ex.message
    assert "contact matrix" in ex.message and "singular" in ex.message
    assert "piston pin is on the crank pivot" in " ".join(figure_message(ex).split())
    cond = float(re.search(r"condition number ([0-9.e+]+)", ex.message).group(1))
    assert cond > 1e12
    with pytest.raises(SingularConfigurationError) as err:
        scenes.build("slider-crank", l=2.29, psi=math.pi)
    assert ex.message == f"{err.value} (refused: ψ₀ = 180°, rod length l = 2.29 m)"
    assert err.value.cond > 1e12


@pytest.mark.parametrize("frames", [1, 45, 90])
def test_joint_angles_read_within_half_a_turn_during_play(ex, frames):
    # the crank turns many times in Play: each joint angle reads in (−180°, 180°], and is the
    # relative turn between its bodies from the pins' positions (ψ + θ + φ = 90° on the loop, 9.6)
    for _ in range(frames // 10):
        ex.advance(10)
    ex.advance(frames % 10 or 1)
    r = ex.readout_values
    psi, h = math.radians(r["crank angle ψ"]), r["piston height h"]
    pin, wrist = np.array([R * math.cos(psi), R * math.sin(psi)]), np.array([0.0, h - T])
    rod = math.degrees(math.atan2(*(wrist - pin)[::-1]))               # the rod's direction, absolute
    for key, expected in (("rod joint angle θ", rod - r["crank angle ψ"]), ("wrist joint angle φ", 90.0 - rod)):
        assert -180.0 < r[key] <= 180.0, (key, r[key])
        assert math.remainder(r[key] - expected, 360.0) == pytest.approx(0.0, abs=1e-6), key
    assert -180.0 < r["crank angle ψ"] <= 180.0
