"""Open the built site in a real (headless) browser and check what a reader sees.

``make docs`` runs it after Sphinx.  From ``docs/_build/html`` through ``file://`` (no server,
no network), with Debian's chromium driven by playwright:

* the index page's figure has loaded;
* the gallery page shows every figure of ``gallery/`` (each image loaded);
* every lesson shows every figure stored in its notebook (as many loaded images as the
  notebook holds image outputs) and every equation typeset by MathJax;
* an API page's equations are typeset too.

Without chromium or playwright it says so and exits 0 (``make test`` installs both where it
can); any problem is printed and the exit status is 1.

Run: ``python docs/check_site.py [docs/_build/html]``.
"""
from __future__ import annotations

import json
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
    try:
        import playwright.sync_api  # noqa: F401
    except ImportError:
        print("check_site: playwright is not installed; the site was not opened in a browser")
        return 0
    if not Path(CHROMIUM).exists():
        print("check_site: chromium not found; the site was not opened in a browser")
        return 0
    sys.path.insert(0, str(ROOT))
    t0 = time.perf_counter()
    problems = check(site)
    for line in problems:
        print(f"check_site: {line}", file=sys.stderr)
    if problems:
        return 1
    print(f"check_site: index, gallery, an API page and every lesson open in chromium with every "
          f"figure and equation shown ({time.perf_counter() - t0:.1f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
