#!/usr/bin/env python3
# Sliding block (README): the friction law checked through the solid, not
# through what the contact condition writes. Writes <case>/results.dat
# (names prefixed by the case's folder name).
#
#   python3 check.py <case>                  dragged: steady sliding at t = 3
#   python3 check.py <case> -stick <bonded>  sheared below the threshold
#
# Dragged (coulomb, lubricatedRateState, curnier; the law and its
# parameters as the run wrote them in D):
#   - the slip rate of every bottom face is derived here from its
#     displacement between the written times 2.5 and 3 (the plane is at
#     rest); in steady sliding the block moves as a whole, every face at
#     the rate of the top (slipRateSpread);
#   - the friction force is the top's reaction Fx (the solid's stresses at
#     the top: equilibrium, no contact output), the normal force its Fy;
#     the law's steady friction at the derived rate, integrated over the
#     bottom, must give it (frictionRelError):
#       coulomb [F8]     Fx = mu N
#       lubricated [F20], [F29]  Fx = (1 - alpha) f mu0(v) N + alpha eta_b v A,
#                        alpha(v) from the lubrication model (constant or
#                        Stribeck [F19]) at the derived rate, mu0 [F18],
#                        steady contact age D0/v: f = 1 + M/2 ln(1 + V_s^2/v^2)
#       shearFactor [F35], [F36]  Fx = m sum(k_i a_i): each face slides at
#                        m times the shear flow stress k_i it was given, on
#                        its current area a_i; generalFriction [F38],
#                        cappedCoulomb [F37] alike with their tau_f(tN_i, k_i)
#                        at each face's pressure (nominalContactPressure over
#                        contactPressure times the reference area); k_i
#                        against sigma_y(epsP_i)/sqrt(3) of the plastic
#                        strain of the face's cell and the hardening table of
#                        mechanicalProperties (shearYieldError), how much
#                        hardening there is (hardeningRatio: mean k over
#                        k at epsP = 0) and how far the initial k would be
#                        off (initialYieldForceError);
#       curnier [F9], [F10]  Fx = (C A + f N - Q sum(g_i) A/n)/(1 - Q/KT):
#                        threshold C + f tN - Q Dc on every face with the
#                        cumulated slip Dc = g - Fx_face/KT of a face whose
#                        total slip g (its displacement) grew monotonically
#                        (wear lowers the friction as the faces slide, the
#                        block unloads: its faces do not move with the top);
#   - the lubrication weight written on each face against alpha at the
#     derived rate (alphaError);
#   - the energy dissipated at the interface ([C7]) against the work of the
#     drag over 2.5-3 (energyRelError; not with wear, which releases
#     elastic energy).
# Sheared (-stick): the block pressed, then its top moved by less than it
# takes to slide: no face may slip, so the solution equals that of the
# same block with a friction coefficient that cannot be reached (the
# bonded case): top reaction and bottom displacements against the bonded
# run (forceRelDiffToBonded, displacementRelDiffToBonded), and the shear
# the faces carry in the bonded run, max |tT|/(mu tN), is real
# (peakShearRatio: well above 0, below 1; frictionOverThreshold: the
# friction force over mu N).
import math
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.environ["TRIBOFOAM_DIR"], "bin", "python"))
import foamio

A = 0.01*0.0005          # bottom and top area [m^2] (system/blockMeshDict)
case = sys.argv[1]
name = os.path.basename(os.path.normpath(case))


def law(key, default=None, c=None):
    """An entry (sub-entries a/b) of the friction law a run used: as its
    contact condition wrote it in D at the latest time."""
    c = c or case
    D = os.path.join(c, foamio.latestTime(c), "D")
    r = subprocess.run(["foamDictionary", D, "-entry",
                        "boundaryField/bottom/frictionLaw/" + key, "-value"],
                       stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                       text=True)
    if r.returncode != 0:
        if default is None:
            sys.exit("check.py: no frictionLaw/%s in %s" % (key, D))
        return default
    v = r.stdout.strip()
    try:
        return float(v)
    except ValueError:
        return v


def rows(c, path):
    return {round(r[0], 9): r for r in (
        [float(v) for v in l.split()] for l in open(os.path.join(c, path))
        if l[0] != "#")}


def patch(c, time, field, p="bottom"):
    n = 40
    return foamio.readPatchField(os.path.join(c, time, field), p, n)


def mag(v):
    return math.sqrt(sum(x*x for x in v))


def tauF(lawType, p, k):
    """Shear strength of the forming laws at pressure p and shear flow
    stress k (doc/theory.md [F36]-[F38])"""
    if lawType == "shearFactor":
        return law("m")*k
    if lawType == "cappedCoulomb":
        return min(law("mu")*p, law("m")*k)
    f, aT = law("f"), law("transitionRealArea", 0.5)
    h = 1 + math.pi/2 + math.acos(f) + math.sqrt(1 - f*f)
    pk = p/k
    alpha = pk/h if pk <= aT*h else \
        1 - (1 - aT)*math.exp(-(pk - aT*h)/((1 - aT)*h))
    return f*alpha*k


res = {}
if len(sys.argv) > 3 and sys.argv[2] == "-stick":
    bonded = sys.argv[3]
    t = foamio.latestTime(case)
    Fs = rows(case, "postProcessing/solidForces/top.dat")
    Fb = rows(bonded, "postProcessing/solidForces/top.dat")
    fs, fb = Fs[max(Fs)], Fb[max(Fb)]
    res["forceRelDiffToBonded"] = max(abs(fs[i] - fb[i]) for i in (1, 2)) \
        / abs(fb[2])
    Ds, Db = patch(case, t, "D"), patch(bonded, t, "D")
    res["displacementRelDiffToBonded"] = max(
        mag([a - b for a, b in zip(u, v)]) for u, v in zip(Ds, Db)) \
        / max(mag(v) for v in Db)
    mu = law("mu")
    if not law("mu", c=bonded) > 3*mu:
        sys.exit("check.py: %s must run with a friction coefficient that "
                 "cannot be reached (it has mu %g)" % (bonded,
                                                      law("mu", c=bonded)))
    res["peakShearRatio"] = max(
        mag(tt)/(mu*p) for tt, p in zip(patch(bonded, t, "frictionTraction"),
                                        patch(bonded, t, "contactPressure")))
    res["frictionOverThreshold"] = abs(fs[1])/(mu*abs(fs[2]))
    print("slidingBlock %s: sheared to %.3f of mu N (peak face %.3f of mu tN)"
          ": top reaction %.3e, bottom displacement %.3e from the bonded run"
          % (name, res["frictionOverThreshold"],
             res["peakShearRatio"], res["forceRelDiffToBonded"],
             res["displacementRelDiffToBonded"]))
else:
    t0, t1 = "2.5", "3"
    dt = float(t1) - float(t0)
    top = rows(case, "postProcessing/solidForces/top.dat")
    Fx, N = top[float(t1)][1], -top[float(t1)][2]
    # rates from the displacements (the plane is at rest)
    v = [(a[0] - b[0])/dt for a, b in zip(patch(case, t1, "D"),
                                          patch(case, t0, "D"))]
    uTop = [(a[0] - b[0]) for a, b in zip(patch(case, t1, "D", "top"),
                                          patch(case, t0, "D", "top"))]
    V = sum(uTop)/len(uTop)/dt
    res["slipRateSpread"] = max(abs(x - V) for x in v)/V
    vm = sum(v)/len(v)
    status = patch(case, t1, "contactStatus")
    res["slidingFaceFraction"] = sum(1 for s in status if s == 2)/len(status)
    lawType = law("type")
    alpha = 0.0
    if lawType == "coulomb":
        pred = law("mu")*N
    elif lawType == "lubricatedRateState":
        M, D0, Vs = law("M"), law("D0"), law("creepVelocity")
        muS, muD, vc = law("muStatic"), law("muDynamic"), law("criticalVelocity")
        etaB = law("filmViscosity")
        if law("lubrication/type") == "constant":
            alpha = law("lubrication/alpha")
        else:
            xi = law("lubrication/filmThickness") \
                / law("lubrication/referenceFilmThickness") \
                * vm/law("lubrication/referenceVelocity")
            n = law("lubrication/n")
            alpha = xi**n/(1 + xi**n)
        f = 1 + 0.5*M*math.log(1 + (Vs/vm)**2)
        mu0 = muD + (muS - muD)*math.exp(-vm/vc)
        pred = (1 - alpha)*f*mu0*N + alpha*etaB*vm*A
        res["alphaError"] = max(abs(a - alpha)
                                for a in patch(case, t1, "lubricationWeight"))
    elif lawType == "curnier":
        f, C, Q = law("f"), law("C", 0.0), law("Q", 0.0)
        KT = float(open(os.path.join(case, "log.largeStrainSolidFoam")).read()
                   .split(" KT ")[1].split()[0])
        g = [d[0] for d in patch(case, t1, "D")]
        pred = (C*A + f*N - Q*sum(g)*A/len(g))/(1 - Q/KT)
        # wear unloads the block: its faces do not move with the top
        del res["slipRateSpread"]
    elif lawType in ("shearFactor", "generalFriction", "cappedCoulomb"):
        k = patch(case, t1, "shearYield")
        tN = patch(case, t1, "contactPressure")
        # current areas of the faces in contact (an open face carries none)
        area = [A/40*q/p if p > 0 else 0 for q, p in zip(
            patch(case, t1, "nominalContactPressure"),
            patch(case, t1, "contactPressure"))]
        pred = sum(tauF(lawType, p, ki)*ai for p, ki, ai in zip(tN, k, area))
        # the flow stress of each face from its plastic strain: the linear
        # hardening table of mechanicalProperties
        r = subprocess.run(["foamDictionary", os.path.join(
            case, "constant", "mechanicalProperties"), "-entry",
            "mechanicalLaw/yieldStress", "-value"], stdout=subprocess.PIPE,
            text=True, check=True)
        pts = [float(x) for x in re.findall(r"[-+]?\d+\.?\d*(?:[eE][-+]?\d+)?", r.stdout)]
        (e0, s0), (e1, s1) = zip(pts[0::2], pts[1::2])
        # the bottom row of cells (blockMesh: x fastest, the bottom
        # faces' order), their plastic strain as the solver writes it
        eps = foamio.readInternalField(os.path.join(case, t1, "epsilonPEq"),
                                       800)[:40]
        sy = [s0 + (s1 - s0)*(e - e0)/(e1 - e0) for e in eps]
        res["shearYieldError"] = max(abs(ki - y/math.sqrt(3))/(y/math.sqrt(3))
                                     for ki, y, a in zip(k, sy, area) if a > 0)
        res["contactFaceFraction"] = sum(1 for a in area if a > 0)/len(area)
        kc = [ki for ki, a in zip(k, area) if a > 0]
        res["hardeningRatio"] = sum(kc)/len(kc)/(s0/math.sqrt(3))
        res["plasticStrainMin"] = min(eps)
        # faces past the switch (cappedCoulomb: mu tN > m k) or the
        # transition (generalFriction: p/k > alphaT h): both sides seen
        if lawType != "shearFactor":
            def high(p, ki):
                if lawType == "cappedCoulomb":
                    return law("mu")*p > law("m")*ki
                f, aT = law("f"), law("transitionRealArea", 0.5)
                h = 1 + math.pi/2 + math.acos(f) + math.sqrt(1 - f*f)
                return p/ki > aT*h
            res["highPressureFraction"] = sum(
                1 for p, ki, a in zip(tN, k, area) if a > 0 and high(p, ki)) \
                / sum(1 for a in area if a > 0)
        res["initialYieldForceError"] = abs(abs(Fx) - sum(
            tauF(lawType, p, s0/math.sqrt(3))*ai
            for p, ai in zip(tN, area)))/abs(Fx)
        print("    %s: faces' epsP %.4g-%.4g, mean k %.4g MPa (%.3f"
              " of the initial), k against sigma_y(epsP)/sqrt(3) %.2e"
              % (lawType, min(eps), max(eps), sum(kc)/len(kc)*1e-6,
                 res["hardeningRatio"], res["shearYieldError"]))
    else:
        sys.exit("check.py: no check for law %s" % lawType)
    res["frictionRelError"] = abs(abs(Fx) - pred)/pred
    # energy: dissipated at the interface against the drag work, 2.5 - 3
    if lawType != "curnier":
        con = rows(case, "postProcessing/contact/bottom.dat")
        work = sum(0.5*(top[a][1] + top[b][1])*1e-5*(b - a)
                   for a, b in zip(sorted(top)[:-1], sorted(top)[1:])
                   if a >= float(t0) - 1e-9)
        diss = con[max(con)][7] - con[float(t0)][7]
        res["energyRelError"] = abs(diss - work)/work
    print("slidingBlock %s (%s): %d of %d faces sliding at %.6g m/s (spread "
          "%.2e, from their displacements), alpha %.4g; top reaction %.8g N"
          " against the law's %.8g N (%.2e)%s" % (
              name, lawType, sum(1 for s in status if s == 2), len(status),
              vm, max(abs(x - V) for x in v)/V, alpha, abs(Fx), pred,
              res["frictionRelError"],
              "; energy %.2e" % res["energyRelError"]
              if "energyRelError" in res else ""))
    for k in ("alphaError",):
        if k in res:
            print("    %s %.3e" % (k, res[k]))

with open(os.path.join(case, "results.dat"), "w") as out:
    for k, val in res.items():
        out.write("%s_%s %.10g\n" % (name, k, val))
