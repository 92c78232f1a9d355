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


def machine_description(extra=()):
    """What a benchmark ran on, for its machine file: date, kernel, cores,
    CPU model, memory, the project's commit, and the given extra lines"""
    import platform
    import subprocess
    import time
    lines = ["date: " + time.strftime("%Y-%m-%d %H:%M:%S UTC", time.gmtime()),
             "os: " + platform.platform(),
             f"cpus: {os.cpu_count()}"]
    for key, path in (("model name", "/proc/cpuinfo"), ("MemTotal", "/proc/meminfo")):
        try:
            found = [l for l in open(path) if l.startswith(key)]
        except OSError:
            found = []
        if found:
            lines.append(f"{key}: {found[0].split(':', 1)[1].strip()}")
    commit = subprocess.run(["git", "-C", benchmarks, "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True).stdout.strip()
    lines.append(f"commit: {commit or 'unknown'}")
    lines.extend(extra)
    return "\n".join(lines) + "\n"


def load_script(path, name):
    """Another benchmark's script (a file without .py) as a module, to use
    its case set-up rather than write it again"""
    import importlib.machinery
    import importlib.util
    loader = importlib.machinery.SourceFileLoader(name, path)
    spec = importlib.util.spec_from_loader(name, loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module
