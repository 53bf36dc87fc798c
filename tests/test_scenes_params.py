"""Up-front parameter validation of every scene (scenes.check_param): messages name the parameter."""
import re

import numpy as np
import pytest

from planargeo import scenes
from planargeo.errors import InputError, NonFiniteError, SceneError, ShapeError
from planargeo.scenes import check_param

ALL = scenes.names()
NUMERIC = [(s, k) for s in ALL for k, v in scenes.parameters(s).items()
           if isinstance(v, float) and not isinstance(v, bool)]
INTEGER = [(s, k) for s in ALL for k, v in scenes.parameters(s).items()
           if isinstance(v, int) and not isinstance(v, bool)]


def test_every_issue_scene_is_registered():
    assert set(ALL) >= {"chain", "car", "two-body", "horizontal-chain", "mobility-example", "slider-crank",
                        "tree", "constrained-tree"}


@pytest.mark.parametrize("scene, name", NUMERIC)
@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite_parameter_is_named(scene, name, bad):
    with pytest.raises(SceneError, match=f"^{name} must be finite, got {bad!r}$") as e:
        scenes.build(scene, **{name: bad})
    assert isinstance(e.value, NonFiniteError)


@pytest.mark.parametrize("scene, name", NUMERIC)
@pytest.mark.parametrize("bad", [True, "fast", None])
def test_non_numeric_parameter_is_named(scene, name, bad):
    with pytest.raises(SceneError, match=f"^{name} must be numeric, got {bad!r}$"):
        scenes.build(scene, **{name: bad})


@pytest.mark.parametrize("scene, name", NUMERIC)
def test_array_parameter_is_a_shape_error(scene, name):
    with pytest.raises(ShapeError, match=f"^{name} must be a scalar, got shape \\(2,\\)$") as e:
        scenes.build(scene, **{name: [1.0, 2.0]})
    assert isinstance(e.value, SceneError)


@pytest.mark.parametrize("scene, name", INTEGER)
@pytest.mark.parametrize("bad", [True, False, 0, -2, 2.5, "3", np.nan])
def test_integer_parameter(scene, name, bad):
    with pytest.raises(SceneError, match=f"^{name} must be a positive integer, got {bad!r}$"):
        scenes.build(scene, **{name: bad})


@pytest.mark.parametrize("bad", [-1, 1.5, True, "3", np.int64(-4)])
def test_chain_seed(bad):
    with pytest.raises(SceneError, match="^" + re.escape(f"seed must be a non-negative integer, got {bad!r}") + "$"):
        scenes.build("chain", seed=bad)


def test_chain_seed_accepts_integers_and_integral_floats():
    a, b, c = (scenes.build("chain", n=2, seed=s) for s in (4, np.int64(4), 4.0))
    assert a.state == b.state == c.state
    assert a.params["seed"] == 4 and type(c.params["seed"]) is int
    assert scenes.build("chain", n=2, seed=0).state["q"] == np.random.default_rng(0).normal(size=(3, 2))[0].tolist()


@pytest.mark.parametrize("scene, name, value, msg", [
    ("chain", "joint", "plane", "joint must be 'revolute' or 'prismatic', got 'plane'"),
    ("slider-crank", "drive", "turbo", "drive must be 'free' or 'constant-speed', got 'turbo'"),
    ("slider-crank", "r", 0.0, "r must be positive, got 0.0"),
    ("tree", "mass", -1.0, "mass must be positive, got -1.0"),
    ("constrained-tree", "length", 0.0, "length must be positive, got 0.0"),
    ("mobility-example", "tau", 0.0, "tau must be non-zero, got 0.0"),
])
def test_range_and_choice_messages(scene, name, value, msg):
    with pytest.raises(SceneError, match=f"^{msg}$"):
        scenes.build(scene, **{name: value})


def test_check_param_conversions():
    assert check_param("x", np.float32(1.5)) == 1.5 and type(check_param("x", 2)) is float
    assert check_param("n", np.int64(3), "int") == 3 and type(check_param("n", 3.0, "int")) is int
    assert check_param("s", None, "int", optional=True) is None
    assert check_param("x", -0.0, nonnegative=True) == 0.0
    with pytest.raises(SceneError, match="^x must be non-negative, got -1.0$"):
        check_param("x", -1, nonnegative=True)
    with pytest.raises(InputError, match="^kind must be 'float', 'int' or 'choice', got 'complex'$"):
        check_param("x", 1, "complex")


# --------------------------------------------------------------------------- issue 16: beyond double precision, sizes
@pytest.mark.parametrize("scene, params, was", [
    ("horizontal-chain", {"lam": 1e300}, "ZeroDivisionError"),     # rho = L / lam: rho² underflows to 0
    ("car", {"rho": 1e300}, "OverflowError"),
    ("tree", {"speed": 1e300}, "inf/NaN quantities"),
    ("slider-crank", {"psidot": 1e200}, "NaN quantities"),
])
def test_beyond_double_precision_is_a_named_scene_error(scene, params, was):
    """Finite parameters the scene cannot evaluate raise SceneRangeError naming them (it was: {was})."""
    from planargeo.errors import NumericOverflowError

    (k, v), = params.items()
    with pytest.raises(scenes.SceneRangeError, match=rf"^scene '{scene}' .* with {k}={re.escape(f'{v:g}')} "
                                                     r"\(beyond what double precision can evaluate\)$") as e:
        scenes.build(scene, **params, **({"mass": 2.0} if scene == "tree" else {}))   # mass is not named
    assert isinstance(e.value, NumericOverflowError) and isinstance(e.value, SceneError)


def test_sizes_past_the_limit_fail_fast_with_an_opt_in():
    """scenes.build('chain', n=1e300) hung; now the limit is stated (and lifted with allow_big=True)."""
    from planargeo.errors import SizeLimitError

    assert scenes.limits("chain") == {"n": 200} and scenes.limits("horizontal-chain") == {"n": 2000}
    for n in (1e300, 10**7, 201):
        with pytest.raises(SizeLimitError, match=r"past the limit of 200 for scene 'chain'.*allow_big=True"):
            scenes.build("chain", n=n)
    with pytest.raises(SceneError, match="n must be a positive integer"):
        scenes.build("chain", n=2.5, allow_big=True)
    r = scenes.build("horizontal-chain", n=2001, allow_big=True)
    assert r.params["n"] == 2001 and len(r.state["q"]) == 2001
    # the closed form of the module docstring: d/L = (λ² + 12) / (2 (λ² + 8)) = 2/3 at λ = 2, for any n
    assert r.quantities["d_over_L"] == pytest.approx(2 / 3, rel=1e-12)


def test_integer_parameters_are_recorded_as_integers():
    """horizontal-chain accepted n=3.0 and reported n: 3.0."""
    r = scenes.build("horizontal-chain", n=3.0)
    assert r.params["n"] == 3 and type(r.params["n"]) is int
    for bad in (True, 2.5, "3"):
        with pytest.raises(SceneError, match="n must be a positive integer"):
            scenes.build("horizontal-chain", n=bad)


def test_huge_integers_and_complex_are_refused():
    with pytest.raises(NonFiniteError, match="beyond double precision"):
        check_param("m", 10**400)
    with pytest.raises(SceneError, match="must be real"):
        check_param("m", 1 + 2j)
