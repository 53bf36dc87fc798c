"""Smoke test of the benchmark machinery (no timing assertions)."""
import argparse

import numpy as np

from planargeo import bench


def test_tables_and_charts(tmp_path):
    single = bench.run_single((2,), budget=0.001)
    batch = bench.run_batch((1, 20), budget=0.001, N=3)
    for r in single:
        assert r["err_crba"]["aba"] < 1e-12
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
    argv = bench._single_threaded_argv(args)
    assert argv[1:] == ["-m", "planargeo.bench", "--out", "x", "--sizes", "2,5", "--quick"]
    for v in bench._THREAD_VARS:
        monkeypatch.setenv(v, "1")
    assert bench._single_threaded_argv(args) is None
