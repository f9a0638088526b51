# Homogeneous neo-Hookean bar under uniaxial stress (doc/theory.md [S4],
# [V3]): the exact lateral stretch and stresses, shared by check.py and
# checkFollower.py. License: GPL-3.0-or-later
import math


def lateralStretch(l, mu, lam):
    """Lateral stretch with zero lateral stress at axial stretch l:
    mu (l2 - 1/l2) + lam ln(J)/l2 = 0, J = l l2^2 (bisection, single root)"""
    lo, hi = 1e-3, 1e3
    for _ in range(200):
        m = 0.5*(lo + hi)
        if mu*(m - 1/m) + lam*math.log(l*m*m)/m > 0:
            hi = m
        else:
            lo = m
    return 0.5*(lo + hi)


def nominalStress(l, mu, lam):
    """Axial first Piola-Kirchhoff stress P11"""
    l2 = lateralStretch(l, mu, lam)
    return mu*(l - 1/l) + lam*math.log(l*l2*l2)/l


def cauchyStress(l, mu, lam):
    """Axial Cauchy stress sigma11 = P11 l / J"""
    l2 = lateralStretch(l, mu, lam)
    return nominalStress(l, mu, lam)*l/(l*l2*l2)
