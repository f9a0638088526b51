# -----------------------------------------------------------------------------
# triboFoam stress tests: the contact state as written by frictionalContact
# and the physical checks on it (the laws face by face, the pressed block).
#
# License: GPL-3.0-or-later
# -----------------------------------------------------------------------------
import math
import os
import re

from stressTools import foamio


# ------------------------------------------------- reading the contact state
def patchEntry(path, patch, key, nFaces):
    """Entry 'key' of boundaryField/patch in a field file (the frictional
    contact writes its face state there: totalSlip, contactAge, ...)."""
    with open(path) as f:
        text = f.read()
    m = re.search(r"\n\s*" + re.escape(patch) + r"\s*\n\s*\{", text)
    if not m:
        raise ValueError("patch %s not in %s" % (patch, path))
    k = re.compile(r"\n\s*%s\s+" % re.escape(key)).search(text, m.end())
    if not k:
        raise ValueError("%s not in patch %s of %s" % (key, patch, path))
    body = text[k.end() - 1:]
    kind = re.match(r"\s*(nonuniform|uniform)", body).group(1)
    if kind == "uniform":
        val = body[len(re.match(r"\s*uniform", body).group(0)):
                   body.index(";")].strip()
        if val.startswith("("):
            v = tuple(float(x) for x in val.strip("()").split())
        else:
            v = float(val)
        return [v]*nFaces
    m2 = re.compile(r"\s*nonuniform\s+List<(\w+)>\s*(\d+)\s*\(").match(body)
    n = int(m2.group(2))
    depth, i = 1, m2.end()
    while depth:
        depth += (body[i] == "(") - (body[i] == ")")
        i += 1
    inner = body[m2.end():i - 1]
    if m2.group(1) == "scalar":
        vals = [float(x) for x in inner.split()]
    else:
        vals = [tuple(float(x) for x in t.split())
                for t in re.findall(r"\(([^()]*)\)", inner)]
    if len(vals) != n:
        raise ValueError("%s: expected %d values, read %d" % (key, n,
                                                              len(vals)))
    return vals


def nPatchFaces(case, patch):
    text = open(os.path.join(case, "constant", "polyMesh",
                             "boundary")).read()
    return int(re.search(r"\n\s*" + re.escape(patch)
                         + r"\s*\n\s*\{[^}]*nFaces\s+(\d+);",
                         text).group(1))


def contactState(case, time, patch):
    """Per-face contact state at a written time: a list of dicts with tN,
    tT (vector, the friction traction ON THE BODY, as written), status,
    v (|slip rate|), theta, alpha, gT (total slip), gTp (plastic slip)."""
    n = nPatchFaces(case, patch)
    d = os.path.join(case, time)

    def pf(name):
        # a variable the law does not declare (contactAge of Coulomb's
        # law) is not written: zero, as a fresh face
        path = os.path.join(d, name)
        if not os.path.isfile(path):
            return [0.0]*n
        return foamio.readPatchField(path, patch, n)

    def de(key):
        return patchEntry(os.path.join(d, "D"), patch, key, n)

    if not os.path.isfile(os.path.join(d, "contactPressure")):
        # the initial time: fresh, open faces
        return [dict(tN=0.0, tT=(0.0, 0.0, 0.0), status=0, v=0.0,
                     theta=0.0, alpha=0.0, gT=(0.0, 0.0, 0.0),
                     gTp=(0.0, 0.0, 0.0)) for i in range(n)]
    faces = []
    for tN, tT, st, v, th, al, gT, gTp in zip(
            pf("contactPressure"), pf("frictionTraction"),
            pf("contactStatus"), pf("slipRate"), pf("contactAge"),
            pf("lubricationWeight"), de("totalSlip"), de("plasticSlip")):
        faces.append(dict(tN=tN, tT=tT, status=int(round(st)), v=v,
                          theta=th, alpha=al, gT=gT, gTp=gTp))
    return faces


def contactRows(case, patch):
    """postProcessing/contact/<patch>.dat as {time: row}; row: time,
    normal force (3), friction force (3), dissipated energy, largest
    penetration, where (3), faces in contact, faces slipping."""
    path = os.path.join(case, "postProcessing", "contact", patch + ".dat")
    rows = {}
    if os.path.isfile(path):
        for line in open(path):
            if line[0] != "#":
                r = [float(x) for x in line.split()]
                rows[r[0]] = r
    return rows


def rowAt(rows, t, tol=1e-4):
    """The row of contactRows() at time t (a time directory's value: its
    name may carry more digits than the file's column); None if absent."""
    if not rows:
        return None
    key = min(rows, key=lambda k: abs(k - t))
    return rows[key] if abs(key - t) <= tol + 1e-12*abs(t) else None


def mag(v):
    return math.sqrt(sum(c*c for c in v))


# ------------------------------------------ the laws, face by face (checks)
def coulombError(faces, mu, muStatic=None):
    """Largest violation of Coulomb's law over the faces, relative to
    mu tN: |tT| = mu tN on sliding faces [F8], |tT| <= mu_s tN on sticking
    ones, no traction on open ones. Returns (error, nSlip, nStick, nOpen)."""
    muS = mu if muStatic is None else muStatic
    err, nSlip, nStick, nOpen = 0.0, 0, 0, 0
    for f in faces:
        t = mag(f["tT"])
        Y = mu*f["tN"]
        scale = max(Y, 1e-12*f["tN"], 1e-300)
        if f["status"] == 2:
            nSlip += 1
            err = max(err, abs(t - Y)/scale)
        elif f["status"] == 1:
            nStick += 1
            err = max(err, max(0.0, t - muS*f["tN"])/scale)
        else:
            nOpen += 1
            err = max(err, (t + f["tN"])/max(1.0, f["tN"]))
    return err, nSlip, nStick, nOpen


class lubricatedLaw:
    """The lubricated law (doc/theory.md [F16]-[F20], [F29]) for the checks:
    constant or Stribeck lubrication weight, exponential mu0 [F18]."""

    def __init__(self, M, D0, Vs, muS, muD, vc, etaB, alpha=None,
                 stribeck=None):
        self.M, self.D0, self.Vs = M, D0, Vs
        self.muS, self.muD, self.vc, self.etaB = muS, muD, vc, etaB
        self.alphaConst = alpha
        self.stribeck = stribeck     # (D, Db, vb, n)

    def alpha(self, v):
        if self.alphaConst is not None:
            return self.alphaConst
        D, Db, vb, n = self.stribeck
        xi = (D/Db)*(v/vb)
        return 0.0 if xi <= 0 else xi**n/(1 + xi**n)

    def threshold(self, v, theta, tN):
        """Y = f mu0 tN with f = 1 + M ln(theta v_eff/D0) >= 0 [F17]."""
        f = max(1 + self.M*math.log(theta*math.hypot(v, self.Vs)/self.D0),
                0.0)
        mu0 = self.muD + (self.muS - self.muD)*math.exp(-v/self.vc)
        return f*mu0*tN

    def contactAge(self, theta0, v, dt):
        """Exact contact-age step at constant |v| [F13]."""
        x = v*dt/self.D0
        if x < 1e-3:
            g = 1 + x*(-0.5 + x*(1.0/6.0 - x/24.0))
        else:
            g = -math.expm1(-x)/x
        return theta0*math.exp(-x) + dt*g

    def error(self, faces, oldFaces, dt):
        """Largest violation of the law [F29] over the faces: with the step's
        total slip-rate vector vv = P (gT - gT_n)/dt (the film's rate) and
        sliding rate vp = |gTp - gTp_n|/dt (ageing and mu0, [F16]), both
        from the previous written step, the contact age follows its exact
        update at vp from the previous step's, the frictional part
        F_T = (tT - alpha eta_b vv)/(1 - alpha) has |F_T| = Y(vp) on
        sliding faces and <= Y on sticking ones; alpha(|vv|) follows its
        model. Relative to Y + alpha eta_b |v| (the contact age: to
        itself). Returns (error, nSlip, nStick, nOpen)."""
        err, nSlip, nStick, nOpen = 0.0, 0, 0, 0
        for f, o in zip(faces, oldFaces):
            if f["status"] == 0:
                nOpen += 1
                err = max(err, (mag(f["tT"]) + f["tN"])/max(1.0, f["tN"]))
                continue
            tT = [-c for c in f["tT"]]        # conjugate to the slip
            vv = [(a - b)/dt for a, b in zip(f["gT"], o["gT"])]
            v = mag(vv)
            # the written sliding rate drives ageing and mu0; it must match
            # the written plastic slips to their written precision (1e-10
            # relative: a step's slip is a small difference of large slips)
            vp = f["v"]
            dgp = mag([a - b for a, b in zip(f["gTp"], o["gTp"])])
            err = max(err, abs(dgp - vp*dt)
                      / max(vp*dt, 1e-10*max(mag(f["gTp"]), 1e-9)))
            al = self.alpha(v)
            Y = self.threshold(vp, f["theta"], f["tN"])
            scale = max(Y + al*self.etaB*v, 1e-12*f["tN"], 1e-300)
            theta = self.contactAge(o["theta"] if o["status"] else
                                    self.D0/self.Vs, vp, dt)
            err = max(err, abs(al - f["alpha"]),
                      abs(f["theta"] - theta)/theta)
            if al >= 1:
                F = 0.0
                err = max(err, mag([t - self.etaB*w
                                    for t, w in zip(tT, vv)])/scale)
            else:
                F = mag([(t - al*self.etaB*w)/(1 - al)
                         for t, w in zip(tT, vv)])
            if f["status"] == 2:
                nSlip += 1
                if al < 1:
                    err = max(err, (1 - al)*abs(F - Y)/scale)
            else:
                nStick += 1
                err = max(err, (1 - al)*max(0.0, F - Y)/scale)
        return err, nSlip, nStick, nOpen


# ----------------------------------------------- the sliding block, 1-D
def pressedBlockForce(d, H, E, A, KN, e):
    """Normal force of the sliding block pressed by d (nu = 0: uniaxial
    stress, exact for the discretisation): E (d - p)/H = KN s(p), with the
    penetration p and the smoothed penalty s(p) = p above e,
    (p + e)^2/(4e) within +-e, 0 below (doc/theory.md [C2b], [F1])."""
    def s(p):
        if p >= e:
            return p
        if p <= -e:
            return 0.0
        return (p + e)**2/(4*e)
    lo, hi = -max(e, d), d
    for _ in range(300):
        p = 0.5*(lo + hi)
        if E*(d - p)/H > KN*s(p):
            lo = p
        else:
            hi = p
    return E*(d - 0.5*(lo + hi))/H*A
