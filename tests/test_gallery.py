"""Tests of the SVG gallery: reproducible bytes, --check, atomic writes, CLI."""
from __future__ import annotations

import argparse
import warnings

import matplotlib

matplotlib.use("Agg")
import pytest  # noqa: E402

from planargeo.draw import gallery  # noqa: E402
from planargeo.draw.figures import REGISTRY, load_all  # noqa: E402

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
    monkeypatch.setattr("planargeo.draw.figures.load_all", lambda: dict(sub))
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


def test_registry_covers_chapter_4_and_5():
    specs = load_all()
    for n in [f"fig4_{k}" for k in range(1, 11)] + [f"fig5_{k}" for k in range(1, 8)]:
        assert n in specs
    assert set(specs) == set(REGISTRY)


def test_cli_dispatch(tmp_path, small_registry):
    from planargeo.cli import main

    assert main(["gallery", "--out", str(tmp_path)]) == 0
    assert main(["gallery", "--check", "--out", str(tmp_path)]) == 0
