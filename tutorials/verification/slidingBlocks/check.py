#!/usr/bin/env python3
# An elastic block dragged over another with Coulomb friction
# (deformableContact, doc/theory.md [C10]-[C12], [V5]). In steady sliding
# (t = 2.5 - 3, 5 um of drag) the blocks keep their shape, so every slave
# face slips by the drag distance and:
#   - the friction force is mu N: the top's reaction Fx against mu times its
#     normal reaction;
#   - the energy dissipated at the interface [C7] equals mu N slip and the
#     work of the drag;
#   - the contact forces on the two surfaces cancel (momentum).
# Writes results.dat.
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blockData  # noqa: E402
import foamio  # noqa: E402  (on the path blockData sets)

mu, V = 0.2, 1e-5           # 0/D: friction coefficient, drag rate [m/s]
slave, master = "upperBottom", "lowerTop"
case = sys.argv[1] if len(sys.argv) > 1 else "."
t0, t1 = 2.5, 3.0


top = blockData.rows(case, "postProcessing/solidForces/top.dat")
con = blockData.rows(case, "postProcessing/contact/%s.dat" % slave)
mas = blockData.rows(case, "postProcessing/contact/%s.dat" % master)
nS, nM, S0 = 40, 50, 0.00025*0.0005     # faces, slave face area [m^2]


def field(time, name, side, n):
    return blockData.field(case, time, name, side, n)


slips = blockData.relativeSlips(case, slave, master, nS, nM, "2.5", "3")
# face by face: mu x (normal force of the face, mean over the interval) x
# its slip; the normal force per reference area is nominalContactPressure
p0 = field("2.5", "nominalContactPressure", slave, nS)
p1 = field("3", "nominalContactPressure", slave, nS)
muNslip = sum(mu*0.5*(a + b)*S0*s for a, b, s in zip(p0, p1, slips))

work = sum(0.5*(top[a][1] + top[b][1])*V*(b - a)
           for a, b in zip(sorted(top)[:-1], sorted(top)[1:]) if a >= t0 - 1e-9)
diss = con[t1][7] - con[t0][7]
status = field("3", "contactStatus", slave, nS)
N = (con[t1][1]**2 + con[t1][2]**2)**0.5
F = (con[t1][4]**2 + con[t1][5]**2)**0.5
fs = [con[t1][1] + con[t1][4], con[t1][2] + con[t1][5]]
fm = [mas[t1][1] + mas[t1][4], mas[t1][2] + mas[t1][5]]
slip = sum(slips)/len(slips)

res = {
    "slidingFaceFraction": sum(1 for s in status if s == 2)/len(status),
    "frictionRelError": abs(F - mu*N)/(mu*N),
    "energyVsMuNSlipRelError": abs(diss - muNslip)/muNslip,
    "energyVsWorkRelError": abs(diss - work)/work,
    "slipOverDrag": slip/(V*(t1 - t0)),
    "momentumRelError": ((fs[0] + fm[0])**2 + (fs[1] + fm[1])**2)**0.5
    / (fs[0]**2 + fs[1]**2)**0.5,
}
print("slidingBlocks: %d of %d slave faces sliding; friction force %.8g N "
      "against mu N = %.8g N (%.2e); dissipated %.8g J against mu N slip "
      "%.8g J (%.2e) and the drag work %.6g J (%.2e); slip %.6f of the drag;"
      " slave + master force %.1e"
      % (sum(1 for s in status if s == 2), len(status), F, mu*N,
         res["frictionRelError"], diss, muNslip,
         res["energyVsMuNSlipRelError"], work, res["energyVsWorkRelError"],
         res["slipOverDrag"], res["momentumRelError"]))
foamio.writeResults(os.path.join(case, "results.dat"), res,
                    "two blocks sliding with Coulomb friction")
