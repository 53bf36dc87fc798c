"""Sphinx configuration of planargeo's documentation site (``make docs``).

The site is built from what the repository already holds; nothing is executed but
imports (autodoc) and the gallery registry (captions):

* the lessons, ``notebooks/*.ipynb``, rendered with their stored outputs
  (``nb_execution_mode = "off"``: the notebooks are stored from a deterministic run and
  tested as such, so the site shows exactly what a reader opening them sees);
* the gallery page, generated from :mod:`planargeo.gallery.figures`' registry (caption and
  thesis figure number of every SVG in ``gallery/``);
* the API reference, one page per subpackage, from the docstrings (autodoc + numpydoc);
* the equation → code index (``equations.md``), the errata, the conventions, scenes and
  simulation notes of ``docs/``; the benchmark results ``benchmarks/RESULTS.md`` with its
  tables and charts; installation and the README's two commands.

Generated sources go to ``docs/_gen/`` (git-ignored, rewritten on every build by
:mod:`site_sources`, beside this file), with a local MathJax so that the equations of the
lessons and the docstrings show offline and from ``file://``.
"""
from __future__ import annotations

import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(ROOT))          # document this checkout, not an installed copy
sys.path.insert(0, str(HERE))

import site_sources  # noqa: E402  (docs/site_sources.py)

site_sources.generate(ROOT, HERE / "_gen")

project = "planargeo"
author = "planargeo contributors"
copyright = "2026, planargeo contributors"
release = site_sources.version(ROOT)

extensions = [
    "myst_nb",
    "sphinx.ext.autodoc",
    "sphinx.ext.mathjax",
    "numpydoc",
]

root_doc = "index"
exclude_patterns = ["_build", "equations_index.py", "thesis_equation_labels.txt", "site_sources.py", "check_site.py",
                    "plain_titles.py", "_static", "scenes.md", "**/.ipynb_checkpoints"]
source_suffix = {".md": "myst-nb", ".ipynb": "myst-nb"}

# --- lessons: stored outputs, never executed here -------------------------------------------
nb_execution_mode = "off"
nb_merge_streams = True
# Interactive widgets need a running kernel: their stored state is not shown, the static
# fallback (the figure the notebook stored as image/png or text) is.
nb_mime_priority_overrides = [
    ("html", "application/vnd.jupyter.widget-view+json", None),
    ("html", "application/vnd.jupyter.widget-state+json", None),
]
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence", "deflist"]
myst_heading_anchors = 3

# --- API reference -----------------------------------------------------------------------------
autodoc_default_options = {"member-order": "bysource"}   # members: listed by site_sources
add_module_names = False                   # each module has its own heading
autodoc_typehints = "none"                 # the numpydoc sections give the types
autodoc_mock_imports: list[str] = []
numpydoc_show_class_members = False        # autodoc lists the members itself
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False
numpydoc_validation_checks: set[str] = set()   # tests/test_docstrings.py checks the sections

# --- output ------------------------------------------------------------------------------------
html_theme = "furo"
html_title = f"planargeo {release}"
# Equations: a local MathJax 3 (TeX to SVG, no web fonts: works from file:// and offline), copied
# by site_sources.mathjax from the django-static-mathjax package; without it, MathJax from the web.
if (HERE / "_gen" / "_static" / "mathjax" / "tex-svg.js").exists():
    html_static_path = ["_gen/_static"]
    mathjax_path = "mathjax/tex-svg.js"
    mathjax3_config = {
        "tex": {"inlineMath": [["\\(", "\\)"]], "displayMath": [["\\[", "\\]"]]},
        "options": {"processHtmlClass": "tex2jax_process|mathjax_process|math|output_area"},
        "svg": {"fontCache": "global"},
    }
else:
    html_static_path: list[str] = []
# the site's own style (docs/_static): code outputs wrap, code scrolls, nothing runs out of its box
html_static_path = [*html_static_path, "_static"]
html_css_files = ["planargeo.css"]
html_show_sourcelink = False


# --- docstring post-processing (the rendered text only; the sources are untouched) -------------
import re  # noqa: E402

_HEADING = re.compile(r"^(\S.*)\n(-{3,}|={3,})$", re.M)

#: Temporary fixes of module docstrings whose reStructuredText docutils rejects, owned by other
#: people and to be fixed in their own files (then delete the entry): planargeo.draw.style's
#: table has a cell ("a reaction / internal force") wider than its column.  A table that no
#: longer has that layout is left alone.
DOC_FIXES: dict = {}     # {module: (column start, next column start, widen by)}


def _widen_column(text: str, start: int, nxt: int, by: int) -> str:
    """Widen one column of the first simple table in ``text`` by ``by`` characters."""
    lines = text.split("\n")
    borders = [i for i, l in enumerate(lines) if l.startswith("=") and set(l.replace(" ", "")) == {"="}]
    if len(borders) < 3 or len(lines[borders[0]]) <= nxt or lines[borders[0]][nxt - 2:nxt] != "  ":
        return text                                   # not the table this fix was written for
    for i in range(borders[0], borders[-1] + 1):
        l = lines[i]
        if i in borders:
            lines[i] = l[:nxt - 2] + "=" * by + l[nxt - 2:]
        elif l.strip():
            lines[i] = l[:start] + l[start:nxt].rstrip().ljust(nxt - start + by) + l[nxt:]
    return "\n".join(lines)


def _module_sections_to_rubrics(app, what, name, obj, options, lines):
    """Module docstrings' numpydoc-style headings ("Examples" over dashes) as rubrics.

    numpydoc parses the docstrings of functions and classes; a module docstring goes to
    docutils as it is, where every "Examples" heading would become a section with the same
    id on one page.
    """
    if what != "module":
        return
    text = "\n".join(lines)
    if name in DOC_FIXES:
        text = _widen_column(text, *DOC_FIXES[name])
    text = _HEADING.sub(lambda m: f".. rubric:: {m.group(1).strip()}\n", text)
    lines[:] = text.split("\n")


def setup(app):
    from plain_titles import plain_titles   # docs/plain_titles.py

    app.connect("autodoc-process-docstring", _module_sections_to_rubrics, priority=400)
    # after Sphinx has collected the titles (priority 500): their copies in the sidebar, the
    # <title> and the prev / next links read Unicode, not raw TeX (the heading keeps its math)
    app.connect("doctree-read", plain_titles, priority=900)
