"""Where a benchmark writes.

By default next to its script (work/, results.csv, the plot, machine.txt:
what the benchmark commits). With the environment variable
DLMFD_BENCHMARK_OUTPUT set to a folder, into <that folder>/<the benchmark's
path below benchmarks/> instead: the smoke forms of ./Alltest run the
scripts that way, on tiny cases, so that the committed results are never
touched and a benchmark that no longer runs on the current code fails the
suite.
"""
import os

benchmarks = os.path.dirname(os.path.abspath(__file__))


def output_folder(here):
    """The folder a benchmark whose script is in here writes into"""
    base = os.environ.get("DLMFD_BENCHMARK_OUTPUT")
    if not base:
        return here
    out = os.path.join(os.path.abspath(base), os.path.relpath(here, benchmarks))
    os.makedirs(out, exist_ok=True)
    return out
