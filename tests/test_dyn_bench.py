"""Smoke test of the benchmark machinery (no timing assertions)."""
import argparse
from pathlib import Path

import numpy as np
import pytest

import bench
from planargeo.algorithms.aba import forward_dynamics
from planargeo.mechanics.model import chain_model, random_model


def test_tables_and_charts(tmp_path):
    single = bench.run_single((2,), budget=0.001)
    batch = bench.run_batch((1, 20), budget=0.001, N=3)
    for r in single:
        assert r["err_crba"]["aba"] < 1e-12      # the harness's agreement columns, not a reference test
        if "pinocchio" in r["times"]:
            assert r["err_pin"]["aba"] < 1e-12
        assert all(t > 0 for t in r["times"].values() if np.isfinite(t))
    assert all(r["err"] < 1e-12 for r in batch)
    text = bench.write_single(single, tmp_path)
    assert "aba µs" in text and (tmp_path / "single_state.md").exists()
    bench.write_accuracy(single, tmp_path)
    bench.write_batch(batch, tmp_path)
    bench.write_charts(single, batch, tmp_path)
    for name in ("single_state", "batch", "speed_accuracy"):
        assert (tmp_path / f"{name}.svg").stat().st_size > 1000
        assert (tmp_path / f"{name}.png").exists()


def test_arguments_and_single_thread_rerun(monkeypatch):
    p = argparse.ArgumentParser()
    bench.add_arguments(p)
    args = p.parse_args(["--quick", "--sizes", "2,5", "--out", "x"])
    for v in bench._THREAD_VARS:
        monkeypatch.setenv(v, "4")
    assert args.summary is None and args.gallery == ""          # nothing outside --out unless named
    argv = bench._single_threaded_argv(args)
    assert argv[1:] == [str(Path(bench.__file__).with_name("run.py")), "--out", "x", "--sizes", "2,5", "--quick"]
    assert Path(argv[1]).is_file()
    for v in bench._THREAD_VARS:
        monkeypatch.setenv(v, "1")
    assert bench._single_threaded_argv(args) is None


# --------------------------------------------------------------------------- MuJoCo peer
@pytest.mark.parametrize("make", [
    pytest.param(lambda n: chain_model(n), id="chain"),
    pytest.param(lambda n: chain_model(n, joint="prismatic"), id="prismatic-chain"),
    pytest.param(lambda n: random_model(n, seed=n), id="random"),
    pytest.param(lambda n: random_model(n, seed=n + 7, tree=True), id="random-tree"),
])
@pytest.mark.parametrize("n", [1, 2, 5, 20, 100])
def test_mujoco_agrees_with_pinocchio_and_aba(make, n):
    mujoco = pytest.importorskip("mujoco")
    pytest.importorskip("pinocchio")
    model = make(n)
    mjm = bench.to_mujoco(model)
    assert mjm.nv == model.nq and mjm.opt.gravity[1] == model.gravity[1]
    assert not mjm.dof_armature.any() and not mjm.dof_damping.any()
    assert mjm.opt.disableflags & mujoco.mjtDisableBit.mjDSBL_CONTACT
    mjd = mujoco.MjData(mjm)
    dofs = bench.mujoco_dofs(mjm, model)
    rng = np.random.default_rng(n)
    for _ in range(3):
        q, qd, tau = rng.normal(size=(3, model.nq))
        got = bench.mujoco_forward(mjm, mjd, q, qd, tau, dofs)
        ref = bench.pinocchio_forward(model, q, qd, tau)
        assert np.abs(got - ref).max() <= 1e-9 * np.abs(ref).max()
        assert np.abs(forward_dynamics(model, q, qd, tau) - ref).max() <= 1e-9 * np.abs(ref).max()


def test_mujoco_xml_is_explicit():
    xml = bench.to_mujoco_xml(random_model(3, seed=1))
    for s in ('<flag contact="disable"/>', 'gravity="0.0 -9.81 0"', 'armature="0"', 'damping="0"',
              "<inertial ", 'inertiafromgeom="false"'):
        assert s in xml
    assert "<geom" not in xml


def test_mujoco_tree_dof_order_is_mapped():
    pytest.importorskip("mujoco")
    m = random_model(12, seed=19, tree=True)
    mjm = bench.to_mujoco(m)
    dofs = bench.mujoco_dofs(mjm, m)
    assert dofs is not None and sorted(dofs) == list(range(m.nq))   # a real permutation is exercised


# --------------------------------------------------------------------------- reference, RESULTS.md
def test_reference_errors_and_scaling_ratio():
    rows = bench.run_single((2, 8), budget=0.001, rounds=2)
    for r in rows:
        assert r["ref"]["mode"] == ("exact" if r["N"] <= bench.EXACT_MAX else "longdouble")
        for name in ("aba", "projective", "mobility_split", "stacked", "crba"):
            assert r["err_ref"][name] < 1e-12
        for peer in bench.PEERS:
            if peer in r["times"]:
                assert r["err_ref"][peer] < 1e-12
    assert bench.scaling_pair(rows) == (2, 8)
    assert set(bench.scaling_ratios(rows)) == set(rows[0]["times"])


def test_quick_main_writes_results_with_sections(tmp_path, monkeypatch):
    for v in bench._THREAD_VARS:
        monkeypatch.setenv(v, "1")
    p = argparse.ArgumentParser()
    bench.add_arguments(p)
    out = tmp_path / "results"
    gallery = tmp_path / "gallery" / "benchmarks"
    monkeypatch.setattr(bench, "QUICK_BATCH_SIZES", (1, 50))
    startup = {"import": 0.1, "first_compile": 1.5, "first_cached": 0.2, "batch_compile": 3.0, "batch_cached": 0.1,
               "import_loads_numba": False}
    monkeypatch.setattr(bench, "run_startup", lambda repeat: startup)    # fresh processes: test_startup_...
    args = p.parse_args(["--quick", "--only", "dynamics", "--sizes", "2,10", "--out", str(out),
                         "--gallery", str(gallery)])
    assert bench.main(args) == 0
    assert sorted(x.name for x in tmp_path.iterdir()) == ["gallery", "results"]     # the summary went into --out
    text = (out / "RESULTS.md").read_text(encoding="utf-8")
    assert "| first `forward_dynamics` call in a fresh process, compiling (empty numba cache) | 1.50 s | ≤ 2 s (met) |" \
        in text
    for heading in ("## Headline", "## Charts", "## Single call: ratios to Pinocchio and MuJoCo",
                    "## Single call: time per call", "## Accuracy: error against the extended-precision reference",
                    "## Batched sweeps", "## Scaling", "## Other results"):
        assert heading in text
    for link in ("scaling.svg", "work_precision.svg", "breakdown.md", "page_latency.md", "integrators.md",
                 "scene_cost.md"):
        assert f"](./{link})" in text                      # beside RESULTS.md
    assert "single call, N = 10: `aba` / pin.aba" in text or "pinocchio" not in bench._peers(chain_model(1))
    assert "t(10) / t(2)" in text
    for name in bench.CHARTS:
        assert (out / f"{name}.svg").stat().st_size > 1000
        assert (gallery / f"{name}.svg").read_bytes() == (out / f"{name}.svg").read_bytes()
    assert (out / "dynamics.json").exists()


# --------------------------------------------------------------------------- no peers installed
def test_without_peers_fast_methods_share_the_rounds(tmp_path, monkeypatch):
    # Pinocchio and MuJoCo absent: the fast methods are still interleaved among themselves (no †),
    # and the table headers don't claim peers that did not take part
    monkeypatch.setattr(bench, "_peers", lambda m: {})
    monkeypatch.setattr(bench, "_versions", lambda: {"Python": "x", "Pinocchio": "not installed",
                                                     "MuJoCo": "not installed"})
    rows = bench.run_single((2,), budget=0.01, rounds=2)     # every method shares the rounds, even on a busy machine
    r = rows[0]
    assert not set(bench.PEERS) & set(r["times"])
    assert "aba" not in r.get("alone", []) and "crba" not in r.get("alone", [])
    assert {"aba", "crba", "projective"} <= set(r["times_median"])       # timed in the shared rounds
    text = bench.write_single(rows, tmp_path)
    row_aba = [ln for ln in text.splitlines() if ln.startswith("| 2 |")][0]
    cells = row_aba.split("|")[1:-1]
    header = [ln for ln in text.splitlines() if ln.startswith("| N |")][0].split("|")[1:-1]
    for name in ("aba", "crba"):
        assert "†" not in cells[header.index(f" {name} µs ")]
    assert "both peers" not in text and "pin.aba" not in text and "mj_forward" not in text
    assert "neither Pinocchio nor MuJoCo" in text
