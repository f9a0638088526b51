#!/usr/bin/env python3
# Neo-Hookean block in uniaxial strain (stretch 2, plane strain, displacement
# controlled): reaction force on the top against the exact nominal stress
# P22 = mu (l - 1/l) + lambda ln(l)/l times the reference area
# (doc/theory.md [V3]). Appends to results.dat.
import math
import os
import sys

E, nu, W, T = 10e6, 0.3, 0.01, 0.001
mu = E/(2*(1 + nu))
lam = E*nu/((1 + nu)*(1 - 2*nu))
l = 2.0
fExact = (mu*(l - 1/l) + lam*math.log(l)/l)*W*T

case = sys.argv[1]
rows = [r.split() for r in open(os.path.join(
    case, "postProcessing", "solidForces", "top.dat")) if r[0] != "#"]
fy = float(rows[-1][2])
err = abs(fy - fExact)/fExact
print("uniaxialStrain: reaction force %.6g N, exact %.6g N, error %.2e"
      % (fy, fExact, err))
with open(sys.argv[2], "a") as f:
    f.write("reactionForceRelError %.10g\n" % err)
