#!/usr/bin/env python3
# Axisymmetric tube: radial displacement against the Lame solution
# (doc/theory.md [V1], plane strain: the symmetry planes at both ends hold
# the axial strain at zero). Usage: check.py <case> [<finer case>]; with a
# finer case (twice the radial cells) also the observed order. Writes
# results.dat.
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ["TRIBOFOAM_DIR"], "bin", "python"))
import foamio

a, b = 0.01, 0.02
E, nu, p = 200e9, 0.3, 100e6


def lame(r):
    return (1 + nu)*p*a*a/(E*(b*b - a*a))*((1 - 2*nu)*r + b*b/r)


def errors(case):
    """max and rms of |u_r - Lame|/u_r(a), max |u_axial|/u_r(a)."""
    t = foamio.latestTime(case)
    D = foamio.readInternalField(os.path.join(case, t, "D"))
    C = foamio.readInternalField(os.path.join(case, "0", "C"))
    # x is radial in the centre plane z = 0 of the wedge, y the axis
    e = [abs(d[0] - lame(c[0])) for c, d in zip(C, D)]
    axial = max(abs(d[1]) for d in D)
    scale = lame(a)
    return (max(e)/scale, math.sqrt(sum(x*x for x in e)/len(e))/scale,
            axial/scale, len(C))


res = {}
eMax, eRms, axial, n = errors(sys.argv[1])
res.update({"uRelErrorMax": eMax, "uRelErrorRms": eRms,
            "axialRelDisplacement": axial, "nCells": n})
print("axisymmetricTube: %d cells, max |u_r - Lame|/u_r(a) = %.3e, rms = "
      "%.3e, max |u_axial|/u_r(a) = %.1e" % (n, eMax, eRms, axial))
if len(sys.argv) > 2:
    fMax, fRms, fAxial, fn = errors(sys.argv[2])
    res.update({"uRelErrorRmsFine": fRms,
                "order": math.log(eRms/fRms)/math.log(2)})
    print("axisymmetricTube: %d cells, rms = %.3e, observed order %.2f"
          % (fn, fRms, res["order"]))
foamio.writeResults("results.dat", res, "axisymmetric tube against Lame")
