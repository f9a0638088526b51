#!/usr/bin/env python3
# Neo-Hookean bar compressed by a follower pressure p on its end: the state
# is homogeneous with Cauchy stress sigma11 = -p, i.e. P11 = -p l2^2 on the
# reference area (doc/theory.md [S12], [V3]). Compares the computed stretch
# with the exact one. Appends to results.dat.
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ["TRIBOFOAM_DIR"], "bin", "python"))
import foamio
import neoHookeanBar as bar

E, nu, L, p = 10e6, 0.3, 0.1, 2e6
mu = E/(2*(1 + nu))
lam = E*nu/((1 + nu)*(1 - 2*nu))


def cauchy11(l):
    return bar.cauchyStress(l, mu, lam)


lo, hi = 0.2, 1.0
for _ in range(200):
    m = 0.5*(lo + hi)
    if cauchy11(m) > -p:
        hi = m
    else:
        lo = m
exact = 0.5*(lo + hi)

case, out = sys.argv[1], sys.argv[2]
t = foamio.latestTime(case)
ux = [d[0] for d in foamio.readPatchField(os.path.join(case, t, "D"), "xMax")]
stretch = 1 + sum(ux)/len(ux)/L
err = abs(stretch - exact)/(1 - exact)
# the written Cauchy stress: -p along the bar, 0 otherwise; sigmaEq = p
sig = foamio.readInternalField(os.path.join(case, t, "sigma"))
sigEq = foamio.readInternalField(os.path.join(case, t, "sigmaEq"), len(sig))
sigErr = max(max(abs(s[0] + p), *(abs(c) for c in s[1:])) for s in sig)/p
sigEqErr = max(abs(e - p) for e in sigEq)/p
print("followerCompression: stretch %.8f, exact %.8f (Cauchy stress -p); "
      "error %.2e of the shortening; written sigma %.2e, sigmaEq %.2e off"
      % (stretch, exact, err, sigErr, sigEqErr))
with open(out, "a") as f:
    f.write("followerPressureRelError %.10g\n" % err)
    f.write("followerSigmaRelError %.10g\n" % sigErr)
    f.write("followerSigmaEqRelError %.10g\n" % sigEqErr)
