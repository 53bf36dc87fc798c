"""Every public object of planargeo has a numpydoc docstring (issue 15).

What counts as public
    Every module of ``planargeo/`` whose dotted name has no part starting with ``_``.  Its
    public objects are the functions and classes named in its ``__all__`` (a module without
    ``__all__``: the functions and classes it defines whose names do not start with ``_``),
    each checked once, in the module that defines it (a re-export is not checked twice), and
    the public methods, class/static methods and properties each of those classes defines
    itself (inherited members are checked in the class that defines them; members a base class
    generates for its subclasses, like matplotlib's ``Artist.set``, are the base's).  Constants,
    submodules, ``namedtuple`` types and exception classes without a constructor of their own
    are not functions or classes with a signature to document and are left out.

What a docstring must have (parsed with :class:`numpydoc.docscrape.NumpyDocString`)
    * a summary line;
    * a ``Parameters`` section naming every parameter of the signature except ``self`` and
      ``cls`` (``*args``/``**kwargs`` under either spelling; ``x, y : float`` names both).  A
      class documents its constructor in its own docstring or ``__init__``'s; a dataclass may
      name its fields under ``Attributes`` instead;
    * a ``Returns`` (or ``Yields``) section if the function's own body has a ``return <expr>``
      whose value is not the constant ``None`` (nested functions and classes excluded; found
      by parsing the source) -- properties are documented like attributes and need none;
    * a ``Raises`` section if its own body has a ``raise X`` statement (a bare re-``raise``
      re-raises what it caught and needs none).

    One exception: a gallery figure's drawing function (registered with
    :func:`planargeo.gallery.figures.register`) has its caption for a docstring -- the gallery
    and the documentation site show it under the figure -- so it needs only its summary.

``PENDING`` (below) lists the modules or objects whose docstrings other people are writing in
the same session; their failures are reported as expected failures, not hidden, and the set
is emptied when they land.  Run ``python tests/test_docstrings.py`` for the coverage table.
"""
from __future__ import annotations

import ast
import importlib
import inspect
import pkgutil
import sys
import textwrap
import warnings
from functools import lru_cache

import pytest

numpydoc_docscrape = pytest.importorskip("numpydoc.docscrape")

import planargeo

#: Modules (or ``module.object`` names) whose docstrings are being written by their owners in
#: the same session (s11: widgets, drawing, report/cli, loops, articulated mobility, chain
#: splitting).  Checked all the same: a failure there is an expected
#: failure listing the names.  Empty this set when they are done.
PENDING: set[str] = set()


# ---------------------------------------------------------------------------------------------
# discovery

def public_modules() -> list[str]:
    """Dotted names of planargeo's public modules, imported."""
    names = ["planargeo"]
    for info in pkgutil.walk_packages(planargeo.__path__, "planargeo."):
        if any(part.startswith("_") for part in info.name.split(".")):
            continue
        names.append(info.name)
    out = []
    for name in sorted(names):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            importlib.import_module(name)
        out.append(name)
    return out


def _unwrap(obj):
    obj = getattr(obj, "py_func", obj)          # numba dispatchers
    return inspect.unwrap(obj)


def _is_checked_class(cls) -> bool:
    if issubclass(cls, tuple) and hasattr(cls, "_fields"):       # namedtuple
        return False
    return True


def _owner_module(obj) -> str | None:
    return getattr(_unwrap(obj), "__module__", None)


def module_objects(modname: str) -> list[tuple[str, object]]:
    """``(qualified name, object)`` of the functions and classes ``modname`` defines publicly."""
    mod = sys.modules[modname]
    if hasattr(mod, "__all__"):
        names = list(mod.__all__)
    else:
        names = [n for n in vars(mod) if not n.startswith("_")]
    out = []
    for name in names:
        obj = getattr(mod, name, None)
        if obj is None:
            continue
        base = _unwrap(obj)
        if not (inspect.isfunction(base) or inspect.isclass(base)):
            continue
        if _owner_module(obj) != modname:        # a re-export: checked where it is defined
            continue
        if inspect.isclass(base) and not _is_checked_class(base):
            continue
        out.append((f"{modname}.{name}", obj))
    return out


def _written_here(func, cls) -> bool:
    """Whether ``func`` was written in ``cls``'s module (not generated for it by a base
    class, like the ``set`` method matplotlib's ``Artist`` adds to every subclass)."""
    return getattr(func, "__module__", None) == cls.__module__


def class_members(qualname: str, cls) -> list[tuple[str, object, str]]:
    """``(name, function, kind)`` for the public members ``cls`` defines itself."""
    out = []
    for name, raw in vars(cls).items():
        if name.startswith("_"):
            continue
        func = raw.fget if isinstance(raw, property) else getattr(raw, "__func__", getattr(raw, "func", raw))
        if callable(func) and not _written_here(func, cls):
            continue
        if isinstance(raw, property):
            if raw.fget is not None:
                out.append((f"{qualname}.{name}", raw.fget, "property"))
        elif isinstance(raw, (staticmethod, classmethod)):
            out.append((f"{qualname}.{name}", raw.__func__, "method"))
        elif inspect.isfunction(raw):
            out.append((f"{qualname}.{name}", raw, "method"))
        elif hasattr(raw, "func") and inspect.isfunction(getattr(raw, "func")):  # cached_property
            out.append((f"{qualname}.{name}", raw.func, "property"))
    return out


def all_targets() -> list[tuple[str, object, str]]:
    """Every public object: ``(qualified name, object, kind)``, kind function/class/method/property."""
    out = []
    for modname in public_modules():
        for qualname, obj in module_objects(modname):
            base = _unwrap(obj)
            if inspect.isclass(base):
                out.append((qualname, base, "class"))
                out.extend(class_members(qualname, base))
            else:
                out.append((qualname, obj, "function"))
    return out


# ---------------------------------------------------------------------------------------------
# the rules

def _own_statements(func_node):
    """Walk a function's body without entering nested functions, lambdas or classes."""
    nested = (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda, ast.ClassDef)
    stack = [n for n in func_node.body if not isinstance(n, nested)]
    while stack:
        node = stack.pop()
        yield node
        stack.extend(c for c in ast.iter_child_nodes(node) if not isinstance(c, nested))


@lru_cache(maxsize=None)
def _body_facts(func) -> tuple[bool, bool, bool]:
    """(returns a value, raises, yields) from the function's source, or all False without one."""
    try:
        src = textwrap.dedent(inspect.getsource(func))
        tree = ast.parse(src)
    except (OSError, TypeError, SyntaxError):
        return False, False, False
    node = next((n for n in ast.walk(tree) if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef))), None)
    if node is None:
        return False, False, False
    returns = raises = yields = False
    for n in _own_statements(node):
        if isinstance(n, ast.Return) and n.value is not None and not (
                isinstance(n.value, ast.Constant) and n.value.value is None):
            returns = True
        elif isinstance(n, ast.Raise) and n.exc is not None:
            raises = True
        elif isinstance(n, (ast.Yield, ast.YieldFrom)):
            yields = True
    return returns, raises, yields


def _is_figure(func) -> bool:
    """Whether ``func`` is a registered gallery figure (its docstring is a caption)."""
    figures = sys.modules.get("planargeo.gallery.figures")
    if figures is None:
        return False
    spec = figures.REGISTRY.get(getattr(func, "__name__", ""))
    return spec is not None and func.__module__.startswith("planargeo.gallery.figures.")


def _documented_names(section) -> set[str]:
    names = set()
    for p in section:
        for part in p.name.split(","):
            part = part.strip().split(":")[0].strip()
            if part:
                names.add(part)
                names.add(part.lstrip("*"))
    return names


def _signature_params(func, skip_first: bool) -> list[str]:
    try:
        sig = inspect.signature(func)
    except (TypeError, ValueError):
        return []
    params = list(sig.parameters.values())
    if skip_first and params and params[0].name in ("self", "cls"):
        params = params[1:]
    return [p.name for p in params if p.name not in ("self", "cls")]


class Malformed(Exception):
    """numpydoc could not parse the docstring (e.g. a section given twice)."""


def _parse(doc: str | None):
    if not doc or not doc.strip():
        return None
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            return numpydoc_docscrape.NumpyDocString(doc)
        except ValueError as exc:
            raise Malformed(str(exc).split("\n")[0]) from None


def problems(qualname: str, obj, kind: str) -> list[str]:
    """What the docstring of one public object lacks (an empty list: nothing)."""
    try:
        return _problems(qualname, obj, kind)
    except Malformed as exc:
        return [f"numpydoc cannot parse it: {exc}"]


def _problems(qualname: str, obj, kind: str) -> list[str]:
    if kind == "class":
        return _class_problems(obj)
    func = _unwrap(obj)
    doc = _parse(inspect.getdoc(func))
    if doc is None:
        return ["no docstring"]
    out = []
    if not " ".join(doc["Summary"]).strip():
        out.append("no summary")
    if _is_figure(func):
        return out
    returns, raises, yields = _body_facts(func)
    if kind == "property":
        if raises and not doc["Raises"]:
            out.append("no Raises section")
        return out
    params = _signature_params(func, skip_first=kind == "method")
    documented = _documented_names(doc["Parameters"]) | _documented_names(doc["Other Parameters"])
    missing = [p for p in params if p not in documented]
    if missing:
        out.append("parameters not documented: " + ", ".join(missing))
    if returns and not (doc["Returns"] or doc["Yields"]):
        out.append("no Returns section")
    if yields and not (doc["Yields"] or doc["Returns"]):
        out.append("no Yields section")
    if raises and not doc["Raises"]:
        out.append("no Raises section")
    return out


def _class_problems(cls) -> list[str]:
    doc = _parse(inspect.getdoc(cls) if cls.__doc__ else None)
    if doc is None:
        return ["no docstring"]
    out = []
    if not " ".join(doc["Summary"]).strip():
        out.append("no summary")
    init = vars(cls).get("__init__")
    if init is None and "__dataclass_fields__" in vars(cls):
        init = cls.__init__
    if init is None:
        inherited = _constructor_owner(cls)
        if inherited is not None and inherited.__name__.startswith("_"):
            # a constructor inherited from a private base (Twist, Wrench from _Screw): its docstring
            # is not public, so the class documents the constructor's parameters itself
            documented = _documented_names(doc["Parameters"]) | _documented_names(doc["Other Parameters"])
            missing = [p for p in _signature_params(inherited.__init__, skip_first=True) if p not in documented]
            if missing:
                out.append("constructor parameters not documented: " + ", ".join(missing))
        return out                               # otherwise documented where it is defined
    if not inspect.isfunction(init):
        return out
    documented = _documented_names(doc["Parameters"]) | _documented_names(doc["Attributes"]) \
        | _documented_names(doc["Other Parameters"])
    init_doc = _parse(init.__doc__) if "__dataclass_fields__" not in vars(cls) else None
    if init_doc is not None:
        documented |= _documented_names(init_doc["Parameters"])
    missing = [p for p in _signature_params(init, skip_first=True) if p not in documented]
    if missing:
        out.append("constructor parameters not documented: " + ", ".join(missing))
    _, raises, _ = _body_facts(init)
    if raises and "__dataclass_fields__" not in vars(cls):
        has = doc["Raises"] or (init_doc is not None and init_doc["Raises"])
        if not has:
            out.append("constructor raises but no Raises section")
    return out


def _constructor_owner(cls):
    """The class of ``cls``'s MRO that defines the ``__init__`` it uses (None: ``object``'s, or an exception's)."""
    if issubclass(cls, BaseException):
        return None
    for k in cls.__mro__[1:]:
        if "__init__" in vars(k):
            return None if k is object or not inspect.isfunction(vars(k)["__init__"]) else k
    return None


def is_pending(qualname: str) -> bool:
    """Whether ``qualname`` lies under an entry of :data:`PENDING`."""
    return any(qualname == p or qualname.startswith(p + ".") for p in PENDING)


def report() -> tuple[int, int, dict[str, list[str]]]:
    """(public objects, documented, {qualname: problems}) over the whole package."""
    targets = all_targets()
    failing = {}
    for qualname, obj, kind in targets:
        p = problems(qualname, obj, kind)
        if p:
            failing[qualname] = p
    return len(targets), len(targets) - len(failing), failing


# ---------------------------------------------------------------------------------------------
# the tests

_TARGETS = all_targets()
_MODULES = sorted({q.rsplit(".", 1)[0] if k in ("function", "class") else q.rsplit(".", 2)[0]
                   for q, _, k in _TARGETS})


def _targets_of(modname):
    for qualname, obj, kind in _TARGETS:
        owner = qualname.rsplit(".", 1)[0] if kind in ("function", "class") else qualname.rsplit(".", 2)[0]
        if owner == modname:
            yield qualname, obj, kind


def test_there_is_a_public_api_to_check():
    assert len(_TARGETS) > 300
    assert "planargeo.geometry.projective.join" in {q for q, _, _ in _TARGETS}
    assert "planargeo.screws.twists.Twist.pole" in {q for q, _, _ in _TARGETS}


@pytest.mark.parametrize("modname", _MODULES)
def test_every_public_object_has_a_numpydoc_docstring(modname):
    failing, pending = [], []
    for qualname, obj, kind in _targets_of(modname):
        for p in problems(qualname, obj, kind):
            (pending if is_pending(qualname) else failing).append(f"{qualname}: {p}")
    assert not failing, "\n".join(failing)
    if pending:
        pytest.xfail(f"{len(pending)} docstring problems in PENDING: " + "; ".join(pending[:20]))


def test_the_top_level_names_are_all_checked():
    """Issue 24: 100 % of ``planargeo.__all__``'s functions and classes, the lazily loaded main jobs
    included, are checked (where they are defined), and so are those of every subpackage's ``__all__``."""
    checked = {id(_unwrap(o)) for _, o, _ in _TARGETS}
    missing = []
    for modname in public_modules():
        mod = sys.modules[modname]
        for name in getattr(mod, "__all__", []):
            obj = getattr(mod, name)
            base = _unwrap(obj)
            if inspect.ismodule(obj) or not (inspect.isfunction(base) or inspect.isclass(base)):
                continue                        # constants, submodules (``pg.simulate`` is the subpackage)
            if inspect.isclass(base) and (not _is_checked_class(base) or issubclass(base, BaseException)):
                continue
            if id(base) not in checked:
                missing.append(f"{modname}.{name}")
    assert not missing, missing
    for name in ("forward_dynamics", "inverse_dynamics", "chain_model", "scene", "Twist", "Wrench", "JointSpace"):
        obj = getattr(planargeo, name, None) or getattr(planargeo.joints, name)
        assert id(_unwrap(obj)) in checked, name
    assert id(planargeo.simulate.integrate.simulate) in checked


def test_twist_and_wrench_document_their_parameters():
    """The two classes every lesson uses: their constructor's ``array`` is in their own Parameters."""
    for cls in (planargeo.Twist, planargeo.Wrench):
        doc = numpydoc_docscrape.NumpyDocString(inspect.getdoc(cls))
        assert "array" in _documented_names(doc["Parameters"]), cls.__name__
        assert _class_problems(cls) == [], cls.__name__


def test_pending_entries_that_are_done_are_named():
    """A PENDING entry whose objects all pass is reported (a warning): remove it from the set."""
    done = []
    for entry in sorted(PENDING):
        mine = [(q, o, k) for q, o, k in _TARGETS if q == entry or q.startswith(entry + ".")]
        if mine and not any(problems(q, o, k) for q, o, k in mine):
            done.append(entry)
    if done:
        warnings.warn(f"docstrings complete, remove from PENDING: {', '.join(done)}", UserWarning)


def test_the_rules_catch_what_they_should():
    def good(a, b=1, *args, **kwargs):
        """Add.

        Parameters
        ----------
        a, b : float
            Terms.
        *args, **kwargs
            Ignored.

        Returns
        -------
        float
            The sum.

        Raises
        ------
        ValueError
            Never.
        """
        if a is None:
            raise ValueError("a")
        return a + b

    def bad(a, b):
        """Add."""
        def inner():
            raise ValueError
        if a:
            raise
        return a + b

    def quiet(a):
        """Do nothing.

        Parameters
        ----------
        a : object
            Anything.
        """
        return None

    assert problems("good", good, "function") == []
    assert problems("quiet", quiet, "function") == []
    assert problems("bad", bad, "function") == ["parameters not documented: a, b", "no Returns section"]

    class _Base:
        def __init__(self, array):
            """Store.

            Parameters
            ----------
            array : object
                Anything.
            """

    class Undocumented(_Base):
        """A public class whose constructor comes from a private base."""

    class Public(_Base):
        """A public base."""

        def __init__(self, array):
            """Store.

            Parameters
            ----------
            array : object
                Anything.
            """

    class Inherits(Public):
        """Documented where its public base's constructor is."""

    assert _class_problems(Undocumented) == ["constructor parameters not documented: array"]
    assert _class_problems(Inherits) == []


if __name__ == "__main__":
    total, ok, failing = report()
    mods: dict[str, list[str]] = {}
    for q in failing:
        mods.setdefault(q, failing[q])
    print(f"public objects: {total}; complete docstrings: {ok} ({100 * ok / total:.1f} %)")
    pend = {q: p for q, p in failing.items() if is_pending(q)}
    print(f"failing: {len(failing)} ({len(pend)} in PENDING)")
    if "-v" in sys.argv:
        for q, p in sorted(failing.items()):
            print(("P " if is_pending(q) else "  ") + q + ": " + "; ".join(p))
