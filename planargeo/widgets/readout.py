"""Readout text of the explorers: numbers with their units, points, and the "what is shown" panel.

The readout says each unit once.  A row whose numbers share one unit -- a number, a vector or a
point -- reads ``numbers unit`` (``"(0, -0.8) m"``) and the table puts the unit in its own column;
a vector whose components differ in unit names each after its number
(``"(1 m/s, -1.5 m/s, 3 rad/s)"``).  A unit follows numbers only (never a word, "at rest"), and
reads as a student writes it: ``kg⁻¹`` for ``1/kg`` (never ``0 1/kg``).  Numbers keep 4
significant digits, plain from 0.001 to 100000 (``10120``, not ``1.012e+04``); round-off prints
as ``0``; a point at infinity (:func:`~planargeo.geometry.projective.is_ideal`) reads
"at infinity (direction (dx, dy))".
"""
from __future__ import annotations

import html
import math
import numbers
import re
from typing import Any

import numpy as np

from planargeo.draw.picture import plain_text
from planargeo.geometry.projective import direction, is_ideal, to_xy

__all__ = ["QuantityText", "fmt", "unit_text", "point_text", "point_value",
           "value_text", "value_texts", "split_units", "explain_html", "is_numeric", "plain_symbol"]

#: units that mean "dimensionless": nothing is written
NO_UNIT = ("", "—", "-")


class QuantityText(str):
    """Text of numbers with one unit, ``"(1, 2) m"``, that keeps its numbers and unit apart.

    It is the text itself (a ``str``, equal to ``"(1, 2) m"``); :func:`fmt` gives its numbers and
    :func:`value_text` its numbers and unit, so a readout table puts the unit in its own column,
    as for any other row (:func:`point_text` returns one).

    Parameters
    ----------
    numbers : str
        The numbers, already formatted (plain text).
    unit : str
        Their unit ("" or "—": none).

    Examples
    --------
    >>> q = QuantityText("(1, 2)", "m")
    >>> q == "(1, 2) m", q.numbers, q.unit, fmt(q), value_text(q)
    (True, '(1, 2)', 'm', '(1, 2)', '(1, 2) m')
    """

    numbers: str
    unit: str

    def __new__(cls, numbers: str, unit: str = "") -> "QuantityText":
        unit = "" if unit in NO_UNIT or unit is None else str(unit)
        self = super().__new__(cls, f"{numbers} {unit}" if unit else str(numbers))
        self.numbers, self.unit = str(numbers), unit
        return self

    def __reduce__(self):
        return (QuantityText, (self.numbers, self.unit))


_FACTOR = re.compile(r"^([A-Za-zΩμ°]+)([²³]?)$")
_INVERSE = {"": "⁻¹", "²": "⁻²", "³": "⁻³"}


def unit_text(unit: str) -> str:
    """A unit as a student reads it: a reciprocal ``1/…`` in negative powers, others unchanged.

    Parameters
    ----------
    unit : str
        A unit of the explorers' data (``"m/s²"``, ``"1/kg"``, ``"1/(kg·m²)"``).

    Returns
    -------
    str

    Examples
    --------
    >>> unit_text("1/kg"), unit_text("1/(kg·m²)"), unit_text("m/s²"), unit_text("N·m")
    ('kg⁻¹', 'kg⁻¹·m⁻²', 'm/s²', 'N·m')
    """
    u = str(unit)
    if not u.startswith("1/"):
        return u
    rest = u[2:]
    if rest.startswith("(") and rest.endswith(")"):
        rest = rest[1:-1]
    factors = [_FACTOR.match(f) for f in rest.split("·")]
    if not rest or not all(factors):
        return u
    return "·".join(f[1] + _INVERSE[f[2]] for f in factors)


def fmt(x: Any, digits: int = 4, zero: float = 0.0) -> str:
    """Readable text for a readout value (numbers rounded, ideal values named).

    Parameters
    ----------
    x : Any
        A number, a tuple / array of numbers, a boolean or any object (shown as text).
    digits : int
        Significant digits of a number.
    zero : float
        Numbers whose magnitude is at most ``zero`` print as ``0`` (round-off).

    Returns
    -------
    str
        HTML-safe text.

    Examples
    --------
    >>> fmt(0.123456), fmt(float("inf")), fmt((1.0, -2.5)), fmt(True), fmt(-1.2e-16, zero=1e-9)
    ('0.1235', '∞', '(1, -2.5)', 'yes', '0')
    >>> fmt(10116.3), fmt(123456.0), fmt(-5.293e-08), fmt(QuantityText("(0, -0.8)", "m"))
    ('10120', '1.235×10⁵', '-5.293×10⁻⁸', '(0, -0.8)')
    """
    if isinstance(x, QuantityText):
        return html.escape(x.numbers)
    if isinstance(x, (bool, np.bool_)):
        return "yes" if x else "no"
    if isinstance(x, (int, np.integer)):
        return str(int(x))
    if isinstance(x, (float, np.floating)):
        if not np.isfinite(x):
            return "∞" if x > 0 else ("−∞" if x < 0 else "—")
        if x == 0 or abs(x) <= zero:
            return "0"
        if abs(x) >= 1e5 or abs(x) < 1e-3:
            return power_text(x, digits)
        if abs(x) >= 10.0 ** digits:          # 10116.3 -> 10120 ("g" would write 1.012e+04)
            return f"{round(float(x), digits - 1 - int(math.floor(math.log10(abs(x))))):.0f}"
        return f"{x:.{digits}g}"
    if isinstance(x, (tuple, list, np.ndarray)):
        return "(" + ", ".join(fmt(v, digits, zero) for v in _components(x)) + ")"
    return html.escape(str(x))


_SUPERSCRIPT = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")


def power_text(x: float, digits: int = 4) -> str:
    """``x`` to ``digits`` significant digits times a power of ten written with superscripts, as a
    student reads it (and as the controls' messages write it): ``-5.293×10⁻⁸``, never ``-5.293e-08``.

    Parameters
    ----------
    x : float
        A finite number.
    digits : int
        Significant digits (trailing zeros dropped).

    Returns
    -------
    str

    Examples
    --------
    >>> power_text(-5.293e-08), power_text(1234567.0), power_text(1e-12), power_text(9.99996e-4)
    ('-5.293×10⁻⁸', '1.235×10⁶', '1×10⁻¹²', '1×10⁻³')
    """
    mant, exp = f"{float(x):.{max(int(digits), 1) - 1}e}".split("e")
    if "." in mant:
        mant = mant.rstrip("0").rstrip(".")
    return f"{mant}×10{str(int(exp)).translate(_SUPERSCRIPT)}"


def _components(x) -> list:
    """The entries of a vector, those at rounding level relative to the largest set to 0."""
    a = np.ravel(np.asarray(x, dtype=object))
    try:
        f = np.asarray(a, dtype=float)
        big = np.max(np.abs(f[np.isfinite(f)]), initial=0.0)
        return list(np.where(np.isfinite(f) & (np.abs(f) <= 1e-12 * big), 0.0, f))
    except (TypeError, ValueError):
        return list(a)


def is_numeric(x: Any) -> bool:
    """True for a real number (not a boolean) or a non-empty vector of them: what takes a unit.

    Parameters
    ----------
    x : Any
        A readout value.

    Returns
    -------
    bool

    Examples
    --------
    >>> is_numeric(2.0), is_numeric((1, 2)), is_numeric("at rest"), is_numeric(True)
    (True, True, False, False)
    """
    if isinstance(x, (bool, np.bool_)):
        return False
    if isinstance(x, numbers.Real):
        return True
    if isinstance(x, (tuple, list, np.ndarray)):
        a = np.ravel(np.asarray(x, dtype=object))
        return len(a) > 0 and all(is_numeric(v) for v in a)
    return False


def split_units(unit, n: int) -> list[str]:
    """One unit per component of an ``n``-vector from a unit string or a tuple of them.

    Parameters
    ----------
    unit : str or tuple of str
        One common unit, or one per component.
    n : int
        Number of components.

    Returns
    -------
    list of str
        ``n`` units ("" for none).

    Raises
    ------
    ValueError
        A tuple whose length is not ``n`` (a programming error in an explorer's units).

    Examples
    --------
    >>> split_units("m", 2), split_units(("m/s", "rad/s"), 2)
    (['m', 'm'], ['m/s', 'rad/s'])
    """
    if isinstance(unit, (tuple, list)):
        units = [("" if u in NO_UNIT else str(u)) for u in unit]
        if len(units) != n:
            raise ValueError(f"{len(units)} units given for a vector of {n} components")
        return units
    u = "" if unit in NO_UNIT or unit is None else str(unit)
    return [u] * n


def value_text(x: Any, unit: Any = "", zero: float = 0.0, digits: int = 4) -> str:
    """The readout text of a value with its unit: the unit after numbers only.

    Parameters
    ----------
    x : Any
        The value (a number, a vector, a word...).
    unit : str or tuple of str
        One unit, or one per component of a vector ("" or "—": none).
    zero : float
        Round-off level (:func:`fmt`).
    digits : int
        Significant digits.

    Returns
    -------
    str

    Examples
    --------
    >>> value_text((1.0, -2.0, 0.5), ("m/s", "m/s", "rad/s")), value_text("at rest", "m")
    ('(1 m/s, -2 m/s, 0.5 rad/s)', 'at rest')
    >>> value_text((0.0, 2.0), ("1/kg", "1/(kg·m)")), value_text(point_text([0.0, -2.0, 1.0]))
    ('(0 kg⁻¹, 2 kg⁻¹·m⁻¹)', '(2, 0) m')
    """
    return value_texts(x, unit, zero, digits)[1]


def value_texts(x: Any, unit: Any = "", zero: float = 0.0, digits: int = 4) -> tuple[str, str]:
    """The numbers of a value alone (:func:`fmt`) and with its unit (:func:`value_text`).

    Parameters
    ----------
    x, unit, zero, digits
        As for :func:`value_text`.

    Returns
    -------
    (str, str)

    Examples
    --------
    >>> value_texts(2.5, "m"), value_texts((1.0, 2.0), ("m", "rad"))
    (('2.5', '2.5 m'), ('(1, 2)', '(1 m, 2 rad)'))
    """
    text = fmt(x, digits, zero)
    return text, _with_unit(text, x, unit, zero, digits)


def _with_unit(text: str, x: Any, unit: Any, zero: float, digits: int) -> str:
    """:func:`value_text` of ``x`` from its numbers ``text`` (:func:`fmt`)."""
    if isinstance(x, QuantityText):
        return f"{text} {html.escape(unit_text(x.unit))}" if x.unit else text
    if not is_numeric(x):
        return text
    if isinstance(x, (tuple, list, np.ndarray)):
        comps = _components(x)
        units = [unit_text(u) for u in split_units(unit, len(comps))]
        if len(set(units)) == 1:
            return f"{text} {html.escape(units[0])}" if units[0] else text
        parts = [fmt(v, digits, zero) + (f" {html.escape(u)}" if u else "")
                 for v, u in zip(comps, units)]
        return "(" + ", ".join(parts) + ")"
    u = unit_text(split_units(unit, 1)[0])
    return f"{text} {html.escape(u)}" if u else text


def point_text(p, unit: str = "m", zero: float = 0.0, digits: int = 4) -> str:
    """Readout text of a homogeneous point: ``"(x, y) m"`` or ``"at infinity (direction (dx, dy))"``.

    Parameters
    ----------
    p : array_like (3,)
        Homogeneous point ``[a, b, w]`` (thesis 5.49).
    unit : str
        Unit of the coordinates.
    zero, digits : float, int
        Round-off level and significant digits of the coordinates (:func:`fmt`).

    Returns
    -------
    QuantityText or str
        The coordinates and their unit (a readout table puts the unit in its own column), or words.

    Examples
    --------
    >>> point_text([4.0, -2.0, 2.0]), point_text([0.0, 1.0, 0.0])
    ('(1, 2) m', 'at infinity (direction (-1, 0))')
    >>> point_text([4.0, -2.0, 2.0]).unit
    'm'
    """
    p = np.asarray(p, dtype=float).reshape(3)
    if bool(is_ideal(p)):
        return f"at infinity (direction {fmt(tuple(direction(p)), digits, 1e-12)})"
    xy = to_xy(p)
    return QuantityText(html.unescape(fmt(tuple(xy), digits, zero)), unit)


def point_value(p):
    """``(x, y)`` of a finite homogeneous point, or :func:`point_text`'s words for one at infinity.

    Parameters
    ----------
    p : array_like, shape (3,)
        ``[a, b, w]`` with ``x = −b/w``, ``y = a/w`` (thesis 5.49).

    Returns
    -------
    tuple of float or str

    Examples
    --------
    >>> point_value([2.0, -1.0, 1.0]), point_value([0.0, -1.0, 0.0])
    ((1.0, 2.0), 'at infinity (direction (1, 0))')
    """
    p = np.asarray(p, dtype=float)
    if bool(is_ideal(p)):
        return point_text(p)
    return (float(-p[1] / p[2]) + 0.0, float(p[0] / p[2]) + 0.0)


#: a label's mathtext (``$\\dot{q}_1$``) as readable Unicode (``q̇₁``): the pictures' own reader
plain_symbol = plain_text


def explain_html(meanings: dict[str, str], title: str = "What is shown") -> str:
    """A collapsible list of symbols and their meanings (the explorer's "what is shown" panel).

    Parameters
    ----------
    meanings : dict
        ``{symbol or readout name: one-line meaning}``.
    title : str
        The panel's heading.

    Returns
    -------
    str
        HTML (a ``<details>`` list; empty text when there is nothing to explain).

    Examples
    --------
    >>> "<b>ω</b>" in explain_html({"ω": "angular velocity (thesis 2.3)"})
    True
    """
    if not meanings:
        return ""
    items = "".join(f"<li style='margin:1px 0'><b>{html.escape(plain_symbol(k))}</b>: "
                    f"{html.escape(plain_symbol(v))}</li>"
                    for k, v in meanings.items())
    return (f"<details class='planargeo-explain'><summary style='cursor:pointer'><b>{html.escape(title)}"
            f"</b> ({len(meanings)} symbols)</summary><ul style='margin:2px 0 2px 14px;padding:0;"
            f"font-size:12px;line-height:1.3'>{items}</ul></details>")
