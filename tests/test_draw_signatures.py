"""Every drawing function of planargeo.draw takes ``ax=None`` the same way (issue 13).

What is drawn comes first; ``ax`` is a parameter with default ``None`` (the
current axes, :func:`planargeo.draw.style.get_ax`), never the first parameter.
A function whose only parameter is ``ax`` (``legend_handles(ax=None)``) is fine.
The test inspects every public function of every module of ``planargeo.draw``
(names in the module's ``__all__``, or, without one, every public function
defined there): one that has an ``ax`` parameter, or whose name says it draws
(``draw_*``, ``plot_*``), must follow the rule.  Classes (artists) are not
functions and are left out; :func:`~planargeo.draw.style.get_ax` itself is the
rule's implementation and exempt.
"""
from __future__ import annotations

import importlib
import inspect
import pkgutil

import numpy as np
import pytest

import planargeo.draw

#: Functions that still take ``ax`` first (none left: setup_axes, fit_view and fit_panel moved it
#: to a keyword in issue 13 and still read the former order, see the last test).
KNOWN: dict[str, str] = {}
EXEMPT = {"planargeo.draw.style.get_ax"}


def _public_functions():
    out = []
    for info in sorted(pkgutil.iter_modules(planargeo.draw.__path__), key=lambda m: m.name):
        mod = importlib.import_module(f"planargeo.draw.{info.name}")
        names = getattr(mod, "__all__", None)
        if names is None:
            names = [n for n, f in vars(mod).items() if not n.startswith("_")
                     and inspect.isfunction(f) and f.__module__ == mod.__name__]
        for n in names:
            f = getattr(mod, n)
            if inspect.isfunction(f):
                out.append((f"{mod.__name__}.{n}", f))
    return out


def _drawing_functions():
    out = []
    for qual, f in _public_functions():
        if qual in EXEMPT:
            continue
        params = inspect.signature(f).parameters
        short = qual.rsplit(".", 1)[1]
        if "ax" in params or short.startswith(("draw_", "plot_")):
            marks = ([pytest.mark.xfail(reason=KNOWN[qual], strict=False)] if qual in KNOWN else [])
            out.append(pytest.param(qual, f, id=qual.removeprefix("planargeo.draw."), marks=marks))
    return out


def ax_problem(f) -> str | None:
    """What is wrong with ``f``'s ``ax`` parameter, or None when it follows the rule."""
    params = list(inspect.signature(f).parameters.values())
    ax = [p for p in params if p.name == "ax"]
    if not ax:
        return "has no ax parameter"
    p = ax[0]
    positional = [q for q in params if q.kind in (q.POSITIONAL_ONLY, q.POSITIONAL_OR_KEYWORD)]
    if positional and positional[0].name == "ax" and len(positional) > 1:
        return "takes ax as its first parameter"       # (ax alone, e.g. legend_handles(ax=None), is fine)
    if p.kind is p.POSITIONAL_ONLY:
        return "takes ax positionally only"
    if p.default is not None:
        return f"ax has default {p.default!r}, not None"
    return None


def test_the_rule_itself():
    def good(x, ax=None, *, k=1):
        pass

    def kwonly(*args, ax=None):
        pass

    def first(ax, x):
        pass

    def nodefault(x, ax):
        pass

    def alone(ax=None):
        pass

    assert ax_problem(good) is None and ax_problem(kwonly) is None and ax_problem(alone) is None
    assert ax_problem(first) == "takes ax as its first parameter"
    assert ax_problem(nodefault) == "ax has default <class 'inspect._empty'>, not None"
    assert ax_problem(lambda x: 0) == "has no ax parameter"


def test_some_functions_are_inspected():
    names = {p.values[0] for p in _drawing_functions()}
    assert {"planargeo.draw.constructions.draw_twist_sum", "planargeo.draw.constructions.label",
            "planargeo.draw.charts.plot_curves", "planargeo.draw.artists.plot_point"} <= names


@pytest.mark.parametrize("qual, f", _drawing_functions())
def test_ax_is_a_keyword_with_default_none(qual, f):
    problem = ax_problem(f)
    assert problem is None, f"{qual} {problem}"


def test_former_order_still_draws_where_the_new_order_draws():
    """label / draw_segment / draw_dimension moved ax to a keyword; the old call order still works."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from planargeo.draw.constructions import draw_dimension, draw_segment, label

    fig, ax = plt.subplots()
    try:
        a = label((1.0, 2.0), "P", ax=ax)
        b = label(ax, (1.0, 2.0), "P")
        assert a.xy == b.xy == (1.0, 2.0) and a.get_text() == b.get_text() == "P"
        s1 = draw_segment((0, 0), (1, 1), ax=ax, role="wrench")
        s2 = draw_segment(ax, (0, 0), (1, 1), "wrench")
        assert s1.get_color() == s2.get_color() and list(s1.get_xdata()) == [0, 1]
        d1 = draw_dimension((0, 0), (2, 0), "d", ax=ax)
        d2 = draw_dimension(ax, (0, 0), (2, 0), "d")
        assert d1[1].xy == d2[1].xy == (1.0, 0.0)
        plt.sca(ax)
        assert label((0, 0), "cur").axes is ax            # ax=None: the current axes
    finally:
        plt.close(fig)


def test_former_order_of_setup_axes_fit_view_fit_panel_still_works():
    """setup_axes / fit_view / fit_panel moved ax to a keyword; the old ax-first calls still work."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from planargeo.draw.layout import fit_panel, fit_view
    from planargeo.draw.style import setup_axes
    from planargeo.errors import InputError

    fig, (a, b) = plt.subplots(1, 2)
    try:
        assert setup_axes((0, 2, 0, 1), ax=a) is a and a.get_xlim() == (0, 2)
        assert setup_axes(b, (0, 2, 0, 1), grid=True, axis_off=False) is b and b.get_xlim() == (0, 2)
        P = [[0.0, 0.0], [4.0, 1.0]]
        fit_view(P, ax=a, margin=0.1)
        fit_view(b, P, margin=0.1)
        assert np.allclose(a.get_xlim(), b.get_xlim()) and np.allclose(a.get_ylim(), b.get_ylim())
        b.set_xlim(0, 1)
        fit_view(P, 0.1, ax=b)
        assert np.allclose(a.get_xlim(), b.get_xlim())
        plt.sca(b)
        assert fit_view(P, margin=0.3) is b
        with pytest.raises(InputError, match="ax given twice"):
            fit_view(a, P, ax=b)
        with pytest.raises(InputError, match="margin given twice"):
            fit_view(P, 0.1, ax=a, margin=0.2)
        with pytest.raises(InputError, match="ax given twice"):
            setup_axes(a, ax=b)
    finally:
        plt.close(fig)
    got = []
    for call in (lambda ax: fit_panel(P, ax=ax, margin=0.05), lambda ax: fit_panel(ax, P, margin=0.05)):
        fig, ax = plt.subplots(figsize=(3.4, 2.8))
        try:
            call(ax)
            got.append([*fig.get_size_inches(), *ax.get_xlim(), *ax.get_ylim()])
        finally:
            plt.close(fig)
    assert np.allclose(got[0], got[1]) and got[0][1] < 2.8      # the height followed the points
