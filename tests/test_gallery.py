"""Tests of the SVG gallery: reproducible bytes, --check, atomic writes, CLI."""
from __future__ import annotations

import argparse
import warnings

import matplotlib

matplotlib.use("Agg")
import pytest  # noqa: E402

from planargeo.gallery import build as gallery  # noqa: E402
from planargeo.gallery.figures import REGISTRY, load_all  # noqa: E402

SUBSET = ("fig4_3", "fig5_6")


def _args(**kw):
    p = argparse.ArgumentParser()
    gallery.add_arguments(p)
    ns = p.parse_args([])
    for k, v in kw.items():
        setattr(ns, k, v)
    return ns


@pytest.fixture
def small_registry(monkeypatch):
    """Restrict the gallery to two figures (fast mutation tests)."""
    specs = load_all()
    sub = {k: specs[k] for k in SUBSET}
    monkeypatch.setattr("planargeo.gallery.figures.load_all", lambda: dict(sub))
    return sub


def test_repository_gallery_is_current():
    """The committed gallery/ equals a fresh render (so runs are byte-identical over time)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        problems = gallery.check(gallery.DEFAULT_OUT)
    assert problems == []


def test_two_runs_identical_bytes(tmp_path, small_registry):
    a = gallery.generate(tmp_path / "a")
    b = gallery.generate(tmp_path / "b")
    assert a.keys() == b.keys() == {f"{n}.svg" for n in SUBSET} | {"README.md"}
    for k in a:
        assert a[k] == b[k], k
        assert (tmp_path / "a" / k).read_bytes() == a[k]
    svg = a["fig4_3.svg"].decode()
    assert "dc:date" not in svg


def test_check_reports_stale_missing_extra(tmp_path, small_registry, capsys):
    out = tmp_path / "g"
    gallery.generate(out)
    assert gallery.check(out) == []
    assert gallery.main(_args(out=str(out), check=True)) == 0
    (out / "fig4_3.svg").write_bytes(b"<svg/>")
    (out / "fig5_6.svg").unlink()
    (out / "old.svg").write_text("<svg/>")
    problems = gallery.check(out)
    assert problems == ["stale: fig4_3.svg", "missing: fig5_6.svg", "extra: old.svg"]
    assert gallery.main(_args(out=str(out), check=True)) == 1
    err = capsys.readouterr().err
    assert "stale: fig4_3.svg" in err and "missing: fig5_6.svg" in err and "extra: old.svg" in err
    # regenerating repairs everything and removes the extra file
    assert gallery.main(_args(out=str(out))) == 0
    assert gallery.check(out) == []
    assert not (out / "old.svg").exists()


def test_no_temporary_files_left(tmp_path, small_registry):
    out = tmp_path / "g"
    gallery.generate(out)
    assert sorted(p.name for p in out.iterdir()) == sorted(
        [f"{n}.svg" for n in SUBSET] + ["README.md"])


def test_readme_indexes_every_figure_with_caption(tmp_path, small_registry):
    files = gallery.generate(tmp_path)
    text = files["README.md"].decode()
    for name, spec in small_registry.items():
        assert f"![{name}]({name}.svg)" in text
        assert spec.caption in text
        assert spec.caption.startswith("Fig.") or spec.caption.startswith("Extra")


def test_only_unknown_name(tmp_path):
    from planargeo.errors import InputError

    with pytest.raises(InputError, match="only"):
        gallery.generate(tmp_path, only=["no_such_figure"])


#: Every planar figure issue 4 asks for (1.2, 1.3, 3.1, 3.2, 4.1–4.10, 5.1–5.7, 6.1–6.6,
#: 7.1–7.11, 9.1–9.3), written out from the issue, not from the registry.
THESIS_FIGURES = (["fig1_2", "fig1_3", "fig3_1", "fig3_2"]
                  + [f"fig4_{k}" for k in range(1, 11)] + [f"fig5_{k}" for k in range(1, 8)]
                  + [f"fig6_{k}" for k in range(1, 7)] + [f"fig7_{k}" for k in range(1, 12)]
                  + [f"fig9_{k}" for k in range(1, 4)])
#: The three extras and what each caption must name.
EXTRAS = {"extra_inertia_field": ("point→line", "axes of percussion"),
          "extra_joint_splits": ("every joint", "active", "reaction"),
          "extra_slider_crank": ("contact force", "closed-loop accelerations")}


def test_registry_covers_every_thesis_figure_and_the_extras():
    specs = load_all()
    missing = [n for n in THESIS_FIGURES + list(EXTRAS) if n not in specs]
    assert missing == []
    assert len(THESIS_FIGURES) == 4 + 10 + 7 + 6 + 11 + 3
    for n in THESIS_FIGURES:   # each caption names its thesis figure
        ch, k = n[3:].split("_")
        assert specs[n].caption.startswith(f"Fig. {ch}.{k} "), n
    for n, words in EXTRAS.items():
        for w in words:
            assert w in specs[n].caption, (n, w)
    assert set(specs) == set(REGISTRY)


def test_cli_dispatch(tmp_path, small_registry):
    from planargeo.cli import main

    assert main(["gallery", "--out", str(tmp_path)]) == 0
    assert main(["gallery", "--check", "--out", str(tmp_path)]) == 0


def test_readme_indexes_benchmark_charts(tmp_path, small_registry):
    """Charts copied by `planargeo bench` into benchmarks/ get a captioned entry; --check follows them."""
    out = tmp_path / "g"
    (out / "benchmarks").mkdir(parents=True)
    (out / "benchmarks" / "scaling.svg").write_text("<svg/>")
    (out / "benchmarks" / "batch.svg").write_text("<svg/>")
    text = gallery.generate(out)["README.md"].decode()
    assert text.index("![batch](benchmarks/batch.svg)") < text.index("![scaling](benchmarks/scaling.svg)")
    assert "O(N³) guides" in text                      # scaling's caption
    assert gallery.check(out) == []                    # the benchmark SVGs are not "extra" files
    assert gallery.generate(tmp_path / "h", benchmarks=out / "benchmarks")["README.md"].decode() == text
    (out / "benchmarks" / "new_chart.svg").write_text("<svg/>")
    assert gallery.check(out) == ["stale: README.md"]  # a new chart makes the index stale
    text2 = gallery.generate(out)["README.md"].decode()
    assert "new_chart: benchmark chart (see benchmarks/README.md)." in text2


def test_readme_without_benchmarks_has_no_benchmark_section(tmp_path, small_registry):
    text = gallery.generate(tmp_path)["README.md"].decode()
    assert "Benchmark charts" not in text


def test_load_all_fails_loudly_on_a_broken_module(monkeypatch):
    """A figure module that cannot be imported is an error, not a silently missing figure."""
    from planargeo.gallery import figures

    monkeypatch.setattr(figures, "MODULES", figures.MODULES + ("no_such_chapter",))
    with pytest.raises(ModuleNotFoundError, match="no_such_chapter"):
        figures.load_all()
