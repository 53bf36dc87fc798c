"""Open the built site in a real (headless) browser and check what a reader sees.

``make docs`` runs it after Sphinx.  From ``docs/_build/html`` through ``file://`` (no server,
no network), with Debian's chromium driven by playwright:

* the index page's figure has loaded;
* the gallery page shows every figure of ``gallery/`` (each image loaded);
* every lesson shows every figure stored in its notebook (as many loaded images as the
  notebook holds image outputs) and every equation typeset by MathJax;
* an API page's equations are typeset too;
* no page anywhere on the site shows raw TeX: no ``\\(`` or ``\\[`` outside the math that
  MathJax typesets (the sidebar, titles, captions, text), read from the HTML files themselves
  (:func:`raw_tex`; this needs no browser).

Without chromium or playwright the browser checks are skipped (it says so) (``make test`` installs both where it
can); any problem is printed and the exit status is 1.

Run: ``python docs/check_site.py [docs/_build/html]``.
"""
from __future__ import annotations

import html.parser
import json
import re
import shutil
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
        "--disable-component-update", "--disable-sync", "--no-first-run", "--disable-dev-shm-usage"]

#: What a page shows: loaded and broken images, and typeset and raw equations.
_PROBE = """async () => {
  if (window.MathJax && MathJax.startup && MathJax.startup.promise) { await MathJax.startup.promise; }
  const imgs = [...document.querySelectorAll('article img')];
  await Promise.all(imgs.map(i => i.complete ? null : new Promise(r => { i.onload = i.onerror = r; })));
  const maths = [...document.querySelectorAll('article .math')];
  return {images: imgs.length,
          broken: imgs.filter(i => !(i.naturalWidth > 0)).map(i => i.getAttribute('src')),
          maths: maths.length,
          raw: maths.filter(m => !m.querySelector('mjx-container')).map(m => m.textContent.slice(0, 60))};
}"""


#: elements whose text is not shown as text, or is code: raw TeX there is not a reader's problem
_SKIP_TAGS = {"script", "style", "pre", "code", "textarea", "svg", "math", "mjx-container"}
_VOID = {"area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta", "source",
         "track", "wbr"}
_TEX = re.compile(r"\\[(\[]")


class _TextOutsideMath(html.parser.HTMLParser):
    """Collects the text of a page that is shown as text: outside math, code and scripts."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.stack: list[tuple[str, bool]] = []   # open elements: (tag, inside a skipped one?)
        self.found: list[str] = []

    def _skipped(self) -> bool:
        return bool(self.stack) and self.stack[-1][1]

    def handle_starttag(self, tag, attrs):
        if tag in _VOID:
            return
        classes = (dict(attrs).get("class") or "").split()
        self.stack.append((tag, self._skipped() or tag in _SKIP_TAGS or "math" in classes))

    def handle_startendtag(self, tag, attrs):
        pass

    def handle_endtag(self, tag):
        for i in range(len(self.stack) - 1, -1, -1):     # close up to the matching element
            if self.stack[i][0] == tag:
                del self.stack[i:]
                return

    def handle_data(self, data):
        m = _TEX.search(data)
        if m and not self._skipped():
            i = m.start()
            self.found.append(" ".join(data[max(0, i - 30):i + 40].split()))


def raw_tex(page: str) -> list[str]:
    r"""Snippets of raw TeX a reader would see on an HTML page: ``\(`` or ``\[`` outside math.

    Math that MathJax typesets sits in elements of class ``math``; code (``pre``, ``code``),
    scripts and styles are not prose.  Everything else (the sidebar, the ``<title>``, links,
    captions, paragraphs) must not show TeX delimiters.

    Parameters
    ----------
    page : str
        An HTML page.

    Returns
    -------
    list of str
        One snippet of text around each raw ``\(`` or ``\[`` (empty: none).

    Examples
    --------
    >>> raw_tex(r'<p>Lesson 5: <span class="math notranslate nohighlight">\(s\)</span></p>')
    []
    >>> raw_tex(r'<a class="reference">Lesson 5: \(s\), \(R\)</a><pre>x = "\(a\)"</pre>')
    ['Lesson 5: \\(s\\), \\(R\\)']
    """
    parser = _TextOutsideMath()
    parser.feed(page)
    parser.close()
    return parser.found


def raw_tex_problems(site: Path) -> list[str]:
    """Every page of the built site with raw TeX outside math, one line per page.

    Parameters
    ----------
    site : pathlib.Path
        The built site.

    Returns
    -------
    list of str
    """
    problems = []
    for path in sorted(site.rglob("*.html")):
        found = raw_tex(path.read_text(encoding="utf-8", errors="replace"))
        if found:
            problems.append(f"{path.relative_to(site)}: {len(found)} raw TeX outside math, "
                            f"e.g. {found[0]!r}")
    return problems


def stored_images(notebook: Path) -> int:
    """How many figures a notebook stores (outputs with an image), as the site shows them.

    Parameters
    ----------
    notebook : pathlib.Path
        An ``.ipynb`` file.

    Returns
    -------
    int
        The number of outputs holding ``image/png``, ``image/svg+xml`` or ``image/jpeg``.
    """
    nb = json.loads(notebook.read_text(encoding="utf-8"))
    kinds = ("image/png", "image/svg+xml", "image/jpeg")
    return sum(1 for cell in nb.get("cells", []) for out in cell.get("outputs", [])
               if any(k in out.get("data", {}) for k in kinds))


def check(site: Path) -> list[str]:
    """Problems a reader would see on the built site (an empty list: none).

    Parameters
    ----------
    site : pathlib.Path
        The built site (``docs/_build/html``).

    Returns
    -------
    list of str
        One line per problem, naming the page.
    """
    from playwright.sync_api import sync_playwright

    from planargeo.gallery.figures import load_all

    problems = []
    pages = {"index.html": None, "_gen/gallery.html": len(load_all()), "_gen/api/geometry.html": None}
    for nb in sorted((ROOT / "notebooks").glob("*.ipynb")):
        pages[f"_gen/lessons/{nb.stem}.html"] = stored_images(nb)
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=ARGS)
        page = browser.new_page(viewport={"width": 1200, "height": 900})
        for rel, want_images in pages.items():
            path = site / rel
            if not path.exists():
                problems.append(f"{rel}: missing")
                continue
            page.goto(path.as_uri(), wait_until="load")
            seen = page.evaluate(_PROBE)
            if seen["broken"]:
                problems.append(f"{rel}: {len(seen['broken'])} images not shown: {seen['broken'][:3]}")
            if rel == "index.html" and seen["images"] < 1:
                problems.append(f"{rel}: no figure")
            if want_images is not None and seen["images"] < want_images:
                problems.append(f"{rel}: {seen['images']} images shown, {want_images} expected")
            if seen["raw"]:
                problems.append(f"{rel}: {len(seen['raw'])} of {seen['maths']} equations not typeset, "
                                f"e.g. {seen['raw'][0]!r}")
        browser.close()
    return problems


def main(argv: list[str]) -> int:
    """Check the site; print what was checked or the problems.

    Parameters
    ----------
    argv : list of str
        ``[site folder]`` (default ``docs/_build/html``).

    Returns
    -------
    int
        Exit status: 0 when the site shows everything (or no browser is available), 1 otherwise.
    """
    site = (Path(argv[0]) if argv else HERE / "_build" / "html").resolve()
    tex = raw_tex_problems(site)              # no browser needed
    for line in tex:
        print(f"check_site: {line}", file=sys.stderr)
    try:
        import playwright.sync_api  # noqa: F401
    except ImportError:
        print("check_site: playwright is not installed; the site was not opened in a browser")
        return 1 if tex else 0
    if not Path(CHROMIUM).exists():
        print("check_site: chromium not found; the site was not opened in a browser")
        return 1 if tex else 0
    sys.path.insert(0, str(ROOT))
    t0 = time.perf_counter()
    problems = tex + check(site)
    for line in problems[len(tex):]:
        print(f"check_site: {line}", file=sys.stderr)
    if problems:
        return 1
    print(f"check_site: no raw TeX on any page; index, gallery, an API page and every lesson open in "
          f"chromium with every figure and equation shown ({time.perf_counter() - t0:.1f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
