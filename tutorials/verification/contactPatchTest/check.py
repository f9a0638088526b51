#!/usr/bin/env python3
# Contact patch test (doc/theory.md [C10], [C12]): two blocks on
# non-matching meshes pressed by a uniform pressure p (and, with Coulomb
# friction, a uniform shear tau below mu p, in stick). The exact solution
# is uniform: every face of both contact surfaces carries p per reference
# area (nominalContactPressure) and the same friction traction. Also the
# momentum of the pair: the contact forces on the two surfaces sum to zero.
# Usage: check.py <case> <p> <tau> [<A0>] (A0: the interface's reference
# area, 0.1 m^2 in 2-D, 1 m^2 in 3-D). Writes <case>/results.dat.
import os
import sys

sys.path.insert(0, os.path.join(os.environ["TRIBOFOAM_DIR"], "bin", "python"))
import foamio

case, p, tau = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
slave, master = "upperBottom", "lowerTop"
A0 = float(sys.argv[4]) if len(sys.argv) > 4 else 1.0*0.1

t = foamio.latestTime(case)
res = {}
for side in (slave, master):
    pn = foamio.readPatchField(os.path.join(case, t, "nominalContactPressure"),
                               side)
    ft = foamio.readPatchField(os.path.join(case, t, "frictionTraction"), side)
    res[side + "PressureRelError"] = max(abs(x - p) for x in pn)/p
    ftx = [v[0] for v in ft]
    mean = sum(ftx)/len(ftx)
    res[side + "FrictionSpread"] = (max(abs(x - mean) for x in ftx)/abs(mean)
                                    if tau > 0 else max(abs(x) for x in ftx)/p)
    res[side + "Faces"] = len(pn)

# forces of the last step: slave [normal friction], master the same
def lastForce(side):
    rows = [r.split() for r in open(os.path.join(
        case, "postProcessing", "contact", side + ".dat")) if r[0] != "#"]
    v = [float(x) for x in rows[-1][1:7]]
    return [v[0] + v[3], v[1] + v[4], v[2] + v[5]]

fs, fm = lastForce(slave), lastForce(master)
mag = lambda v: sum(x*x for x in v)**0.5
res["momentumRelError"] = mag([a + b for a, b in zip(fs, fm)])/mag(fs)
res["normalForceRelError"] = abs(fs[1] - p*A0)/(p*A0)
if tau > 0:
    res["frictionForceRelError"] = abs(-fs[0] - tau*A0)/(tau*A0)

print("contactPatchTest %s: nominal pressure off p by at most %.2e (slave, "
      "%d faces) and %.2e (master, %d faces); friction traction spread "
      "%.2e / %.2e; slave + master force %.2e of the force"
      % (case, res[slave + "PressureRelError"], res[slave + "Faces"],
         res[master + "PressureRelError"], res[master + "Faces"],
         res[slave + "FrictionSpread"], res[master + "FrictionSpread"],
         res["momentumRelError"]))
foamio.writeResults(os.path.join(case, "results.dat"), res,
                    "contact patch test")
