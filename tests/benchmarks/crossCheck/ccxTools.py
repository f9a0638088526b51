# -----------------------------------------------------------------------------
# triboFoam cross-check against CalculiX (tests/benchmarks/crossCheck): the
# pieces both CalculiX models share. Units of the .inp files: mm, N, MPa, s.
#
#   quadMesh      structured mesh of 8-node quadrilaterals (CAX8R, CPE8R)
#   swiftTable    the Swift hardening curve, tabulated for *PLASTIC
#   runCcx        ccx on one .inp, serial, niced, timed
#   readDat       the blocks of *NODE PRINT / *CONTACT PRINT in the .dat
#
# License: GPL-3.0-or-later
# -----------------------------------------------------------------------------
import math
import os
import re
import shutil
import subprocess
import time

# SS304 of both tutorials (their constant/mechanicalProperties), in MPa
E, NU = 193e3, 0.29
SWIFT_K, SWIFT_EPS0, SWIFT_N = 1270.0, 0.03, 0.45


def swiftTable(epsMax=2.5, ratio=1.04):
    """(sigma_y [MPa], epsP) rows of the Swift curve sigma_y = K (eps0 +
    epsP)^n, the points geometric in eps0 + epsP (ratio 1.04, 109 points:
    the linear interpolation between them is within 0.1 MPa of the curve,
    1e-4 of the yield stress; the CPU time of CalculiX grows with the
    length of the table: 400 points cost 9 times the elastic run, measured
    on the pear tube before contact)."""
    rows = []
    x = SWIFT_EPS0
    while True:
        rows.append((SWIFT_K*x**SWIFT_N, x - SWIFT_EPS0))
        if x - SWIFT_EPS0 >= epsMax:
            break
        x *= ratio
    return rows


def swiftYield(epsP):
    return SWIFT_K*(SWIFT_EPS0 + epsP)**SWIFT_N


def materialCards(name="SS304", yieldScale=1.0):
    """yieldScale: the tabulated yield stresses times this (a test of the
    yield condition's stress measure: CalculiX yields on the Cauchy stress,
    this project on the Kirchhoff stress J sigma)."""
    lines = ["*MATERIAL, NAME=%s" % name, "*ELASTIC", "%.6g, %.6g" % (E, NU),
             "*PLASTIC"]
    lines += ["%.8g, %.8g" % (yieldScale*r[0], r[1]) for r in swiftTable()]
    return lines


class QuadMesh:
    """8-node quadrilaterals on a structured (i, j) grid of corner points.
    xy(i2, j2) gives the coordinates of the point (i2, j2) of the doubled
    grid (corners at even indices, mid-side nodes between); i runs along the
    first direction (ni elements), j along the second (nj). Elements are
    counter-clockwise when x(i) and y(j) form a right-handed pair.
    Faces (CalculiX): S1 j = j0, S2 i = i0 + 1, S3 j = j0 + 1, S4 i = i0."""

    def __init__(self, ni, nj, xy, firstNode=1, firstElement=1):
        self.ni, self.nj = ni, nj
        self.node = {}
        self.coords = {}
        n = firstNode
        for j2 in range(2*nj + 1):
            for i2 in range(2*ni + 1):
                if i2 % 2 and j2 % 2:
                    continue
                self.node[(i2, j2)] = n
                self.coords[n] = xy(i2, j2)
                n += 1
        self.nextNode = n
        self.element = {}
        e = firstElement
        for j in range(nj):
            for i in range(ni):
                self.element[(i, j)] = e
                e += 1
        self.nextElement = e

    def connectivity(self, i, j):
        a, b = 2*i, 2*j
        nd = self.node
        return [nd[(a, b)], nd[(a + 2, b)], nd[(a + 2, b + 2)], nd[(a, b + 2)],
                nd[(a + 1, b)], nd[(a + 2, b + 1)], nd[(a + 1, b + 2)],
                nd[(a, b + 1)]]

    def nodeCards(self):
        return ["%d, %.12g, %.12g" % (n, x[0], x[1])
                for n, x in sorted(self.coords.items())]

    def elementCards(self, etype, elset):
        lines = ["*ELEMENT, TYPE=%s, ELSET=%s" % (etype, elset)]
        for (i, j), e in sorted(self.element.items(), key=lambda t: t[1]):
            c = self.connectivity(i, j)
            lines.append("%d, %s" % (e, ", ".join(str(k) for k in c)))
        return lines

    def faces(self, side):
        """(element, face) of one side of the block: 'j0', 'j1', 'i0',
        'i1' (j = 0, j = nj, i = 0, i = ni)."""
        if side == "j0":
            return [(self.element[(i, 0)], "S1") for i in range(self.ni)]
        if side == "j1":
            return [(self.element[(i, self.nj - 1)], "S3")
                    for i in range(self.ni)]
        if side == "i0":
            return [(self.element[(0, j)], "S4") for j in range(self.nj)]
        return [(self.element[(self.ni - 1, j)], "S2") for j in range(self.nj)]

    def sideNodes(self, side):
        """The nodes of one side, in order along it."""
        if side in ("j0", "j1"):
            j2 = 0 if side == "j0" else 2*self.nj
            return [self.node[(i2, j2)] for i2 in range(2*self.ni + 1)]
        i2 = 0 if side == "i0" else 2*self.ni
        return [self.node[(i2, j2)] for j2 in range(2*self.nj + 1)]


def setCards(kind, name, items, perLine=8):
    """*NSET or *ELSET cards."""
    lines = ["*%s, %s=%s" % (kind, "NSET" if kind == "NSET" else "ELSET",
                             name)]
    items = list(items)
    for k in range(0, len(items), perLine):
        lines.append(", ".join(str(i) for i in items[k:k + perLine]))
    return lines


def surfaceCards(name, faces):
    return (["*SURFACE, NAME=%s, TYPE=ELEMENT" % name]
            + ["%d, %s" % f for f in faces])


def runCcx(directory, job, timeout=7200):
    """ccx -i job in directory, serial (OMP_NUM_THREADS=1), at nice 10.
    Returns wall and CPU (user + system) time [s] and whether the run
    ended normally (the .dat written and no *ERROR in the output)."""
    ccx = shutil.which("ccx")
    if ccx is None:
        raise RuntimeError("ccx not found: apt-get install calculix-ccx "
                           "(etc/installDependencies)")
    env = dict(os.environ, OMP_NUM_THREADS="1", CCX_NPROC_EQUATION_SOLVER="1",
               CCX_NPROC_RESULTS="1", CCX_NPROC_STIFFNESS="1")
    t0 = time.time()
    c0 = os.times()
    with open(os.path.join(directory, "log.ccx"), "w") as out:
        rc = subprocess.call(["nice", "-n", "10", ccx, "-i", job],
                             cwd=directory, stdout=out,
                             stderr=subprocess.STDOUT, env=env,
                             timeout=timeout)
    c1 = os.times()
    log = open(os.path.join(directory, "log.ccx"), errors="replace").read()
    ok = rc == 0 and "*ERROR" not in log and \
        os.path.exists(os.path.join(directory, job + ".dat"))
    incs = len(re.findall(r"^ increment \d+ attempt", log, re.M))
    iters = len(re.findall(r"^ iteration \d+", log, re.M))
    return {"wall": time.time() - t0,
            "cpu": (c1.children_user - c0.children_user)
            + (c1.children_system - c0.children_system),
            "ok": ok, "rc": rc, "increments": incs, "iterations": iters,
            "log": log[-1500:]}


def lastConvergedTime(directory, job):
    """The total time of the last converged increment (the .sta file's
    last row), 0 if none."""
    t = 0.0
    try:
        for line in open(os.path.join(directory, job + ".sta")):
            w = line.split()
            if len(w) >= 7 and w[0].isdigit():
                t = float(w[4])
    except OSError:
        pass
    return t


_header = re.compile(r"^\s*(.+?)\s*for (?:set (\S+)|all contact elements)"
                     r" and time\s+(\S+)")


def readDat(path):
    """The .dat blocks: {(quantity, set): {time: [rows]}}, quantity the
    words before 'for set' (e.g. 'displacements (vx,vy,vz)', 'total force
    (fx,fy,fz)', 'contact stress (slave element+face)'), rows lists of
    floats (integers included as floats)."""
    blocks = {}
    cur = None
    for line in open(path, errors="replace"):
        m = _header.match(line)
        if m:
            cur = blocks.setdefault((m.group(1).strip(), m.group(2) or ""),
                                    {})
            cur = cur.setdefault(float(m.group(3)), [])
            continue
        w = line.split()
        if not w or cur is None:
            continue
        try:
            cur.append([float(v) for v in w])
        except ValueError:
            cur = None
    return blocks


def block(blocks, quantity, nset):
    """The block whose quantity starts with the given words, for set nset
    (CalculiX writes set names in capitals)."""
    for (q, s), b in blocks.items():
        if q.startswith(quantity) and s == nset.upper():
            return b
    raise KeyError("no '%s' for set %s in the .dat" % (quantity, nset))


def interp(x, xs, ys):
    """Linear interpolation in a table with increasing xs."""
    if x <= xs[0]:
        return ys[0]
    for k in range(1, len(xs)):
        if x <= xs[k]:
            f = (x - xs[k - 1])/(xs[k] - xs[k - 1])
            return ys[k - 1] + f*(ys[k] - ys[k - 1])
    return ys[-1]


def polar(r, thetaDeg):
    """A point at radius r and angle theta from the -y axis towards +x
    (the pear tube's original angle: 0 at the bottom, 180 at the top)."""
    t = math.radians(thetaDeg)
    return (r*math.sin(t), -r*math.cos(t))
