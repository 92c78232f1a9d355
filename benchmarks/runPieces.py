"""What the long-run scripts (accuracyCost/run, tutorialRuns/run) share about
a run made in pieces: a run a session's end cut short goes on from its last
write, the logs of each earlier piece kept in pieces/<n>/ beside the case.

  written_times(folder)   the time folders past 0 (their names)
  piece_folders(case)     pieces/1, pieces/2, ... in order
  piece_times(folder, timeFile, log)
                          (wall, cpu, peak RSS MiB) of a piece: its GNU time
                          record, else (a piece stopped from outside) its
                          solver's last ClockTime and ExecutionTime, RSS 0
  solver_times(text)      the solver log's last (ClockTime, ExecutionTime)
  cost_seconds(text)      the seconds of the five phases of the solver log's
                          last cost line (fluid, DLM/FD, granular,
                          communication, output), None without one
"""
import os
import re

COST_LINE = re.compile(r"Cost \(wall clock\): fluid ([0-9.eE+-]+) s .*?DLM/FD ([0-9.eE+-]+) s .*?"
                       r"granular ([0-9.eE+-]+) s .*?communication ([0-9.eE+-]+) s .*?"
                       r"output ([0-9.eE+-]+) s")


def written_times(folder):
    if not os.path.isdir(folder):
        return []
    return [d for d in os.listdir(folder) if re.fullmatch(r"[0-9.eE+-]+", d) and float(d) > 0
            and os.path.isdir(os.path.join(folder, d))]


def piece_folders(case):
    folder = os.path.join(case, "pieces")
    return [os.path.join(folder, d) for d in sorted(os.listdir(folder), key=int)] if os.path.isdir(folder) else []


def solver_times(text):
    m = re.findall(r"ExecutionTime = ([0-9.]+) s\s+ClockTime = ([0-9.]+) s", text)
    return (float(m[-1][1]), float(m[-1][0])) if m else None


def cost_seconds(text):
    m = COST_LINE.findall(text)
    return [float(x) for x in m[-1]] if m else None


def piece_times(folder, timeFile, log):
    path = os.path.join(folder, timeFile)
    t = open(path).read().split()[-4:] if os.path.exists(path) else []
    if len(t) == 4:
        return float(t[0]), float(t[1]) + float(t[2]), float(t[3]) / 1024
    path = os.path.join(folder, log)
    clock = solver_times(open(path).read()) if os.path.exists(path) else None
    return (clock[0], clock[1], 0.0) if clock else None
