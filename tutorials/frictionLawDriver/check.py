#!/usr/bin/env python3
# -----------------------------------------------------------------------------
# frictionLawDriver tutorials: each run against its reference (doc/theory.md
# sections 8.6 and 8.8). Prints one line per check and writes results.dat.
#
#   python3 check.py                      check every run
#   python3 check.py noise IN OUT COL SIGMA SEED [rel]
#                                         copy table IN to OUT with Gaussian
#                                         noise on column COL (absolute, or
#                                         relative with 'rel')
#
# License: GPL-3.0-or-later
# -----------------------------------------------------------------------------
import math
import random
import re
import sys


def rows(path):
    return [[float(v) for v in l.split()] for l in open(path)
            if l.strip() and not l.startswith("#")]


def addNoise(src, dst, col, sigma, seed, relative):
    rng = random.Random(seed)
    with open(dst, "w") as out:
        for line in open(src):
            if line.startswith("#") or not line.strip():
                out.write(line)
                continue
            v = line.split()
            x = float(v[col])
            v[col] = "%.12g" % (x*(1 + rng.gauss(0, sigma)) if relative
                                else x + rng.gauss(0, sigma))
            out.write(" ".join(v) + "\n")


res = {}
ok = True


def check(name, value, bound, what):
    """value <= bound, printed and recorded"""
    global ok
    res[name] = value
    good = value <= bound
    ok = ok and good
    print("%-44s %.4g (%s %.3g) %s" % (name, value, "<=", bound,
                                        "" if good else "FAILED: " + what))


def fitted(path):
    """{name: (value, lower, upper)} from the comments of a law written by
    the identification or the fit"""
    out = {}
    for l in open(path):
        m = re.match(r"^(\w+)\s+([-+0-9.eE]+);\s*// (\d+) % interval "
                     r"\[([-+0-9.eE]+), ([-+0-9.eE]+)\]", l)
        if m:
            out[m.group(1)] = (float(m.group(2)), float(m.group(4)),
                               float(m.group(5)))
        m = re.match(r"^// (\w+) = ([-+0-9.eE]+) \+- ([-+0-9.eE]+)", l)
        if m:
            v, h = float(m.group(2)), float(m.group(3))
            out[m.group(1)] = (v, v - h, v + h)
    return out


def velocityStep():
    # ageing law, exact solution [F23]
    a, b, muStar, VStar, L, v1, v2, t1 = 0.01, 0.015, 0.6, 1e-6, 1e-5, \
        1e-6, 1e-5, 10.0
    r = rows("velocityStep/velocityStep.dat")
    s0 = [x for x in r if x[0] <= t1][-1][1]
    err = 0.0
    for x in r:
        if x[0] > t1 + 0.02:
            d = x[1] - s0
            theta = L/v2 + (L/v1 - L/v2)*math.exp(-d/L)
            mu = muStar + a*math.log(v2/VStar) + b*math.log(VStar*theta/L)
            err = max(err, abs(x[5] - mu))
    print("velocityStep: max |mu - exact| = %.3g (tolerance 1e-3)" % err)
    check("velocityStepError", err, 1e-3, "[F23]")


def slideHoldSlide():
    # [F28]: steady friction before the hold (V*) and at the end (10 V*)
    r = rows("slideHoldSlide/slideHoldSlide.dat")
    mu = lambda t: min(r, key=lambda x: abs(x[0] - t))[5]
    muSs1, muSs2 = 0.6, 0.6 + (0.01 - 0.015)*math.log(10)
    check("slideHoldSlide_steadyError",
          max(abs(mu(100) - muSs1), abs(mu(400) - muSs2)), 1e-6,
          "steady friction [F28] before the hold and after the step")
    hold = [x[5] for x in r if 100.02 <= x[0] <= 200]
    rises = max(b - a for a, b in zip(hold[:-1], hold[1:]))
    res["slideHoldSlide_holdDrop"] = hold[0] - hold[-1]
    check("slideHoldSlide_holdRise", rises, 0.0,
          "the friction relaxes monotonically in the hold")
    peak = max(x[5] for x in r if 200 < x[0] <= 350)
    check("slideHoldSlide_negativeHealing", -(peak - muSs1), 0.0,
          "the reloaded contact peaks above the steady friction (healing)")
    res["slideHoldSlide_healing"] = peak - muSs1
    print("slideHoldSlide: friction drop in the hold %.4g, healing peak "
          "%.4g above steady" % (hold[0] - hold[-1], peak - muSs1))


def stabilityCurve():
    # [F22], [F22b]: k_c = (b - a) sigma/L (1 + M V^2/(a sigma L)),
    # omega_c = (V/L) sqrt((b - a)/a), independent of M
    a, b, L, sigma, M = 0.01, 0.015, 1e-5, 1e6, 1e10
    errK = errW = 0.0
    for x in rows("stabilityCurve/stabilityCurve.dat"):
        V = x[0]
        kStar = (b - a)*sigma/L
        w = V/L*math.sqrt((b - a)/a)
        for kc, wc, M_ in ((x[5], x[6], 0.0), (x[8], x[9], M)):
            errK = max(errK, abs(kc/(kStar*(1 + M_*V*V/(a*sigma*L))) - 1))
            errW = max(errW, abs(wc/w - 1))
    check("stabilityCurve_kcRelError", errK, 1e-6, "closed form [F22b]")
    check("stabilityCurve_omegacRelError", errW, 1e-6, "closed form [F31]")


def paperBoard():
    # [F32]: gamma = 0.723, t** = 2.729 s back from the onsets
    for tag, path, tol in (("", "paperBoard/identifiedLawDict", 5e-3),
                           ("Noisy", "paperBoard/identifiedNoisyLawDict",
                            0.05)):
        f = fitted(path)
        for key, truth, name in (("gamma", 0.723, "gamma"),
                                 ("relaxationTime", 2.729, "tStar")):
            v, lo, hi = f[key]
            check("paperBoard_%sRelError%s" % (name, tag),
                  abs(v/truth - 1), tol, "identification [F32]")
            if tag:
                check("paperBoard_%sOutsideInterval" % name,
                      0 if lo <= truth <= hi else 1, 0,
                      "the 95 % interval covers the truth")
                print("paperBoard: %s = %.4g, 95 %% interval [%.4g, %.4g], "
                      "true %.4g" % (name, v, lo, hi, truth))


def frictionMap():
    # [F33]: the regimes of the Stribeck map, [F29], [F19], [F20]
    M, D0, Vs, muS, muD, vc, eta = 0.1, 1e-6, 1e-9, 0.12, 0.1, 1e-3, 3e9
    r = rows("frictionMap/frictionMap.dat")
    err = 0.0
    for tN, D, v, mu, alpha, regime, sp, sm in r:
        xi = D/1e-6*v/1e-3
        al = xi/(1 + xi)
        f = 1 + 0.5*M*math.log1p(Vs*Vs/(v*v))
        mu0 = muD + (muS - muD)*math.exp(-v/vc)
        expected = (1 - al)*f*mu0 + al*eta*v/tN
        err = max(err, abs(mu/expected - 1), abs(alpha - al))
    check("frictionMap_steadyError", err, 1e-9,
          "steady friction [F20] with alpha_ss [F19] and f_ss [F17]")
    regimes = set(int(x[5]) for x in r)
    check("frictionMap_missingRegimes", 3 - len(regimes), 0,
          "boundary, mixed and hydrodynamic points in the map")
    nPub = sum(1 for x in r if x[6] < 0)
    nMem = sum(1 for x in r if x[7] < 0)
    res["frictionMap_illPosedPublished"] = nPub
    check("frictionMap_illPosedFilmMemory", nMem, 0,
          "the film memory is well posed everywhere [F30]")
    check("frictionMap_noIllPosedPublished", 1 if nPub == 0 else 0, 0,
          "the published form is ill posed at high pressure [F21]")
    print("frictionMap: %d points, ill posed: published %d, film memory %d"
          % (len(r), nPub, nMem))


def velocityStepFit():
    # [F34]: a, b, L of the velocity step
    truth = {"a": 0.01, "b": 0.015, "L": 1e-5}
    f = fitted("velocityStepFit/fittedLawDict")
    check("fit_maxRelError", max(abs(f[k][0]/v - 1) for k, v in truth.items()),
          1e-4, "noise-free record")
    g = fitted("velocityStepFit/fittedNoisyLawDict")
    check("fit_outsideInterval",
          sum(0 if g[k][1] <= v <= g[k][2] else 1 for k, v in truth.items()),
          0, "the 95 % intervals cover the truth")
    res["fit_maxRelErrorNoisy"] = max(abs(g[k][0]/v - 1)
                                      for k, v in truth.items())
    for k, v in truth.items():
        print("fit (noise 1e-4): %s = %.5g +- %.2g, true %.5g"
              % (k, g[k][0], (g[k][2] - g[k][1])/2, v))


if __name__ == "__main__":
    if len(sys.argv) > 1 and sys.argv[1] == "noise":
        addNoise(sys.argv[2], sys.argv[3], int(sys.argv[4]),
                 float(sys.argv[5]), int(sys.argv[6]),
                 len(sys.argv) > 7 and sys.argv[7] == "rel")
        sys.exit(0)
    for fn in (velocityStep, slideHoldSlide, stabilityCurve, paperBoard,
               frictionMap, velocityStepFit):
        try:
            fn()
        except (OSError, ValueError, KeyError, IndexError) as e:
            print("%s: cannot check (%s)" % (fn.__name__, e))
            ok = False
    with open("results.dat", "w") as out:
        out.write("# frictionLawDriver tutorials (check.py)\n")
        for k, v in res.items():
            out.write("%s %.10g\n" % (k, v))
    sys.exit(0 if ok else 1)
