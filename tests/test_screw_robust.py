"""Twists, wrenches and inertias: finite in, finite out, or a named error (issue 16, items 4-6).

Expected values are hand-computed closed forms (comments) at the ends of double precision's range.
"""
from __future__ import annotations

import warnings

import numpy as np
import pytest

import planargeo as pg
from planargeo.errors import InputError, NumericOverflowError
from planargeo.geometry import projective as P
from planargeo.screws import inertia as In
from planargeo.screws import twists as T


def test_kinetic_energy_near_and_past_the_range():
    """m = J = 1e300 at the origin spinning at ω: T = ½ J ω² = 5e301 for ω = 10 (finite), 5e319 for
    ω = 1e10 (beyond 1.8e308: named, where inf came back before)."""
    I = T.inertia_matrix(1e300, [0.0, 0.0], 1e300)
    assert float(T.kinetic_energy(I, [0.0, 0.0, 10.0])) == pytest.approx(5e301, rel=1e-15)
    with pytest.raises(NumericOverflowError, match="kinetic_energy"):
        T.kinetic_energy(I, [0.0, 0.0, 1e10])
    with pytest.raises(NumericOverflowError, match="power"):
        T.power([1e200, 0.0, 0.0], [1e200, 0.0, 0.0])


def test_add_twists_of_huge_twists_has_a_finite_construction():
    """v1 = [1e300, 0, 1] has its pole at (0, 1e300), v2 = [0, 1e300, 1] at (-1e300, 0); the join of the
    poles (v1 × v2 = 1e600 before rescaling) passes through both."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        c = T.add_twists([1e300, 0.0, 1.0], [0.0, 1e300, 1.0])
    assert c.case == "rotations" and c.beta == 0.5
    for Q in (c.Q1, c.Q2, c.P):
        assert abs(float(P.signed_distance(Q, c.line))) <= 1e-15 * 1e300
    with pytest.raises(NumericOverflowError, match="add_twists"):
        T.add_twists([1.7e308, 0.0, 1.0], [1.7e308, 0.0, 1.0])       # v1 + v2 overflows


def test_wrench_axis_of_a_line_beyond_the_range():
    """[0, 1e-300, -1e200]: a force 1e-300 along a line 1e500 from the origin."""
    with pytest.raises(NumericOverflowError, match="wrench_axis"):
        T.wrench_axis([0.0, 1e-300, -1e200])
    e, d, n = T.wrench_axis([0.0, 1e-300, -1e-100])   # 1e200 away: representable, direction +y
    np.testing.assert_allclose(e, [0.0, 1.0])
    assert float(d) == pytest.approx(-1e200, rel=1e-15)
    with pytest.raises(NumericOverflowError, match="wrench_magnitude"):       # |f| = 2.4e308
        T.wrench_magnitude([1.7e308, 1.7e308, 0.0])
    np.testing.assert_allclose(T.unit_translation([-1.7e308, -1.7e308]), [-np.sqrt(0.5), -np.sqrt(0.5), 0.0])


def test_percussion_pole_keeps_its_scale():
    """I = diag(1e-300, 1e-300, 1e-300) (m = J = 1e-300) and f = 1e-10 [1, 2, 3]: a = I⁻¹ f = 1e290 [1, 2, 3]."""
    I = 1e-300 * np.eye(3)
    np.testing.assert_allclose(In.percussion_pole(I, 1e-10 * np.array([1.0, 2.0, 3.0])),
                               1e290 * np.array([1.0, 2.0, 3.0]), rtol=1e-15)
    with pytest.raises(NumericOverflowError, match="percussion_pole"):
        In.percussion_pole(I, [1e10, 0.0, 1.0])          # 1e310
    with pytest.raises(NumericOverflowError, match="centre_of_mass"):
        In.centre_of_mass(T.inertia_matrix(1e-300, [0.0, 0.0], 1.0) + np.array(
            [[0, 0, -1e10], [0, 0, 0], [-1e10, 0, 0]]))    # c_y = 1e10 / 1e-300


def test_tolerances_and_complex_are_refused():
    with pytest.raises(InputError, match="rtol must be a non-negative number"):
        T.reciprocal([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], rtol=-1.0)
    with pytest.raises(InputError, match="must be real"):
        pg.Twist(np.array([1.0, 0.0, 1j]))
    with pytest.raises(InputError, match="must be real"):
        pg.Inertia.from_mass(1.0 + 0j, [0.0, 0.0], 1.0)
