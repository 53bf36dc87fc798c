"""``planargeo report --list``: quantities with description, thesis symbol and equation, units;
round-off printed as 0 in the table, full precision in ``--json``."""
import argparse
import json
import re

import numpy as np
import pytest

from planargeo import report, scenes
from planargeo.errors import InputError, SceneError

FAST = [n for n in scenes.names() if n != "chain"]       # chain's first build compiles (seconds)


def call(*argv, capsys):
    p = argparse.ArgumentParser()
    report.add_arguments(p)
    code = report.main(p.parse_args(list(argv)))
    out, err = capsys.readouterr()
    return code, out, err


@pytest.mark.parametrize("name", FAST)
def test_every_reported_quantity_is_described(name):
    """Each quantity a scene reports has a description, a thesis symbol, an equation number and a unit."""
    info = report.quantity_info(name)
    res = scenes.build(name)
    assert set(res.quantities) <= set(info), set(res.quantities) - set(info)
    for key in res.quantities:
        d = info[key]
        assert d["description"] and d["symbol"] and d["unit"], key
        assert re.search(r"\d+\.\d+|—", d["equation"]), (key, d["equation"])


def test_chain_quantities_described_without_building():
    assert set(report.quantity_info("chain")) == {"q", "qd", "tau", "qdd", "max_disagreement"}


def test_list_text_shows_symbols_equations_and_units(capsys):
    code, out, err = call("--list", capsys=capsys)
    assert code == 0 and err == ""
    lines = out.splitlines()
    assert "slider-crank: psi=0.4, psidot=20.0, m1=0.4, m2=0.15, m3=0.3, r=2.29, l=5.0, t=0.5, g=9.81, drive=free" in lines
    row = next(ln for ln in lines if ln.split()[:1] == ["f"] and "9.61" in ln and "wrist pin" in ln)
    assert "(9.61)" in row and "N, N, N·m" in row
    xi = next(ln for ln in lines if ln.startswith("  xi ") and "ξ₃" in ln)
    assert "(9.89, 9.90)" in xi and "N, N·m" in xi
    # every scene's heading line stays as before (parameters), followed by its quantity rows
    for name in scenes.names():
        assert any(ln.startswith(name + ":") for ln in lines)


def test_list_columns_line_up_with_combining_marks(capsys):
    """q̇ (q + a combining dot) takes one column: the equation column starts at the same place in each row."""
    _, out, _ = call("--list", capsys=capsys)
    lines = out.splitlines()
    start = next(i for i, ln in enumerate(lines) if ln.startswith("chain:")) + 1
    rows = []
    for ln in lines[start:]:                    # the chain's rows: indented, up to the next scene
        if not ln.startswith(" "):
            break
        rows.append(ln)
    assert len(rows) >= 4
    cols = {report._width(r[:r.index("(")]) for r in rows}
    assert len(cols) == 1


def test_list_json(capsys):
    code, out, _ = call("--list", "--json", capsys=capsys)
    obj = json.loads(out)
    assert obj["scenes"]["slider-crank"]["psi"] == 0.4                 # parameters as before
    f = obj["quantities"]["slider-crank"]["f"]
    assert f == {"description": f["description"], "symbol": "f", "equation": "9.61", "unit": "N, N, N·m"}
    assert set(obj["quantities"]) == set(scenes.names())


def test_table_rounds_off_and_json_keeps_full_precision(capsys):
    """The piston's a3 has round-off components (~4e-12 m/s² against accelerations of ~10³): 0 in the
    table, the exact doubles in --json; the free pins' moments about themselves likewise."""
    code, js, _ = call("slider-crank", "--json", capsys=capsys)
    q = json.loads(js)["quantities"]
    assert 0 < abs(q["a3"][0]) < 1e-9 * np.abs(q["a"]).max()
    assert 0 < abs(q["reaction_moments"]["f_2"]) < 1e-9
    code, out, _ = call("slider-crank", capsys=capsys)
    a3 = next(ln for ln in out.splitlines() if ln.startswith("  a3 "))
    assert a3.split()[1:4] == ["[0.0,", f"{q['a3'][1]:.6g},", "0.0]"]
    assert a3.endswith("m/s², m/s², rad/s²")
    f2 = next(ln for ln in out.splitlines() if ln.strip().startswith("f_2: ") and "[" not in ln)
    assert f2.split() == ["f_2:", "0.0"]
    assert "e-1" not in out.split("quantities")[1]          # no round-off left anywhere in the table
    assert "-0.0" not in out


def test_round_off_by_unit_groups():
    info = {"a": {"unit": "N"}, "b": {"unit": "N"}, "c": {"unit": "m"}}
    out = report.round_off({"a": [1e3, 1e-7], "b": 5e-7, "c": [1e-7, -0.0], "d": 1e-20, "n": 3}, info)
    # N: scale 1e3, limit 1e-6; m: its own scale 1e-7 (kept); d: no unit, its own group (kept)
    assert out == {"a": [1e3, 0.0], "b": 0.0, "c": [1e-7, 0.0], "d": 1e-20, "n": 3}
    assert report.round_off({"x": {"k": [1.0, 1e-12]}}, {"x": {"unit": "N"}}) == {"x": {"k": [1.0, 0.0]}}
    with pytest.raises(InputError, match="tol must be"):
        report.round_off({}, tol=-1.0)


def test_quantity_info_unknown_scene():
    with pytest.raises(SceneError):
        report.quantity_info("no-such-scene")


def test_scene_module_may_describe_its_own_quantities(monkeypatch):
    """A scene module's QUANTITY_INFO attribute completes the table (the way new scenes describe theirs)."""
    import planargeo.scenes.trees as trees_module

    monkeypatch.setattr(trees_module, "QUANTITY_INFO", {"tree": {"x": ("a length", "x", "1.1", "m")}},
                        raising=False)
    info = report.quantity_info("tree")
    assert info["x"] == {"description": "a length", "symbol": "x", "equation": "1.1", "unit": "m"}
    assert info["f"]["equation"] == "9.41"                              # the table's entries stay
