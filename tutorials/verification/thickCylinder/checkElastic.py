#!/usr/bin/env python3
# Thick cylinder, elastic: radial displacement against the Lame solution
# (doc/theory.md [V1]). Writes results.dat.
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ["TRIBOFOAM_DIR"], "bin", "python"))
import foamio

a, b = 0.01, 0.02
E, nu, p = 200e9, 0.3, 100e6


def lame(r):
    return (1 + nu)*p*a*a/(E*(b*b - a*a))*((1 - 2*nu)*r + b*b/r)


case = sys.argv[1] if len(sys.argv) > 1 else "elastic"
t = foamio.latestTime(case)
D = foamio.readInternalField(os.path.join(case, t, "D"))
C = foamio.readInternalField(os.path.join(case, "0", "C"))

errMax = 0.0
errSq = 0.0
for (x, y, z), (dx, dy, dz) in zip(C, D):
    r = math.hypot(x, y)
    ur = (dx*x + dy*y)/r
    e = abs(ur - lame(r))
    errMax = max(errMax, e)
    errSq += e*e
scale = lame(a)
res = {
    "uRelErrorMax": errMax/scale,
    "uRelErrorRms": math.sqrt(errSq/len(C))/scale,
    "nCells": len(C),
}
print("thickCylinder elastic: %d cells, max |u_r - Lame|/u_r(a) = %.3e, "
      "rms = %.3e" % (len(C), res["uRelErrorMax"], res["uRelErrorRms"]))
foamio.writeResults(os.path.join(case, "results.dat"), res,
                    "thick cylinder, elastic, against Lame")
