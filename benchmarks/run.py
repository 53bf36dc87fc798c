"""Regenerate the committed benchmark results: ``python benchmarks/run.py`` (same as ``planargeo bench``)."""
import argparse
import sys

import bench

if __name__ == "__main__":
    p = argparse.ArgumentParser(description=bench.__doc__.splitlines()[0])
    bench.add_arguments(p)
    sys.exit(bench.main(p.parse_args()))
