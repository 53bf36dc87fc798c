"""Tests of the SVG gallery: reproducible bytes, --check, atomic writes, CLI."""
from __future__ import annotations

import argparse
import warnings

import matplotlib

matplotlib.use("Agg")
import pytest  # noqa: E402

from planargeo.gallery import build as gallery  # noqa: E402
from planargeo.files import read_manifest  # noqa: E402
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
    assert a.keys() == b.keys() == {f"{n}.svg" for n in SUBSET} | {"README.md", gallery.MANIFEST}
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
    # fig4_3.svg no longer holds what the gallery wrote: it is the user's, so only --force replaces it
    from planargeo.errors import OutputError

    with pytest.raises(OutputError, match=r"did not write, or that changed since it wrote them \(fig4_3.svg\)"):
        gallery.main(_args(out=str(out)))
    assert (out / "fig4_3.svg").read_bytes() == b"<svg/>"
    # with --force, regenerating repairs everything but keeps old.svg, which the gallery did not write
    assert gallery.main(_args(out=str(out), force=True)) == 0
    assert gallery.check(out) == ["extra: old.svg"]
    assert (out / "old.svg").read_text() == "<svg/>"


def test_no_temporary_files_left(tmp_path, small_registry):
    out = tmp_path / "g"
    gallery.generate(out)
    assert sorted(p.name for p in out.iterdir()) == sorted(
        [f"{n}.svg" for n in SUBSET] + ["README.md", gallery.MANIFEST])


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
THESIS_FIGURES = (["fig1_1", "fig1_2", "fig1_3", "fig1_4", "fig2_1", "fig3_1", "fig3_2", "fig3_3"]
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
    assert len(THESIS_FIGURES) == 8 + 10 + 7 + 6 + 11 + 3
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


# --------------------------------------------------------------------------- never lose a user's file (issue 16.1, 16.8)
def _cli(*args, limit=None):
    """``planargeo gallery ARGS`` in a fresh process, optionally under a file-size limit (RLIMIT_FSIZE)."""
    import subprocess
    import sys

    pre = ("import resource, signal; signal.signal(signal.SIGXFSZ, signal.SIG_IGN); "
           f"resource.setrlimit(resource.RLIMIT_FSIZE, ({limit}, {limit})); ") if limit else ""
    code = pre + f"import sys; from planargeo.cli import main; sys.exit(main({['gallery', *args]!r}))"
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)


def _one_line_error(r, *words):
    assert r.returncode == 1, (r.returncode, r.stderr)
    assert "Traceback" not in r.stderr
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("planargeo gallery: error: "), r.stderr
    for w in words:
        assert w in lines[0], (w, lines[0])


def test_foreign_folder_is_refused_and_untouched(tmp_path, small_registry, capsys):
    """A folder holding my.svg and README.md is not the gallery's: nothing is deleted or overwritten."""
    from planargeo.errors import OutputError

    (tmp_path / "my.svg").write_text("<svg>mine</svg>")
    (tmp_path / "README.md").write_text("my notes")
    with pytest.raises(OutputError, match="--force"):
        gallery.generate(tmp_path)
    from planargeo.cli import main

    assert main(["gallery", "--out", str(tmp_path)]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "README.md" in err[0] and "did not write" in err[0]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["README.md", "my.svg"]
    assert (tmp_path / "README.md").read_text() == "my notes"
    # a folder with other files only (no clash) is refused too: it is not empty and has no manifest
    (tmp_path / "README.md").unlink()
    with pytest.raises(OutputError, match="not empty"):
        gallery.generate(tmp_path)
    # --force writes the gallery there; it still deletes nothing it did not write
    (tmp_path / "README.md").write_text("my notes")
    assert gallery.main(_args(out=str(tmp_path), force=True)) == 0
    assert (tmp_path / "my.svg").read_text() == "<svg>mine</svg>"
    assert (tmp_path / "README.md").read_text().startswith("# planargeo gallery")
    gallery.generate(tmp_path)       # now the gallery's folder: no --force needed
    assert (tmp_path / "my.svg").read_text() == "<svg>mine</svg>"


def test_only_its_own_stale_files_are_deleted(tmp_path, small_registry):
    """A figure the gallery wrote and no longer renders goes; a file of the user's of the same kind stays."""
    out = tmp_path / "g"
    gallery.generate(out)
    (out / "user.svg").write_text("<svg/>")
    gallery.generate(out, only=["fig4_3"])                # --only keeps the manifest's other entries
    assert sorted(read_manifest(out / gallery.MANIFEST)) == ["README.md", "fig4_3.svg", "fig5_6.svg"]
    small_registry.pop("fig5_6")                          # the registry drops a figure
    gallery.generate(out)
    assert not (out / "fig5_6.svg").exists()
    assert (out / "user.svg").read_text() == "<svg/>"
    # a user's file named like a new figure is not overwritten without --force
    (out / "fig5_6.svg").write_text("<svg>user</svg>")
    small_registry["fig5_6"] = load_all()["fig5_6"]
    from planargeo.errors import OutputError

    with pytest.raises(OutputError, match="fig5_6.svg"):
        gallery.generate(out)
    assert (out / "fig5_6.svg").read_text() == "<svg>user</svg>"


def test_files_get_normal_permissions(tmp_path, small_registry):
    import os

    mask = os.umask(0o022)
    try:
        gallery.generate(tmp_path / "g")
    finally:
        os.umask(mask)
    modes = {p.name: p.stat().st_mode & 0o777 for p in (tmp_path / "g").iterdir()}
    assert set(modes.values()) == {0o644}, modes


def test_out_missing_parent_file_or_device_is_one_line(tmp_path):
    (tmp_path / "afile").write_text("x")
    _one_line_error(_cli("--out", str(tmp_path / "no" / "such"), "--only", "fig1_2"), "does not exist")
    _one_line_error(_cli("--out", str(tmp_path / "afile"), "--only", "fig1_2"), "is a file")
    _one_line_error(_cli("--out", "/dev/full", "--only", "fig1_2"), "is a file")
    assert (tmp_path / "afile").read_text() == "x"
    assert not (tmp_path / "no").exists()


def test_full_device_midway_leaves_the_old_gallery_intact(tmp_path):
    """Under a file-size limit between the two figures' sizes the first one stages and the second fails:
    neither is replaced (all-or-nothing) and no temporary file is left."""
    out = tmp_path / "g"
    assert _cli("--out", str(out), "--only", "fig1_2", "fig4_3").returncode == 0
    sizes = {n: (out / f"{n}.svg").stat().st_size for n in ("fig1_2", "fig4_3")}
    assert sizes["fig1_2"] < 18000 < sizes["fig4_3"]
    for n in sizes:                                     # mark the old files (now the user's: --force below)
        (out / f"{n}.svg").write_text(f"<svg>old {n}</svg>")
    before = sorted(p.name for p in out.iterdir())
    r = _cli("--out", str(out), "--only", "fig1_2", "fig4_3", "--force", limit=18000)
    _one_line_error(r, "fig4_3.svg")
    for n in sizes:
        assert (out / f"{n}.svg").read_text() == f"<svg>old {n}</svg>"
    assert sorted(p.name for p in out.iterdir()) == before


# --------------------------------------------------------------------------- the manifest keeps hashes (issue 23.4)
def _sha256(path) -> str:
    import hashlib

    return hashlib.sha256(path.read_bytes()).hexdigest()


def test_manifest_records_the_sha256_of_every_file_written(tmp_path, small_registry):
    out = tmp_path / "g"
    gallery.generate(out)
    lines = [ln for ln in (out / gallery.MANIFEST).read_text().splitlines() if not ln.startswith("#")]
    names = sorted(f"{n}.svg" for n in SUBSET) + ["README.md"]
    assert sorted(lines) == sorted(f"{_sha256(out / n)}  {n}" for n in names)   # sha256sum's format


def test_a_users_file_under_a_listed_name_is_kept(tmp_path, small_registry, capsys):
    """The manifest lists fig5_6.svg; the user has since put their own file by that name there. When the
    registry drops the figure, the next run keeps the user's file, says so in one line and stops listing it."""
    from planargeo.cli import main

    out = tmp_path / "g"
    gallery.generate(out)
    (out / "fig5_6.svg").write_text("<svg>my own figure</svg>")
    small_registry.pop("fig5_6")
    assert main(["gallery", "--out", str(out)]) == 0
    assert (out / "fig5_6.svg").read_text() == "<svg>my own figure</svg>"
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "fig5_6.svg" in err[0] and "yours" in err[0], err
    assert "fig5_6.svg" not in read_manifest(out / gallery.MANIFEST)
    assert main(["gallery", "--out", str(out)]) == 0                   # and it stays the user's
    assert (out / "fig5_6.svg").read_text() == "<svg>my own figure</svg>"
    # an unchanged file the gallery wrote and no longer renders is still deleted
    small_registry.pop("fig4_3")
    assert main(["gallery", "--out", str(out)]) == 0
    assert not (out / "fig4_3.svg").exists()


def test_an_old_manifest_without_hashes_is_migrated_safely(tmp_path, small_registry):
    """Bare names (no hash): a file counts as the gallery's only if identical to what would be written."""
    from planargeo.errors import OutputError

    out = tmp_path / "g"
    fresh = gallery.generate(tmp_path / "fresh")
    out.mkdir()
    for n in ("fig4_3.svg", "fig5_6.svg", "README.md"):
        (out / n).write_bytes(fresh[n])
    (out / "old_figure.svg").write_text("<svg>the user's, under a name the old gallery listed</svg>")
    old_manifest = "# files written by `planargeo gallery`; it overwrites or deletes only these\n" \
                   "README.md\nfig4_3.svg\nfig5_6.svg\nold_figure.svg\n"
    (out / gallery.MANIFEST).write_text(old_manifest)
    notes = []
    gallery.generate(out, say=notes.append)
    assert (out / "old_figure.svg").read_text().startswith("<svg>the user's")
    assert len(notes) == 1 and "old_figure.svg" in notes[0]
    m = read_manifest(out / gallery.MANIFEST)
    assert m == {n: _sha256(out / n) for n in ("README.md", "fig4_3.svg", "fig5_6.svg")}
    # an unhashed entry whose bytes differ from the new render is the user's: refused, untouched
    (out / gallery.MANIFEST).write_text(old_manifest)
    (out / "fig5_6.svg").write_text("<svg>edited by hand</svg>")
    with pytest.raises(OutputError, match="fig5_6.svg"):
        gallery.generate(out)
    assert (out / "fig5_6.svg").read_text() == "<svg>edited by hand</svg>"
    # --only keeps the unhashed entries of the figures it does not render
    gallery.generate(out, only=["fig4_3"])
    assert read_manifest(out / gallery.MANIFEST)["fig5_6.svg"] is None


# --------------------------------------------------------------------------- an unwritable target (issue 23.3)
def test_unwritable_targets_get_one_line_naming_the_folder(tmp_path):
    """/proc/nope (mkdir fails), inside /proc (no file can be created): one line naming the folder, exit 1."""
    for out, words in (("/proc/nope", "cannot create the folder"), ("/proc", "cannot write in the folder")):
        r = _cli("--out", out, "--only", "fig1_2")
        _one_line_error(r, f"--out {out}", words)
        assert "wrote" not in r.stdout


def test_read_only_file_system_is_one_line(tmp_path):
    import sys

    from _readonly_fs import run_readonly

    code = "import sys; from planargeo.cli import main; sys.exit(main(sys.argv[1:]))"
    ro = tmp_path / "ro"
    ro.mkdir()
    for out in (ro / "new", ro):                         # a new folder in it, and the folder itself
        r = run_readonly(ro, [sys.executable, "-c", code, "gallery", "--out", str(out), "--only", "fig1_2"], empty=True)
        _one_line_error(r, f"--out {out}", "Read-only file system")
        assert r.stdout == ""
    # an existing gallery on a read-only file system: the same, and its files are unchanged
    g = tmp_path / "g"
    assert _cli("--out", str(g), "--only", "fig1_2").returncode == 0
    before = {p.name: p.read_bytes() for p in g.iterdir()}
    r = run_readonly(g, [sys.executable, "-c", code, "gallery", "--out", str(g), "--only", "fig1_2", "fig4_3"])
    _one_line_error(r, f"--out {g}", "Read-only file system")
    assert {p.name: p.read_bytes() for p in g.iterdir()} == before
