"""The documentation site's generated sources (run by ``docs/conf.py`` on every build).

:func:`generate` writes into ``docs/_gen/`` (git-ignored; rewritten each build):

* ``lessons/``: a copy of every ``notebooks/*.ipynb`` (with their stored outputs) and an index;
* ``gallery.md`` and ``gallery/*.svg``: every registered gallery figure with its thesis figure
  number and caption (from :func:`planargeo.gallery.figures.load_all`, the same registry that
  ``planargeo gallery`` renders), the SVG committed in ``gallery/``;
* ``benchmarks/``: ``benchmarks/RESULTS.md`` with its tables and charts (``benchmarks/results``);
* ``scenes.md``: ``docs/scenes.md`` with its links into ``benchmarks/results`` pointed at the copy;
* ``_static/mathjax``: a local MathJax (:func:`mathjax`), so equations show offline;
* ``api/``: one page per subpackage, each module's docstring and its public functions and
  classes (``__all__``, or the names it defines when it has none), each documented once,
  where it is defined.

Run it alone with ``python docs/site_sources.py`` to see what a build would read.
"""
from __future__ import annotations

import importlib
import inspect
import json
import pkgutil
import re
import shutil
import sys
from pathlib import Path

#: The API reference's pages: (page name, title, subpackage or None for the top-level modules).
API_PAGES = [
    ("planargeo", "planargeo: package, errors, files, command line", None),
    ("geometry", "planargeo.geometry: points, lines, conics", "planargeo.geometry"),
    ("screws", "planargeo.screws: twists, wrenches, inertia", "planargeo.screws"),
    ("mechanics", "planargeo.mechanics: joints, subspaces, models", "planargeo.mechanics"),
    ("algorithms", "planargeo.algorithms: dynamics algorithms", "planargeo.algorithms"),
    ("simulate", "planargeo.simulate: time integration", "planargeo.simulate"),
    ("scenes", "planargeo.scenes: named scenes", "planargeo.scenes"),
    ("draw", "planargeo.draw: drawing", "planargeo.draw"),
    ("gallery", "planargeo.gallery: the thesis's figures", "planargeo.gallery"),
    ("widgets", "planargeo.widgets: explorers", "planargeo.widgets"),
]


def version(root: Path) -> str:
    """The package version from ``pyproject.toml``.

    Parameters
    ----------
    root : pathlib.Path
        The repository's root folder.

    Returns
    -------
    str
        The ``version = "…"`` of ``[project]``, or ``"unknown"``.
    """
    m = re.search(r'^version\s*=\s*"([^"]+)"', (root / "pyproject.toml").read_text(encoding="utf-8"), re.M)
    return m.group(1) if m else "unknown"


def _write(path: Path, text: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    if not path.exists() or path.read_text(encoding="utf-8") != text:    # keep mtimes: incremental builds
        path.write_text(text, encoding="utf-8")


def _copy(src: Path, dst: Path) -> None:
    dst.parent.mkdir(parents=True, exist_ok=True)
    if not dst.exists() or dst.read_bytes() != src.read_bytes():
        shutil.copyfile(src, dst)


def _sync(out: Path, keep: set[Path]) -> None:
    """Delete files under ``out`` that this build did not write (a removed notebook, a renamed figure)."""
    for p in sorted(out.rglob("*"), reverse=True):
        if p.is_file() and p not in keep:
            p.unlink()
        elif p.is_dir() and not any(p.iterdir()):
            p.rmdir()


def _md_escape(text: str) -> str:
    """Text shown literally by MyST (captions hold ``*``, ``_``, ``|``, brackets...)."""
    return re.sub(r"([\\`*_\[\]<>#|$])", r"\\\1", text)


def _notebook_title(path: Path) -> str:
    nb = json.loads(path.read_text(encoding="utf-8"))
    for cell in nb.get("cells", []):
        if cell.get("cell_type") == "markdown":
            src = "".join(cell.get("source", []))
            m = re.search(r"^#\s+(.+)$", src, re.M)
            if m:
                return m.group(1).strip()
    return path.stem


def lessons(root: Path, out: Path) -> set[Path]:
    """Copy the notebooks and write the lessons' index.

    Parameters
    ----------
    root : pathlib.Path
        The repository's root folder.
    out : pathlib.Path
        The generated-sources folder.

    Returns
    -------
    set of pathlib.Path
        The files written.
    """
    written = set()
    books = sorted((root / "notebooks").glob("*.ipynb"))
    for nb in books:
        _copy(nb, out / "lessons" / nb.name)
        written.add(out / "lessons" / nb.name)
    rows = "\n".join(f"* [{_md_escape(_notebook_title(nb))}]({nb.stem}.ipynb)" for nb in books)
    toc = "\n".join(nb.stem for nb in books)
    text = f"""# Lessons

The lessons are the Jupyter notebooks of `notebooks/`, shown here with the outputs they
were stored with.  To play with the explorers, run them: `make lab` opens the first.

{rows}

```{{toctree}}
:hidden:
:maxdepth: 1

{toc}
```
"""
    _write(out / "lessons" / "index.md", text)
    written.add(out / "lessons" / "index.md")
    return written


def figure_number(name: str) -> str:
    """The thesis figure a gallery figure redraws, from its name.

    Parameters
    ----------
    name : str
        A gallery figure's name: ``figC_K`` for the thesis's Fig. C.K, ``extra_…`` for the
        package's own figures.

    Returns
    -------
    str
        ``"Fig. C.K"``, or ``"extra"``.

    Examples
    --------
    >>> figure_number("fig7_10"), figure_number("extra_style_key")
    ('Fig. 7.10', 'extra')
    """
    m = re.fullmatch(r"fig(\d+)_(\d+)", name)
    return f"Fig. {m.group(1)}.{m.group(2)}" if m else "extra"


#: The titles of the thesis's chapters that have planar figures (the gallery's headings).
CHAPTERS = {1: "Introduction", 3: "Equations of motion", 4: "Graphical view of planar dynamics",
            5: "Planar projective geometry", 6: "Subspaces", 7: "Articulated inertias",
            9: "Trees and loops"}


def _section(name: str, order: float) -> str:
    """The gallery heading a figure goes under: its thesis chapter, the key, or the extras."""
    if order < 1:
        return "Key"
    ch = int(order)
    if ch in CHAPTERS:
        return f"Chapter {ch}: {CHAPTERS[ch]}"
    return "Beyond the thesis's figures"


def gallery(root: Path, out: Path) -> set[Path]:
    """Write the gallery page: every registered figure, its number, caption and SVG.

    Parameters
    ----------
    root : pathlib.Path
        The repository's root folder.
    out : pathlib.Path
        The generated-sources folder.

    Returns
    -------
    set of pathlib.Path
        The files written.

    Raises
    ------
    FileNotFoundError
        If a registered figure has no SVG in ``gallery/`` (run ``planargeo gallery``).
    """
    from planargeo.gallery.figures import load_all

    specs = load_all()
    written = set()
    parts = ["# Gallery", "",
             f"The {len(specs)} figures of `gallery/`, redrawn from planargeo's own numbers by "
             "`planargeo gallery` (which `planargeo gallery --check` verifies).  Each caption names "
             "the thesis figure and the equations it illustrates, and says where a printed result was "
             "corrected (see [the errata](../errata.md)).  Colours: twists and velocity poles blue, "
             "accelerations vermillion, wrenches orange, reactions green, momenta and active parts "
             "purple, inertias dashed (their radius-of-gyration circles), constructions grey dashed "
             "(the key comes first).", ""]
    section = None
    for name, spec in specs.items():
        svg = root / "gallery" / f"{name}.svg"
        if not svg.exists():
            raise FileNotFoundError(f"gallery/{name}.svg is missing: run `planargeo gallery`")
        _copy(svg, out / "gallery" / svg.name)
        written.add(out / "gallery" / svg.name)
        number = figure_number(name)
        title = number if number != "extra" else "Extra: " + name.removeprefix("extra_").replace("_", " ")
        head = _section(name, spec.order)
        if head != section:
            parts += [f"## {head}", ""]
            section = head
        parts += [f"### {title}", "",
                  f"```{{figure}} gallery/{name}.svg", f":alt: {name}", f":name: {name}", ":width: 100%", "",
                  _md_escape(spec.caption), "```", ""]
    _write(out / "gallery.md", "\n".join(parts))
    written.add(out / "gallery.md")
    return written


def benchmarks(root: Path, out: Path) -> set[Path]:
    """Copy ``benchmarks/RESULTS.md`` and its tables and charts.

    Parameters
    ----------
    root : pathlib.Path
        The repository's root folder.
    out : pathlib.Path
        The generated-sources folder.

    Returns
    -------
    set of pathlib.Path
        The files written.
    """
    written = set()
    res = root / "benchmarks" / "results"
    tables = []
    for f in sorted(res.iterdir()) if res.is_dir() else []:
        if f.suffix in (".svg", ".png", ".md", ".json"):
            if f.suffix == ".md":        # its links to docs/ point at the site's pages
                _write(out / "benchmarks" / "results" / f.name,
                       f.read_text(encoding="utf-8").replace("](../../docs/", "](../../"))
            else:
                _copy(f, out / "benchmarks" / "results" / f.name)
            written.add(out / "benchmarks" / "results" / f.name)
            if f.suffix == ".md":
                tables.append(f"results/{f.stem}")
    text = (root / "benchmarks" / "RESULTS.md").read_text(encoding="utf-8")
    text += ("\n\n## All result tables\n\n" + "\n".join(f"* [{t.split('/')[1]}]({t}.md)" for t in tables)
             + "\n\n```{toctree}\n:hidden:\n\n" + "\n".join(tables) + "\n```\n")
    _write(out / "benchmarks" / "index.md", text)
    written.add(out / "benchmarks" / "index.md")
    return written


def scenes_page(root: Path, out: Path) -> set[Path]:
    """``docs/scenes.md`` with its links into ``benchmarks/results`` pointed at the site's copy.

    Parameters
    ----------
    root : pathlib.Path
        The repository's root folder.
    out : pathlib.Path
        The generated-sources folder.

    Returns
    -------
    set of pathlib.Path
        The files written.
    """
    text = (root / "docs" / "scenes.md").read_text(encoding="utf-8")
    text = text.replace("](../benchmarks/results/", "](benchmarks/results/")
    _write(out / "scenes.md", text)
    return {out / "scenes.md"}


def _public(modname: str) -> list[tuple[str, object]]:
    mod = sys.modules[modname]
    names = list(getattr(mod, "__all__", [n for n in vars(mod) if not n.startswith("_")]))
    out = []
    for name in names:
        obj = getattr(mod, name, None)
        base = inspect.unwrap(getattr(obj, "py_func", obj)) if obj is not None else None
        if not (inspect.isfunction(base) or inspect.isclass(base)):
            continue
        if getattr(base, "__module__", None) != modname:
            continue
        out.append((name, obj))
    return out


def api_modules(package: str | None) -> list[str]:
    """The public modules one API page documents.

    Parameters
    ----------
    package : str or None
        A subpackage (``"planargeo.geometry"``), or None for the top-level modules.

    Returns
    -------
    list of str
        Dotted module names, the package itself first.
    """
    import planargeo

    if package is None:
        names = ["planargeo"] + [f"planargeo.{m.name}" for m in pkgutil.iter_modules(planargeo.__path__)
                                 if not m.ispkg and not m.name.startswith("_")]
    else:
        pkg = importlib.import_module(package)
        names = [package] + [m.name for m in pkgutil.walk_packages(pkg.__path__, package + ".")
                             if not any(p.startswith("_") for p in m.name.split("."))]
    for n in names:
        importlib.import_module(n)
    return names


def api(out: Path) -> set[Path]:
    """Write the API reference: one page per subpackage.

    Parameters
    ----------
    out : pathlib.Path
        The generated-sources folder.

    Returns
    -------
    set of pathlib.Path
        The files written.
    """
    written = set()
    index = ["# API reference", "",
             "Generated from the docstrings.  Every public function and class has a numpydoc "
             "docstring with its parameters (shapes ``(..., 3)`` broadcast over leading "
             "dimensions), returns, the errors it raises (all from `planargeo.errors`) and the "
             "thesis equations it implements (the [equation index](../../equations.md) lists them).", "",
             "```{toctree}", ":maxdepth: 1", ""]
    for page, title, package in API_PAGES:
        lines = [f"# {title}", ""]
        for k, modname in enumerate(api_modules(package)):
            if k or package is None:
                lines += [f"## `{modname}`", ""]
            lines += ["```{eval-rst}", f".. automodule:: {modname}", ""]     # one block per module
            for name, obj in _public(modname):
                base = inspect.unwrap(getattr(obj, "py_func", obj))
                if inspect.isclass(base):
                    lines += [f".. autoclass:: {modname}.{name}", "   :members:", ""]
                else:
                    lines += [f".. autofunction:: {modname}.{name}", ""]
            lines += ["```", ""]
        _write(out / "api" / f"{page}.md", "\n".join(lines))
        written.add(out / "api" / f"{page}.md")
        index.append(page)
    index += ["```", ""]
    _write(out / "api" / "index.md", "\n".join(index))
    written.add(out / "api" / "index.md")
    return written


def mathjax(out: Path) -> set[Path]:
    """Copy a local MathJax into the site, so its equations show without a network.

    MathJax 3's single-file TeX-to-SVG component (``es5/tex-svg.js``: SVG output needs no web
    fonts, so it works from ``file://`` too) and the TeX extensions it may load, from the
    ``django-static-mathjax`` package (plain MathJax 3.2.2 static files; a dev dependency), go
    to ``_static/mathjax``.  Without that package nothing is copied and the site loads
    MathJax from its usual web address.

    Parameters
    ----------
    out : pathlib.Path
        The generated-sources folder.

    Returns
    -------
    set of pathlib.Path
        The files written (empty without the package).
    """
    try:
        import mathjax as _mathjax_files
    except ImportError:
        return set()
    src = Path(_mathjax_files.__file__).parent / "static" / "mathjax" / "es5"
    if not (src / "tex-svg.js").exists():
        return set()
    written = set()
    for f in [src / "tex-svg.js", *sorted((src / "input" / "tex" / "extensions").rglob("*.js"))]:
        dst = out / "_static" / "mathjax" / f.relative_to(src)
        _copy(f, dst)
        written.add(dst)
    return written


def generate(root: Path, out: Path) -> None:
    """Write every generated source of the site into ``out``.

    Parameters
    ----------
    root : pathlib.Path
        The repository's root folder.
    out : pathlib.Path
        The generated-sources folder (``docs/_gen``); files a previous build wrote there
        and this one does not are removed.
    """
    import matplotlib

    matplotlib.use("Agg")
    out.mkdir(parents=True, exist_ok=True)
    written = set()
    written |= lessons(root, out)
    written |= gallery(root, out)
    written |= benchmarks(root, out)
    written |= scenes_page(root, out)
    written |= api(out)
    written |= mathjax(out)
    _sync(out, written)


if __name__ == "__main__":
    here = Path(__file__).resolve().parent
    sys.path.insert(0, str(here.parent))
    generate(here.parent, here / "_gen")
    print("wrote", here / "_gen")
