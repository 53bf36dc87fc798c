"""Docstring entries that many functions share, written once (private; the lowest layer, so every layer can use it).

A docstring line that holds only names in braces, such as ``{C p}``, stands for those entries:
:func:`entries` writes them in at the line's indentation.  A line naming something the table does
not hold is left as it is.
"""
from __future__ import annotations

import inspect
import re
import textwrap

_PLACE = re.compile(r"^( *)\{([\w ]+)\}$", re.M)

#: Returns sections of broadcast arrays, by shape, and the Parameters heading: every table holds
#: them (a line ``{parameters point returns_3}`` is a whole Parameters and Returns).
RETURNS = {f"returns_{key}": f"Returns\n-------\nnumpy.ndarray{kind}, shape (...{shape})"
           for key, kind, shape in [("scalar", "", ""), ("bool", " of bool", ""), ("2", "", ", 2"),
                                    ("3", "", ", 3"), ("3x3", "", ", 3, 3")]}
RETURNS["parameters"] = "Parameters\n----------"


def entries(*tables):
    """A decorator writing the entries of ``tables`` and :data:`RETURNS` into a docstring.

    It fills the docstring of the function or class it decorates, and of the function it wraps.

    >>> @entries({"x": "x : float\\n    A number."})
    ... def f(x):
    ...     '''Nothing.
    ...
    ...     {x}
    ...     '''
    >>> print(f.__doc__.splitlines()[2])
        x : float
    """
    table = {name: text for t in (RETURNS, *tables) for name, text in t.items()}

    def fill(match):
        names = match[2].split()
        if not all(name in table for name in names):
            return match[0]
        out = ""
        for k, name in enumerate(names):      # a section (a title underlined) after a blank line
            lines = table[name].split("\n", 2)
            section = len(lines) > 1 and set(lines[1]) == {"-"}
            out += ("\n\n" if section else "\n") * (k > 0) + textwrap.indent(table[name], match[1])
        return out

    def decorate(f):
        for g in {f, inspect.unwrap(f)}:
            if g.__doc__:
                g.__doc__ = _PLACE.sub(fill, g.__doc__)
        return f

    return decorate
