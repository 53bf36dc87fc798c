"""``planargeo report``: tables, --json, --list, and one-line errors without tracebacks."""
from __future__ import annotations

import argparse
import json
import subprocess
import sys

import numpy as np
import pytest

from planargeo import report, scenes
from planargeo.errors import InputError


def run(*args):
    return subprocess.run([sys.executable, "-m", "planargeo.cli", "report", *args],
                          capture_output=True, text=True, timeout=120)


def call(*argv, capsys):
    p = argparse.ArgumentParser()
    report.add_arguments(p)
    code = report.main(p.parse_args(list(argv)))
    out = capsys.readouterr()
    return code, out.out, out.err


def test_json_object_has_the_four_keys_and_scene_values(capsys):
    code, out, err = call("two-body", "--set", "phi=0", "--set", "rho=1", "--json", capsys=capsys)
    assert code == 0 and err == ""
    obj = json.loads(out)
    assert set(obj) == {"scene", "params", "state", "quantities"}
    assert obj["scene"] == "two-body"
    assert obj["params"] == {"m": 1.0, "rho": 1.0, "L": 1.0, "phi": 0.0}
    assert isinstance(obj["params"]["rho"], float)          # int promoted to the default's float
    # phi = 0: m_x = 2 m (7.20)
    assert obj["quantities"]["m_x"] == pytest.approx(2.0)
    assert np.array(obj["quantities"]["A1"]).shape == (3, 3)


def test_json_over_subprocess_mobility_example_closed_form():
    """x/L = 1 + 2 eta^2 cos(phi) / (4 + 5 eta^2) (7.48, derived by hand; eta = L/rho = 2 here)."""
    r = run("mobility-example", "--set", "phi=0.3", "--set", "tau=2", "--json")
    assert r.returncode == 0, r.stderr
    obj = json.loads(r.stdout)
    assert obj["quantities"]["x_over_L"] == pytest.approx(1 + 8 * np.cos(0.3) / (4 + 20), rel=1e-13)
    # a2 = -Lambda2_inv f3 with f3 = [0, 0, 2]: a rotation about (x, 0)
    a2 = np.array(obj["quantities"]["a2"])
    assert -a2[1] / a2[2] == pytest.approx(obj["quantities"]["x_over_L"], rel=1e-13)
    assert a2[0] == pytest.approx(0.0, abs=1e-13 * np.abs(a2).max())


def test_json_car_omega_dot_6_131(capsys):
    """omega_dot = F_A sqrt(d^2 + L^2) / (m (rho^2 + d^2 + (1 - eps)^2 L^2)): drive moment over inertia at the ICR."""
    code, out, _ = call("car", "--json", capsys=capsys)
    assert code == 0
    m, rho, L, d, eps, F = 1200.0, 1.2, 2.6, 8.0, 0.45, 2000.0
    ref = F * np.hypot(d, L) / (m * (rho ** 2 + d ** 2 + (1 - eps) ** 2 * L ** 2))
    assert json.loads(out)["quantities"]["omega_dot"] == pytest.approx(ref, rel=1e-13)
    assert ref == pytest.approx(0.2077, abs=5e-5)


@pytest.mark.parametrize("phi", [0.0, np.pi / 3, np.pi / 2])
def test_json_two_body_m_x_7_20(phi, capsys):
    """m_x / m = (8 + lambda^2 (1 + cos^2 phi)) / (lambda^2 + 4) (7.22), lambda = 2 by default."""
    code, out, _ = call("two-body", "--set", f"phi={phi}", "--json", capsys=capsys)
    assert code == 0
    q = json.loads(out)["quantities"]
    assert q["m_x"] == pytest.approx((8 + 4 * (1 + np.cos(phi) ** 2)) / 8, rel=1e-13)
    assert q["A1"][0][0] == q["m_x"]


def test_table_lists_parameters_state_and_quantities(capsys):
    code, out, _ = call("horizontal-chain", "--set", "n=3", "--set", "lam=2", capsys=capsys)
    assert code == 0
    assert out.startswith("scene: horizontal-chain")
    for word in ("parameters", "state", "quantities", "d_over_L", "mx_over_m", "my_over_m", "Az_over_m_rho2"):
        assert word in out
    line = next(l for l in out.splitlines() if l.strip().startswith("d_over_L"))
    assert float(line.split()[-1]) == pytest.approx(2 / 3, rel=1e-5)


def test_list_shows_every_scene_and_its_parameters(capsys):
    code, out, _ = call("--list", capsys=capsys)
    assert code == 0
    for name in scenes.names():
        assert any(l.startswith(name + ":") or l == name for l in out.splitlines())
    assert "horizontal-chain: n=4, lam=2.0" in out
    code, out, _ = call("--list", "--json", capsys=capsys)
    listing = json.loads(out)["scenes"]
    assert listing["mobility-example"] == {"m": 1.0, "rho": 0.5, "L": 1.0, "phi": np.pi / 4, "tau": 1.0}


@pytest.mark.parametrize("args, code, msg", [
    (("no-such-scene",), 1, "scene must be one of"),
    (("two-body", "--set", "mass=2"), 1, "has no parameter 'mass'"),
    (("two-body", "--set", "m=-1"), 1, "m must be positive"),
    (("horizontal-chain", "--set", "n=0"), 1, "n must be a positive integer"),
    (("mobility-example", "--set", "tau=0"), 1, "tau must be non-zero"),
    (("two-body", "--set", "phi"), 2, "--set expects NAME=VALUE"),
    ((), 2, "a scene name is required"),
])
def test_errors_are_one_line_messages(args, code, msg, capsys):
    got, out, err = call(*args, capsys=capsys)
    assert got == code
    assert msg in err
    assert len(err.strip().splitlines()) == 1
    assert out == ""


@pytest.mark.parametrize("args, msg", [
    (("no-such-scene",), "scene must be one of"),
    (("two-body", "--set", "m=-1"), "m must be positive"),
])
def test_errors_over_subprocess_have_no_traceback(args, msg):
    r = run(*args)
    assert r.returncode == 1
    assert msg in r.stderr
    assert "Traceback" not in r.stderr
    assert len(r.stderr.strip().splitlines()) == 1
    assert r.stdout == ""


@pytest.mark.parametrize("text, value", [
    ("3", 3), ("-2", -2), ("2.5", 2.5), ("1e-3", 1e-3), ("true", True), ("False", False),
    ("none", None), ("[1, 2]", [1, 2]), ("revolute", "revolute"), ("[oops", "[oops"),
])
def test_parse_value(text, value):
    assert report.parse_value(text) == value


def test_parse_value_nan_and_inf():
    assert np.isnan(report.parse_value("nan"))
    assert report.parse_value("-inf") == -np.inf


def test_parse_sets_last_wins_and_keeps_int_parameters_int():
    assert report.parse_sets(["n=2", "n=5", "lam=3"], {"n": 4, "lam": 2.0}) == {"n": 5, "lam": 3.0}
    assert type(report.parse_sets(["n=2"], {"n": 4})["n"]) is int
    with pytest.raises(InputError, match="^--set expects NAME=VALUE, got '=3'$"):
        report.parse_sets(["=3"])


def test_to_plain_converts_numpy():
    out = report.to_plain({"a": np.float64(1.5), "b": np.arange(3), "c": (np.int64(2), None), "d": np.bool_(True)})
    assert out == {"a": 1.5, "b": [0, 1, 2], "c": [2, None], "d": True}
    json.dumps(out)


# --------------------------------------------------------------------------- table formatting
def _table_block(text, name):
    """The lines of quantity ``name`` in a report table (its first line and the indented ones after it)."""
    lines = text.splitlines()
    start = next(i for i, ln in enumerate(lines) if ln.startswith(f"  {name} "))
    out = [lines[start]]
    for ln in lines[start + 1:]:
        if not ln.startswith("   "):          # the next quantity starts at column 2
            break
        out.append(ln)
    return out


def test_table_three_level_array_shape_and_rows(capsys):
    """The tree's nine 3×3 mobilities Λ_i⁻¹: a shape line, then nine labelled 3×3 blocks whose numbers
    are those of --json (to the table's 6 significant digits); --json itself keeps the nested lists."""
    code, out, _ = call("tree", capsys=capsys)
    assert code == 0
    block = _table_block(out, "Lambda_inv")
    assert block[0].split()[:5] == ["Lambda_inv", "shape", "(9,", "3,", "3)"]
    assert block[0].endswith("1/kg, 1/(kg·m), 1/(kg·m²)")                # the unit after the first line
    assert len(block) == 1 + 9 * 3
    code, js, _ = call("tree", "--json", capsys=capsys)
    lam = np.array(json.loads(js)["quantities"]["Lambda_inv"])
    assert lam.shape == (9, 3, 3)
    for i in range(9):
        rows = block[1 + 3 * i: 4 + 3 * i]
        assert rows[0].split()[0] == f"[{i}]"
        nums = [float(x) for r in rows for x in r.replace(f"[{i}]", "").replace("[", " ").replace("]", " ").split()]
        # round-off (|x| < 1e-9 × the scene's scale for the unit) prints as 0
        assert np.allclose(nums, lam[i].ravel(), rtol=1e-5, atol=1e-9 * np.abs(lam).max())
        assert all(n == 0.0 for n, x in zip(nums, lam[i].ravel()) if abs(x) < 1e-9 * np.abs(lam).max())
    # no raw nested list anywhere in the table
    assert "[[" not in out


def test_table_wide_matrix_is_summarised_and_json_keeps_it(capsys):
    code, out, _ = call("tree", capsys=capsys)
    assert code == 0
    assert _table_block(out, "L") == ["  L           27×27 matrix, too wide for the table (--json gives its values)"]
    code, js, _ = call("tree", "--json", capsys=capsys)
    L = np.array(json.loads(js)["quantities"]["L"])
    assert L.shape == (27, 27) and np.allclose(np.diag(L), 1.0)      # unit triangular (9.31)


def test_fmt_value_arrays_by_hand():
    three = [[[1.0, 2.0], [3.0, 4.0]], [[5.0, 6.0], [7.0, 8.5]]]
    assert report._fmt_value(three, 0) == ["shape (2, 2, 2)",
                                           "[0]  [1.0  2.0]", "     [3.0  4.0]",
                                           "[1]  [5.0  6.0]", "     [7.0  8.5]"]
    four = [three, three]
    lines = report._fmt_value(four, 0)
    assert lines[0] == "shape (2, 2, 2, 2)" and lines[1] == "[0]  [0]  [1.0  2.0]" and len(lines) == 1 + 8
    assert report._fmt_value([[1.0, [2.0]], [3.0]], 0) == ["[[1.0, [2.0]], [3.0]]"]     # ragged: JSON
    assert report._fmt_value([[0.0] * 13] * 2, 0) == [
        "2×13 matrix, too wide for the table (--json gives its values)"]
    assert report._fmt_value([[0.0] * 12] * 2, 0)[0].count("0.0") == 12                  # 12 columns shown
