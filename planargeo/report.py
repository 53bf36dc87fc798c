"""``planargeo report``: print a scene's parameters, state and solved quantities.

Usage::

    planargeo report SCENE [--set NAME=VALUE ...] [--json] [--allow-big]
    planargeo report --list [--json]

Values given with ``--set`` are read as ``int``, ``float`` (``1e-3``, ``nan``,
``inf``), ``bool`` (``true``/``false``), ``none``, a JSON list (``[1, 2]``) or
else kept as a string; an integer given for a parameter whose default is a
float becomes a float.  Errors (unknown scene or parameter, a value that makes
the scene impossible or beyond double precision, a size past the scene's limit
without ``--allow-big``) exit with status 1 and one line on stderr; malformed
arguments exit with status 2.

Examples
--------
>>> import argparse
>>> p = argparse.ArgumentParser(); add_arguments(p)
>>> main(p.parse_args(["two-body", "--set", "phi=0", "--json"]))  # doctest: +ELLIPSIS
{"scene": "two-body", "params": {"m": 1.0, "rho": 0.5, "L": 1.0, "phi": 0.0}, ...
0
>>> parse_value("3"), parse_value("2.5"), parse_value("True"), parse_value("none"), parse_value("abc")
(3, 2.5, True, None, 'abc')
"""
from __future__ import annotations

import argparse
import json
import math
import sys
from typing import Any

import numpy as np

__all__ = ["add_arguments", "main", "parse_value", "parse_sets", "to_plain", "format_table"]


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Register the ``report`` command's arguments on ``parser``."""
    parser.add_argument("scene", nargs="?", help="scene name (see --list)")
    parser.add_argument("--set", dest="sets", action="append", default=[], metavar="NAME=VALUE",
                        help="set a scene parameter (repeatable)")
    parser.add_argument("--json", action="store_true", help="print one JSON object instead of a table")
    parser.add_argument("--list", action="store_true", help="list the scenes and their parameters")
    parser.add_argument("--allow-big", action="store_true",
                        help="lift the scene's size limits (e.g. chain n <= 200) for a deliberate big job")


def parse_value(text: str) -> Any:
    """Read a command-line value as int, float, bool, None, JSON list or string.

    Examples
    --------
    >>> parse_value("-4"), parse_value("1e-3"), parse_value("[1, 2.5]"), parse_value("FALSE")
    (-4, 0.001, [1, 2.5], False)
    """
    t = text.strip()
    low = t.lower()
    if low in ("true", "false"):
        return low == "true"
    if low in ("none", "null"):
        return None
    try:
        return int(t)
    except ValueError:
        pass
    try:
        return float(t)
    except ValueError:
        pass
    if t.startswith("["):
        try:
            return json.loads(t)
        except json.JSONDecodeError:
            pass
    return text


def parse_sets(sets: list[str], defaults: dict[str, Any] | None = None) -> dict[str, Any]:
    """``["a=1", "b=x"]`` -> ``{"a": 1, "b": "x"}``; ints become floats where the default is a float.

    Raises :class:`~planargeo.errors.InputError` for an item without ``=`` or
    with an empty name (``planargeo report`` exits with status 2 on it).

    Examples
    --------
    >>> parse_sets(["n=2", "lam=3"], {"n": 4, "lam": 2.0})
    {'n': 2, 'lam': 3.0}
    >>> parse_sets(["n"])
    Traceback (most recent call last):
        ...
    planargeo.errors.InputError: --set expects NAME=VALUE, got 'n'
    """
    from planargeo.errors import InputError

    out: dict[str, Any] = {}
    for item in sets:
        name, sep, value = item.partition("=")
        name = name.strip()
        if not sep or not name:
            raise InputError(f"--set expects NAME=VALUE, got {item!r}")
        v = parse_value(value)
        if defaults is not None and isinstance(defaults.get(name), float) and type(v) is int:
            v = float(v)
        out[name] = v
    return out


def to_plain(x: Any) -> Any:
    """Plain JSON-able Python values: numbers, strings, bools, None, lists and dicts."""
    if isinstance(x, dict):
        return {str(k): to_plain(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [to_plain(v) for v in x]
    if isinstance(x, np.ndarray):
        return to_plain(x.tolist())
    if isinstance(x, (bool, np.bool_)):
        return bool(x)
    if isinstance(x, (int, np.integer)):
        return int(x)
    if isinstance(x, (float, np.floating)):
        return float(x)
    if x is None or isinstance(x, str):
        return x
    return str(x)


def _fmt_number(v: Any) -> str:
    if isinstance(v, bool) or v is None:
        return str(v)
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isfinite(v) and v == int(v) and abs(v) < 1e12:
            return f"{v:.1f}"
        return f"{v:.6g}"
    return str(v)


#: Matrices with more columns than this are summarised in the table (``--json`` has the values).
MAX_TABLE_COLUMNS = 12


def _is_matrix(v: Any) -> bool:
    return (isinstance(v, list) and len(v) > 0 and all(isinstance(r, list) for r in v)
            and all(not isinstance(x, (list, dict)) for r in v for x in r))


def _shape(v: Any) -> tuple[int, ...] | None:
    """Shape of a rectangular nested list of numbers (``()`` for a number), else None."""
    if isinstance(v, list):
        if not v:
            return (0,)
        subs = [_shape(x) for x in v]
        if subs[0] is None or any(s != subs[0] for s in subs):
            return None
        return (len(v),) + subs[0]
    if isinstance(v, (int, float)) and not isinstance(v, bool):
        return ()
    return None


def _fmt_value(v: Any, indent: int) -> list[str]:
    """Lines for one value: scalars and vectors on one line, matrices as aligned rows.

    A matrix wider than :data:`MAX_TABLE_COLUMNS` is summarised by its shape
    (``--json`` gives its values); an array of three or more dimensions gets
    a shape line, then its matrices one after the other, each labelled with
    its leading indices.  Ragged nested lists are printed as JSON.

    Examples
    --------
    >>> for line in _fmt_value([[[1.0, 0.0], [0.0, 1.0]], [[2.0, 0.5], [0.5, 3.0]]], 0):
    ...     print(line)
    shape (2, 2, 2)
    [0]  [1.0  0.0]
         [0.0  1.0]
    [1]  [2.0  0.5]
         [0.5  3.0]
    >>> _fmt_value([[0.0] * 27] * 27, 0)
    ['27×27 matrix, too wide for the table (--json gives its values)']
    """
    shape = _shape(v)
    if shape is not None and len(shape) == 2 and shape[1] > MAX_TABLE_COLUMNS:
        return [f"{shape[0]}×{shape[1]} matrix, too wide for the table (--json gives its values)"]
    if shape is not None and len(shape) >= 3:
        if shape[-1] > MAX_TABLE_COLUMNS:
            dims = " × ".join(map(str, shape))
            return [f"{dims} array, too wide for the table (--json gives its values)"]
        lines = [f"shape {shape}"]
        width = len(str(shape[0] - 1)) + 2
        for i, sub in enumerate(v):
            body = _fmt_value(sub, indent + width + 2)
            if body and body[0].startswith("shape "):
                body = body[1:]
            label = f"[{i}]".ljust(width)
            lines.append(f"{label}  {body[0]}")
            lines.extend(" " * (width + 2) + s for s in body[1:])
        return lines
    if _is_matrix(v):
        cells = [[_fmt_number(x) for x in r] for r in v]
        width = max((len(c) for r in cells for c in r), default=1)
        return ["[" + "  ".join(c.rjust(width) for c in r) + "]" for r in cells]
    if isinstance(v, list) and all(not isinstance(x, (list, dict)) for x in v):
        return ["[" + ", ".join(_fmt_number(x) for x in v) + "]"]
    if isinstance(v, dict):
        lines = []
        for k, w in v.items():
            sub = _fmt_value(w, indent + 2)
            lines.append(f"{k}: {sub[0]}")
            lines.extend(" " * (len(str(k)) + 2) + s for s in sub[1:])
        return lines or ["{}"]
    if isinstance(v, list):
        return [json.dumps(v)]
    return [_fmt_number(v)]


def format_table(result: dict) -> str:
    """Readable text of a plain report ``{"scene", "params", "state", "quantities"}``.

    Examples
    --------
    >>> print(format_table({"scene": "x", "params": {"a": 1.5}, "state": {}, "quantities": {"M": [[1.0, 0.0], [0.0, 2.0]]}}))
    scene: x
    <BLANKLINE>
    parameters
      a  1.5
    <BLANKLINE>
    state
      (none)
    <BLANKLINE>
    quantities
      M  [1.0  0.0]
         [0.0  2.0]
    """
    out = [f"scene: {result['scene']}"]
    for title, key in (("parameters", "params"), ("state", "state"), ("quantities", "quantities")):
        out += ["", title]
        items = result.get(key) or {}
        if not items:
            out.append("  (none)")
            continue
        width = max(len(str(k)) for k in items)
        for k, v in items.items():
            lines = _fmt_value(v, 0)
            out.append(f"  {str(k).ljust(width)}  {lines[0]}")
            out.extend(" " * (width + 4) + line for line in lines[1:])
    return "\n".join(out)


def _error(msg: str, code: int) -> int:
    print(f"planargeo report: error: {msg}", file=sys.stderr)
    return code


def main(args: argparse.Namespace) -> int:
    """Run ``planargeo report``; returns the exit status."""
    from planargeo import scenes
    from planargeo.errors import InputError, PlanargeoError

    if args.list:
        listing = {}
        for name in scenes.names():
            try:
                listing[name] = to_plain(scenes.parameters(name))
            except PlanargeoError as exc:  # pragma: no cover - a broken scene module
                return _error(str(exc).splitlines()[0], 1)
        if args.json:
            print(json.dumps({"scenes": listing}))
        else:
            for name, params in listing.items():
                ps = ", ".join(f"{k}={_fmt_number(v) if not isinstance(v, str) else v}" for k, v in params.items())
                print(f"{name}: {ps}" if ps else name)
        return 0
    if not args.scene:
        return _error("a scene name is required (planargeo report --list shows them)", 2)
    try:
        defaults = scenes.parameters(args.scene)
    except PlanargeoError as exc:
        return _error(str(exc).splitlines()[0], 1)
    try:
        params = parse_sets(args.sets, defaults)
    except InputError as exc:                  # a malformed --set: a usage error
        return _error(str(exc).splitlines()[0], 2)
    try:       # results beyond double precision are a SceneRangeError naming the parameters
        res = scenes.build(args.scene, allow_big=args.allow_big, **params)
    except PlanargeoError as exc:
        return _error(str(exc).splitlines()[0] if str(exc) else type(exc).__name__, 1)
    report = {"scene": res.name, "params": to_plain(res.params), "state": to_plain(res.state),
              "quantities": to_plain(res.quantities)}
    print(json.dumps(report, allow_nan=False) if args.json else format_table(report))
    return 0
