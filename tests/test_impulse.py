"""Impulses on a body at rest (planargeo.mechanics.impulse, scene ``impulse``) against closed forms and momentum.

References: a uniform rod (and the door, a rod of width w) pivoted at one end, by hand:
``J_P = m (4L² + w²)/12``, ``ω = J d / J_P``, reaction ``J (m d L / (2 J_P) − 1)`` (``J (3d/(2L) − 1)`` as
``w → 0``), centre of percussion ``2L/3 + w²/(6L)``, apparent masses ``J_P / d²`` (held) and
``1 / (1/m + (d − L/2)²/J_c)`` (free); for the bat, the impulse–momentum balance with the mass,
centre and moment of its outline integrated here by the shoelace formulas.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from planargeo import scenes
from planargeo.errors import DegenerateGeometryError, SceneError, SingularConfigurationError
from planargeo.mechanics.impulse import apparent_mass, centre_of_percussion, impulse_response
from planargeo.scenes.impulse import BODIES

L, W = 0.9, 0.04                         # the door


def door_closed_forms(m, d, J=1.0):
    Jc = m * (L * L + W * W) / 12
    JP = Jc + m * (L / 2) ** 2
    omega = J * d / JP
    return dict(Jc=Jc, JP=JP, omega=omega, reaction=J * (m * d * L / (2 * JP) - 1),
                cop=2 * L / 3 + W * W / (6 * L), held=JP / d ** 2 if d else math.inf,
                free=1.0 / (1.0 / m + (d - L / 2) ** 2 / Jc))


@pytest.mark.parametrize("m", [0.5, 3.0, 20.0])
@pytest.mark.parametrize("d", [0.1, 0.3, 0.6, 0.6002962962962963, 0.85])
def test_door_struck_across_against_the_rod_closed_forms(m, d):
    q = scenes.build("impulse", body="door", m=m, x=d, angle_deg=90.0, J=1.0).quantities
    ref = door_closed_forms(m, d)
    assert q["omega"] == pytest.approx(ref["omega"], rel=1e-12)
    assert q["reaction_across"] == pytest.approx(ref["reaction"], rel=1e-10, abs=1e-13)
    assert q["reaction_along"] == pytest.approx(0.0, abs=1e-13)
    assert q["centre_of_percussion"] == pytest.approx([ref["cop"], 0.0], rel=1e-12, abs=1e-15)
    assert q["apparent_mass_held"] == pytest.approx(ref["held"], rel=1e-12)
    assert q["apparent_mass_free"] == pytest.approx(ref["free"], rel=1e-12)
    assert q["pole"] == [0.0, 0.0]                        # held: it turns about the hinge
    assert q["kinetic_energy"] == pytest.approx(0.5 * ref["JP"] * ref["omega"] ** 2, rel=1e-12)


def test_body_inertia_kept_per_outline_and_mass_follows_every_change():
    """The scene keeps each body's inertia per (outline, mass): after changes of body and mass each
    door still meets its closed forms, the bat its polygon's inertia, and the kept matrix is read-only."""
    from shapely.geometry import Polygon

    from planargeo.screws.inertia import Inertia

    for body, m in (("door", 3.0), ("bat", 3.0), ("door", 0.5), ("bat", 0.9), ("door", 3.0)):
        r = scenes.build("impulse", body=body, m=m, x=0.6, angle_deg=90.0, J=1.0)
        if body == "door":
            ref = door_closed_forms(m, 0.6)
            assert r.quantities["omega"] == pytest.approx(ref["omega"], rel=1e-12)
            assert r.quantities["rho"] == pytest.approx(math.sqrt(ref["Jc"] / m), rel=1e-12)
        else:
            unit = Inertia.from_polygon(Polygon(BODIES["bat"]))
            assert np.allclose(r.extra["I"], unit.matrix * (m / float(unit.mass)), rtol=1e-14, atol=0.0)
        with pytest.raises(ValueError):
            r.extra["I"][0, 0] = 1.0


def test_thin_rod_limit_3d_over_2L():
    """w → 0: reaction J (3d/(2L) − 1), zero at d = 2L/3 (the brief's hand derivation)."""
    m, d = 2.0, 0.3
    ref = door_closed_forms(m, d)
    assert ref["reaction"] == pytest.approx(3 * d / (2 * L) - 1, rel=2e-3)
    q = scenes.build("impulse", body="door", m=m, x=ref["cop"]).quantities
    assert abs(q["reaction_across"]) < 1e-13 and np.allclose(q["reaction"], 0.0, atol=1e-13)
    assert q["pole_if_free"] == pytest.approx([0.0, 0.0], abs=1e-12)   # free, it would turn about the hinge


def test_oblique_blow_reaction_along_the_door_takes_the_whole_along_component():
    m, d, a = 2.0, 0.5, 30.0
    q = scenes.build("impulse", body="door", m=m, x=d, angle_deg=a, J=2.0).quantities
    ref = door_closed_forms(m, d, J=2.0 * math.sin(math.radians(a)))
    assert q["reaction_along"] == pytest.approx(-2.0 * math.cos(math.radians(a)), rel=1e-12)
    assert q["reaction_across"] == pytest.approx(ref["reaction"], rel=1e-10)


def shoelace(poly):
    """Area, centroid, polar moment about the centroid of a simple polygon (unit density)."""
    p = np.asarray(poly, float)
    x, y = p[:, 0], p[:, 1]
    x1, y1 = np.roll(x, -1), np.roll(y, -1)
    cr = x * y1 - x1 * y
    A = cr.sum() / 2
    cx = ((x + x1) * cr).sum() / (6 * A)
    cy = ((y + y1) * cr).sum() / (6 * A)
    Ixx = ((y * y + y * y1 + y1 * y1) * cr).sum() / 12
    Iyy = ((x * x + x * x1 + x1 * x1) * cr).sum() / 12
    return A, np.array([cx, cy]), Ixx + Iyy - A * (cx * cx + cy * cy)


@pytest.mark.parametrize("support", ["held", "free"])
@pytest.mark.parametrize("x, y, a, J", [(0.55, 0.0, 90.0, 1.0), (0.7, 0.02, 60.0, 3.0), (0.2, -0.1, 170.0, 0.4),
                                         (-0.05, 0.0, 45.0, 1.0)])
def test_bat_impulse_momentum_balance(support, x, y, a, J):
    """m Δv_c = ĵ + ĵ_R and J_c Δω = moments about c of the blow and of the grip's reaction (at the grip)."""
    m = 0.9
    A, c, Jc = shoelace(BODIES["bat"])
    Jc *= m / A
    q = scenes.build("impulse", body="bat", support=support, m=m, x=x, y=y, angle_deg=a, J=J).quantities
    e = J * np.array([math.cos(math.radians(a)), math.sin(math.radians(a))])
    R = np.array(q["reaction_force"])
    np.testing.assert_allclose(q["com"], c, atol=1e-12)
    np.testing.assert_allclose(m * np.array(q["v_com"]), e + R, atol=1e-12 * J)
    moment = (x - c[0]) * e[1] - (y - c[1]) * e[0] + (0 - c[0]) * R[1] - (0 - c[1]) * R[0]
    assert Jc * q["omega"] == pytest.approx(moment, abs=1e-12 * J)
    assert q["reaction"][2] == pytest.approx(0.0, abs=1e-12 * J)         # the reaction acts through the grip
    if support == "free":
        assert R @ R == 0.0 and q["pole"] == q["pole_if_free"]
        assert q["apparent_mass"] == q["apparent_mass_free"]
    else:
        np.testing.assert_allclose(q["v_grip"], 0.0, atol=1e-15)


def test_blow_through_the_grip_has_infinite_apparent_mass_when_held():
    q = scenes.build("impulse", x=0.0, y=0.0, angle_deg=30.0).quantities
    assert q["apparent_mass_held"] is None and q["omega"] == 0.0
    np.testing.assert_allclose(q["reaction_force"], [-math.cos(math.pi / 6), -0.5], atol=1e-15)
    I = np.array(q["I"])
    assert apparent_mass(I, q["impulse"], [0.0, 0.0, 1.0]) == math.inf


def test_functions_refuse_bad_input_by_name():
    from planargeo.screws.twists import inertia_matrix
    I = inertia_matrix(3.0, [1.0, 0.0], 1.0)
    with pytest.raises(DegenerateGeometryError, match="line must be a force line"):
        apparent_mass(I, [0.0, 0.0, 1.0])
    with pytest.raises(DegenerateGeometryError, match="pivot must differ from the centre of mass"):
        centre_of_percussion(I, (1.0, 0.0))
    with pytest.raises(SingularConfigurationError):
        impulse_response(inertia_matrix(1.0, [1.0, 0.0], 0.0), [0.0, 1.0, 0.0], [0.0, -1.0, 1.0])
    with pytest.raises(SceneError, match="^J must be non-zero"):
        scenes.build("impulse", J=0.0)
    with pytest.raises(SceneError, match="^body must be 'bat' or 'door'"):
        scenes.build("impulse", body="club")


@pytest.mark.parametrize("theta", np.linspace(0.0, math.pi, 7))
def test_apparent_mass_of_an_articulated_inertia_figure_3_3(theta):
    """Figure 3.3 in the plane: a slider (m) in a slot along x of a disc (m), both centred at the origin and
    free.  By hand its articulated inertia is diag(m, 2m, J_S + J_B) (the slot passes the disc's y-force and
    couple on); the apparent mass through the centre is 1 / (cos²θ/m + sin²θ/(2m)): m along, 2m across."""
    m, JS, JB = 1.5, 0.02, 0.3
    A = np.diag([m, 2 * m, JS + JB])
    line = [math.cos(theta), math.sin(theta), 0.0]
    ref = 1.0 / (math.cos(theta) ** 2 / m + math.sin(theta) ** 2 / (2 * m))
    assert apparent_mass(A, line) == pytest.approx(ref, rel=1e-12)
    assert apparent_mass(A, np.multiply(line, -3.0)) == pytest.approx(ref, rel=1e-12)   # any multiple


_BLOWS = [(0.0, 1.0, 0.55), (0.6, -0.8, 0.3), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (-3.0, 4.0, -1.2),
          (5e-320, 0.0, 1e-320), (0.0, 1e300, 9e299), (2.0 ** 600, -(2.0 ** 599), 0.0)]


def _bits(a) -> bytes:
    return np.asarray(a, dtype=float).tobytes()


@pytest.mark.parametrize("held", [True, False])
@pytest.mark.parametrize("body", list(BODIES))
def test_struck_body_answers_many_blows_as_the_one_blow_functions_bit_for_bit(body, held):
    """A body inverted once (StruckBody) gives, blow after blow, exactly the bits of impulse_response and
    apparent_mass, which check and invert the inertia anew each call; the door meets its closed forms."""
    from planargeo.mechanics.impulse import StruckBody

    I = np.asarray(scenes.build("impulse", body=body, m=3.0).quantities["I"], dtype=float)
    s = [0.0, 0.0, 1.0] if held else None
    b = StruckBody(I, s)
    assert b.held is held and not b.M.flags.writeable and not b.I.flags.writeable
    for j in _BLOWS:
        dv, jr = b.response(j)
        dv1, jr1 = impulse_response(I, j, s)
        assert _bits(dv) == _bits(dv1) and _bits(jr) == _bits(jr1), j
        if math.hypot(j[0], j[1]) > 0:
            assert _bits(b.apparent_mass(j)) == _bits(apparent_mass(I, j, s)), j
    if body == "door":
        ref = door_closed_forms(3.0, 0.6)
        omega = ref["omega"] if held else (0.6 - L / 2) / ref["Jc"]         # about the hinge / the centre
        assert b.response([0.0, 1.0, 0.6])[0][2] == pytest.approx(omega, rel=1e-12)
        assert b.apparent_mass([0.0, 1.0, 0.6]) == pytest.approx(ref["held" if held else "free"], rel=1e-12)


@pytest.mark.parametrize("support", ["held", "free"])
def test_scene_struck_over_one_body_equals_the_one_blow_functions_bit_for_bit(support):
    """The scene keeps one inverted body per (outline, mass): a blow moved over it gives exactly what
    impulse_response and apparent_mass give for the scene's own I, ĵ and joint."""
    for x, y, a in ((0.55, 0.0, 90.0), (0.3, 0.02, 33.0), (0.0, 0.0, 90.0), (0.8, -0.01, 180.0)):
        r = scenes.build("impulse", body="bat", support=support, m=0.9, x=x, y=y, angle_deg=a, J=1.0)
        I, j, s = r.extra["I"], r.extra["impulse"], r.extra["s"]
        dv, jr = impulse_response(I, j, s if support == "held" else None)
        assert _bits(r.extra["dv"]) == _bits(dv) and _bits(r.extra["reaction"]) == _bits(jr)
        assert _bits(r.extra["dv_free"]) == _bits(impulse_response(I, j)[0])
        held = apparent_mass(I, j, s)
        assert r.quantities["apparent_mass_held"] == (held if math.isfinite(held) else None)
        assert _bits(r.quantities["apparent_mass_free"]) == _bits(apparent_mass(I, j))


def test_struck_body_refuses_bad_input_by_name():
    from planargeo.errors import InputError, SingularInertiaError
    from planargeo.mechanics.impulse import StruckBody

    with pytest.raises(SingularInertiaError):
        StruckBody(np.diag([1.0, 1.0, 0.0]))
    with pytest.raises(InputError, match=r"^I must have shape \(\.\.\., 3, 3\)"):
        StruckBody([[1.0, 0.0], [0.0, 1.0]], [0.0, 0.0, 1.0])
    b = StruckBody(np.diag([2.0, 2.0, 1.0]))
    with pytest.raises(InputError, match="impulse"):
        b.response([1.0, float("nan"), 0.0])
    with pytest.raises(DegenerateGeometryError, match="line"):
        b.apparent_mass([0.0, 0.0, 1.0])
