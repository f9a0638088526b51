#!/usr/bin/env python3
# Thick cylinder, elastic: radial displacement and the written stress
# (sigma, sigmaEq) against the Lame solution (doc/theory.md [V1]). Writes
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

# The written Cauchy stress against Lame's, sigma_r,theta = A -+ B/r^2,
# sigma_z = nu (sigma_r + sigma_theta) (plane strain), at the cell centres
# away from the boundaries: a cell's sigma is the mean of its internal
# faces' stresses (totalLagrangianSolidFields.C), one-sided next to a
# boundary
A = p*a*a/(b*b - a*a)
B = A*b*b
h = (b - a)/math.sqrt(len(C)/1.5)
dth = math.pi/2/math.sqrt(1.5*len(C))
sig = foamio.readInternalField(os.path.join(case, t, "sigma"), len(C))
sigEq = foamio.readInternalField(os.path.join(case, t, "sigmaEq"), len(C))
sigErr = sigEqErr = 0.0
for (x, y, z), s, se in zip(C, sig, sigEq):
    r, th = math.hypot(x, y), math.atan2(y, x)
    if not (a + h < r < b - h and dth < th < math.pi/2 - dth):
        continue
    c, sn = x/r, y/r
    sr, st = A - B/(r*r), A + B/(r*r)
    sz = nu*(sr + st)
    exact = (sr*c*c + st*sn*sn, (sr - st)*sn*c, 0, sr*sn*sn + st*c*c, 0, sz)
    sigErr = max(sigErr, max(abs(u - v) for u, v in zip(s, exact))/p)
    eq = math.sqrt(0.5*((sr - st)**2 + (st - sz)**2 + (sz - sr)**2))
    sigEqErr = max(sigEqErr, abs(se - eq)/eq)
res = {
    "sigmaMaxError": sigErr,
    "sigmaEqRelErrorMax": sigEqErr,
    "uRelErrorMax": errMax/scale,
    "uRelErrorRms": math.sqrt(errSq/len(C))/scale,
    "nCells": len(C),
}
print("thickCylinder elastic: %d cells, max |u_r - Lame|/u_r(a) = %.3e, "
      "rms = %.3e; written sigma max |sigma - Lame|/p = %.3e, sigmaEq %.3e "
      "(cells off the boundaries)" % (len(C), res["uRelErrorMax"],
                                      res["uRelErrorRms"], sigErr, sigEqErr))
foamio.writeResults(os.path.join(case, "results.dat"), res,
                    "thick cylinder, elastic, against Lame")
