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
