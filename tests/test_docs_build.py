"""The documentation site's generated sources cover what they must (issue 15).

``make docs`` (run by ``make test`` after the suite) builds the whole site with Sphinx and
warnings as errors; these tests check, without Sphinx and in about a second, what
``docs/site_sources.py`` writes for it: every gallery SVG with its caption and thesis figure
number, every public module in the API reference (each public function and class once, where
it is defined), every lesson, the benchmark results with their charts.
"""
from __future__ import annotations

import importlib.util
import re
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
_spec = importlib.util.spec_from_file_location("site_sources", ROOT / "docs" / "site_sources.py")
site_sources = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(site_sources)


def test_gallery_page_shows_every_figure_with_number_and_caption(tmp_path):
    from planargeo.gallery.figures import load_all

    site_sources.gallery(ROOT, tmp_path)
    page = (tmp_path / "gallery.md").read_text(encoding="utf-8")
    specs = load_all()
    committed = {p.stem for p in (ROOT / "gallery").glob("*.svg")}
    assert committed == set(specs), "gallery/*.svg and the registry differ: run `planargeo gallery`"
    for name, spec in specs.items():
        assert f"```{{figure}} gallery/{name}.svg" in page
        assert (tmp_path / "gallery" / f"{name}.svg").read_bytes() == (ROOT / "gallery" / f"{name}.svg").read_bytes()
        number = site_sources.figure_number(name)
        if number != "extra":
            assert f"### {number}\n" in page
        # the caption, as MyST will show it (escapes removed)
        shown = re.sub(r"\\(.)", r"\1", page)
        assert spec.caption in shown
    # thesis order: Fig. 4.9 before Fig. 4.10
    assert page.index("### Fig. 4.9\n") < page.index("### Fig. 4.10\n")


def test_api_reference_documents_every_public_object_once(tmp_path):
    sys.path.insert(0, str(ROOT / "tests"))
    try:
        import test_docstrings as td
    finally:
        sys.path.remove(str(ROOT / "tests"))
    site_sources.api(tmp_path)
    text = "\n".join(p.read_text(encoding="utf-8") for p in sorted((tmp_path / "api").glob("*.md")))
    modules = set(re.findall(r"^\.\. automodule:: (\S+)$", text, re.M))
    assert modules == set(td.public_modules())
    documented = re.findall(r"^\.\. auto(?:function|class):: (\S+)$", text, re.M)
    assert len(documented) == len(set(documented)), "an object is documented twice"
    expected = {q for q, _, kind in td.all_targets() if kind in ("function", "class")}
    assert expected <= set(documented)
    for extra in set(documented) - expected:         # shown, though they have no docstring rule
        mod, name = extra.rsplit(".", 1)
        obj = getattr(sys.modules[mod], name)
        assert issubclass(obj, tuple) and hasattr(obj, "_fields"), f"{extra} is documented but not checked"
    pages = {p.stem for p in (tmp_path / "api").glob("*.md")} - {"index"}
    assert pages == {page for page, _, _ in site_sources.API_PAGES}


def test_every_lesson_is_on_the_site(tmp_path):
    site_sources.lessons(ROOT, tmp_path)
    books = sorted(p.name for p in (ROOT / "notebooks").glob("*.ipynb"))
    assert books and sorted(p.name for p in (tmp_path / "lessons").glob("*.ipynb")) == books
    index = (tmp_path / "lessons" / "index.md").read_text(encoding="utf-8")
    for b in books:
        assert f"({b})" in index and f"\n{Path(b).stem}\n" in index


def test_benchmark_results_and_charts_are_on_the_site(tmp_path):
    site_sources.benchmarks(ROOT, tmp_path)
    page = (tmp_path / "benchmarks" / "index.md").read_text(encoding="utf-8")
    assert page.startswith((ROOT / "benchmarks" / "RESULTS.md").read_text(encoding="utf-8"))
    for link in re.findall(r"\]\((results/[^)#]+)\)", page):
        assert (tmp_path / "benchmarks" / link).exists(), link


@pytest.mark.parametrize("name,number", [("fig1_2", "Fig. 1.2"), ("fig7_10", "Fig. 7.10"),
                                         ("extra_style_key", "extra")])
def test_figure_numbers_are_read_from_names(name, number):
    assert site_sources.figure_number(name) == number


def test_the_site_carries_its_own_mathjax(tmp_path):
    """Equations show offline and from file:// (MathJax 3, TeX to SVG: no web fonts)."""
    pytest.importorskip("mathjax", reason="django-static-mathjax (a dev dependency) is not installed")
    written = site_sources.mathjax(tmp_path)
    js = tmp_path / "_static" / "mathjax" / "tex-svg.js"
    assert js in written and js.stat().st_size > 500_000
    assert (tmp_path / "_static" / "mathjax" / "input" / "tex" / "extensions" / "ams.js") in written


# ---------------------------------------------------------------- issue 22: no raw TeX on the site
_spec2 = importlib.util.spec_from_file_location("check_site", ROOT / "docs" / "check_site.py")
check_site = importlib.util.module_from_spec(_spec2)
_spec2.loader.exec_module(check_site)
sys.path.insert(0, str(ROOT / "docs"))
try:
    import plain_titles
finally:
    sys.path.remove(str(ROOT / "docs"))


def test_raw_tex_is_found_outside_math_only():
    sidebar = ('<li class="toctree-l1"><a class="reference internal" href="05.html">Lesson 5 — '
               'Subspace decompositions: \\(s\\), \\(R\\), \\(T\\) and \\(U\\)</a></li>')
    found = check_site.raw_tex(sidebar)
    assert len(found) == 1 and "decompositions: \\(s\\), \\(R\\)" in found[0]
    page = ('<title>Lesson: \\(s\\)</title><h1>Lesson <span class="math notranslate nohighlight">'
            '\\(s\\)</span></h1><div class="math notranslate nohighlight">\\[a = b\\]</div>'
            '<pre>print("\\(x\\)")</pre><script>var t = "\\(y\\)";</script><p>done</p>')
    assert check_site.raw_tex(page) == ["Lesson: \\(s\\)"]        # the <title> is text a reader sees
    assert check_site.raw_tex(page.replace("<title>Lesson: \\(s\\)</title>", "")) == []


def test_titles_lose_their_math_in_the_navigation_only():
    from docutils import nodes

    toc = nodes.bullet_list("", nodes.list_item("", nodes.paragraph(
        "", "", nodes.Text("Lesson 5 — Subspace decompositions: "), nodes.math("", "s"),
        nodes.Text(", "), nodes.math("", "R"), nodes.Text(", "), nodes.math("", "T"),
        nodes.Text(" and "), nodes.math("", "U"))))
    plain_titles.plain_math(toc)
    assert not list(toc.findall(nodes.math))
    assert toc.astext() == "Lesson 5 — Subspace decompositions: s, R, T and U"


def test_the_built_site_shows_no_raw_tex():
    """On the site as built (``make docs``): no page shows ``\\(`` outside math."""
    site = ROOT / "docs" / "_build" / "html"
    if not (site / "index.html").exists():
        pytest.skip("the site is not built (make docs)")
    assert check_site.raw_tex_problems(site) == []


def test_code_outputs_wrap_or_scroll():
    """The site's style keeps code and its printed output inside their boxes."""
    import ast

    css = (ROOT / "docs" / "_static" / "planargeo.css").read_text(encoding="utf-8")
    assert re.search(r"div\.cell_output pre[^{]*\{[^}]*white-space:\s*pre-wrap", css, re.S)
    assert re.search(r"div\.highlight pre[^{]*\{[^}]*overflow-x:\s*auto", css, re.S)
    conf = ast.parse((ROOT / "docs" / "conf.py").read_text(encoding="utf-8"))
    names = {t.id for node in ast.walk(conf) if isinstance(node, ast.Assign) for t in node.targets
             if isinstance(t, ast.Name)}
    assert {"html_css_files", "html_static_path"} <= names
    assert "planargeo.css" in (ROOT / "docs" / "conf.py").read_text(encoding="utf-8")
