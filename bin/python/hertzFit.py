# triboFoam: Hertz pressure-profile fit for the verification checks
# (doc/theory.md [V4], [V9], [V11]). License: GPL-3.0-or-later
import math


def fitProfile(points):
    """p0 and a of p^2 = p0^2 (1 - x^2/a^2) fitted by least squares to the
    (x, p) points given (x: distance from the centre of the contact)."""
    xs = [x*x for x, _ in points]
    ys = [p*p for _, p in points]
    n = len(xs)
    mx, my = sum(xs)/n, sum(ys)/n
    B = sum((x - mx)*(y - my) for x, y in zip(xs, ys)) \
        / sum((x - mx)**2 for x in xs)
    A = my - B*mx
    return math.sqrt(A), math.sqrt(-A/B)


def fitHertz(points):
    """fitProfile() of the (x, p) points in contact of a line contact, all
    but the outermost (the one face the contact edge may cut): the whole
    profile, not the one face nearest the edge, sets a."""
    return fitProfile(sorted(points)[:-1])


def sphereContact(case, patch, R, Estar):
    """The last step's contact force P of a quarter model (4 times the
    magnitude of the z component in postProcessing/contact/<patch>.dat),
    its largest penetration and Hertz's a and p0 for a sphere of radius R
    and modulus E* ([V9], [V12])"""
    import os
    rows = [r.split() for r in open(os.path.join(
        case, "postProcessing", "contact", patch + ".dat")) if r[0] != "#"]
    # the force on the patch: downward on the lower body's surface
    P = 4*abs(float(rows[-1][3]))
    a = (3*P*R/(4*Estar))**(1.0/3.0)
    return P, float(rows[-1][8]), a, 3*P/(2*math.pi*a*a)
