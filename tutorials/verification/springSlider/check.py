#!/usr/bin/env python3
# Continuum spring-slider: amplitude of the friction coefficient's
# oscillation over the last quarter of the run, for a slab thinner (stable)
# and thicker (unstable) than h_c = G L/((b - a) sigma) (doc/theory.md
# [V6], [F22], [F22c]). Appends to results.dat.
import os
import sys

case, name = sys.argv[1], sys.argv[2]
rows = [[float(v) for v in r.split()] for r in open(os.path.join(
    case, "postProcessing", "contact", "base.dat")) if r[0] != "#"]
tEnd = rows[-1][0]
mu = [(r[0], -r[4]/r[2]) for r in rows if r[2] > 0]
late = [m for t, m in mu if t > 0.75*tEnd]
first = [m for t, m in mu if 1 < t <= 0.1*tEnd + 1]
amplitude = max(late) - min(late)
growth = amplitude/(max(first) - min(first))
mean = sum(late)/len(late)
print("springSlider %s: friction coefficient %.4f +- %.2e over the last "
      "quarter of the run; amplitude ratio last quarter / first tenth %.3g"
      % (name, mean, amplitude/2, growth))
with open("results.dat", "a") as f:
    f.write("%sAmplitude %.10g\n%sMeanFriction %.10g\n%sGrowth %.10g\n"
            % (name, amplitude, name, mean, name, growth))
