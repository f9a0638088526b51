#!/usr/bin/env python3
# Neo-Hookean bar in uniaxial tension: applied nominal stress against the
# exact homogeneous solution at the computed stretch (doc/theory.md [V3]);
# the written Cauchy stress sigma and sigmaEq against the exact one.
# Writes results.dat.
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ["TRIBOFOAM_DIR"], "bin", "python"))
import foamio
import neoHookeanBar as bar

E, nu, L, W = 10e6, 0.3, 0.1, 0.01
mu = E/(2*(1 + nu))
lam = E*nu/((1 + nu)*(1 - 2*nu))


def lateralStretch(l):
    return bar.lateralStretch(l, mu, lam)


def nominalStress(l):
    return bar.nominalStress(l, mu, lam)


case = sys.argv[1] if len(sys.argv) > 1 else "."
pApplied = float(sys.argv[2])
t = foamio.latestTime(case)
ux = [d[0] for d in foamio.readPatchField(os.path.join(case, t, "D"), "xMax")]
Ds = foamio.readPatchField(os.path.join(case, t, "D"), "sides")
Cs = foamio.readPatchField(os.path.join(case, "0", "C"), "sides")
stretch = 1 + sum(ux)/len(ux)/L
# lateral stretch from the y = W side faces
uy = [d[1] for d, c in zip(Ds, Cs) if abs(c[1] - W) < 1e-9]
lateral = 1 + sum(uy)/len(uy)/W

pExact = nominalStress(stretch)

# The written Cauchy stress and its equivalent ([S4]; sigma and sigmaEq are
# what a user reads): uniform, sigma11 = P11 l/J, every other component 0
sig = foamio.readInternalField(os.path.join(case, t, "sigma"))
sigEq = foamio.readInternalField(os.path.join(case, t, "sigmaEq"), len(sig))
s11 = bar.cauchyStress(stretch, mu, lam)
res = {
    "sigmaRelError": max(max(abs(s[0] - s11), *(abs(c) for c in s[1:]))
                         for s in sig)/s11,
    "sigmaEqRelError": max(abs(e - s11) for e in sigEq)/s11,
    "stretch": stretch,
    "forceRelError": abs(pApplied - pExact)/pExact,
    "lateralStretchRelError": abs(lateral - lateralStretch(stretch))
    / lateralStretch(stretch),
    "stretchSpread": (max(ux) - min(ux))/L,
}
print("largeStrainTension: stretch %.6f, nominal stress %.6g Pa applied, "
      "%.6g Pa exact: error %.2e; lateral stretch error %.2e; written sigma "
      "against the exact Cauchy stress %.6g Pa: %.2e, sigmaEq %.2e"
      % (stretch, pApplied, pExact, res["forceRelError"],
         res["lateralStretchRelError"], s11, res["sigmaRelError"],
         res["sigmaEqRelError"]))
foamio.writeResults(os.path.join(case, "results.dat"), res,
                    "neo-Hookean uniaxial tension")
