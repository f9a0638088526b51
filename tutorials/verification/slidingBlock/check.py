#!/usr/bin/env python3
# Sliding block: stick while pressed, then the law holds exactly on every
# sliding face, and the dissipated energy equals the work of the drag in
# steady sliding (doc/theory.md [C7], [V5]). Writes <case>/results.dat.
#   python3 check.py <case> coulomb <mu>
#   python3 check.py <case> lubricated <M> <D0> <muS> <muD> <vc> <etaB>
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ["TRIBOFOAM_DIR"], "bin", "python"))
import foamio

case, law = sys.argv[1], sys.argv[2]
par = [float(v) for v in sys.argv[3:]]


def rows(path):
    return [[float(v) for v in r.split()] for r in open(path) if r[0] != "#"]


nFaces = len(foamio.readPatchField(os.path.join(case, "0", "C"), "bottom"))


def patch(time, name):
    return foamio.readPatchField(os.path.join(case, time, name), "bottom",
                                 nFaces)


res = {}

# 1. stick phase (pressed, t = 1): no plastic slip, every face sticks
slip1 = patch("1", "plasticSlip")
status1 = patch("1", "contactStatus")
res["stickPhaseMaxPlasticSlip"] = max(math.sqrt(sum(c*c for c in s))
                                      for s in slip1)
res["stickPhaseFacesNotSticking"] = sum(1 for s in status1 if s != 1)

# 2. sliding (t = 3): the law on every sliding face
p = patch("3", "contactPressure")
tT = patch("3", "frictionTraction")
status = patch("3", "contactStatus")
rate = patch("3", "slipRate")
# Coulomb's law has no lubrication weight (it writes only what it declares)
alpha = patch("3", "lubricationWeight") if law != "coulomb" else [0.0]*nFaces
err = 0.0
nSlip = 0
for pi, ti, si, vi, ai in zip(p, tT, status, rate, alpha):
    if si != 2:
        continue
    nSlip += 1
    mag = math.sqrt(sum(c*c for c in ti))
    if law == "coulomb":
        expected = par[0]*pi
    else:
        M, D0, muS, muD, vc, etaB = par
        mu0 = muD + (muS - muD)*math.exp(-abs(vi)/vc)
        expected = (1 - ai)*mu0*pi + ai*etaB*abs(vi)
    err = max(err, abs(mag - expected)/expected)
res["lawMaxRelError"] = err
res["slidingFaceFraction"] = nSlip/len(p)

# 3. energy in steady sliding (t = 2.5 to 3, 15 memory distances after the
#    start of sliding): work of the drag = dissipation
top = rows(os.path.join(case, "postProcessing", "solidForces", "top.dat"))
con = rows(os.path.join(case, "postProcessing", "contact", "bottom.dat"))
drag = [(r[0], r[1]) for r in top]
# the top's x displacement follows the table in 0/D: 10 um/s after t = 1
def topUx(t):
    return max(0.0, t - 1)*1e-5
work = 0.0
for (t0, f0), (t1, f1) in zip(drag[:-1], drag[1:]):
    if t0 >= 2.5 - 1e-9:
        work += 0.5*(f0 + f1)*(topUx(t1) - topUx(t0))
E = {r[0]: r[7] for r in con}
t2 = min(E, key=lambda t: abs(t - 2.5))
t3 = max(E)
dissipated = E[t3] - E[t2]
res["energyRelError"] = abs(dissipated - work)/work
res["dissipatedEnergy"] = dissipated
print("slidingBlock %s: stick phase max plastic slip %.3g m (%d faces not "
      "sticking); %d of %d faces sliding, law error %.2e; drag work %.6g J,"
      " dissipated %.6g J (%.2e)" % (
          law, res["stickPhaseMaxPlasticSlip"],
          res["stickPhaseFacesNotSticking"], nSlip, len(p),
          res["lawMaxRelError"], work, dissipated, res["energyRelError"]))
with open(os.path.join(case, "results.dat"), "w") as f:
    for k, v in res.items():
        f.write("%s_%s %.10g\n" % (law, k, v))
