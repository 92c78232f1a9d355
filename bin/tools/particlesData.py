"""The one Python reader of dlmfdFoam's particle time series,
postProcessing/dlmfdParticles/<startTime>/particles.dat.

Each line: time id x y z qw qx qy qz Ux Uy Uz omegax omegay omegaz Fhx Fhy
Fhz Thx Thy Thz (SI units, world frame; F and T hydrodynamic), '#' comments.
A restart writes a new file under its own start time; its rows replace
those of earlier files from that time on.

    import particlesData
    byTime = particlesData.read(case)          # {time: {id: [21 floats]}}
    i = particlesData.COLUMN["Uz"]             # 11
"""
import glob
import os

COLUMNS = ("time", "id", "x", "y", "z", "qw", "qx", "qy", "qz", "Ux", "Uy", "Uz",
           "omegax", "omegay", "omegaz", "Fhx", "Fhy", "Fhz", "Thx", "Thy", "Thz")
COLUMN = {name: i for i, name in enumerate(COLUMNS)}


def files(case):
    """The particles.dat files of case, by start time"""
    found = glob.glob(os.path.join(case, "postProcessing", "dlmfdParticles", "*", "particles.dat"))
    return sorted(found, key=lambda f: float(os.path.basename(os.path.dirname(f))))


def read(case, ids=None, start=None):
    """{time: {id: row}} over every file of case (rows: lists of floats,
    COLUMNS); only the particles in ids if given, only times >= start if
    given. Raises FileNotFoundError naming the case if there is no file,
    ValueError naming the file and line of a malformed row."""
    paths = files(case)
    if not paths:
        raise FileNotFoundError(f"no postProcessing/dlmfdParticles/*/particles.dat in {case}")
    byTime = {}
    for path in paths:
        restart = float(os.path.basename(os.path.dirname(path)))
        # A restart rewrites the times from its start on
        for t in [t for t in byTime if t > restart]:
            del byTime[t]
        with open(path) as f:
            for n, line in enumerate(f, 1):
                if line.startswith("#") or not line.strip():
                    continue
                try:
                    row = [float(x) for x in line.split()]
                except ValueError:
                    raise ValueError(f"{path}, line {n}: not a row of numbers") from None
                if len(row) != len(COLUMNS):
                    raise ValueError(f"{path}, line {n}: {len(row)} columns, expected {len(COLUMNS)}")
                if (ids is not None and int(row[1]) not in ids) or (start is not None and row[0] < start):
                    continue
                byTime.setdefault(row[0], {})[int(row[1])] = row
    return byTime
