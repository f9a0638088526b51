#!/usr/bin/env python3
# Set the mesh size of the Hertz sphere: setMesh.py N [case] writes nContact
# N and what follows from it into <case>/system/meshParameters: cell counts
# (blockMesh needs whole numbers, which #eval cannot give) and the
# expansions beyond the contact zone, where the cells grow geometrically
# from the zone's size h = contactZone/N, by at most 'growth' per cell, so
# that no cell is much larger than its neighbour. License: GPL-3.0-or-later
import math
import os
import re
import sys

R = 0.01            # sphere radius [m] (blockMeshDict)
c = 0.5*R           # inner cube's side

n = int(sys.argv[1])
case = sys.argv[2] if len(sys.argv) > 2 else "."
path = os.path.join(case, "system", "meshParameters")
text = open(path).read()


def value(key):
    return float(re.search(r"^%s\s+([^;\s]+);" % key, text, re.M).group(1))


def cellsFor(L, h, r):
    """Cells growing from h by r per cell to fill L"""
    return max(1, int(math.ceil(math.log(1 + L*(r - 1)/h)/math.log(r))))


def expansionFor(L, h, N):
    """last/first of N cells filling L whose first is h (bisection on the
    growth per cell q: h (q^N - 1)/(q - 1) = L)"""
    lo, hi = 1e-3, 10.0
    for _ in range(200):
        q = 0.5*(lo + hi)
        s = N*h if abs(q - 1) < 1e-12 else h*(q**N - 1)/(q - 1)
        lo, hi = (q, hi) if s < L else (lo, q)
    return q**(N - 1)


zone = value("contactZone")
h = zone/n
r = value("growth")
arcOuter = math.pi*R/4 - zone
depth = 0.5*zone
radial = {"Axis": R - c - depth, "Edge": R - c*math.sqrt(2) - depth,
          "Corner": R - c*math.sqrt(3) - depth}
nArcOuter = cellsFor(arcOuter, h, r)
nRadialOuter = cellsFor(radial["Axis"], h, r)
values = {
    "nContact": n,
    "nArcZone": n,
    "nArc": n + nArcOuter,
    "nRadialZone": max(1, int(round(depth/h))),
    "nInner": max(2, int(round(value("nInnerRatio")*n))),
    "arcExpansion": expansionFor(arcOuter, h, nArcOuter),
}
values["nRadial"] = values["nRadialZone"] + nRadialOuter
for k, L in radial.items():
    values["radialExpansion" + k] = expansionFor(L, h, nRadialOuter)
for k, v in values.items():
    text, found = re.subn(r"^(%s\s+)[^;\s]+;" % k, r"\g<1>%.6g;" % v, text,
                          flags=re.M)
    if not found:
        sys.exit("setMesh.py: no '%s' in %s" % (k, path))
open(path, "w").write(text)
