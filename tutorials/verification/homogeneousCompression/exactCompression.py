# Homogeneous uniaxial compression of a finite-strain J2 solid with Swift
# hardening (doc/theory.md [V8]): the exact state, elasticity included, and
# the rotation of the rotated copy of the case. Used by check.py and
# makeRotated.py. License: GPL-3.0-or-later
import math

# constant/mechanicalProperties
E, nu = 193e9, 0.29
K, eps0, n = 1270e6, 0.03, 0.45
# system/blockMeshDict: side of the one-eighth cube [m]
L = 0.01


def sigmaY(epsP):
    """Swift hardening [S8]"""
    return K*(eps0 + epsP)**n


def plasticStrainAtStrain(eps):
    """Equivalent plastic strain at the logarithmic compressive strain
    eps = ln(h0/h): the root of epsP + sigma_y(epsP)/E = eps (bisection;
    the left side increases)"""
    lo, hi = 0.0, eps
    for _ in range(200):
        m = 0.5*(lo + hi)
        if m + sigmaY(m)/E > eps:
            hi = m
        else:
            lo = m
    return 0.5*(lo + hi)


def plasticStrainAtNominalStress(P):
    """Equivalent plastic strain under the nominal compressive stress P
    (force per reference area): sigma_y(epsP) exp(epsP + sigma_y/E) = P"""
    lo, hi = 0.0, 10.0
    for _ in range(200):
        m = 0.5*(lo + hi)
        s = sigmaY(m)
        if s*math.exp(m + s/E) > P:
            hi = m
        else:
            lo = m
    return 0.5*(lo + hi)


def state(epsP):
    """Exact homogeneous state at plastic strain epsP: Kirchhoff stress
    tau = sigma_y (compressive), axial and lateral stretches, volume ratio,
    Cauchy von Mises stress and nominal stress P = tau h0/h"""
    tau = sigmaY(epsP)
    axial = math.exp(-(epsP + tau/E))
    lateral = math.exp(epsP/2 + nu*tau/E)
    J = math.exp(-(1 - 2*nu)*tau/E)
    return {"tau": tau, "axial": axial, "lateral": lateral, "J": J,
            "cauchy": tau/J, "nominal": tau/axial}


def rotation():
    """Rotation of the rotated copy: 35 degrees about (1, 2, 3)"""
    a = [1/math.sqrt(14), 2/math.sqrt(14), 3/math.sqrt(14)]
    t = math.radians(35)
    c, s = math.cos(t), math.sin(t)
    Kx = [[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]]
    K2 = [[sum(Kx[i][k]*Kx[k][j] for k in range(3)) for j in range(3)]
          for i in range(3)]
    return [[(i == j) + s*Kx[i][j] + (1 - c)*K2[i][j] for j in range(3)]
            for i in range(3)]


def apply(R, v):
    return [sum(R[i][j]*v[j] for j in range(3)) for i in range(3)]


def applyT(R, v):
    return [sum(R[j][i]*v[j] for j in range(3)) for i in range(3)]
