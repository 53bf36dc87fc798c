"""Shared argument validation: every failure is a package exception naming the argument."""
import warnings

import numpy as np
import pytest

import planargeo as pg
from planargeo import errors
from planargeo.mechanics.contacts import Contact
from planargeo._validate import (as_array, as_mat3, as_scalar, as_vec3, check_positive,
                                 check_positive_definite)


def test_shape_error_names_argument_and_shapes():
    with pytest.raises(errors.ShapeError, match=r"twist must have shape \(\.\.\., 3\), got shape \(2,\)"):
        as_vec3([1.0, 2.0], "twist")


def test_non_finite_named():
    with pytest.raises(errors.NonFiniteError, match="wrench must be finite"):
        as_vec3([1.0, np.nan, 0.0], "wrench")


def test_non_numeric_named():
    with pytest.raises(errors.InputError, match="point must be numeric"):
        as_array(["a", "b"], "point", (2,))


def test_scalar_required():
    with pytest.raises(errors.ShapeError, match="mass must be a scalar"):
        as_scalar([1.0, 2.0], "mass")


@pytest.mark.parametrize("bad", [0.0, -1.0])
def test_positive(bad):
    with pytest.raises(errors.InputError, match="mass must be positive"):
        check_positive(bad, "mass")


def test_indefinite_matrix_reports_condition():
    with pytest.raises(errors.SingularInertiaError) as info:
        check_positive_definite(np.diag([1.0, 1.0, -1.0]), "inertia")
    assert "inertia must be positive definite" in str(info.value)
    assert info.value.cond == np.inf


def test_nonsymmetric_rejected():
    m = np.eye(3)
    m[0, 1] = 0.5
    with pytest.raises(errors.InputError, match="inertia must be symmetric"):
        check_positive_definite(m, "inertia")


def test_batches_pass_through():
    a = as_mat3(np.zeros((4, 5, 3, 3)), "C")
    assert a.shape == (4, 5, 3, 3)


def test_hierarchy():
    for exc in (errors.ShapeError, errors.NonFiniteError, errors.InvalidPolygonError,
                errors.TopologyError, errors.SceneError):
        assert issubclass(exc, errors.InputError) and issubclass(exc, ValueError)
    assert issubclass(errors.SingularInertiaError, errors.SingularError)
    assert issubclass(errors.SingularConfigurationError, np.linalg.LinAlgError)
    assert issubclass(errors.DegenerateGeometryError, errors.PlanargeoError)


def test_symmetry_is_scale_relative():
    from planargeo._validate import check_symmetric
    m = np.array([[1.0, 0.5, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
    for scale in (1e-11, 1e-200, 1.0, 1e8):
        with pytest.raises(errors.InputError, match=r"^C must be symmetric, got asymmetry "):
            check_symmetric(scale * m, "C")
    # the message gives the (absolute) asymmetry of the tiny matrix itself
    with pytest.raises(errors.InputError, match=r"^C must be symmetric, got asymmetry 5e-12$"):
        check_symmetric(1e-11 * m, "C")
    # rounding-level asymmetry passes at every scale, and so does the all-zero matrix
    r = np.array([[1.0, 0.3, 0.0], [0.3 * (1 + 1e-15), 1.0, 0.0], [0.0, 0.0, 2.0]])
    for scale in (1e-11, 1.0, 1e8):
        check_symmetric(scale * r, "C")
    check_symmetric(np.zeros((3, 3)), "C")


def test_symmetry_checked_matrix_by_matrix_in_a_batch():
    from planargeo._validate import check_symmetric
    big = 1e6 * np.eye(3)
    small = 1e-6 * np.array([[1.0, 0.5, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])   # asymmetry 5e-7 < 1e-10 * 1e6
    with pytest.raises(errors.InputError, match=r"^C must be symmetric, got asymmetry 5e-07$"):
        check_symmetric(np.stack([big, small]), "C")


def test_small_asymmetric_inertia_rejected():
    from planargeo.screws.inertia import Inertia
    m = 1e-11 * np.array([[1.0, 0.5, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
    with pytest.raises(errors.InputError, match=r"^matrix must be symmetric, got asymmetry 5e-12$"):
        Inertia(m)
    # the same body, symmetric, is accepted at that scale
    Inertia(1e-11 * np.eye(3))


def test_positive_semidefinite_check():
    from planargeo._validate import PSD_RTOL, check_positive_semidefinite
    with pytest.raises(errors.SingularInertiaError,
                       match=r"^A must be positive semi-definite, got smallest eigenvalue -2 \(condition number inf\)$"):
        check_positive_semidefinite(np.diag([1.0, 3.0, -2.0]), "A")
    with pytest.raises(errors.SingularInertiaError, match="A must be positive semi-definite"):
        check_positive_semidefinite(-np.eye(3), "A")
    with pytest.raises(errors.InputError, match="A must be symmetric"):
        check_positive_semidefinite(np.triu(np.ones((3, 3))), "A")
    # singular and zero matrices pass; a negative eigenvalue within the scaled tolerance is rounding
    check_positive_semidefinite(np.diag([1.0, 1.0, 0.0]), "A")
    check_positive_semidefinite(np.zeros((3, 3)), "A")
    check_positive_semidefinite(np.diag([1e6, 1.0, -0.5 * PSD_RTOL * 1e6]), "A")
    with pytest.raises(errors.SingularInertiaError):
        check_positive_semidefinite(np.diag([1e6, 1.0, -2.0 * PSD_RTOL * 1e6]), "A")
    # tiny matrices are judged relative to their own scale
    with pytest.raises(errors.SingularInertiaError):
        check_positive_semidefinite(1e-20 * np.diag([1.0, 1.0, -1.0]), "A")
    m, w = check_positive_semidefinite(np.diag([3.0, 1.0, 2.0]), "A", eig=True)
    np.testing.assert_array_equal(w, [1.0, 2.0, 3.0])


# --------------------------------------------------------------------------- issue 16.6: complex, strings, None
@pytest.mark.parametrize("make", [
    lambda: as_array(np.array([1.0, 2.0 + 1e-9j]), "q"),
    lambda: pg.revolute(np.array([1.0, 1j])),
    lambda: pg.prismatic(direction=np.array([1.0 + 0j, 0.0])),
    lambda: Contact("pin", 0, point_a=np.array([1.0 + 2j, 0.0])),
    lambda: pg.Point(np.array([0.0, 0.0, 1.0 + 1j])),
])
def test_complex_is_refused_not_truncated(make):
    """Complex arrays lost their imaginary part with only numpy's ComplexWarning (Point, Contact, joints)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")                    # no ComplexWarning on the way
        with pytest.raises(errors.InputError, match="must be real, got complex values"):
            make()


@pytest.mark.parametrize("bad", ["1.5", None, [None, 1.0], b"ab"])
def test_strings_and_none_are_not_numbers(bad):
    """numpy reads "1.5" as 1.5 and None as NaN; the package says what it got."""
    with pytest.raises(errors.InputError, match="x must be numeric"):
        as_array(bad, "x")
