"""Regenerate the committed benchmark results: ``python benchmarks/run.py`` (same as ``planargeo bench``)."""
import argparse
import sys

import bench

# the truncated articulated recursion (thesis 10.2.2): benchmarks/truncated.py, group "truncated"
bench.SCRIPTS.setdefault("truncated", "truncated.py")
bench.GROUPS = ("dynamics",) + tuple(bench.SCRIPTS)
bench.OTHER_RESULTS += (("truncated.md", "truncated articulated recursion: speed against accuracy (10.2.2)"),)

if __name__ == "__main__":
    p = argparse.ArgumentParser(description=bench.__doc__.splitlines()[0])
    bench.add_arguments(p)
    sys.exit(bench.main(p.parse_args()))
