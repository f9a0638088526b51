#!/usr/bin/env python3
# Elastic bar, bottom fixed, end load applied suddenly: the stress wave
# makes the reaction at the fixed end oscillate about the static value with
# the period of the bar's first mode T = 4 L/c, c = sqrt(E/rho)
# (doc/theory.md [S13], [V7]). Backward Euler damps the oscillation but
# keeps its period to O((w dt)^2). A copy with massScaling 4 [S13b] must
# oscillate with twice the period. Writes results.dat.
import math
import os

L, E, rho, q, A = 1.0, 2e9, 2000.0, 1e5, 0.05*0.05


def reactionPeriod(case):
    """Mean period of the fixed-end reaction's upward zero crossings about
    the static value, the mean reaction over the second half (over the
    static one, - 1) and the number of crossings."""
    rows = [[float(v) for v in r.split()] for r in
            open(os.path.join(case, "postProcessing/solidForces/bottom.dat"))
            if r[0] != "#"]
    t = [r[0] for r in rows]
    f = [r[2]/(q*A) - 1 for r in rows]
    ups = [t[i] - f[i]*(t[i + 1] - t[i])/(f[i + 1] - f[i])
           for i in range(len(f) - 1) if f[i] < 0 <= f[i + 1]]
    periods = [b - a for a, b in zip(ups[:-1], ups[1:])]
    half = f[len(f)//2:]
    return sum(periods)/len(periods), sum(half)/len(half), len(ups)


T = 4*L/math.sqrt(E/rho)
period, mean, crossings = reactionPeriod(".")
err = abs(period - T)/T
print("elasticWave: period %.6g s (4L/c = %.6g s, error %.2e) from %d "
      "crossings; mean reaction over the second half %.4f of static"
      % (period, T, err, crossings, 1 + mean))

# [S13b] massScaling 4 halves the wave speed: T_s = 2 T
Ts = 2*T
periodS, meanS, crossingsS = reactionPeriod("massScaled")
errS = abs(periodS - Ts)/Ts
print("elasticWave, massScaling 4: period %.6g s (8L/c = %.6g s, error "
      "%.2e) from %d crossings" % (periodS, Ts, errS, crossingsS))

with open("results.dat", "w") as out:
    out.write("periodRelError %.10g\nmeanReactionRelError %.10g\n"
              "crossings %d\nmassScaledPeriodRelError %.10g\n"
              "massScaledCrossings %d\n"
              % (err, abs(mean), crossings, errS, crossingsS))
