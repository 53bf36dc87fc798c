"""Shared argument validation: every failure is a package exception naming the argument."""
import numpy as np
import pytest

from planargeo import errors
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
