#!/usr/bin/env python3
# Thick cylinder, elastic-perfectly plastic: plastic radius against the
# classical partly-plastic solution p = k (1 - c^2/b^2 + 2 ln(c/a))
# (doc/theory.md [V2]). Writes results.dat.
#
# The plastic radius c is measured from the outer-surface displacement:
# the zone c < r < b is elastic and yields exactly at r = c, so u(b) is an
# exact, monotone function of c for any nu (Lame solution of that zone).
# The relation p(c) above is exact only for nu -> 0.5; at nu = 0.49 its
# error is part of what is measured.
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ["TRIBOFOAM_DIR"], "bin", "python"))
import foamio

a, b = 0.01, 0.02
E, nu, sy = 200e9, 0.49, 250e6
k = sy/math.sqrt(3)


def pressureOfRadius(c):
    return k*(1 - c*c/(b*b) + 2*math.log(c/a))


def outerDisplacementOfRadius(c):
    # elastic zone c < r < b with the pressure that makes r = c yield
    A = c*c/(b*b - c*c)                 # per unit pressure
    sr, st, sz = A*(1 - b*b/(c*c)), A*(1 + b*b/(c*c)), 2*nu*A
    q = math.sqrt(0.5*((sr - st)**2 + (st - sz)**2 + (sz - sr)**2))
    pc = sy/q
    return (1 + nu)*pc*c*c/(E*(b*b - c*c))*((1 - 2*nu)*b + b)


def radiusOfOuterDisplacement(ub):
    lo, hi = a, b*(1 - 1e-9)
    for _ in range(200):
        mid = 0.5*(lo + hi)
        if outerDisplacementOfRadius(mid) < ub:
            lo = mid
        else:
            hi = mid
    return 0.5*(lo + hi)


case = sys.argv[1] if len(sys.argv) > 1 else "plastic"
pApplied = float(sys.argv[2]) if len(sys.argv) > 2 else 180.1955e6
t = foamio.latestTime(case)
Db = foamio.readPatchField(os.path.join(case, t, "D"), "outer")
Cb = foamio.readPatchField(os.path.join(case, "0", "C"), "outer")
ur = [(d[0]*c[0] + d[1]*c[1])/math.hypot(c[0], c[1]) for d, c in zip(Db, Cb)]
ub = sum(ur)/len(ur)

c = radiusOfOuterDisplacement(ub)
pTheory = pressureOfRadius(c)
cExpected = 0.015

# The plastic zone seen in the written fields, independently of u(b): its
# edge (half way between the outermost cell with plastic strain and the
# innermost without) against c = 15 mm, and sigmaEq = sigma_y in it (cells
# a cell's width inside; perfectly plastic: the Cauchy equivalent stress
# is the yield stress up to the volume change, 1e-4 at nu = 0.49)
C = foamio.readInternalField(os.path.join(case, "0", "C"))
eps = foamio.readInternalField(os.path.join(case, t, "epsilonPEq"), len(C))
sigEq = foamio.readInternalField(os.path.join(case, t, "sigmaEq"), len(C))
r = [math.hypot(x, y) for x, y, z in C]
rPlastic = max(ri for ri, e in zip(r, eps) if e > 0)
rElastic = min(ri for ri, e in zip(r, eps) if e <= 0)
h = (b - a)/len(set(round(ri, 9) for ri in r))
edge = 0.5*(rPlastic + rElastic)

res = {
    "plasticRadius": c,
    "plasticRadiusError": abs(c - cExpected)/cExpected,
    "plasticZoneEdgeRelError": abs(edge - cExpected)/cExpected,
    "plasticSigmaEqRelError": max(abs(s/sy - 1) for ri, s in zip(r, sigEq)
                                  if ri < cExpected - h),
    "pOfPlasticRadiusRelError": abs(pApplied - pTheory)/pApplied,
    "uOuterSpread": (max(ur) - min(ur))/ub,
}
print("thickCylinder plastic: c from u(b) = %.4f mm (theory 15 mm, error "
      "%.2f %%); the plastic strain ends between r = %.3f and %.3f mm "
      "(edge %.2e off 15 mm); sigmaEq = sigma_y in the plastic zone to %.2e"
      % (c*1e3, 100*res["plasticRadiusError"], rPlastic*1e3, rElastic*1e3,
         res["plasticZoneEdgeRelError"], res["plasticSigmaEqRelError"]))
foamio.writeResults(os.path.join(case, "results.dat"), res,
                    "thick cylinder, elastic-perfectly plastic")
