#!/usr/bin/env python3
# The sliding blocks with the lubricated rate-and-state law (lubricatedLaw,
# constant lubrication weight alpha): in steady sliding at the slip rate v
# the interface's friction force is the point-wise law's steady friction,
# (1 - alpha) f(v) mu0(v) N + alpha eta_b v A (doc/theory.md [F18]-[F20],
# [F29]), with f = 1 + M/2 ln(1 + (V_s/v)^2), mu0 = mu_d + (mu_s - mu_d)
# exp(-v/v_c), N and the friction force from the interface's integrals, v
# the slave faces' mean slip rate over t = 2.5 - 3 relative to the master
# surface (from their displacements) and A the contact area (the slave's
# current face areas: its normal force over its contact pressure).
# Appends to results.dat in the tutorial.
import math
import os
import sys

sys.path.insert(0, os.path.join(os.environ["TRIBOFOAM_DIR"], "bin", "python"))
import foamio

M, D0, Vs, muS, muD, vc, etaB, alpha = \
    0.1, 1e-6, 1e-9, 0.12, 0.07, 1e-3, 3e11, 0.3
case = sys.argv[1]
slave, master, nS, nM = "upperBottom", "lowerTop", 40, 50


def rows(path):
    return {round(r[0], 9): r for r in (
        [float(v) for v in l.split()] for l in open(os.path.join(case, path))
        if l[0] != "#")}


def field(time, name, side, n):
    return foamio.readPatchField(os.path.join(case, time, name), side, n)


con = rows("postProcessing/contact/%s.dat" % slave)
N = math.hypot(con[3.0][1], con[3.0][2])
F = math.hypot(con[3.0][4], con[3.0][5])

Cs, Cm = field("0", "C", slave, nS), field("0", "C", master, nM)
dS = [a[0] - b[0] for a, b in zip(field("3", "D", slave, nS),
                                   field("2.5", "D", slave, nS))]
dM = [a[0] - b[0] for a, b in zip(field("3", "D", master, nM),
                                   field("2.5", "D", master, nM))]
xm = [c[0] for c in Cm]


def masterAt(x):
    for k in range(len(xm) - 1):
        if xm[k] <= x <= xm[k + 1]:
            w = (x - xm[k])/(xm[k + 1] - xm[k])
            return (1 - w)*dM[k] + w*dM[k + 1]
    return dM[0] if x < xm[0] else dM[-1]


v = sum(d - masterAt(c[0]) for d, c in zip(dS, Cs))/nS/0.5
p = field("3", "contactPressure", slave, nS)
pn = field("3", "nominalContactPressure", slave, nS)
A = sum(b/a*0.00025*0.0005 for a, b in zip(p, pn))
f = 1 + 0.5*M*math.log(1 + (Vs/v)**2)
mu0 = muD + (muS - muD)*math.exp(-v/vc)
pred = (1 - alpha)*f*mu0*N + alpha*etaB*v*A
err = abs(F - pred)/pred
print("slidingBlocks lubricated: slip rate %.6g m/s, friction force %.8g N "
      "against the steady law's %.8g N (%.2e)" % (v, F, pred, err))
with open("results.dat", "a") as out:
    out.write("lubricatedFrictionRelError %.10g\n" % err)
    out.write("lubricatedSlipRate %.10g\n" % v)
