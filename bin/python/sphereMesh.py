# triboFoam: cell counts and expansions of the sphere meshes of the Hertz
# tutorials (hertzSphere, hertzSpheres): an inner cube of side R/2 and three
# blocks out to the sphere, the cells uniform cubes of side h = zone/N over
# the contact zone (the first 'zone' of arc from the contact point, half of
# it deep) and growing geometrically beyond it by at most 'growth' per cell.
# blockMesh needs whole numbers, which #eval cannot give, and the expansions
# solve an equation. License: GPL-3.0-or-later
import math
import re


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


def counts(R, zone, n, growth, innerRatio):
    """The counts and expansions of a sphere of radius R with n cells
    across the contact zone, keyed as in system/meshParameters"""
    c = 0.5*R
    h = zone/n
    arcOuter = math.pi*R/4 - zone
    depth = 0.5*zone
    radial = {"Axis": R - c - depth, "Edge": R - c*math.sqrt(2) - depth,
              "Corner": R - c*math.sqrt(3) - depth}
    nArcOuter = cellsFor(arcOuter, h, growth)
    nRadialOuter = cellsFor(radial["Axis"], h, growth)
    values = {
        "nContact": n,
        "nArcZone": n,
        "nArc": n + nArcOuter,
        "nRadialZone": max(1, int(round(depth/h))),
        "nInner": max(2, int(round(innerRatio*n))),
        "arcExpansion": expansionFor(arcOuter, h, nArcOuter),
    }
    values["nRadial"] = values["nRadialZone"] + nRadialOuter
    for k, L in radial.items():
        values["radialExpansion" + k] = expansionFor(L, h, nRadialOuter)
    return values


def value(text, key):
    """The number of entry 'key' of a dictionary's text"""
    return float(re.search(r"^%s\s+([^;\s]+);" % key, text, re.M).group(1))


def setValues(text, values, path, suffix=""):
    """The text with each entry key + suffix set to values[key]"""
    for k, v in values.items():
        text, found = re.subn(r"^(%s%s\s+)[^;\s]+;" % (k, suffix),
                              r"\g<1>%.6g;" % v, text, flags=re.M)
        if not found:
            raise SystemExit("setMesh.py: no '%s%s' in %s" % (k, suffix, path))
    return text
