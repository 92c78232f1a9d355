"""Runs of the periodic suspension tutorials for the parallel benchmarks
(exchangeCounts, scalingModel): a case made from a tutorial at a given mesh
and number of steps, a run on 1 to 16 processes with a given build, and the
two blocks the solver logs at its end (the master's cost line, the per-rank
exchange counts).
"""
import os
import re
import shutil
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(here), "validation"))
from caseTools import foam_set, sub  # noqa: E402

project = os.path.dirname(os.path.dirname(here))
tutorials = {"sphere": "periodicSuspensionSpheres", "cube": "periodicSuspensionCubes"}
quantities = ["bodies in the list", "bodies with cells here", "their cells", "bodies solved", "messages received",
              "bytes received", "state messages per step", "state bytes per step"]
# simple decomposition along x, then y, then z
splits = {2: "(2 1 1)", 4: "(2 2 1)", 8: "(2 2 2)", 16: "(4 2 2)", 27: "(3 3 3)", 32: "(4 4 2)", 64: "(4 4 4)"}
PHASES = ["fluid", "DLM/FD", "granular", "communication", "output"]


def fail(message):
    sys.exit(f"{os.path.relpath(sys.argv[0], project)}: {message}")


def sh(cmd, cwd, log, env=None):
    with open(os.path.join(cwd, log), "w") as f:
        r = subprocess.run(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT, shell=True, env=env)
    if r.returncode:
        fail(f"'{cmd}' failed in {cwd} (see {log})")


def build_env(folder):
    """The environment that runs the build in folder (bin/ and lib/)"""
    env = dict(os.environ)
    env["PATH"] = os.path.join(folder, "bin") + os.pathsep + env["PATH"]
    env["LD_LIBRARY_PATH"] = os.path.join(folder, "lib") + os.pathsep + env.get("LD_LIBRARY_PATH", "")
    return env


def make_case(work, shape, steps, cells, env, name=None, box=None):
    """The tutorial of shape in work/<name or shape>, cells^3 cells (0: the
    tutorial's mesh), steps time steps of t_g/20, no writing, placed; box:
    the periodic box's side over D (None: the tutorial's 8), filled at the
    tutorial's solid fraction"""
    case = os.path.join(work, name or shape)
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(os.path.join(project, "tutorials", tutorials[shape]), case)
    if cells:
        sub(os.path.join(case, "system", "blockMeshDict"), r"^n [^\n]*;", f"n   {cells};")
    if box:
        sub(os.path.join(case, "system", "blockMeshDict"), r"^L [^\n]*;", f"L   {box:.12g};")
        foam_set(case, "constant/collisionProperties", "domain/max", f"({box:.12g} {box:.12g} {box:.12g})")
    for entry, value in [("endTime", f"{0.05*steps:g}"), ("deltaT", "0.05"),
                         ("adjustTimeStep", "no"), ("writeControl", "timeStep"),
                         ("writeInterval", "1000000")]:
        foam_set(case, "system/controlDict", entry, value)
    shutil.copytree(os.path.join(case, "0.orig"), os.path.join(case, "0"))
    for app in ("galileoScales", "blockMesh", "placeParticles"):
        sh(app, case, f"log.{app}", env)
    return case


def counts_of(text, log):
    """The block the solver logs at its end in parallel: {quantity: (max, mean)}"""
    block = re.search(r"^DLM/FD work and exchange per solve \((\d+) solves\).*\n((?:    .*\n)+)",
                      text, re.M)
    if not block:
        fail(f"no exchange counts in {log}")
    found = {}
    for line in block.group(2).splitlines():
        m = re.match(r"\s+(.*?)\s+([0-9.eE+-]+), ([0-9.eE+-]+)$", line)
        if m:
            found[m.group(1)] = (float(m.group(2)), float(m.group(3)))
    missing = [q for q in quantities if q not in found]
    if missing:
        fail(f"{log} lacks {', '.join(missing)}")
    return found


def cost_of(text, log):
    """The master's cost line: {phase: seconds}"""
    m = re.search(r"^Cost \(wall clock\): (.*)$", text, re.M)
    if not m:
        fail(f"no cost line in {log}")
    secs = {}
    for phase in PHASES:
        v = re.search(re.escape(phase) + r" ([0-9.eE+-]+) s", m.group(1))
        if not v:
            fail(f"no {phase} seconds in {log}")
        secs[phase] = float(v.group(1))
    return secs


def run(case, nprocs, name, env):
    """dlmfdFoam on nprocs processes (1: serial, no counts): (counts, cost)"""
    log = f"log.dlmfdFoam.{name}.np{nprocs}"
    if nprocs == 1:
        sh("dlmfdFoam", case, log, env)
        text = open(os.path.join(case, log)).read()
        return None, cost_of(text, os.path.join(case, log))
    if nprocs not in splits:
        fail(f"{nprocs} processes: allowed 1 and {sorted(splits)}")
    foam_set(case, "system/decomposeParDict", "numberOfSubdomains", str(nprocs))
    foam_set(case, "system/decomposeParDict", "method", "simple")
    foam_set(case, "system/decomposeParDict", "simpleCoeffs",
             f"{{ n {splits[nprocs]}; delta 0.001; }}")
    sh("decomposePar -force", case, f"log.decomposePar.np{nprocs}", env)
    sh(f"mpirun --oversubscribe -np {nprocs} dlmfdFoam -parallel", case, log, env)
    text = open(os.path.join(case, log)).read()
    return counts_of(text, os.path.join(case, log)), cost_of(text, os.path.join(case, log))
