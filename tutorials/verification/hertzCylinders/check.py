#!/usr/bin/env python3
# Hertz contact of two elastic cylinders (plane strain, frictionless,
# deformableContact): peak pressure and half-width of the computed contact
# pressure against Hertz for the computed contact force (doc/theory.md [V11]).
# Writes results.dat.
#
# The half model carries half the load per thickness t: P = 2 Fy/t. Hertz:
# 1/R* = 1/R1 + 1/R2, 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2,
# a = sqrt(4 P R*/(pi E*)), p0 = 2 P/(pi a), p(x) = p0 sqrt(1 - x^2/a^2).
# As in the hertzContact tutorial, the pressure compared is the normal force
# per reference area (nominalContactPressure, [C4]) of the slave faces at
# their undeformed centres (the linear theory's frame), fitted by
# p^2 = p0^2 (1 - x^2/a^2) over the faces in contact but the outermost.
# The master faces' pressure is fitted alike and reported, and each
# surface's scatter about its fitted profile (root mean square over the
# fitted faces, over p0): the slave's faces scatter when its partner
# deforms, the more so the more compliant the master and the finer the
# slave (doc/theory.md [C10b]).
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ["TRIBOFOAM_DIR"], "bin", "python"))
import foamio
import hertzFit

R1, E1, nu1 = 0.010, 200e9, 0.3
R2, E2, nu2 = 0.015, 70e9, 0.33
t = 0.0005
Rstar = 1/(1/R1 + 1/R2)
Estar = 1/((1 - nu1**2)/E1 + (1 - nu2**2)/E2)
slave, master = "upperContact", "lowerContact"

case = sys.argv[1] if len(sys.argv) > 1 else "."


def lastRow(side):
    rows = [r.split() for r in open(os.path.join(
        case, "postProcessing", "contact", side + ".dat")) if r[0] != "#"]
    return [float(x) for x in rows[-1]]


s, m = lastRow(slave), lastRow(master)
Fy = s[2]
P = 2*Fy/t
aH = math.sqrt(4*P*Rstar/(math.pi*Estar))
p0H = 2*P/(math.pi*aH)

time = foamio.latestTime(case)


def fitSurface(patch):
    p = foamio.readPatchField(
        os.path.join(case, time, "nominalContactPressure"), patch)
    C = foamio.readPatchField(os.path.join(case, "0", "C"), patch)
    pts = sorted((c[0], pi) for c, pi in zip(C, p) if pi > 0)
    p0, a = hertzFit.fitHertz(pts)
    fit = pts[:-1]
    scatter = math.sqrt(sum(
        (pp - p0*math.sqrt(max(1 - x*x/(a*a), 0)))**2 for x, pp in fit)
        / len(fit))/p0
    return p0, a, pts, scatter


p0, a, pts, scatter = fitSurface(slave)
p0m, am, ptsM, scatterM = fitSurface(master)

fs = [s[1] + s[4], s[2] + s[5]]
fm = [m[1] + m[4], m[2] + m[5]]
res = {
    "contactForcePerLength": P,
    "peakPressureRelError": abs(p0 - p0H)/p0H,
    "halfWidthRelError": abs(a - aH)/aH,
    "masterPeakPressureRelError": abs(p0m - p0H)/p0H,
    "masterHalfWidthRelError": abs(am - aH)/aH,
    "peakPressureScatter": scatter,
    "masterPeakPressureScatter": scatterM,
    "penetrationOverHalfWidth": s[8]/aH,
    "facesInContact": len(pts),
    "momentumRelError": math.hypot(fs[0] + fm[0], fs[1] + fm[1])/math.hypot(*fs),
}
print("hertzCylinders: P = %.4g N/m; Hertz (R* = %.3f mm, E* = %.4g Pa) "
      "a = %.4f mm, p0 = %.4g Pa; computed a = %.4f mm (%.2f %%), p0 = %.4g Pa"
      " (%.2f %%); %d faces in contact, scatter %.2f %% of p0; master surface"
      " a %.2f %%, p0 %.2f %% off (%d faces), scatter %.2f %%; penetration"
      " %.2e of a; slave + master force %.1e of the force"
      % (P, Rstar*1e3, Estar, aH*1e3, p0H, a*1e3,
         100*res["halfWidthRelError"], p0, 100*res["peakPressureRelError"],
         len(pts), 100*scatter, 100*res["masterHalfWidthRelError"],
         100*res["masterPeakPressureRelError"], len(ptsM), 100*scatterM,
         res["penetrationOverHalfWidth"], res["momentumRelError"]))
foamio.writeResults(os.path.join(case, "results.dat"), res,
                    "Hertz contact of two cylinders")
