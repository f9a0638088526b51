# -----------------------------------------------------------------------------
# triboFoam cross-check (tests/benchmarks/crossCheck): the CalculiX model of
# tutorials/pearShapedTube, Coulomb friction. Units mm, N, MPa, s.
#
# Plane strain (CPE8R, 1 mm deep), the half tube x >= 0 (outer radius
# 28.5 mm, wall 1.6 mm), nWall x nAround 8-node elements, uniform; the
# symmetry plane x = 0 held in x. The die: the tutorial's profile
# (base/system/dieProfileDict: circle R 28.6 mm, the flank tangent to it
# through the apex (0, 50 mm), the 4 mm apex fillet), a band of CPE4
# elements whose faces follow it (1 deg facets on the circle: chordal
# error 1.1 um), continued a little across x = 0, every node fixed: a
# rigid die. Contact: surface to surface, penalty, Coulomb friction with a
# stick slope. The vertical rigid-body mode: a SPRING1 on the inner wall's
# bottom node, 100 times the tutorial's foundation (1e7 Pa/m over the
# inner wall; 'foundation' scales it; with 1 the results move by 0.002 %,
# doc/performance.md section 16). Internal follower
# pressure 0 -> 80 MPa over 8 s, static (no inertia: the hold to 10 s of
# the tutorial changes nothing for a rate-independent law).
#
# License: GPL-3.0-or-later
# -----------------------------------------------------------------------------
import math
import os

import ccxTools as ct

R_OUT, WALL = 28.5, 1.6
R_DIE, APEX, FILLET = 28.6, 50.0, 4.0
P_END, T_END = 80.0, 8.0
FOUNDATION = 1e7*1e-9             # [N/mm^3] (1e7 Pa/m)


def dieProfile(circleStep=0.25, flankStep=0.2, filletStep=1.0, overlap=3):
    """Points along the die profile from below the bottom (across x = 0
    by overlap segments) to beyond the apex, in order (counter-clockwise
    about the cavity)."""
    tx = R_DIE*math.sqrt(APEX**2 - R_DIE**2)/APEX
    ty = R_DIE**2/APEX
    phiT = math.degrees(math.atan2(tx, -ty))       # from -y towards +x
    cy = APEX - FILLET*APEX/R_DIE                  # fillet centre (0, cy)
    fx, fy = FILLET*tx/R_DIE, APEX - FILLET*(APEX - ty)/R_DIE
    pts = []
    n = int(math.ceil(phiT/circleStep))
    for k in range(-overlap, n):
        pts.append(ct.polar(R_DIE, phiT*k/n))
    L = math.hypot(fx - tx, fy - ty)
    m = int(math.ceil(L/flankStep))
    for k in range(m):
        pts.append((tx + (fx - tx)*k/m, ty + (fy - ty)*k/m))
    a0 = math.degrees(math.atan2(fy - cy, fx))     # from +x, about C
    q = int(math.ceil((90 - a0)/filletStep))
    for k in range(q + overlap + 1):
        a = math.radians(a0 + (90 - a0)*k/q)
        pts.append((FILLET*math.cos(a), cy + FILLET*math.sin(a)))
    return pts


def write(directory, job, nWall, nAround, mu, penalty=1e5, stickSlope=1e4,
          maxInc=0.1, element="CPE8R", contact="SURFACE TO SURFACE",
          foundation=100.0, circleStep=1.0, yieldScale=1.0):
    """Writes directory/job.inp; returns the tube mesh."""
    r0 = R_OUT - WALL
    tube = ct.QuadMesh(
        nWall, nAround,
        lambda i2, j2: ct.polar(r0 + WALL*i2/(2*nWall),
                                180.0*j2/(2*nAround)))
    # die band: profile points p and their offsets 1 mm outwards
    p = dieProfile(circleStep)
    n0, e0 = tube.nextNode, tube.nextElement
    dieNodes, dieElems = [], []
    q = []
    for k, (x, y) in enumerate(p):
        a = p[max(k - 1, 0)]
        b = p[min(k + 1, len(p) - 1)]
        tx, ty = b[0] - a[0], b[1] - a[1]
        t = math.hypot(tx, ty)
        q.append((x + ty/t, y - tx/t))             # right of the walk: out
    np_ = len(p)
    for k in range(np_):
        dieNodes.append("%d, %.12g, %.12g" % (n0 + k, p[k][0], p[k][1]))
        dieNodes.append("%d, %.12g, %.12g" % (n0 + np_ + k, q[k][0], q[k][1]))
    for k in range(np_ - 1):
        dieElems.append("%d, %d, %d, %d, %d" % (
            e0 + k, n0 + k + 1, n0 + k, n0 + np_ + k, n0 + np_ + k + 1))
    bottomInner = tube.node[(0, 0)]
    eSpring = e0 + np_
    # the foundation on the mean displacement of the inner wall, lumped
    kSpring = foundation*FOUNDATION*math.pi*r0*1.0

    L = ["*HEADING", "triboFoam crossCheck: pear-shaped tube, mu %g, "
         "%d x %d %s" % (mu, nWall, nAround, element)]
    L += ["*NODE"] + tube.nodeCards() + dieNodes
    L += tube.elementCards(element, "TUBE")
    L += ["*ELEMENT, TYPE=CPE4, ELSET=DIE"] + dieElems
    L += ["*ELEMENT, TYPE=SPRING1, ELSET=FOUNDATION", "%d, %d"
          % (eSpring, bottomInner)]
    sym = tube.sideNodes("j0") + tube.sideNodes("j1")
    L += ct.setCards("NSET", "NSYM", sym)
    L += ct.setCards("NSET", "NINNER", tube.sideNodes("i0"))
    L += ct.setCards("NSET", "NOUTER", tube.sideNodes("i1"))
    L += ct.setCards("NSET", "NDIE", range(n0, n0 + 2*np_))
    L += ct.setCards("ELSET", "EINNER", [e for e, _ in tube.faces("i0")])
    L += ct.surfaceCards("SOUTER", tube.faces("i1"))
    L += ct.surfaceCards("SDIE", [(e0 + k, "S1") for k in range(np_ - 1)])
    L += ct.materialCards(yieldScale=yieldScale)
    L += ["*SOLID SECTION, ELSET=TUBE, MATERIAL=SS304", "1.0",
          "*SOLID SECTION, ELSET=DIE, MATERIAL=SS304", "1.0",
          "*SPRING, ELSET=FOUNDATION", "2", "%.6g" % kSpring]
    L += ["*SURFACE INTERACTION, NAME=DIECONTACT",
          "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR", "%.6g" % penalty]
    if mu > 0:
        L += ["*FRICTION", "%.6g, %.6g" % (mu, stickSlope)]
    L += ["*CONTACT PAIR, INTERACTION=DIECONTACT, TYPE=%s" % contact,
          "SOUTER, SDIE"]
    L += ["*BOUNDARY", "NSYM, 1, 1, 0.", "NDIE, 1, 2, 0."]
    L += ["*AMPLITUDE, NAME=PRESSURE", "0., 0., %g, 1." % T_END]
    L += ["*TIME POINTS, NAME=OUT", "3., %g" % T_END]
    L += ["*STEP, NLGEOM, INC=100000",
          "*STATIC", "%g, %g, 1e-7, %g" % (maxInc, T_END, maxInc),
          "*DLOAD, AMPLITUDE=PRESSURE"]
    L += ["%d, P4, %g" % (e, P_END) for e, _ in tube.faces("i0")]
    L += ["*NODE PRINT, NSET=NINNER, TIME POINTS=OUT", "U",
          "*NODE PRINT, NSET=NOUTER, TIME POINTS=OUT", "U",
          "*NODE PRINT, NSET=NDIE, TOTALS=ONLY, TIME POINTS=OUT", "RF",
          "*CONTACT PRINT, TIME POINTS=OUT", "CSTR",
          "*NODE FILE, TIME POINTS=OUT", "U",
          "*CONTACT FILE, TIME POINTS=OUT", "CSTR",
          "*END STEP"]
    os.makedirs(directory, exist_ok=True)
    with open(os.path.join(directory, job + ".inp"), "w") as f:
        f.write("\n".join(L) + "\n")
    return tube


def _distanceToPolyline(p, poly):
    best = float("inf")
    for a, b in zip(poly[:-1], poly[1:]):
        dx, dy = b[0] - a[0], b[1] - a[1]
        lengthSqr = dx*dx + dy*dy
        s = 0.0 if lengthSqr == 0 else max(0.0, min(1.0, ((p[0] - a[0])*dx
                                                  + (p[1] - a[1])*dy)/lengthSqr))
        best = min(best, math.hypot(p[0] - a[0] - s*dx, p[1] - a[1] - s*dy))
    return best


def results(directory, job, tube, time=T_END):
    """Protrusion [mm] (highest deformed outer node above 28.5 mm), the
    thickness profile [(original angle [deg], thickness [mm])] (each outer
    node's distance to the polyline of the deformed inner nodes, closed at
    x = 0 by its mirror image), its minimum and angle, and the contact
    pressure [(angle of the slave face's centre, p [MPa])]."""
    b = ct.readDat(os.path.join(directory, job + ".dat"))
    X = tube.coords
    inner = ct.block(b, "displacements", "NINNER")[time]
    outer = ct.block(b, "displacements", "NOUTER")[time]

    def moved(rows):
        return {int(r[0]): (X[int(r[0])][0] + r[1], X[int(r[0])][1] + r[2])
                for r in rows}
    xi, xo = moved(inner), moved(outer)
    poly = [xi[n] for n in tube.sideNodes("i0")]
    poly = [(-poly[1][0], poly[1][1])] + poly + [(-poly[-2][0], poly[-2][1])]
    profile = []
    for n in tube.sideNodes("i1"):
        x0 = X[n]
        ang = math.degrees(math.atan2(x0[0], -x0[1]))
        profile.append((ang, _distanceToPolyline(xo[n], poly)))
    tmin = min(profile, key=lambda t: t[1])
    prot = max(y for _, y in xo.values()) - R_OUT
    pressure = []
    try:
        cs = ct.block(b, "contact stress", "")[time]
    except KeyError:
        cs = []
    faceAngle = {}
    for e, _ in tube.faces("i1"):
        j = [jj for (ii, jj), ee in tube.element.items() if ee == e][0]
        faceAngle[e] = 180.0*(j + 0.5)/tube.nj
    perFace = {}
    for r in cs:
        if int(r[0]) in faceAngle and len(r) >= 5:
            perFace.setdefault(int(r[0]), []).append(r[2])
    for e, ps in perFace.items():
        # the mean over the face's contact elements (its integration
        # points against the die's faces)
        pressure.append((faceAngle[e], sum(ps)/len(ps)))
    return {"protrusion": prot, "profile": profile, "minThickness": tmin[1],
            "minThicknessAngle": tmin[0], "pressure": sorted(pressure)}
