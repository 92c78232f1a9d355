"""The one Python reader of dlmfdFoam's particle time series,
postProcessing/dlmfdParticles/<startTime>/particles.dat.

Each line: time id x y z qw qx qy qz Ux Uy Uz omegax omegay omegaz Fhx Fhy
Fhz Thx Thy Thz Fcx Fcy Fcz Tcx Tcy Tcz (SI units, world frame; Fh and Th
the hydrodynamic force and torque, Fc and Tc the contacts' mean over the
step), '#' comments. A series without the last six columns (written by
dlmfdFoam before they were added) is read with rows of 21 numbers.
A restart writes a new file under its own start time; its rows replace
those of earlier files from that time on.

    import particlesData
    byTime = particlesData.read(case)          # {time: {id: [27 floats]}}
    i = particlesData.COLUMN["Uz"]             # 11
"""
import glob
import os

COLUMNS = ("time", "id", "x", "y", "z", "qw", "qx", "qy", "qz", "Ux", "Uy", "Uz",
           "omegax", "omegay", "omegaz", "Fhx", "Fhy", "Fhz", "Thx", "Thy", "Thz",
           "Fcx", "Fcy", "Fcz", "Tcx", "Tcy", "Tcz")
COLUMN = {name: i for i, name in enumerate(COLUMNS)}
WITHOUT_CONTACTS = COLUMN["Fcx"]


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
                if len(row) not in (len(COLUMNS), WITHOUT_CONTACTS):
                    raise ValueError(f"{path}, line {n}: {len(row)} columns, expected {len(COLUMNS)}"
                                     f" (or {WITHOUT_CONTACTS} without the contact columns)")
                if (ids is not None and int(row[1]) not in ids) or (start is not None and row[0] < start):
                    continue
                byTime.setdefault(row[0], {})[int(row[1])] = row
    return byTime
