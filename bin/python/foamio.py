# -----------------------------------------------------------------------------
# triboFoam: small readers for OpenFOAM ASCII output, used by the tutorials'
# checks and the benchmarks. No third-party dependency.
#
# License: GPL-3.0-or-later
# -----------------------------------------------------------------------------
import math
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


# ------------------------------------------------------------ polyMesh (ASCII)

def _listStart(text):
    """Count and start of the first top-level 'N (' list after the header."""
    h = text.find("FoamFile")
    start = text.find("}", h) + 1 if h >= 0 else 0
    m = re.compile(r"(\d+)\s*\(").search(text, start)
    return int(m.group(1)), m.end()


def readPoints(path):
    """Points of an ASCII pointField (constant/polyMesh/points) as tuples."""
    with open(path) as f:
        text = f.read()
    n, pos = _listStart(text)
    num = r"([-+0-9.eE]+)"
    pts = re.findall(r"\(\s*%s\s+%s\s+%s\s*\)" % (num, num, num), text[pos:])
    if len(pts) < n:
        raise ValueError("%s: read %d of %d points" % (path, len(pts), n))
    return [tuple(float(c) for c in p) for p in pts[:n]]


def readFaces(path):
    """Faces of an ASCII faceList (constant/polyMesh/faces): point labels."""
    with open(path) as f:
        text = f.read()
    n, pos = _listStart(text)
    out = [[int(v) for v in m.group(1).split()] for m in
           re.compile(r"\d+\s*\(([\d\s]+)\)").finditer(text, pos)]
    if len(out) < n:
        raise ValueError("%s: read %d of %d faces (binary mesh?)"
                         % (path, len(out), n))
    return out[:n]


def readLabels(path):
    """An ASCII labelList (constant/polyMesh/owner, neighbour)."""
    with open(path) as f:
        text = f.read()
    n, pos = _listStart(text)
    vals = text[pos:text.index(")", pos)].split()
    if len(vals) != n:
        raise ValueError("%s: read %d of %d labels" % (path, len(vals), n))
    return [int(v) for v in vals]


def readBoundary(path):
    """Patches of constant/polyMesh/boundary: {name: (type, nFaces,
    startFace)}."""
    with open(path) as f:
        text = f.read()
    out = {}
    for m in re.finditer(r"\n\s*(\w+)\s*\n\s*\{([^{}]*)\}", text):
        d = dict(re.findall(r"(\w+)\s+([^;]+);", m.group(2)))
        if "nFaces" in d and "startFace" in d:
            out[m.group(1)] = (d.get("type", "patch").strip(),
                               int(d["nFaces"]), int(d["startFace"]))
    return out


class polyMesh(object):
    """The undeformed mesh of a case (points, faces, patches), read once."""

    def __init__(self, case):
        d = os.path.join(case, "constant", "polyMesh")
        self.points = readPoints(os.path.join(d, "points"))
        self.faces = readFaces(os.path.join(d, "faces"))
        self.patches = readBoundary(os.path.join(d, "boundary"))
        self.owner = readLabels(os.path.join(d, "owner"))
        self.neighbour = readLabels(os.path.join(d, "neighbour"))
        self.nCells = max(self.owner) + 1

    def patchFaces(self, name):
        """Faces (point labels) of a patch."""
        if name not in self.patches:
            raise ValueError("no patch %s (have %s)"
                             % (name, " ".join(self.patches)))
        _, n, start = self.patches[name]
        return self.faces[start:start + n]

    def patchPoints(self, name):
        """Sorted point labels of a patch."""
        return sorted(set(p for f in self.patchFaces(name) for p in f))

    def boundaryFaces(self):
        """Faces of every patch (the closed surface of the body, with its
        symmetry planes)."""
        return [f for name in self.patches for f in self.patchFaces(name)]


def faceAreaVector(pts):
    """Area vector of a polygon (its vertices in order): the sum of the
    triangles from the vertex mean, as OpenFOAM does for non-planar faces."""
    n = len(pts)
    c = [sum(p[i] for p in pts)/n for i in range(3)]
    s = [0.0, 0.0, 0.0]
    for k in range(n):
        a = [pts[k][i] - c[i] for i in range(3)]
        b = [pts[(k + 1) % n][i] - c[i] for i in range(3)]
        s[0] += 0.5*(a[1]*b[2] - a[2]*b[1])
        s[1] += 0.5*(a[2]*b[0] - a[0]*b[2])
        s[2] += 0.5*(a[0]*b[1] - a[1]*b[0])
    return s


def enclosedVolume(points, faces):
    """Volume enclosed by a closed surface of outward polygons:
    sum over the triangles (vertex mean, edge) of x . S / 3."""
    vol = 0.0
    for f in faces:
        n = len(f)
        c = [sum(points[p][i] for p in f)/n for i in range(3)]
        for k in range(n):
            a = points[f[k]]
            b = points[f[(k + 1) % n]]
            # triple product c . (a x b) / 6 (tetrahedron with the origin)
            vol += (c[0]*(a[1]*b[2] - a[2]*b[1])
                    + c[1]*(a[2]*b[0] - a[0]*b[2])
                    + c[2]*(a[0]*b[1] - a[1]*b[0]))/6.0
    return vol


def _solve4(A, b):
    """Solve the 4 x 4 system A x = b (Gaussian elimination, partial
    pivoting); b holds three right-hand sides (columns)."""
    M = [A[i][:] + b[i][:] for i in range(4)]
    for k in range(4):
        piv = max(range(k, 4), key=lambda i: abs(M[i][k]))
        M[k], M[piv] = M[piv], M[k]
        for i in range(k + 1, 4):
            f = M[i][k]/M[k][k]
            for j in range(k, 7):
                M[i][j] -= f*M[k][j]
    x = [[0.0]*3 for _ in range(4)]
    for i in range(3, -1, -1):
        for c in range(3):
            s = M[i][4 + c] - sum(M[i][j]*x[j][c] for j in range(i + 1, 4))
            x[i][c] = s/M[i][i]
    return x


def boundaryPointDisplacements(mesh, C, D, faceValues):
    """Displacement of every boundary point of a solid-mechanics case,
    fitted linearly (weighted least squares, weights 1/|d|^2, as the
    solver's cell gradients, doc/theory.md [S10]) to the cell centres of
    the point's cells and the centres of its boundary faces that have a
    value, with the mirror images of all of them across the symmetryPlane
    and wedge patches through the point (an axisymmetric field is mirror
    symmetric about any meridional plane). Exact for a linear field, second
    order otherwise; volPointInterpolation (the solver's pointD) is not
    exact for a linear field at boundary points.

    C, D: cell centres and displacements; faceValues: {patch: (centres,
    displacements)} for the patches whose D values are written.
    Returns {point label: displacement}."""
    nInternal = len(mesh.neighbour)
    bPoints = set(p for f in mesh.boundaryFaces() for p in f)
    samples = dict((p, []) for p in bPoints)
    for facei, f in enumerate(mesh.faces):
        cells = [mesh.owner[facei]]
        if facei < nInternal:
            cells.append(mesh.neighbour[facei])
        for p in f:
            if p in samples:
                for c in cells:
                    if (C[c], D[c]) not in samples[p]:
                        samples[p].append((C[c], D[c]))
    planes = {}
    for name, (ptype, n, start) in mesh.patches.items():
        faces = mesh.patchFaces(name)
        if ptype in ("symmetryPlane", "wedge") and faces:
            S = faceAreaVector([mesh.points[i] for i in faces[0]])
            m = math.sqrt(sum(s*s for s in S))
            planes[name] = ([s/m for s in S], mesh.points[faces[0][0]])
        elif name in faceValues:
            for f, x, d in zip(faces, *faceValues[name]):
                for p in f:
                    samples[p].append((x, d))
    onPlanes = dict((p, []) for p in bPoints)
    for name, plane in planes.items():
        for p in mesh.patchPoints(name):
            onPlanes[p].append(plane)

    def mirror(v, n, p0=None):
        s = sum((v[i] - (p0[i] if p0 else 0))*n[i] for i in range(3))
        return tuple(v[i] - 2*s*n[i] for i in range(3))

    out = {}
    for p, smp in samples.items():
        for n, p0 in onPlanes[p]:
            smp = smp + [(mirror(x, n, p0), mirror(d, n)) for x, d in smp]
        X = mesh.points[p]
        A = [[0.0]*4 for _ in range(4)]
        b = [[0.0]*3 for _ in range(4)]
        for x, d in smp:
            r = [1.0] + [x[i] - X[i] for i in range(3)]
            w = 1.0/max(sum(v*v for v in r[1:]), 1e-300)
            for i in range(4):
                for j in range(4):
                    A[i][j] += w*r[i]*r[j]
                for c in range(3):
                    b[i][c] += w*r[i]*d[c]
        # a point whose samples are coplanar (no spread along one
        # direction) keeps a tiny gradient there instead of a singular fit
        reg = 1e-12*(A[1][1] + A[2][2] + A[3][3])
        for i in range(1, 4):
            A[i][i] += reg
        out[p] = tuple(_solve4(A, b)[0])
    return out
