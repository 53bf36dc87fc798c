"""``planargeo report``: print a scene's parameters, state and solved quantities.

``--list`` prints every scene's parameters and, per quantity, its description, thesis symbol,
equation and unit (:data:`QUANTITY_INFO`).  The table prints each value's unit, and round-off
(:func:`round_off`) as ``0.0``; ``--json`` keeps full precision.

Examples
--------
>>> import argparse
>>> p = argparse.ArgumentParser(); add_arguments(p)
>>> main(p.parse_args(["two-body", "--set", "phi=0", "--json"]))  # doctest: +ELLIPSIS
{"scene": "two-body", "params": {"m": 1.0, "rho": 0.5, "L": 1.0, "phi": 0.0}, ...
0
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import unicodedata
from typing import Any, NamedTuple

import numpy as np

from planargeo._validate import check_tolerance
from planargeo.errors import InputError, PlanargeoError
from planargeo.files import WORDS_FILE, package_words

__all__ = ["add_arguments", "main", "parse_value", "parse_sets", "to_plain", "format_table", "quantity_info",
           "quantity", "Quantity", "round_off", "format_listing", "QUANTITY_INFO", "QUANTITIES_FILE", "ZERO_TOL"]

#: Values below ``ZERO_TOL`` times the scene's scale for their unit print as 0 in the table.
ZERO_TOL = 1e-9

#: The data file of the quantities' descriptions (its ``[scene.*]`` tables).
QUANTITIES_FILE = WORDS_FILE


class Quantity(NamedTuple):
    """One reported quantity: ``description``, thesis ``symbol``, ``equation``, ``unit`` (``"—"``: none)."""

    description: str
    symbol: str
    equation: str
    unit: str


#: ``scene -> quantity -> Quantity`` of every quantity ``planargeo report`` prints, from :data:`QUANTITIES_FILE`.
QUANTITY_INFO: dict[str, dict[str, Quantity]] = {
    scene: {key: Quantity(**entry) for key, entry in table.items()}
    for scene, table in package_words("scene").items()}


def quantity(scene: str, key: str) -> Quantity:
    """Description, thesis symbol, equation and unit of one quantity ``planargeo report`` prints.

    Parameters
    ----------
    scene : str
        A registered scene name (:func:`planargeo.scenes.names`).
    key : str
        The quantity's key in ``SceneResult.quantities``.

    Returns
    -------
    Quantity

    Raises
    ------
    SceneError
        If no scene has that name.
    InputError
        If the scene reports no quantity ``key`` (the message lists those it does).

    Examples
    --------
    >>> quantity("slider-crank", "F3").equation
    '9.91, 9.92'
    """
    table = quantity_info(scene)
    if key not in table:
        raise InputError(f"key must be a quantity of scene {scene!r} ({', '.join(table) or 'none described'}), "
                         f"got {key!r}")
    return Quantity(**table[key])


def quantity_info(scene: str) -> dict[str, dict[str, str]]:
    """Description, thesis symbol, equation and unit of each quantity ``planargeo report`` prints for ``scene``.

    From :data:`QUANTITY_INFO`, completed by the scene module's own ``QUANTITY_INFO`` if it has one.

    Parameters
    ----------
    scene : str
        A registered scene name (:func:`planargeo.scenes.names`).

    Returns
    -------
    dict
        ``{key: {"description", "symbol", "equation", "unit"}}``.

    Raises
    ------
    SceneError
        If no scene has that name.

    Examples
    --------
    >>> quantity_info("slider-crank")["f"]["unit"], quantity_info("slider-crank")["f"]["equation"]
    ('N, N, N·m', '9.61')
    """
    from planargeo import scenes

    fn = scenes.get(scene)
    table = dict(QUANTITY_INFO.get(scene, {}))
    own = getattr(sys.modules.get(getattr(fn, "__module__", ""), None), "QUANTITY_INFO", None)
    if isinstance(own, dict) and own is not QUANTITY_INFO and isinstance(own.get(scene), dict):
        table.update(own[scene])
    return {k: Quantity(*v)._asdict() for k, v in table.items()}


def _magnitude(v: Any) -> float:
    """Largest finite magnitude in a plain value (numbers, nested lists and dicts), 0 if none."""
    if isinstance(v, dict):
        v = list(v.values())
    if isinstance(v, list):
        return max(map(_magnitude, v), default=0.0)
    if isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v):
        return abs(float(v))
    return 0.0


def _zeroed(v: Any, limit: float) -> Any:
    if isinstance(v, float):
        return 0.0 if abs(v) < limit or v == 0 else v
    if isinstance(v, dict):
        return {k: _zeroed(x, limit) for k, x in v.items()}
    if isinstance(v, list):
        return [_zeroed(x, limit) for x in v]
    return v


def round_off(quantities: dict, info: dict | None = None, tol: float = ZERO_TOL) -> dict:
    """Plain quantities with round-off shown as 0: magnitudes below ``tol`` × the scene's scale for their unit.

    The scale of a unit is the largest magnitude among the quantities of that unit; a quantity
    without a unit is its own group.  Integers, booleans and text are kept.

    Parameters
    ----------
    quantities : dict
        Plain values (:func:`to_plain`).
    info : dict, optional
        ``{key: {"unit": ...}}`` as :func:`quantity_info` returns.
    tol : float
        Relative threshold.

    Returns
    -------
    dict
        A copy with the small floats (and ``-0.0``) replaced by ``0.0``.

    Raises
    ------
    InputError
        If ``tol`` is negative, not finite, or not a number.

    Examples
    --------
    >>> round_off({"a": [3.98e-12, -5.7, 1e-12], "b": 2.5e-11}, {"a": {"unit": "m/s²"}, "b": {"unit": "m/s²"}})
    {'a': [0.0, -5.7, 0.0], 'b': 0.0}
    """
    tol = check_tolerance(tol, "tol")
    info = info or {}
    unit_of = {k: (info.get(k) or {}).get("unit") or f"\0{k}" for k in quantities}
    scale: dict[str, float] = {}
    for k, v in quantities.items():
        scale[unit_of[k]] = max(scale.get(unit_of[k], 0.0), _magnitude(v))
    return {k: _zeroed(v, tol * scale[unit_of[k]]) for k, v in quantities.items()}


def _width(text: str) -> int:
    """Columns ``text`` takes in a terminal: combining marks (the dot of ``q̇``) take none."""
    return sum(0 if unicodedata.combining(ch) else 1 for ch in text)


def format_listing(listing: dict, infos: dict) -> str:
    """Text of ``planargeo report --list``: each scene's parameters, then its quantities with symbol, equation, unit.

    Parameters
    ----------
    listing : dict
        ``{scene: {parameter: default}}``.
    infos : dict
        ``{scene: quantity_info(scene)}``.

    Returns
    -------
    str

    Examples
    --------
    >>> print(format_listing({"x": {"a": 1.5}}, {"x": {"h": {"description": "height", "symbol": "h",
    ...                                                      "equation": "9.85", "unit": "m"}}}))
    x: a=1.5
      h  h  (9.85)  m  height
    """
    out = []
    for name, params in listing.items():
        ps = ", ".join(f"{k}={_fmt_number(v) if not isinstance(v, str) else v}" for k, v in params.items())
        out.append(f"{name}: {ps}" if ps else name)
        rows = [(k, d.get("symbol", ""), f"({d.get('equation', '')})", d.get("unit", ""), d.get("description", ""))
                for k, d in infos.get(name, {}).items()]
        if rows:
            widths = [max(_width(r[c]) for r in rows) for c in range(4)]
            out += ["  " + "  ".join(r[c] + " " * (widths[c] - _width(r[c])) for c in range(4)) + "  " + r[4]
                    for r in rows]
    return "\n".join(out)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Register the ``report`` command's arguments on ``parser``.

    Parameters
    ----------
    parser : argparse.ArgumentParser
        The parser of ``planargeo report``.
    """
    parser.add_argument("scene", nargs="?", help="scene name (see --list)")
    parser.add_argument("--set", dest="sets", action="append", default=[], metavar="NAME=VALUE",
                        help="set a scene parameter (repeatable)")
    parser.add_argument("--json", action="store_true", help="print one JSON object instead of a table")
    parser.add_argument("--list", action="store_true", help="list the scenes and their parameters")
    parser.add_argument("--allow-big", action="store_true",
                        help="lift the scene's size limits (e.g. chain n <= 200) for a deliberate big job")


def parse_value(text: str) -> Any:
    """Read a command-line value as int, float, bool, None, JSON list or (else) string.

    Parameters
    ----------
    text : str
        The value as typed.

    Returns
    -------
    int, float, bool, None, list or str

    Examples
    --------
    >>> parse_value("-4"), parse_value("1e-3"), parse_value("[1, 2.5]"), parse_value("FALSE"), parse_value("abc")
    (-4, 0.001, [1, 2.5], False, 'abc')
    """
    t = text.strip()
    low = t.lower()
    if low in ("true", "false"):
        return low == "true"
    if low in ("none", "null"):
        return None
    for number in (int, float):
        try:
            return number(t)
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

    Parameters
    ----------
    sets : list of str
        The ``--set`` items.
    defaults : dict, optional
        The scene's parameters with their defaults.

    Returns
    -------
    dict
        ``{name: value}``, each value read by :func:`parse_value`.

    Raises
    ------
    InputError
        An item without ``=`` or with an empty name (``planargeo report`` exits with status 2).

    Examples
    --------
    >>> parse_sets(["n=2", "lam=3"], {"n": 4, "lam": 2.0})
    {'n': 2, 'lam': 3.0}
    """
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
    """Plain JSON-able Python values: numbers, strings, bools, None, lists and dicts.

    Parameters
    ----------
    x : any
        Nested dicts, lists, tuples, numpy arrays and scalars.

    Returns
    -------
    any
        The same structure with numpy values turned into Python ones (anything else as ``str``).
    """
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
    if not isinstance(v, float):
        return str(v)
    if v == 0:
        return "0.0"                           # also -0.0
    if math.isfinite(v) and v == int(v) and abs(v) < 1e12:
        return f"{v:.1f}"
    return f"{v:.6g}"


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
    """Lines for one value: scalars and vectors on one line, matrices as aligned rows, wider ones as their shape."""
    shape = _shape(v)
    if shape is not None and len(shape) >= 2 and shape[-1] > MAX_TABLE_COLUMNS:
        what = f"{shape[0]}×{shape[1]} matrix" if len(shape) == 2 else f"{' × '.join(map(str, shape))} array"
        return [f"{what}, too wide for the table (--json gives its values)"]
    if shape is not None and len(shape) >= 3:
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


def format_table(result: dict, info: dict | None = None) -> str:
    """Readable text of a plain report ``{"scene", "params", "state", "quantities"}``.

    Parameters
    ----------
    result : dict
        The plain report (:func:`to_plain`).
    info : dict, optional
        :func:`quantity_info` of the scene: each quantity's unit is printed after its first line.

    Returns
    -------
    str

    Examples
    --------
    >>> format_table({"scene": "x", "params": {}, "state": {}, "quantities": {"M": [[1.0, 0.0], [0.0, 2.0]]}}).splitlines()[-2:]
    ['  M  [1.0  0.0]', '     [0.0  2.0]']
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
            unit = ((info or {}).get(k) or {}).get("unit", "") if key == "quantities" else ""
            if unit and unit != "—":
                lines[0] = f"{lines[0]}  {unit}"
            out.append(f"  {str(k).ljust(width)}  {lines[0]}")
            out.extend(" " * (width + 4) + line for line in lines[1:])
    return "\n".join(out)


def _error(msg: str, code: int) -> int:
    print(f"planargeo report: error: {msg}", file=sys.stderr)
    return code


def main(args: argparse.Namespace) -> int:
    """Run ``planargeo report``; returns the exit status.

    Parameters
    ----------
    args : argparse.Namespace
        Parsed arguments (:func:`add_arguments`).

    Returns
    -------
    int
        0 on success, 1 for a scene error, 2 for a usage error (one line on stderr).
    """
    from planargeo import scenes

    if args.list:
        listing, infos = {}, {}
        for name in scenes.names():
            listing[name] = to_plain(scenes.parameters(name))
            infos[name] = quantity_info(name)
        listed = {"scenes": listing, "quantities": infos}
        print(json.dumps(listed) if args.json else format_listing(listing, infos))
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
    if args.json:                              # full precision
        print(json.dumps(report, allow_nan=False))
        return 0
    info = quantity_info(res.name)
    report["quantities"] = round_off(report["quantities"], info)
    print(format_table(report, info))
    return 0
