"""``make fuzz``: call every entry point with generated arguments; a table of what became of the calls.

Usage::

    python tests/fuzz/run.py [--calls N] [--seed S] [--time-limit SECONDS]
                             [--explorer-share F] [--only SUBSTRING ...] [--group GROUP ...]
                             [--json FILE] [--memory GB]

``--calls`` is the total number of calls (default 8000): a share ``--explorer-share`` (default
0.32) goes to the explorers (:mod:`fuzz.explorers`: action sequences through the paths of the mouse
and the page, each followed by the one-state invariant; at the default, every explorer gets more than
200 calls), the rest to the functions, classes, scenes, simulations, files and command line
(:mod:`fuzz.targets`), shared by weight.  Arguments come from each parameter's documented domain,
extremes included, with one hostile argument in about a fifth of the calls (:mod:`fuzz.strategies`).

Each call is *computed* (it returned a result, or the explorer showed a new state), *refused* (a
:class:`~planargeo.errors.PlanargeoError`, or the explorer's own message keeping the last state) or
*failed* (any other exception, numpy's or Python's words shown to a user, a non-finite result from
finite input, a hang past ``--time-limit`` seconds, an explorer that disagrees with a fresh one
built from its controls).  The table lists them per entry point, with the overall share computed;
then one reproducer per failing entry point.  Exit status 1 when any call failed.  The run is
deterministic for a given ``--seed`` (default 0).
"""
from __future__ import annotations

import argparse
import json
import os
import resource
import sys
import time
import warnings
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
os.environ.setdefault("MPLBACKEND", "Agg")

from fuzz.harness import BAD, REFUSALS, Tally, run_target  # noqa: E402

#: Default total number of calls (``make fuzz``: a few minutes on two cores).
DEFAULT_CALLS = 8000
DEFAULT_TIME_LIMIT = 20.0


def table(rows: list[tuple[str, str, Tally]]) -> str:
    """Rows ``(entry point, group, tally)`` as a text table, with a total line.

    >>> t = Tally(); t.counts.update({"ok": 3, "package error": 1})
    >>> print(table([("f", "g", t)]).splitlines()[-1])   # doctest: +NORMALIZE_WHITESPACE
    TOTAL        1 entry points      4         3        1       0        0           0     0             0  0.0
    """
    heads = ["entry point", "group", "calls", "computed", "refused", "failed", *BAD, "s"]
    data = [[name, group, str(t.calls), str(t.computed), str(t.refused), str(t.failed),
             *(str(t.counts[o]) for o in BAD), f"{t.seconds:.1f}"] for name, group, t in rows]
    total = Tally()
    for _, _, t in rows:
        total.counts.update(t.counts)
        total.seconds += t.seconds
    foot = ["TOTAL", f"{len(rows)} entry points", str(total.calls), str(total.computed), str(total.refused),
            str(total.failed), *(str(total.counts[o]) for o in BAD), f"{total.seconds:.1f}"]
    widths = [max(len(r[i]) for r in data + [heads, foot]) for i in range(len(heads))]

    def fmt(r):
        return "  ".join(c.ljust(w) if i < 2 else c.rjust(w) for i, (c, w) in enumerate(zip(r, widths)))

    rule = "  ".join("-" * w for w in widths)
    return "\n".join([fmt(heads), rule, *(fmt(r) for r in data), rule, fmt(foot)])


def summary(rows: list[tuple[str, str, Tally]]) -> dict:
    """Totals: calls, computed, refused, failed, the computed share, and calls per explorer."""
    total = Tally()
    per_explorer: dict[str, int] = {}
    for name, group, t in rows:
        total.counts.update(t.counts)
        if group == "explorer actions":
            per_explorer[name.split(".")[0]] = per_explorer.get(name.split(".")[0], 0) + t.calls
    return {"calls": total.calls, "computed": total.computed, "refused": total.refused,
            "failed": total.failed, "computed_share": total.computed / max(total.calls, 1),
            "explorer_calls": per_explorer}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--calls", type=int, default=DEFAULT_CALLS, help="total number of calls")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--time-limit", type=float, default=DEFAULT_TIME_LIMIT,
                    help="seconds after which one call counts as a hang (the entry point is then left)")
    ap.add_argument("--explorer-share", type=float, default=0.32, help="share of the calls for the explorers")
    ap.add_argument("--refusals", action="store_true", help="also print the first reasons of refusal per entry point")
    ap.add_argument("--json", default=None, help="also write the tallies to this file")
    ap.add_argument("--only", nargs="*", default=None, help="entry points whose name contains one of these")
    ap.add_argument("--group", nargs="*", default=None, help="groups (explorer actions: 'explorer actions')")
    ap.add_argument("--memory", type=float, default=4.0,
                    help="address-space limit in GB (a runaway allocation is a MemoryError, not a swapped machine)")
    args = ap.parse_args(argv)
    limit = int(args.memory * 2**30)
    resource.setrlimit(resource.RLIMIT_AS, (limit, resource.getrlimit(resource.RLIMIT_AS)[1]))
    warnings.simplefilter("default")

    from fuzz.explorers import fuzz_explorers
    from fuzz.targets import all_targets
    from planargeo import widgets

    def log(s):
        print(s, file=sys.stderr, flush=True)

    t0 = time.perf_counter()
    rows: list[tuple[str, str, Tally]] = []
    targets = all_targets()
    if args.only:
        targets = [t for t in targets if any(s in t.name for s in args.only)]
    if args.group:
        targets = [t for t in targets if t.group in args.group]
    names = list(widgets.EXPLORERS)
    if args.only:
        names = [n for n in names if any(s in n for s in args.only)]
    if args.group and "explorer actions" not in args.group:
        names = []
    share = args.explorer_share if names and targets else (1.0 if names else 0.0)
    fn_calls = args.calls * (1 - share)
    total_w = sum(t.weight for t in targets) or 1.0
    for t in targets:
        n = max(5, round(fn_calls * t.weight / total_w))
        tally = run_target(t, n, seed=args.seed, timeout=min(t.timeout, args.time_limit))
        rows.append((t.name, t.group, tally))
        log(f"  {t.name}: {tally.calls} calls, {tally.failed} failed, {tally.seconds:.1f} s")
    if names:
        each = max(5, round(args.calls * share / len(names)))
        ex_tallies = fuzz_explorers(each, seed=args.seed, time_limit=args.time_limit, names=names, log=log)
        rows += [(k, "explorer actions", t) for k, t in ex_tallies.items()]

    print(table(rows))
    s = summary(rows)
    if args.json:
        Path(args.json).write_text(json.dumps({
            "summary": s,
            "entry_points": {name: {"group": group, "counts": dict(t.counts), "examples": t.examples,
                                    "seconds": t.seconds} for name, group, t in rows}}, indent=1))
    if args.refusals:
        print("\nFirst refusals per entry point:")
        for name, _, t in rows:
            for why in t.examples.get(REFUSALS, []):
                print(f"  {name}: {why}")
    bad = [(name, t) for name, _, t in rows if t.failed]
    if bad:
        print("\nFailures (one reproducer per entry point and kind):")
    for name, t in bad:
        for outcome, example in t.examples.items():
            if outcome == REFUSALS:
                continue
            print(f"\n{name} [{outcome}]: {example}")
    if s["explorer_calls"]:
        print("\ncalls per explorer: " + ", ".join(f"{k} {v}" for k, v in s["explorer_calls"].items()))
    print(f"\n{s['calls']} calls to {len(rows)} entry points in {time.perf_counter() - t0:.0f} s: "
          f"computed {s['computed']} ({100 * s['computed_share']:.1f} %), refused {s['refused']}, "
          f"failed {s['failed']} ("
          + ", ".join(f"{o} {sum(t.counts[o] for _, _, t in rows)}" for o in BAD) + ")")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
