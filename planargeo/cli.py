"""The ``planargeo`` command line: ``planargeo --help`` lists the subcommands.

Each subcommand's module (imported only when it runs) has ``add_arguments(parser)`` and
``main(args) -> int``.  A :class:`~planargeo.errors.PlanargeoError` out of it prints one line and
exits with status 1; Ctrl-C exits with 130, never a traceback.
"""
from __future__ import annotations

import argparse
import importlib
import sys

# name -> (module, one-line help)
COMMANDS: dict[str, tuple[str, str]] = {
    "report": ("planargeo.report", "print a scene's parameters, state and solved quantities"),
    "gallery": ("planargeo.gallery.build", "regenerate (or --check) the SVG gallery"),
    "bench": ("planargeo.run_benchmarks", "run the benchmarks and write tables and charts"),
}


def build_parser() -> argparse.ArgumentParser:
    """The top-level parser, one subcommand per module of :data:`COMMANDS`.

    Returns
    -------
    argparse.ArgumentParser
    """
    from planargeo import __version__

    parser = argparse.ArgumentParser(
        prog="planargeo",
        description="Planar rigid-body dynamics made visible: twists as points, wrenches as lines.",
    )
    parser.add_argument("--version", action="version", version=f"planargeo {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name, (_mod, helptext) in COMMANDS.items():
        sub.add_parser(name, help=helptext, description=helptext)
    return parser


def main(argv: list[str] | None = None) -> int:
    """Run the ``planargeo`` command line.

    Parameters
    ----------
    argv : list of str, optional
        The arguments after the program name (default ``sys.argv[1:]``).

    Returns
    -------
    int
        0 on success, 1 for a :class:`~planargeo.errors.PlanargeoError`, 2 for a usage error, 130 on Ctrl-C.
    """
    argv = list(sys.argv[1:] if argv is None else argv)
    parser = build_parser()
    if not argv or argv[0] in ("-h", "--help", "--version"):
        parser.parse_args(argv)  # --version prints and exits
        parser.print_help()
        return 0
    name = argv[0]
    if name not in COMMANDS:
        parser.print_usage(sys.stderr)
        print(f"planargeo: error: unknown command {name!r} (choose from {', '.join(COMMANDS)})",
              file=sys.stderr)
        return 2
    module, helptext = COMMANDS[name]
    mod = importlib.import_module(module)
    sub = argparse.ArgumentParser(prog=f"planargeo {name}", description=helptext)
    mod.add_arguments(sub)
    args = sub.parse_args(argv[1:])
    from planargeo.errors import PlanargeoError

    try:
        return int(mod.main(args) or 0)
    except PlanargeoError as exc:
        print(f"planargeo {name}: error: {(str(exc).splitlines() or [type(exc).__name__])[0]}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print(f"planargeo {name}: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:              # the reader went away (``planargeo report --list | head``): no traceback
        import os

        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
