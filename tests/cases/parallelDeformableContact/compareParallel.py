"""Compare the parallel runs of parallelPair with the serial run (doc/theory.md
[C14]): usage compareParallel.py <name> <slave> <master> <results>; appends
<name>_<decomposition>_<quantity> lines to the file <results>."""
import glob, math, os, re, sys
sys.path.insert(0, os.path.join(os.environ["TRIBOFOAM_DIR"], "bin", "python"))
import foamio

name, slave, master, results = sys.argv[1:5]
stateKeys = {"totalSlip": 3, "plasticSlip": 3, "cumulatedSlip": 1,
             "contactAge": 1, "slipRate": 1, "contactStatus": 1,
             "dissipatedEnergy": 1}


def flat(v):
    return abs(v) if isinstance(v, (int, float)) else max(abs(c) for c in v)


def maxRelDiff(a, b):
    """max |a - b| / max |a| over lists of scalars or vectors."""
    assert len(a) == len(b), (len(a), len(b))
    scale = max(flat(x) for x in a) if a else 0
    d = max((max(abs(x - y) for x, y in zip(u, v)) if isinstance(u, tuple)
             else abs(u - v)) for u, v in zip(a, b)) if a else 0
    return d/scale if scale > 0 else (0.0 if d == 0 else math.inf)


def stateEntries(path, n):
    """The slave's face state written into D."""
    text = open(path).read()
    m = re.search(r"\n\s*" + slave + r"\s*\n\s*\{", text)
    out = {}
    for k, nc in stateKeys.items():
        km = re.compile(r"\n\s*" + k + r"\s").search(text, m.end())
        if not km:
            continue
        kind, vals = foamio._readField(text, km.end(), nc)
        out[k] = vals if kind == "nonuniform" else [vals]*n
    return out


def fields(t):
    D = foamio.readInternalField(t + "/D")
    nS = len(foamio.readPatchField(t + "/D", slave))
    nM = len(foamio.readPatchField(t + "/D", master))
    pS = foamio.readPatchField(t + "/contactPressure", slave, nS)
    pM = foamio.readPatchField(t + "/contactPressure", master, nM)
    return D, pS, pM, stateEntries(t + "/D", nS)


def compare(ref, t):
    D0, pS0, pM0, s0 = fields(ref)
    D1, pS1, pM1, s1 = fields(t)
    assert set(s0) == set(s1) and "totalSlip" in s0, (set(s0), set(s1))
    return (maxRelDiff(D0, D1),
            max(maxRelDiff(pS0, pS1), maxRelDiff(pM0, pM1)),
            max(maxRelDiff(s0[k], s1[k]) for k in s0))


def forces(pp):
    """Last row of a contact file: normal + friction force."""
    rows = [r.split() for r in open(pp) if r[0] != "#"]
    r = [float(x) for x in rows[-1]]
    return [r[1 + i] + r[4 + i] for i in range(3)]


def newton(log):
    return int(re.search(r"Newton iterations: (\d+)", open(log).read()).group(1))


times = sorted((d for d in os.listdir("serial") if re.match(r"^[0-9.e-]+$", d)),
               key=float)
res = {}
fS0 = forces("serial/postProcessing/contact/%s.dat" % slave)
fScale = math.sqrt(sum(x*x for x in fS0))
for d in ("bodies", "contactSplit"):
    p = name + "_" + d + "_"
    diffs = [compare("serial/" + t, d + "/" + t) for t in times]
    res[p + "DMaxRelDifference"] = max(x[0] for x in diffs)
    res[p + "contactPressureMaxRelDifference"] = max(x[1] for x in diffs)
    res[p + "stateMaxRelDifference"] = max(x[2] for x in diffs)
    fS = forces(d + "/postProcessing/contact/%s.dat" % slave)
    fM = forces(d + "/postProcessing/contact/%s.dat" % master)
    res[p + "forceRelDifference"] = \
        math.sqrt(sum((a - b)**2 for a, b in zip(fS, fS0)))/fScale
    res[p + "momentumRelError"] = \
        math.sqrt(sum((a + b)**2 for a, b in zip(fS, fM)))/fScale
    res[p + "newtonIterationsDifference"] = \
        newton("log.largeStrainSolidFoam." + d) - newton("log.largeStrainSolidFoam")
    res[p + "reconstructParExitCode"] = int(open("reconstructPar.%s.rc" % d).read())
    last = times[-1]
    rD, rP, rS = compare(d + "/" + last, d + "/restart/" + last)
    res[p + "restartDMaxRelDifference"] = rD
    res[p + "restartStateMaxRelDifference"] = max(rP, rS)
    sD, sP, sS = compare("serial/" + last, d + "/restart/" + last)
    res[p + "restartSerialDMaxRelDifference"] = sD
    # slave faces in contact on each processor (the final time)
    inContact = []
    for proc in sorted(glob.glob(d + "/restart/processor*")):
        f = proc + "/" + last + "/contactPressure"
        try:
            pS = foamio.readPatchField(f, slave)
        except (ValueError, AttributeError):  # no face here: "0()"
            pS = []
        inContact.append(sum(1 for x in pS if x > 0))
    res[p + "minSlaveFacesInContactPerProcessor"] = min(inContact)
    res[p + "maxSlaveFacesInContactPerProcessor"] = max(inContact)

with open(results, "a") as f:
    for k, v in res.items():
        f.write("%s %.6g\n" % (k, v))
        print("%s %.6g" % (k, v))
