"""Helpers shared by the benchmark scripts that build their cases from a
tutorial: editing a dictionary in place (by pattern, or an entry through
foamDictionary), the decomposition of a case, and the graded mesh of a settling column (uniform around the
vertical axis, growing towards the side walls).
"""
import math
import os
import re
import subprocess
import sys


def sub(path, pattern, repl):
    """Replace the one match of pattern in the file at path; stop if the
    pattern is found zero or several times (the tutorial changed)"""
    text = open(path).read()
    new, n = re.subn(pattern, repl, text, flags=re.M | re.S)
    if n != 1:
        sys.exit(f"{path}: pattern {pattern!r} found {n} times")
    open(path, "w").write(new)


def add_fd_entries(path, entries):
    """Add entries at the end of the fictitiousDomain dictionary of the
    dlmfdProperties at path: after the tutorial's own, so that they win
    over an entry of the same name (OpenFOAM keeps the last)"""
    if entries.strip():
        sub(path, r"^(fictitiousDomain\s*\n\{.*?)^\}", lambda m: m.group(1) + "    " + entries + "\n}")


def foam_set(case, path, entry, value):
    """Set one entry (sub-dictionaries separated by /) of the dictionary at
    case/path with foamDictionary, which reads its #includes and writes the
    whole dictionary back"""
    subprocess.run(["foamDictionary", os.path.join(case, path), "-entry", entry, "-set",
                    str(value)], check=True, capture_output=True)


def decompose_dict(case, cuts):
    """Write case/system/decomposeParDict: method simple, cuts the number of
    pieces along x, y and z"""
    n = " ".join(str(c) for c in cuts)
    with open(os.path.join(case, "system", "decomposeParDict"), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }\n"
                f"numberOfSubdomains {math.prod(cuts)};\nmethod simple;\n"
                f"simpleCoeffs {{ n ({n}); delta 0.001; }}\n")


def growth(L, dx, n):
    """Ratio last/first cell of n cells growing geometrically from dx to
    fill length L"""
    lo, hi = 1.0, 3.0
    for _ in range(200):
        q = 0.5 * (lo + hi)
        if dx * (q**n - 1) / (q - 1) > L:
            hi = q
        else:
            lo = q
    return q**(n - 1)


def write_box(blockMeshDict, collisionProperties, W, H, n, nz, grading="1"):
    """A closed box x, y in [-W, W], z in [0, H] (units of D) of n x n x nz
    cells, grading the x and y grading of simpleGrading: rewrites the
    tutorial's blockMeshDict (from its comment line "// A box" to
    "boundary") and the granular domain of its collisionProperties"""
    sub(blockMeshDict, r"^// A box.*?^boundary",
        f"""vertices
(
    (-{W} -{W} 0) ({W} -{W} 0) ({W} {W} 0) (-{W} {W} 0)
    (-{W} -{W} {H}) ({W} -{W} {H}) ({W} {W} {H}) (-{W} {W} {H})
);

blocks
(
    hex (0 1 2 3 4 5 6 7) ({n} {n} {nz}) simpleGrading ({grading} {grading} 1)
);

boundary""")
    sub(collisionProperties, r"min\s+\([^)]*\);", f"min     (-{W} -{W} 0);")
    sub(collisionProperties, r"max\s+\([^)]*\);", f"max     ({W} {W} {H});")
    return n * n * nz


def column_mesh(blockMeshDict, collisionProperties, N, W, H, core):
    """A closed box x, y in [-W, W], z in [0, H] (units of D): uniform at
    D/dx = N in the column |x|, |y| <= core along the whole height, graded
    geometrically outside it (write_box); returns the number of cells"""
    dx = 1.0 / N
    side = W - core
    nSide = max(6, round(side / (4 * dx) ** 0.5 * 1.5))
    nCore = round(2 * core * N)
    r = growth(side, dx, nSide)
    n = 2 * nSide + nCore
    g = (f"(({side / (2 * W)!r} {nSide / n!r} {1 / r!r}) ({2 * core / (2 * W)!r} {nCore / n!r} 1) "
         f"({side / (2 * W)!r} {nSide / n!r} {r!r}))")
    return write_box(blockMeshDict, collisionProperties, W, H, n, round(H * N), g)
