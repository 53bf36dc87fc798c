"""``make fuzz``: run every fuzz target and print a table of outcomes per entry point.

Usage::

    python tests/fuzz/run.py [--calls N | --per-target N] [--seed S | --derandomize]
                             [--only SUBSTRING ...] [--group GROUP ...] [--json FILE]

``--calls`` is the total number of generated calls (default 12000), shared among the targets
by weight; ``--per-target`` gives each target that many instead (times its weight, at least
5).  ``--derandomize`` draws the same examples every run (the fast profile of ``make test``).
Exit status 1 when any call was a defect (foreign exception, non-finite result from finite
input, hang, inconsistent explorer), with the first example of each; ``--json`` also writes
``{entry point: {"group", "counts", "examples", "seconds"}}``.
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

from fuzz.harness import BAD, OUTCOMES, Tally, run_target  # noqa: E402
from fuzz.targets import all_targets  # noqa: E402


def table(rows: list[tuple[str, str, Tally]]) -> str:
    heads = ["entry point", "group", "calls", *OUTCOMES, "s"]
    lines = []
    data = [[name, group, str(t.calls), *(str(t.counts[o]) for o in OUTCOMES), f"{t.seconds:.1f}"]
            for name, group, t in rows]
    total = Tally()
    for _, _, t in rows:
        total.counts.update(t.counts)
        total.seconds += t.seconds
    data.append(["TOTAL", f"{len(rows)} entry points", str(total.calls),
                 *(str(total.counts[o]) for o in OUTCOMES), f"{total.seconds:.1f}"])
    widths = [max(len(r[i]) for r in data + [heads]) for i in range(len(heads))]
    fmt = lambda r: "  ".join(c.ljust(w) if i < 2 else c.rjust(w) for i, (c, w) in enumerate(zip(r, widths)))
    lines.append(fmt(heads))
    lines.append("  ".join("-" * w for w in widths))
    lines += [fmt(r) for r in data[:-1]]
    lines.append("  ".join("-" * w for w in widths))
    lines.append(fmt(data[-1]))
    return "\n".join(lines)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--calls", type=int, default=12000)
    ap.add_argument("--per-target", type=int, default=None)
    ap.add_argument("--seed", type=int, default=None)
    ap.add_argument("--derandomize", action="store_true")
    ap.add_argument("--json", default=None, help="also write the tallies to this file")
    ap.add_argument("--only", nargs="*", default=None, help="entry points whose name contains one of these")
    ap.add_argument("--group", nargs="*", default=None)
    ap.add_argument("--memory", type=float, default=4.0,
                    help="address-space limit in GB (a runaway allocation is a MemoryError, not a swapped machine)")
    args = ap.parse_args(argv)
    limit = int(args.memory * 2**30)
    resource.setrlimit(resource.RLIMIT_AS, (limit, resource.getrlimit(resource.RLIMIT_AS)[1]))
    warnings.simplefilter("default")
    targets = all_targets()
    if args.only:
        targets = [t for t in targets if any(s in t.name for s in args.only)]
    if args.group:
        targets = [t for t in targets if t.group in args.group]
    total_w = sum(t.weight for t in targets)
    t0 = time.perf_counter()
    rows = []
    for t in targets:
        share = args.per_target * t.weight if args.per_target else args.calls * t.weight / total_w
        tally = run_target(t, max(5, round(share)), seed=args.seed, derandomize=args.derandomize)
        rows.append((t.name, t.group, tally))
        print(f"  {t.name}: {tally.calls} calls, {tally.defects} defects, {tally.seconds:.1f} s",
              file=sys.stderr, flush=True)
    print(table(rows))
    if args.json:
        Path(args.json).write_text(json.dumps({name: {"group": group, "counts": dict(t.counts),
                                                      "examples": t.examples, "seconds": t.seconds}
                                               for name, group, t in rows}, indent=1))
    bad = [(name, t) for name, _, t in rows if t.defects]
    for name, t in bad:
        for outcome, example in t.examples.items():
            print(f"\n{outcome}: {example}")
    print(f"\n{sum(t.calls for _, _, t in rows)} calls to {len(rows)} entry points in "
          f"{time.perf_counter() - t0:.0f} s; defects: "
          + ", ".join(f"{o} {sum(t.counts[o] for _, _, t in rows)}" for o in BAD))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
