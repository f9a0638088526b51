#!/usr/bin/env python3
# Hertz contact of two elastic spheres, frictionless: peak pressure and
# contact radius of the computed contact pressure against Hertz for the
# computed contact force (doc/theory.md [V12]).
# Writes results.dat.
#
# The model is a quarter of each sphere (symmetry planes x = 0 and y = 0),
# so the force is P = 4 Fz. Hertz: 1/R* = 1/R1 + 1/R2,
# 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2, a = (3 P R*/(4 E*))^(1/3),
# p0 = 3 P/(2 pi a^2), p(r) = p0 sqrt(1 - r^2/a^2). The computed a and p0
# come from the least-squares fit of p^2 = p0^2 (1 - r^2/a^2) over the slave
# surface's faces in contact except the outermost ring (faces within one
# face size of the farthest face in contact, which the contact edge cuts),
# as in tutorials/verification/hertzSphere; the master surface's pressure
# is fitted alike and reported. Pressure per reference area
# (nominalContactPressure, [C4]) at the undeformed face centres, where the
# linear theory is posed ([V4]). The slave is the patch that carries the
# frictionLaw in 0/D (either sphere's). Also the scatter of each surface's
# face pressures about its fitted profile (root mean square over the fitted
# faces, over p0): the slave's faces scatter when its partner deforms,
# the more so the more compliant the master and the finer the slave
# (doc/theory.md [C10b]).
# License: GPL-3.0-or-later
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.environ["TRIBOFOAM_DIR"], "bin", "python"))
import foamio  # noqa: E402
import hertzFit  # noqa: E402

case = sys.argv[1] if len(sys.argv) > 1 else "."
mp = open(os.path.join(case, "system", "meshParameters")).read()


def param(key):
    return float(re.search(r"^%s\s+([^;\s]+);" % key, mp, re.M).group(1))


R1, R2 = param("R1"), param("R2")
E1, nu1, E2, nu2 = 200e9, 0.3, 70e9, 0.33    # constant/mechanicalProperties
Rstar = 1/(1/R1 + 1/R2)
Estar = 1/((1 - nu1*nu1)/E1 + (1 - nu2*nu2)/E2)
h = param("contactZone")/param("nContact")

# the slave: the patch of the pair whose entry in 0/D names a frictionLaw
D0 = open(os.path.join(case, "0", "D")).read()


def carriesLaw(patch):
    m = re.search(r"\n\s*%s\s*\{([^}]*)" % patch, D0)
    return m is not None and "frictionLaw" in m.group(1)


slave, master = (("lowerSurface", "upperSurface")
                 if carriesLaw("lowerSurface") else
                 ("upperSurface", "lowerSurface"))
P, pen, aH, p0H = hertzFit.sphereContact(case, slave, Rstar, Estar)

time = foamio.latestTime(case)


def fitSurface(patch):
    p = foamio.readPatchField(
        os.path.join(case, time, "nominalContactPressure"), patch)
    C = foamio.readPatchField(os.path.join(case, "0", "C"), patch)
    inContact = [(math.hypot(c[0], c[1]), pi) for c, pi in zip(C, p)
                 if pi > 0]
    rMax = max(r for r, _ in inContact)
    fit = [(r, pp) for r, pp in inContact if r < rMax - h]
    p0, a = hertzFit.fitProfile(fit)
    scatter = math.sqrt(sum(
        (pp - p0*math.sqrt(max(1 - r*r/(a*a), 0)))**2 for r, pp in fit)
        / len(fit))/p0
    return p0, a, len(inContact), len(fit), scatter


p0, a, nIn, nFit, scatter = fitSurface(slave)
p0m, am, nInM, _, scatterM = fitSurface(master)
res = {
    "contactForce": P,
    "peakPressureRelError": abs(p0 - p0H)/p0H,
    "contactRadiusRelError": abs(a - aH)/aH,
    "masterPeakPressureRelError": abs(p0m - p0H)/p0H,
    "masterContactRadiusRelError": abs(am - aH)/aH,
    "peakPressureScatter": scatter,
    "masterPeakPressureScatter": scatterM,
    "penetrationOverContactRadius": pen/aH,
    "facesInContact": nIn,
    "masterFacesInContact": nInM,
    "facesFitted": nFit,
}
print("hertzSpheres: P = %.4g N; Hertz a = %.4f mm, p0 = %.4g Pa; slave "
      "surface (%s) a = %.4f mm (%.2f %%), p0 = %.4g Pa (%.2f %%), %d faces "
      "in contact (quarter), %d fitted, scatter %.2f %% of p0; master "
      "surface a %.2f %%, p0 %.2f %% off (%d faces), scatter %.2f %%; "
      "penetration %.2e of a"
      % (P, aH*1e3, p0H, slave, a*1e3, 100*res["contactRadiusRelError"], p0,
         100*res["peakPressureRelError"], nIn, nFit, 100*scatter,
         100*res["masterContactRadiusRelError"],
         100*res["masterPeakPressureRelError"], nInM, 100*scatterM,
         res["penetrationOverContactRadius"]))
foamio.writeResults(os.path.join(case, "results.dat"), res,
                    "Hertz contact of two spheres")
