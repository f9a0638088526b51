#!/usr/bin/env python3
# Hertz contact of a sphere on a rigid plane: peak pressure and contact
# radius of the computed contact pressure against Hertz for the computed
# contact force (doc/theory.md [V9]). Writes results.dat.
#
# The model is a quarter of the lower hemisphere (symmetry planes x = 0 and
# y = 0), so the sphere's force is P = 4 Fz. Hertz: a = (3 P R/(4 E*))^(1/3),
# p0 = 3 P/(2 pi a^2), p(r) = p0 sqrt(1 - r^2/a^2). The computed a and p0
# come from a least-squares fit of p^2 = p0^2 (1 - r^2/a^2) over the faces
# in contact except the outermost ring (those within one face size of the
# farthest face in contact, which the contact edge cuts), so the whole
# profile is used rather than the faces nearest the edge.
#
# As for the line contact ([V4], tutorials/verification/hertzContact), the
# comparison is made where the linear theory is posed: the force per
# reference area (nominalContactPressure, doc/theory.md [C4]) at the
# undeformed face centre.
# License: GPL-3.0-or-later
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.environ["TRIBOFOAM_DIR"], "bin", "python"))
import foamio  # noqa: E402
import hertzFit  # noqa: E402

R, E, nu = 0.01, 200e9, 0.3
Estar = E/(1 - nu*nu)

case = sys.argv[1] if len(sys.argv) > 1 else "."
P, pen, aH, p0H = hertzFit.sphereContact(case, "contact", R, Estar)

time = foamio.latestTime(case)
p = foamio.readPatchField(os.path.join(case, time, "nominalContactPressure"),
                          "contact")
C = foamio.readPatchField(os.path.join(case, "0", "C"), "contact")
# the faces over the contact zone are squares of side contactZone/nContact
# (system/meshParameters)
mp = open(os.path.join(case, "system", "meshParameters")).read()
h = float(re.search(r"^contactZone\s+([^;\s]+);", mp, re.M).group(1)) \
    / float(re.search(r"^nContact\s+([^;\s]+);", mp, re.M).group(1))
inContact = [(math.hypot(c[0], c[1]), pi) for c, pi in zip(C, p) if pi > 0]
rMax = max(r for r, _ in inContact)
fit = [(r, pp) for r, pp in inContact if r < rMax - h]
n = len(fit)
p0, a = hertzFit.fitProfile(fit)
pMax = max(pp for _, pp in inContact)

res = {
    "contactForce": P,
    "peakPressureRelError": abs(p0 - p0H)/p0H,
    "maxFacePressureRelError": abs(pMax - p0H)/p0H,
    "contactRadiusRelError": abs(a - aH)/aH,
    "penetrationOverContactRadius": pen/aH,
    "facesInContact": len(inContact),
    "facesFitted": n,
}
print("hertzSphere: P = %.4g N; Hertz a = %.4f mm, p0 = %.4g Pa; computed "
      "a = %.4f mm (%.2f %%), p0 = %.4g Pa (%.2f %%), largest face pressure "
      "%.2f %% off; %d faces in contact (quarter), %d fitted; penetration "
      "%.2e of a"
      % (P, aH*1e3, p0H, a*1e3, 100*res["contactRadiusRelError"], p0,
         100*res["peakPressureRelError"], 100*res["maxFacePressureRelError"],
         len(inContact), n, res["penetrationOverContactRadius"]))
foamio.writeResults(os.path.join(case, "results.dat"), res,
                    "Hertz contact of a sphere")
