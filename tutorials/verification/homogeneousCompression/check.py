#!/usr/bin/env python3
# Homogeneous compression of a Swift-hardening cube: the computed state at
# the end of the load against the exact one (doc/theory.md [V8]). Usage:
#   check.py <case> <nominal stress> [rotated]   appends to <case>/results.dat
# With 'rotated' the case is the copy turned by exactCompression.rotation()
# and its displacements and positions are turned back first.
# License: GPL-3.0-or-later
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ["TRIBOFOAM_DIR"], "bin", "python"))
import foamio  # noqa: E402
import exactCompression as ex  # noqa: E402

case = sys.argv[1]
P = float(sys.argv[2])
rotated = len(sys.argv) > 3 and sys.argv[3] == "rotated"
prefix = "rotated" if rotated else ""
R = ex.rotation() if rotated else [[1, 0, 0], [0, 1, 0], [0, 0, 1]]


def name(s):
    return prefix + s[0].upper() + s[1:] if prefix else s


t = foamio.latestTime(case)
D = os.path.join(case, t, "D")
C = os.path.join(case, "0", "C")
top = [ex.applyT(R, d) for d in foamio.readPatchField(D, "zMax")]
sides = [ex.applyT(R, d) for d in foamio.readPatchField(D, "sides")]
sideC = [ex.applyT(R, c) for c in foamio.readPatchField(C, "sides")]

# Measured stretches: top face (z = L) and the side faces x = L, y = L
axial = 1 + sum(d[2] for d in top)/len(top)/ex.L
lat = [1 + d[0]/ex.L for d, c in zip(sides, sideC) if abs(c[0] - ex.L) < 1e-9] \
    + [1 + d[1]/ex.L for d, c in zip(sides, sideC) if abs(c[1] - ex.L) < 1e-9]
lateral = sum(lat)/len(lat)
spread = (max(d[2] for d in top) - min(d[2] for d in top))/ex.L

# Exact state under the applied nominal stress, and the force the exact
# solution needs at the measured height
exact = ex.state(ex.plasticStrainAtNominalStress(P))
eps = -math.log(axial)
atHeight = ex.state(ex.plasticStrainAtStrain(eps))
noElastic = ex.sigmaY(eps)/axial

nCells = len(foamio.readInternalField(os.path.join(case, t, "epsilonPEq")))
epsP = foamio.readInternalField(os.path.join(case, t, "epsilonPEq"), nCells)
sigEq = foamio.readInternalField(os.path.join(case, t, "sigmaEq"), nCells)
epsPexact = ex.plasticStrainAtNominalStress(P)

res = {
    name("logStrain"): eps,
    name("forceRelError"): abs(P - atHeight["nominal"])/atHeight["nominal"],
    name("heightRelError"): abs(axial/exact["axial"] - 1),
    name("lateralStretchRelError"): abs(lateral/exact["lateral"] - 1),
    name("plasticStrainError"): max(abs(e - epsPexact) for e in epsP),
    name("vonMisesStressRelError"):
        max(abs(s/exact["cauchy"] - 1) for s in sigEq),
    name("heightSpread"): spread,
    name("forceErrorWithoutElasticity"): abs(noElastic - P)/P,
}
print("homogeneousCompression%s: log strain %.6f (exact %.6f), height error"
      " %.2e, force error %.2e, lateral stretch error %.2e, plastic strain"
      " error %.2e, von Mises stress error %.2e; the formula without the"
      " elastic strain is %.2e off"
      % (" (rotated)" if rotated else "", eps, -math.log(exact["axial"]),
         res[name("heightRelError")], res[name("forceRelError")],
         res[name("lateralStretchRelError")], res[name("plasticStrainError")],
         res[name("vonMisesStressRelError")],
         res[name("forceErrorWithoutElasticity")]))
with open(os.path.join(case, "results.dat"), "a") as f:
    for k, v in res.items():
        f.write("%s %.10g\n" % (k, v))
