# -----------------------------------------------------------------------------
# triboFoam cross-check (tests/benchmarks/crossCheck): the CalculiX model of
# tutorials/ringCompression. Units mm, N, MPa.
#
# The upper half of the 6:3:2 ring (radii 7.5-15 mm, half height 5 mm),
# axisymmetric 8-node elements (CAX8R, or CAX8), x the radius and y the
# axis; the mid-plane y = 0 held in y. The platen: a band of CAX4 elements
# above the ring whose every node is prescribed (x fixed, y down by the
# stroke), i.e. a rigid flat platen. Contact: surface to surface, penalty
# (linear pressure-overclosure), Coulomb friction with a stick slope; the
# slave surface is the ring's top and both walls, so that the walls can
# fold onto the platen. NLGEOM, the finite-strain J2 plasticity of
# CalculiX with the Swift curve tabulated. 50 % height reduction at step
# time 1: the reduction is 50 t %.
#
# License: GPL-3.0-or-later
# -----------------------------------------------------------------------------
import os

import ccxTools as ct

R_IN, R_OUT, H_HALF = 7.5, 15.0, 5.0
STROKE = 2.5                      # platen travel: 50 % of the height
PLATEN = (1.0, 30.0, 1.0)         # platen band: r from, r to, thickness
REDUCTIONS = (10, 20, 30, 40, 50)


def write(directory, job, nRadial, mu, element="CAX8R", penalty=1e6,
          stickSlope=None, maxInc=0.01, platenSize=1.0):
    """Writes directory/job.inp; returns the mesh (for the results).
    penalty: the slope of the pressure-overclosure line [MPa/mm]; stick
    slope of the friction [MPa/mm], default penalty/10."""
    nAxial = max(1, round(2*nRadial/3))
    ring = ct.QuadMesh(
        nRadial, nAxial,
        lambda i2, j2: (R_IN + (R_OUT - R_IN)*i2/(2*nRadial),
                        H_HALF*j2/(2*nAxial)))
    # platen: CAX4 elements of platenSize [mm] (flat: their size matters
    # only to the contact search)
    nP = int((PLATEN[1] - PLATEN[0])/platenSize) + 1
    n0, e0 = ring.nextNode, ring.nextElement
    bottom = [n0 + k for k in range(nP + 1)]
    top = [n0 + nP + 1 + k for k in range(nP + 1)]
    pNodes = []
    for row, y in ((bottom, H_HALF), (top, H_HALF + PLATEN[2])):
        for k, n in enumerate(row):
            pNodes.append("%d, %.12g, %.12g"
                          % (n, PLATEN[0] + (PLATEN[1] - PLATEN[0])*k/nP, y))
    pElems = ["%d, %d, %d, %d, %d" % (e0 + k, bottom[k], bottom[k + 1],
                                       top[k + 1], top[k])
              for k in range(nP)]

    L = ["*HEADING", "triboFoam crossCheck: ring compression, mu %g, "
         "nRadial %d, %s" % (mu, nRadial, element)]
    L += ["*NODE"] + ring.nodeCards() + pNodes
    L += ring.elementCards(element, "RING")
    L += ["*ELEMENT, TYPE=CAX4, ELSET=PLATEN"] + pElems
    L += ct.setCards("NSET", "NMID", ring.sideNodes("j0"))
    L += ct.setCards("NSET", "NINNER", ring.sideNodes("i0"))
    L += ct.setCards("NSET", "NOUTER", ring.sideNodes("i1"))
    L += ct.setCards("NSET", "NPLATEN", bottom + top)
    L += ct.surfaceCards("SRING", ring.faces("j1") + ring.faces("i0")
                         + ring.faces("i1"))
    L += ct.surfaceCards("SPLATEN", [(e0 + k, "S1") for k in range(nP)])
    L += ct.materialCards()
    L += ["*SOLID SECTION, ELSET=RING, MATERIAL=SS304",
          "*SOLID SECTION, ELSET=PLATEN, MATERIAL=SS304"]
    L += ["*SURFACE INTERACTION, NAME=PLATENCONTACT",
          "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR",
          "%.6g" % penalty]
    if mu > 0:
        L += ["*FRICTION", "%.6g, %.6g" % (mu, stickSlope or penalty/10)]
    L += ["*CONTACT PAIR, INTERACTION=PLATENCONTACT, TYPE=SURFACE TO SURFACE",
          "SRING, SPLATEN"]
    L += ["*BOUNDARY", "NMID, 2, 2, 0.", "NPLATEN, 1, 1, 0."]
    L += ["*TIME POINTS, NAME=OUT",
          ", ".join("%.6g" % (r/50.0) for r in REDUCTIONS)]
    L += ["*STEP, NLGEOM, INC=100000",
          "*STATIC", "%g, 1.0, 1e-6, %g" % (maxInc, maxInc),
          # up to 10 cut-backs of an increment (default 5): the folding
          # walls' first contact
          "*CONTROLS, PARAMETERS=TIME INCREMENTATION",
          "4, 8, 9, 16, 10, 4, 0, 10",
          "*BOUNDARY", "NPLATEN, 2, 2, %.12g" % -STROKE,
          "*NODE PRINT, NSET=NINNER, TIME POINTS=OUT", "U",
          "*NODE PRINT, NSET=NOUTER, TIME POINTS=OUT", "U",
          "*NODE PRINT, NSET=NPLATEN, TOTALS=ONLY, TIME POINTS=OUT", "RF",
          "*NODE FILE, TIME POINTS=OUT", "U",
          "*END STEP"]
    os.makedirs(directory, exist_ok=True)
    with open(os.path.join(directory, job + ".inp"), "w") as f:
        f.write("\n".join(L) + "\n")
    return ring


def results(directory, job, ring, forceFactor):
    """Per reduction [%]: inner diameter change at the mid-plane and the
    smallest, outer at the mid-plane [%], platen force on the whole ring
    [N] (forceFactor: CalculiX's axisymmetric reaction force to the whole
    ring)."""
    b = ct.readDat(os.path.join(directory, job + ".dat"))
    inner = ct.block(b, "displacements", "NINNER")
    outer = ct.block(b, "displacements", "NOUTER")
    force = ct.block(b, "total force", "NPLATEN")
    x0 = {n: c[0] for n, c in ring.coords.items()}
    out = {}
    for t in sorted(inner):
        red = round(50*t, 6)
        ri = {int(r[0]): x0[int(r[0])] + r[1] for r in inner[t]}
        ro = {int(r[0]): x0[int(r[0])] + r[1] for r in outer[t]}
        midI = ring.sideNodes("i0")[0]
        midO = ring.sideNodes("i1")[0]
        out[red] = {
            "innerMid": 100*(ri[midI]/R_IN - 1),
            "innerMin": 100*(min(ri.values())/R_IN - 1),
            "outerMid": 100*(ro[midO]/R_OUT - 1),
            "force": -forceFactor*force[t][0][1]}
    return out
