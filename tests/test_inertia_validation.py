"""Bad inertia input raises package exceptions naming the argument (conventions: Errors).

References: hand-built matrices (non-symmetric, indefinite, point mass) and the
closed form of a point mass's axis of percussion (it passes through the mass).
"""
import numpy as np
import pytest

import planargeo
from planargeo.errors import InputError, SingularInertiaError
from planargeo.screws.inertia import Inertia, drawable_conic, percussion_axis, percussion_pole
from planargeo.screws.twists import inertia_matrix

NONSYM = np.array([[1.0, 0.5, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
INDEF = np.diag([1.0, 1.0, -1.0])


@pytest.mark.parametrize("fn", [percussion_axis, percussion_pole, planargeo.percussion_axis,
                                planargeo.percussion_pole, drawable_conic])
def test_non_symmetric_inertia_rejected(fn):
    with pytest.raises(InputError, match=r"^inertia must be symmetric, got asymmetry 0\.5$"):
        fn(NONSYM, [0.0, 0.0, 1.0]) if fn is not drawable_conic else fn(NONSYM)


@pytest.mark.parametrize("fn", [percussion_axis, planargeo.percussion_axis, drawable_conic])
def test_indefinite_inertia_rejected_semidefinite_check(fn):
    with pytest.raises(SingularInertiaError,
                       match=r"^inertia must be positive semi-definite, got smallest eigenvalue -1 ") as e:
        fn(INDEF, [0.0, 0.0, 1.0]) if fn is not drawable_conic else fn(INDEF)
    assert e.value.cond == np.inf


@pytest.mark.parametrize("fn", [percussion_pole, planargeo.percussion_pole])
def test_indefinite_and_singular_inertia_rejected_by_pole(fn):
    with pytest.raises(SingularInertiaError, match=r"^inertia must be positive definite, got smallest eigenvalue -1 "):
        fn(INDEF, [0.0, 0.0, 1.0])
    point_mass = inertia_matrix(2.0, [1.0, -0.5], 0.0)             # J = 0: singular, rank 2
    with pytest.raises(SingularInertiaError, match="inertia must be positive definite") as e:
        fn(point_mass, [0.0, 0.0, 1.0])
    assert e.value.cond > 1e12


def test_batch_with_one_bad_inertia_rejected():
    I = np.stack([inertia_matrix(1.0, [0.0, 0.0], 1.0), INDEF])
    with pytest.raises(SingularInertiaError, match="inertia must be positive semi-definite"):
        percussion_axis(I, [0.0, 0.0, 1.0])


def test_point_mass_axis_of_percussion_passes_through_the_mass():
    # J = 0 is legitimate for I a: every axis of percussion passes through the mass (5.67 with ρ = 0)
    c = np.array([1.0, -0.5])
    I = inertia_matrix(2.0, c, 0.0)
    for a in ([0.0, 0.0, 1.0], [3.0, 1.0, 1.0], [1.0, 0.0, 0.0]):
        f = percussion_axis(I, a)
        assert abs(np.array([c[1], -c[0], 1.0]) @ f) < 1e-12
    # hand: pole at the origin, unit α: force m (velocity-rate of c) = m (-c_y, c_x) through c
    np.testing.assert_allclose(percussion_axis(I, [0.0, 0.0, 1.0]),
                               [2.0 * 0.5, 2.0 * 1.0, 2.0 * (1.0 * 1.0 - (-0.5) * 0.5)], atol=1e-15)


def test_inertia_matrix_rejects_bad_mass_and_inertia():
    with pytest.raises(InputError, match=r"^mass must be positive, got -1\.0$"):
        inertia_matrix(-1, [0.0, 0.0], 1.0)
    with pytest.raises(InputError, match=r"^mass must be positive, got 0\.0$"):
        inertia_matrix(0.0, [0.0, 0.0], 1.0)
    with pytest.raises(InputError, match=r"^mass must be positive, got -2\.0$"):
        inertia_matrix([1.0, -2.0], [0.0, 0.0], 1.0)
    with pytest.raises(InputError, match=r"^inertia_about_com must be non-negative, got -0\.5$"):
        inertia_matrix(1.0, [0.0, 0.0], -0.5)
    # J = 0 (point mass) is legitimate and positive semi-definite
    I = inertia_matrix(3.0, [0.0, 2.0], 0.0)
    np.testing.assert_array_equal(I, [[3.0, 0.0, -6.0], [0.0, 3.0, 0.0], [-6.0, 0.0, 12.0]])


def test_inertia_class_still_validates():
    with pytest.raises(SingularInertiaError, match="matrix must be positive definite"):
        Inertia(inertia_matrix(1.0, [0.0, 0.0], 0.0))
    with pytest.raises(InputError, match="matrix must be symmetric"):
        Inertia(NONSYM)


def test_mobility_rejects_indefinite_and_singular():
    from planargeo.screws.inertia import mobility
    with pytest.raises(SingularInertiaError, match="inertia must be positive definite, got smallest eigenvalue -1"):
        mobility(INDEF)
    with pytest.raises(SingularInertiaError, match="inertia must be positive definite"):
        mobility(inertia_matrix(1.0, [0.5, 0.0], 0.0))
    # hand: at the centre of mass I = diag(m, m, J), so I⁻¹ = diag(1/m, 1/m, 1/J)
    np.testing.assert_allclose(mobility(inertia_matrix(4.0, [0.0, 0.0], 0.25)), np.diag([0.25, 0.25, 4.0]))


# ----------------------------------------------------------------------------- rigid-body structure (thesis 4.58)
@pytest.mark.parametrize("M, got", [
    (np.diag([1.0, 2.0, 1.0]), r"matrix\[0, 0\] = 1, matrix\[1, 1\] = 2, matrix\[0, 1\] = 0"),
    ([[1.0, 0.2, 0.0], [0.2, 1.0, 0.0], [0.0, 0.0, 1.0]], r"matrix\[0, 0\] = 1, matrix\[1, 1\] = 1, matrix\[0, 1\] = 0\.2"),
    (np.stack([np.eye(3), np.diag([3.0, 1.0, 1.0])]), r"matrix\[0, 0\] = 3, matrix\[1, 1\] = 1"),
])
def test_inertia_class_requires_rigid_body_structure(M, got):
    # symmetric positive definite, but not m 1 in the linear block: no mass or centre of mass to report
    assert np.linalg.eigvalsh(np.asarray(M)).min() > 0
    with pytest.raises(InputError, match=r"^matrix must be a rigid-body inertia \(matrix\[0, 0\] == matrix\[1, 1\] == mass "
                                         r"and matrix\[0, 1\] == 0, thesis 4\.58\), got " + got):
        Inertia(M)


def test_articulated_inertias_stay_plain_arrays():
    # an articulated inertia (symmetric positive definite, no rigid-body structure) works with the functions
    A = np.array([[2.0, 0.3, 0.0], [0.3, 1.0, 0.5], [0.0, 0.5, 1.0]])
    f = percussion_axis(A, [0.0, 0.0, 1.0])
    np.testing.assert_allclose(f, A[:, 2])
    np.testing.assert_allclose(percussion_pole(A, f), [0.0, 0.0, 1.0], atol=1e-14)


def test_rigid_structure_survives_frame_changes_and_sums():
    I = Inertia.from_mass(2.0, [1.0, -3.0], radius_of_gyration=0.7)
    for theta in np.linspace(-7.0, 7.0, 29):                       # rounding in cos² + sin² is tolerated
        B = I.rotated(theta, about=[0.3, 2.0]).at([-1.0, 5.0])
        assert float(B.mass) == pytest.approx(2.0) and float(B.radius_of_gyration) == pytest.approx(0.7)
    assert float((I + I.rotated(1.0)).mass) == pytest.approx(4.0)
    # a tiny body is judged relative to its own size
    Inertia(1e-12 * inertia_matrix(2.0, [1.0, -3.0], 0.98))
    with pytest.raises(InputError, match="matrix must be a rigid-body inertia"):
        Inertia(1e-12 * np.diag([1.0, 1.001, 1.0]))


@pytest.mark.parametrize("fn", [planargeo.screws.inertia.centre_of_mass, planargeo.screws.inertia.rotational_inertia,
                                planargeo.screws.inertia.radius_of_gyration])
@pytest.mark.parametrize("m, shown", [(-1.0, r"-1\.0"), (0.0, r"0\.0"), (-2.5, r"-2\.5")])
def test_features_reject_zero_or_negative_mass(fn, m, shown):
    # a rigid-body form 4.58 with m <= 0 (hand-built: inertia_matrix itself refuses such a mass)
    I = np.array([[m, 0.0, 0.0], [0.0, m, 0.0], [0.0, 0.0, 1.0]])
    with pytest.raises(InputError, match=rf"^inertia: mass inertia\[0, 0\] must be positive, got {shown}$"):
        fn(I)
    # one bad inertia in a batch is reported by its value
    batch = np.stack([inertia_matrix(1.0, [0.0, 0.0], 1.0), I])
    with pytest.raises(InputError, match=rf"^inertia: mass inertia\[0, 0\] must be positive, got {shown}$"):
        fn(batch)


def test_features_of_good_masses_are_the_hand_values():
    # I = inertia_matrix(m, c, J): c, J and ρ = sqrt(J/m) come back (4.58), for a batch too, without warnings
    I = np.stack([inertia_matrix(2.0, [1.0, -3.0], 0.5), inertia_matrix(4.0, [0.0, 2.0], 9.0)])
    np.testing.assert_allclose(planargeo.screws.inertia.centre_of_mass(I), [[1.0, -3.0], [0.0, 2.0]], atol=1e-14)
    np.testing.assert_allclose(planargeo.screws.inertia.rotational_inertia(I), [0.5, 9.0], atol=1e-13)
    np.testing.assert_allclose(planargeo.screws.inertia.radius_of_gyration(I), [0.5, 1.5], atol=1e-14)


@pytest.mark.parametrize("op, name", [
    (lambda I: I.at([1e200, 0.0]), "inertia_at"),
    (lambda I: I.rotated(1.0, [1e200, 0.0]), "inertia_rotated"),
    (lambda I: I.momentum([1e308, 0.0, 1e308]), "momentum"),
    (lambda I: I.kinetic_energy([1e200, 0.0, 1e200]), "kinetic_energy"),
])
def test_inertia_operations_overflow_like_the_screws_functions(op, name):
    """Inertia's operations go through the screws' functions: an overflow names that function."""
    from planargeo.errors import NumericOverflowError

    with pytest.raises(NumericOverflowError, match=rf"^{name}\b.*overflows double precision"):
        op(Inertia.from_mass(2.0, [1.0, 0.0], inertia=1.0))


def test_inertia_operations_match_the_screws_functions_and_closed_forms():
    """``at``/``rotated``/``momentum``/``kinetic_energy`` of the class equal the hand-built results."""
    I = Inertia.from_mass(2.0, [2.0, 0.0], inertia=0.5)
    np.testing.assert_allclose(I.at([2.0, 0.0]).matrix, np.diag([2.0, 2.0, 0.5]), atol=1e-15)   # about its centre
    np.testing.assert_allclose(I.rotated(np.pi / 2, [1.0, 0.0]).matrix, inertia_matrix(2.0, [1.0, 1.0], 0.5),
                               atol=1e-14)
    np.testing.assert_allclose(I.momentum([0.0, 0.0, 1.0]), [0.0, 4.0, 8.5])   # m ω (−c_y, c_x), (J + m d²) ω
    assert float(I.kinetic_energy([0.0, 0.0, 2.0])) == pytest.approx(0.5 * 8.5 * 4.0)
