"""The label placer's compiled loops (numba) place every label as the same source run as plain
Python (``NUMBA_DISABLE_JIT=1``) does: crowded pictures, labels moved, slid along lines and hidden."""
from __future__ import annotations

import json
import os
import subprocess
import sys

CODE = """
import json, math
from planargeo.draw.picture import Picture
out = []
for n in (3, 12, 40):
    pic = Picture((-2, 2, -2, 2), size=(300, 260), ticks=False)
    pic.text("note", (-1.9, 1.9), "a fixed note", ha="left", va="top")
    for k in range(n):
        a = 2 * math.pi * k / n
        pic.line(f"f{k}", [math.cos(a), math.sin(a), 0.3 * math.sin(3 * a)], symbol=f"f{k}")
        pic.point(f"P{k}", [0.5 * math.sin(2 * a), math.cos(a), 0.7 + 0.2 * k], symbol=f"P{k}")
    out.append(pic.to_dict())
print(json.dumps(out))
"""


def _pictures(plain: bool) -> list:
    env = dict(os.environ, NUMBA_DISABLE_JIT="1" if plain else "0")
    run = subprocess.run([sys.executable, "-c", CODE], capture_output=True, text=True, env=env, check=True)
    return json.loads(run.stdout)


def test_compiled_placer_matches_plain_python():
    compiled, plain = _pictures(False), _pictures(True)
    texts = [p for pic in plain for e in pic["elements"] for p in e["parts"] if p["p"] == "text"]
    assert any(p.get("hidden") for p in texts)            # the crowded picture hides some labels,
    assert any(p["ha"] != "left" for p in texts)          # moves others beside their anchors
    assert compiled == plain
