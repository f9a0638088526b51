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

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blockData  # noqa: E402

M, D0, Vs, muS, muD, vc, etaB, alpha = \
    0.1, 1e-6, 1e-9, 0.12, 0.07, 1e-3, 3e11, 0.3
case = sys.argv[1]
slave, master, nS, nM = "upperBottom", "lowerTop", 40, 50


def field(time, name, side, n):
    return blockData.field(case, time, name, side, n)


con = blockData.rows(case, "postProcessing/contact/%s.dat" % slave)
N = math.hypot(con[3.0][1], con[3.0][2])
F = math.hypot(con[3.0][4], con[3.0][5])

v = sum(blockData.relativeSlips(case, slave, master, nS, nM, "2.5",
                                 "3"))/nS/0.5
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
