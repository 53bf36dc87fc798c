"""Titles without raw TeX: math in a page's title is shown as Unicode in the navigation.

A heading such as ``# Subspace decompositions: $s$, $R$, $T$ and $U$`` is typeset by MathJax
in the page itself, but Sphinx copies the title into the sidebar, the page's ``<title>`` and
the previous / next links, where MathJax does not run: there it read ``\\(s\\), \\(R\\)``.
:func:`plain_math` replaces the math of those copies (``env.titles``, ``env.longtitles``,
``env.tocs``) by readable Unicode (``s, R, T and U``; ``\\dot{q}_1`` reads ``q̇₁``); the heading
on the page keeps its math.

Examples
--------
>>> from docutils import nodes
>>> title = nodes.title("", "", nodes.Text("Subspaces: "), nodes.math("", "s"), nodes.Text(" and "),
...                     nodes.math("", r"\\dot{q}_1"))
>>> plain_math(title).astext()
'Subspaces: s and q̇₁'
"""
from __future__ import annotations

from docutils import nodes

from planargeo.widgets.readout import plain_symbol

__all__ = ["plain_math", "plain_titles"]


def plain_math(tree: nodes.Node) -> nodes.Node:
    """``tree`` with every math node replaced by its Unicode text (in place); returns ``tree``.

    Parameters
    ----------
    tree : docutils.nodes.Node
        A title, or a table of contents.

    Returns
    -------
    docutils.nodes.Node
    """
    for m in list(tree.findall(nodes.math)):
        m.replace_self(nodes.Text(plain_symbol(f"${m.astext()}$")))
    return tree


def plain_titles(app, doctree) -> None:
    """Sphinx ``doctree-read`` handler: the copies of the page's titles without math nodes.

    Parameters
    ----------
    app : sphinx.application.Sphinx
    doctree : docutils.nodes.document
    """
    env = app.env
    name = env.docname
    for store in (env.titles, env.longtitles, env.tocs):
        tree = store.get(name)
        if tree is not None:
            plain_math(tree)
