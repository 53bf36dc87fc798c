"""`planargeo bench`: it writes only into a new folder or one it made (a manifest with hashes), an
unusable --out is one line, and its sizes are bounded (issue 23.2, 23.3 and "every long-running
entry point is bounded").

Most tests run a stand-in suite (``--suite``, a public option): a ``run.py`` that writes a few
result files the way ``benchmarks/run.py`` does, so that they take a second, not minutes."""
from __future__ import annotations

import hashlib
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from planargeo.errors import InputError, NonFiniteError, SizeLimitError
from planargeo.files import read_manifest
from planargeo.run_benchmarks import MANIFEST, MAX_SIZE, parse_sizes

ROOT = Path(__file__).resolve().parents[1]

FAKE_RUN = '''
import argparse, os, sys, time
from pathlib import Path
p = argparse.ArgumentParser()
p.add_argument("--out"); p.add_argument("--summary"); p.add_argument("--gallery")
p.add_argument("--quick", action="store_true"); p.add_argument("--no-charts", action="store_true")
p.add_argument("--sizes"); p.add_argument("--only", action="append")
a = p.parse_args()
out = Path(a.out)
(out / "batch.md").write_text(f"batch {time.time_ns()}")
(out / "sub").mkdir()
(out / "sub" / "raw.json").write_text("{}")
Path(a.summary).write_text(f"summary {time.time_ns()} argv {sys.argv[1:]}")
if os.environ.get("FAKE_SLEEP"):
    try:
        time.sleep(float(os.environ["FAKE_SLEEP"]))
    except KeyboardInterrupt:
        sys.exit(130)
sys.exit(int(os.environ.get("FAKE_RC", "0")))
'''


@pytest.fixture
def suite(tmp_path):
    s = tmp_path / "suite"
    s.mkdir()
    (s / "run.py").write_text(FAKE_RUN)
    return s


def bench(*args, env=None, timeout=120, **kw):
    return subprocess.run([sys.executable, "-m", "planargeo.cli", "bench", *map(str, args)], capture_output=True,
                          text=True, timeout=timeout, cwd=ROOT, env={**os.environ, **(env or {})}, **kw)


def one_line(r, *words, status=1):
    assert r.returncode == status, (r.returncode, r.stderr)
    assert "Traceback" not in r.stderr and "results in" not in r.stdout, (r.stdout, r.stderr)
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("planargeo bench: "), r.stderr
    for w in words:
        assert w in lines[0], (w, lines[0])


def sha(path) -> str:
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def listing(folder) -> dict[str, bytes]:
    return {p.relative_to(folder).as_posix(): p.read_bytes() for p in sorted(Path(folder).rglob("*")) if p.is_file()}


# --------------------------------------------------------------------------- a user's results are never replaced
def test_the_users_results_are_refused_without_force(tmp_path):
    """The issue's run, on the real suite: R holds the user's RESULTS.md and batch.md; refused before anything
    runs, one line, both files unchanged (it used to replace them and exit 0)."""
    r_dir = tmp_path / "R"
    r_dir.mkdir()
    (r_dir / "RESULTS.md").write_text("my results")
    (r_dir / "batch.md").write_text("my batch notes")
    r = bench("--out", r_dir, "--quick", "--only", "dynamics", "--no-charts", timeout=300)
    one_line(r, f"--out {r_dir}", "not a benchmark result", "--force")
    assert listing(r_dir) == {"RESULTS.md": b"my results", "batch.md": b"my batch notes"}


def test_a_new_folder_gets_a_manifest_and_can_be_rerun(tmp_path, suite):
    out = tmp_path / "new"
    r = bench("--suite", suite, "--out", out, "--sizes", "2,5")
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == f"planargeo bench: results in {out}"
    files = listing(out)
    assert sorted(files) == sorted([MANIFEST, "RESULTS.md", "batch.md", "sub/raw.json"])
    assert "'--sizes', '2,5'" in files["RESULTS.md"].decode()          # the sizes reach the suite
    assert read_manifest(out / MANIFEST) == {n: sha(out / n) for n in ("RESULTS.md", "batch.md", "sub/raw.json")}
    # its own folder: a second run replaces its results without --force
    r = bench("--suite", suite, "--out", out)
    assert r.returncode == 0, r.stderr
    again = listing(out)
    assert again["RESULTS.md"] != files["RESULTS.md"] and again["batch.md"] != files["batch.md"]
    assert read_manifest(out / MANIFEST) == {n: sha(out / n) for n in ("RESULTS.md", "batch.md", "sub/raw.json")}
    # an empty folder loses nothing: accepted
    (tmp_path / "empty").mkdir()
    assert bench("--suite", suite, "--out", tmp_path / "empty").returncode == 0


def test_files_the_user_changed_or_added_are_left(tmp_path, suite):
    """In its own folder, a result the user has since edited is theirs: left, named in one line, exit 1; the
    other results are replaced; a file of their own is untouched; --force replaces the edited one."""
    out = tmp_path / "R"
    assert bench("--suite", suite, "--out", out).returncode == 0
    (out / "RESULTS.md").write_text("my edited summary")
    (out / "notes.md").write_text("my notes")
    old_batch = (out / "batch.md").read_bytes()
    r = bench("--suite", suite, "--out", out)
    one_line(r, "RESULTS.md", f"in {out}", "--force")
    assert (out / "RESULTS.md").read_text() == "my edited summary"
    assert (out / "notes.md").read_text() == "my notes"
    assert (out / "batch.md").read_bytes() != old_batch
    m = read_manifest(out / MANIFEST)
    assert "RESULTS.md" not in m and "notes.md" not in m and m["batch.md"] == sha(out / "batch.md")
    r = bench("--suite", suite, "--out", out, "--force")
    assert r.returncode == 0, r.stderr
    assert (out / "RESULTS.md").read_text().startswith("summary ")
    assert (out / "notes.md").read_text() == "my notes"
    assert read_manifest(out / MANIFEST)["RESULTS.md"] == sha(out / "RESULTS.md")


def test_a_failing_suite_gets_no_success_line(tmp_path, suite):
    out = tmp_path / "R"
    r = bench("--suite", suite, "--out", out, env={"FAKE_RC": "3"})
    one_line(r, "exit status 3", str(out), status=3)
    assert (out / "RESULTS.md").is_file()                   # what it wrote is kept
    assert not any(p.name.startswith(".planargeo-bench-run-") for p in out.iterdir())


def test_ctrl_c_keeps_what_was_written(tmp_path, suite):
    out = tmp_path / "R"
    proc = subprocess.Popen([sys.executable, "-m", "planargeo.cli", "bench", "--suite", str(suite), "--out", str(out)],
                            cwd=ROOT, env={**os.environ, "FAKE_SLEEP": "60"}, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        deadline = time.monotonic() + 60
        while not list(out.glob(".planargeo-bench-run-*/RESULTS.md")):
            assert time.monotonic() < deadline and proc.poll() is None, "the stand-in suite never wrote"
            time.sleep(0.1)
        os.killpg(proc.pid, signal.SIGINT)                  # Ctrl-C reaches the whole foreground group
        stdout, stderr = proc.communicate(timeout=60)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
    assert proc.returncode == 130 and "Traceback" not in stderr, stderr
    assert stderr.strip().splitlines() == [f"planargeo bench: interrupted; the 3 result files written so far are "
                                           f"in {out}"]
    assert (out / "RESULTS.md").read_text().startswith("summary ") and "results in" not in stdout
    assert sorted(read_manifest(out / MANIFEST)) == ["RESULTS.md", "batch.md", "sub/raw.json"]


# --------------------------------------------------------------------------- an unusable --out is one line
def test_unwritable_targets_are_one_line_and_no_success(tmp_path, suite):
    (tmp_path / "afile").write_text("x")
    for out, words in (("/proc/nope", "cannot create the folder"),
                       (tmp_path / "no" / "such", "does not exist"),
                       (tmp_path / "afile", "not a folder"), ("/dev/full", "not a folder")):
        one_line(bench("--out", out, "--quick"), f"--out {out}", words)
    one_line(bench("--out", "/proc", "--quick", "--force"), "--out /proc", "cannot write in the folder")
    assert not (tmp_path / "no").exists() and (tmp_path / "afile").read_text() == "x"


def test_read_only_file_system_is_one_line(tmp_path, suite):
    from _readonly_fs import run_readonly

    ro = tmp_path / "ro"
    ro.mkdir()
    cmd = [sys.executable, "-m", "planargeo.cli", "bench", "--suite", suite, "--quick"]
    for out in (ro / "new", ro):          # a new folder on a read-only file system, and an empty one there
        r = run_readonly(ro, [*cmd, "--out", out], empty=True)
        one_line(r, f"--out {out}", "Read-only file system")
    # its own earlier result, now on a read-only file system: one line, the files unchanged
    res = tmp_path / "res"
    assert bench("--suite", suite, "--out", res).returncode == 0
    before = listing(res)
    one_line(run_readonly(res, [*cmd, "--out", res]), f"--out {res}", "Read-only file system")
    assert listing(res) == before


# --------------------------------------------------------------------------- sizes are bounded
HOSTILE = ("1e6", "1e300", "inf", "nan", "-1", "0")


@pytest.mark.parametrize("value", HOSTILE)
def test_sizes_out_of_bounds_get_a_named_error_at_once(tmp_path, suite, value):
    """Each hostile size is refused before anything runs (under a timeout), naming --sizes and, past the
    limit, the limit and the opt-in; nothing is created."""
    out = tmp_path / "R"
    for extra in ((), ("--large",)):
        r = bench("--suite", suite, "--out", out, "--sizes", value, *extra, timeout=60)
        one_line(r, "--sizes", value)
    assert not out.exists()


def test_parse_sizes_errors_are_named():
    for v in ("1e6", "1e300", str(MAX_SIZE + 1)):
        with pytest.raises(SizeLimitError, match=rf"limit of {MAX_SIZE} bodies.*pass --large"):
            parse_sizes(v)
    for v in ("1e6", "1e300"):                    # the model builders' MAX_BODIES = 10000 holds even with --large
        with pytest.raises(SizeLimitError, match="past 10000 bodies.*even with --large"):
            parse_sizes(v, large=True)
    assert parse_sizes(str(MAX_SIZE + 1), large=True) == (MAX_SIZE + 1,)
    for v in ("inf", "nan", "-inf"):
        with pytest.raises(NonFiniteError, match="--sizes: N must be finite"):
            parse_sizes(v)
    for v in ("-1", "0", "2.5", "ten", ""):
        with pytest.raises(InputError, match="--sizes"):
            parse_sizes(v)
    with pytest.raises(SizeLimitError, match="33 sizes, past the limit of 32"):
        parse_sizes(",".join(["1"] * 33))
    assert parse_sizes(" 1, 1e1 ,50") == (1, 10, 50)
