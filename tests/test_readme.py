"""README.md's ```python blocks run, and the results shown in their comments are what they return.

A block is run statement by statement.  An expression statement whose trailing comment starts with
a repr (``Point(...)``, ``Line(...)``, ``array(...)``, a tuple ...) must have exactly that repr; one whose comment starts
with a number must have that value.  Independently of those comments, the "A first look" values
are checked against hand computations (thesis 4.10 pole, power v·f, 5.67 axis of percussion, and the
accelerations of a double pendulum from its Lagrangian written out here).
"""
import ast
import io
import re
import tokenize
from pathlib import Path

import numpy as np
import pytest

README = Path(__file__).resolve().parents[1] / "README.md"
REPR_START = re.compile(r"(Point|Line|Conic|Twist|Wrench|Inertia|JointSpace|array)?\(")   # a repr, or a tuple
NUMBER_START = re.compile(r"[-+]?\d+(\.\d*)?([eE][-+]?\d+)?(?=[\s:;,]|$)")


def python_blocks() -> list[str]:
    blocks = re.findall(r"^```python\n(.*?)^```", README.read_text(encoding="utf-8"), re.S | re.M)
    assert blocks, "README.md has no ```python block"
    return blocks


def _comments(src: str) -> dict[int, str]:
    """Line number -> text of the comment on that line (without '#')."""
    out = {}
    for tok in tokenize.generate_tokens(io.StringIO(src).readline):
        if tok.type == tokenize.COMMENT:
            out[tok.start[0]] = tok.string[1:].strip()
    return out


def _balanced(text: str) -> str:
    """The leading ``Name(...)`` of ``text``, up to its matching closing parenthesis."""
    depth = 0
    for i, ch in enumerate(text):
        depth += ch == "("
        depth -= ch == ")"
        if ch == ")" and depth == 0:
            return text[:i + 1]
    raise AssertionError(f"unbalanced parentheses in README comment {text!r}")


def run_block(src: str):
    """Run ``src``; returns the namespace and ``[(line, source, value, comment)]`` of its expressions."""
    tree = ast.parse(src)
    comments = _comments(src)
    ns: dict = {}
    shown = []
    for stmt in tree.body:
        if isinstance(stmt, ast.Expr):
            value = eval(compile(ast.Expression(stmt.value), "README.md", "eval"), ns)
            shown.append((stmt.lineno, ast.get_source_segment(src, stmt), value, comments.get(stmt.end_lineno, "")))
        else:
            exec(compile(ast.Module([stmt], type_ignores=[]), "README.md", "exec"), ns)
    return ns, shown


@pytest.mark.parametrize("index", range(len(python_blocks())))
def test_readme_block_runs_and_shows_what_it_returns(index):
    _, shown = run_block(python_blocks()[index])
    checked = 0
    for line, source, value, comment in shown:
        if REPR_START.match(comment):
            assert repr(value) == _balanced(comment), f"README python block {index}, line {line}: {source}"
            checked += 1
        elif NUMBER_START.match(comment):
            expected = float(NUMBER_START.match(comment).group(0))
            assert float(np.asarray(value)) == pytest.approx(expected, rel=1e-12, abs=1e-12), \
                f"README python block {index}, line {line}: {source}"
            checked += 1
    assert checked == sum(1 for *_, c in shown if c), "an expression's comment shows no checkable result"


def test_first_look_values_against_hand_computations():
    first = next(b for b in python_blocks() if "import planargeo as pg" in b)
    ns, shown = run_block(first)
    values = {source: value for _, source, value, _ in shown}
    assert len(values) >= 4                                   # pole, line, power, axis of percussion
    # 4.10: the pole of the rotation about (1, 2) is (1, 2)
    pole = values["v.pole"]
    np.testing.assert_allclose(pole.xy, [1.0, 2.0], atol=1e-15)
    # power v·f = ω · (moment of f about the pole): f = (1, 0) through the origin, arm from the pole
    # (0 - 1, 0 - 2): moment = (-1)(0) - (-2)(1) = 2, ω = 3
    assert float(values["v @ f"]) == pytest.approx(3.0 * 2.0, abs=1e-14)
    # 5.67: pole at the origin, c.o.m. at d = 1, ρ = 0.5: the axis is x = d + ρ²/d = 1.25, along y
    axis = values["bat.percussion_axis(pg.Point.from_xy(0.0, 0.0))"]
    assert axis.incidence(ns["pg"].Point.from_xy(1.25, 0.0)) == pytest.approx(0.0, abs=1e-14)
    assert axis.incidence(ns["pg"].Point.from_xy(1.25, 7.0)) == pytest.approx(0.0, abs=1e-13)
    assert abs(axis.incidence(ns["pg"].Point.from_xy(1.0, 0.0))) > 0.1

    # the arm: two uniform links (m = 1, L = 1, centre at L/2, I = m L²/12), at rest, no joint torques.
    # Lagrange: M(q₂) q̈ = -G(q), with
    #   M₁₁ = 2 I + m c² + m (L² + c² + 2 L c cos q₂),  M₁₂ = I + m (c² + L c cos q₂),  M₂₂ = I + m c²,
    #   G₁ = g (m c cos q₁ + m (L cos q₁ + c cos(q₁ + q₂))),  G₂ = g m c cos(q₁ + q₂).
    g, m, L, c, inertia = 9.81, 1.0, 1.0, 0.5, 1.0 / 12

    def lagrange(q):
        q1, q2 = q[..., 0], q[..., 1]
        M11 = 2 * inertia + m * c**2 + m * (L**2 + c**2 + 2 * L * c * np.cos(q2))
        M12 = inertia + m * (c**2 + L * c * np.cos(q2))
        M22 = inertia + m * c**2 + 0 * q2
        G1 = g * (m * c * np.cos(q1) + m * (L * np.cos(q1) + c * np.cos(q1 + q2)))
        G2 = g * m * c * np.cos(q1 + q2)
        M = np.stack([np.stack([M11, M12], -1), np.stack([M12, M22], -1)], -2)
        return np.linalg.solve(M, -np.stack([G1, G2], -1)[..., None])[..., 0]

    straight = values["pg.forward_dynamics(arm, q=[0.0, 0.0], qd=[0.0, 0.0], tau=[0.0, 0.0])"]
    np.testing.assert_allclose(straight, [-9 * g / 7, 12 * g / 7], rtol=1e-13)
    np.testing.assert_allclose(lagrange(np.zeros(2)), [-9 * g / 7, 12 * g / 7], rtol=1e-13)
    q, qdd = ns["q"], ns["qdd"]
    assert q.shape == qdd.shape == (10_000, 2)
    np.testing.assert_allclose(qdd, lagrange(q), rtol=1e-9, atol=1e-9 * g)


# --------------------------------------------------------------------------- make lab (issue 16: servers)
def _listening_addresses(port: int) -> set[str]:
    """Local addresses (hex, as in /proc/net/tcp*) of the sockets listening on ``port``."""
    out = set()
    for table in ("/proc/net/tcp", "/proc/net/tcp6"):
        try:
            rows = Path(table).read_text().splitlines()[1:]
        except OSError:
            continue
        for row in rows:
            local, state = row.split()[1], row.split()[3]
            addr, p = local.rsplit(":", 1)
            if int(p, 16) == port and state == "0A":      # 0A: LISTEN
                out.add(addr)
    return out


@pytest.mark.slow
def test_make_lab_listens_on_localhost_only_with_a_token(tmp_path):
    """The README's promise: `make lab` serves on 127.0.0.1 only and refuses requests without the token.

    The command is the one `make -n lab` prints (with a free port and no browser added)."""
    import json
    import os
    import socket
    import subprocess
    import sys
    import time
    import urllib.error
    import urllib.request

    root = README.parent
    assert "127.0.0.1" in README.read_text() and "token" in README.read_text()
    dry = subprocess.run(["make", "-n", "lab", f"BIN={Path(sys.executable).parent}", "STAMP=Makefile"],
                         cwd=root, capture_output=True, text=True, timeout=60)
    line = next(x for x in dry.stdout.splitlines() if "scripts/lab.py" in x)
    assert "token" not in line.lower()          # the token is made at each start, never on the line
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    env = dict(os.environ, JUPYTER_CONFIG_DIR=str(tmp_path / "cfg"),
               JUPYTER_RUNTIME_DIR=str(tmp_path / "rt"), JUPYTER_DATA_DIR=str(tmp_path / "data"))
    log = tmp_path / "lab.log"
    with log.open("w") as out:
        proc = subprocess.Popen(["bash", "-c", f"exec {line} --ServerApp.port={port} --ServerApp.port_retries=0 "
                                               "--no-browser"], cwd=root, env=env, stdout=out, stderr=out)
    try:
        token, deadline = None, time.monotonic() + 120
        while token is None and time.monotonic() < deadline:      # the server's own record of its token
            assert proc.poll() is None, log.read_text()
            for info in (tmp_path / "rt").glob("jpserver-*.json"):
                try:
                    data = json.loads(info.read_text())
                except ValueError:                                   # being written
                    continue
                token = data.get("token") if data.get("port") == port else None
            time.sleep(0.2)
        assert token and len(token) == 48, log.read_text()
        url = f"http://127.0.0.1:{port}/api/status"
        with pytest.raises(urllib.error.HTTPError) as refused:
            urllib.request.urlopen(url, timeout=10)
        assert refused.value.code == 403
        with urllib.request.urlopen(f"{url}?token={token}", timeout=10) as ok:
            assert ok.status == 200
        assert _listening_addresses(port) == {"0100007F"}        # 127.0.0.1, and nothing else
    finally:
        proc.terminate()
        proc.wait(timeout=30)
