"""Read OpenFOAM ASCII volume fields (internalField) into numpy arrays.

Only what the project's checks need: the internalField of a volScalarField
or volVectorField written with writeFormat ascii, uniform or nonuniform,
and a few dictionary values through OpenFOAM's own foamDictionary.
"""
import os
import re
import subprocess

import numpy as np

_NONUNIFORM = re.compile(
    r"internalField\s+nonuniform\s+List<(scalar|vector)>\s*(\d+)\s*\(", re.S)
_UNIFORM = re.compile(r"internalField\s+uniform\s+(\([^)]*\)|[^;\s]+)\s*;")


def read_internal_field(path, n_cells=None):
    """The internalField of the field file at path, as an (N,) or (N,3)
    float array. A uniform field needs n_cells to be expanded."""
    with open(path) as f:
        text = f.read()
    m = _NONUNIFORM.search(text)
    if m:
        kind, n = m.group(1), int(m.group(2))
        body = text[m.end():]
        values = body[:body.index("\n)")]
        numbers = np.array(values.replace("(", " ").replace(")", " ").split(),
                           dtype=float)
        width = 3 if kind == "vector" else 1
        if numbers.size != n * width:
            raise ValueError(f"{path}: expected {n} {kind}s, read "
                             f"{numbers.size // width}")
        return numbers.reshape(n, 3) if width == 3 else numbers
    m = _UNIFORM.search(text)
    if m:
        if n_cells is None:
            raise ValueError(f"{path}: uniform field, give n_cells")
        value = np.array(m.group(1).strip("()").split(), dtype=float)
        return np.tile(value, (n_cells, 1)) if value.size == 3 \
            else np.full(n_cells, value[0])
    raise ValueError(f"{path}: no ASCII internalField found "
                     "(writeFormat must be ascii)")


def dictionary_value(case, dict_path, entry):
    """The value of entry (a/b/c scoping allowed) of a case dictionary, as
    the string foamDictionary prints."""
    out = subprocess.run(
        ["foamDictionary", "-case", case, "-entry", entry, "-value",
         os.path.join(case, dict_path)],
        check=True, capture_output=True, text=True)
    return out.stdout.strip()


def dimensioned_value(text):
    """The value of a dimensioned entry: '[0 1 -2 0 0 0 0] (1 0 0)' ->
    array([1, 0, 0]); '0.01' -> 0.01."""
    text = re.sub(r"\[[^]]*\]", " ", text)
    text = text.replace("(", " ").replace(")", " ").split()
    values = [float(t) for t in text if re.match(r"^[-+0-9.eE]+$", t)]
    return np.array(values) if len(values) > 1 else values[0]


def latest_time(case):
    """The latest time folder name of a case (not 0)."""
    times = []
    for name in os.listdir(case):
        try:
            value = float(name)
        except ValueError:
            continue
        if os.path.isdir(os.path.join(case, name)):
            times.append((value, name))
    if not times:
        raise ValueError(f"{case}: no time folders")
    return max(times)[1]
