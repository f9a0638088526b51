# -----------------------------------------------------------------------------
# triboFoam: small readers for OpenFOAM ASCII output, used by the tutorials'
# checks and the benchmarks. No third-party dependency.
#
# License: GPL-3.0-or-later
# -----------------------------------------------------------------------------
import os
import re


def timeValues(case):
    """[(time, name)] of the numeric time directories of a case, sorted."""
    out = []
    for d in os.listdir(case):
        try:
            t = float(d)
        except ValueError:
            continue
        if os.path.isdir(os.path.join(case, d)):
            out.append((t, d))
    return sorted(out)


def timeDirs(case):
    """Numeric time directories of a case, sorted by time."""
    return [d for t, d in timeValues(case)]


def readResults(path):
    """A 'name value' results file as a dict of floats (other lines skipped)."""
    values = {}
    with open(path) as f:
        for line in f:
            w = line.split()
            if len(w) >= 2 and not w[0].startswith("#"):
                try:
                    values[w[0]] = float(w[1])
                except ValueError:
                    pass
    return values


def latestTime(case):
    return timeDirs(case)[-1]


def _parseValues(body, nComp):
    if nComp == 1:
        return [float(x) for x in body.split()]
    tuples = re.findall(r"\(([^()]*)\)", body)
    return [tuple(float(v) for v in t.split()) for t in tuples]


def _readField(text, start, nComp):
    """Parse 'uniform X;' or 'nonuniform List<T> N ( ... )' after start."""
    m = re.compile(r"\s*(uniform|nonuniform)\s*").match(text, start)
    if not m:
        raise ValueError("cannot parse field entry")
    pos = m.end()
    if m.group(1) == "uniform":
        end = text.index(";", pos)
        val = text[pos:end].strip()
        return ("uniform", _parseValues(val, nComp)[0] if nComp > 1
                else float(val))
    m2 = re.compile(r"List<\w+>\s*(\d+)\s*\(").match(text, pos)
    n = int(m2.group(1))
    # the list ends at the matching closing parenthesis
    depth = 1
    i = m2.end()
    while depth:
        c = text[i]
        depth += (c == "(") - (c == ")")
        i += 1
    vals = _parseValues(text[m2.end():i - 1], nComp)
    if len(vals) != n:
        raise ValueError("expected %d values, read %d" % (n, len(vals)))
    return ("nonuniform", vals)


def _nComp(text):
    cls = re.search(r"class\s+(\w+);", text).group(1)
    if "Scalar" in cls:
        return 1
    if "SymmTensor" in cls:
        return 6
    if "Tensor" in cls:
        return 9
    return 3


def readInternalField(path, nCells=None):
    """Values of internalField as a list (scalars or tuples)."""
    with open(path) as f:
        text = f.read()
    nComp = _nComp(text)
    start = text.index("internalField") + len("internalField")
    kind, vals = _readField(text, start, nComp)
    if kind == "uniform":
        if nCells is None:
            raise ValueError("uniform field %s needs nCells" % path)
        return [vals] * nCells
    return vals


def readPatchField(path, patch, nFaces=None):
    """Values of boundaryField/patch/value as a list; a uniform value is
    repeated nFaces times when nFaces is given."""
    with open(path) as f:
        text = f.read()
    nComp = _nComp(text)
    m = re.search(r"\n\s*" + re.escape(patch) + r"\s*\n\s*\{", text)
    if not m:
        raise ValueError("patch %s not in %s" % (patch, path))
    vpos = text.index("value", m.end())
    kind, vals = _readField(text, vpos + len("value"), nComp)
    if kind == "nonuniform":
        return vals
    return [vals]*(nFaces if nFaces else 1)


def writeResults(path, values, comment=""):
    """The case tests' results file: one 'name value' per line."""
    with open(path, "w") as f:
        if comment:
            f.write("# %s\n" % comment)
        for k, v in values.items():
            f.write("%s %.10g\n" % (k, v))
