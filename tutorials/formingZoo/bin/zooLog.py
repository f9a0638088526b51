# -----------------------------------------------------------------------------
# triboFoam: what a forming zoo run cost, read from the solver's log
# (largeStrainSolidFoam's lines, applications/solvers/largeStrainSolidFoam):
#   Time = <t>, deltaT = <dt>                 an attempt at a load step
#   retrying the step without the predictor, Jacobian-free: the exact-Jacobian
#   Newton stopped (<reason>) after <n> iterations, force residual <r>
#   accepted: Newton stalled at force residual <f> (acceptableForceTolerance)
#   step not converged (<why>) after <n> Newton iterations, ...
#   cutting the time step back to <dt> s and retrying (<i> of <max>)
#   converged: <n> Newton iterations, <k> Krylov iterations, <r> residual
#       evaluations, force residual <f>, <s> s
#   Linear solver: <name> (<why the default chose it>)
#   Linear solver petsc: the set-up failed with ...: <what it does now>
# A converged step's Newton iterations include those of its Jacobian-free
# retry (the solver's count); the iterations of attempts that ended in a
# cut-back are counted apart (wastedNewton).
#
# License: GPL-3.0-or-later
# -----------------------------------------------------------------------------
import re


def stats(logFile):
    """A dict: steps, newtonMean, newtonMax, newtonTotal, wastedNewton,
    krylovTotal, krylovPerNewton, retries, cutBacks, accepted (steps
    taken at acceptableForceTolerance), stepWall (the sum of
    the steps' clock times), linearSolver, cells, endReached, lastTime (of
    the last attempt), setUpFailures and the first one's message"""
    text = open(logFile, errors="replace").read()
    conv = re.findall(r"^ *converged: (\d+) Newton iterations, (\d+) Krylov"
                      r" iterations, (\d+) residual evaluations, force "
                      r"residual \S+, (\S+) s$", text, re.M)
    newton = [int(c[0]) for c in conv]
    krylov = sum(int(c[1]) for c in conv)
    times = re.findall(r"^Time = (\S+), deltaT", text, re.M)
    m = re.search(r"^Linear solver: (\S+)", text, re.M)
    cells = re.search(r"^Total Lagrangian solid: .*?(\d+) cells", text,
                      re.M)
    setUp = re.findall(r"^Linear solver \S+: the set-up failed (.*)$", text,
                       re.M)
    st = {
        "steps": len(newton),
        "newtonTotal": sum(newton),
        "newtonMean": sum(newton)/len(newton) if newton else float("nan"),
        "newtonMax": max(newton) if newton else float("nan"),
        "wastedNewton": sum(int(n) for n in re.findall(
            r"step not converged \(.*\) after (\d+) Newton", text)),
        "krylovTotal": krylov,
        "krylovPerNewton": krylov/sum(newton) if sum(newton) else
        float("nan"),
        "retries": len(re.findall(r"retrying the step without the "
                                  r"predictor", text)),
        "cutBacks": len(re.findall(r"cutting the time step back", text)),
        "accepted": len(re.findall(r"accepted: Newton stalled", text)),
        "stepWall": sum(float(c[3]) for c in conv),
        "linearSolver": m.group(1) if m else "?",
        "cells": int(cells.group(1)) if cells else 0,
        "endReached": bool(re.search(r"^Steps: \d+, Newton iterations",
                                     text, re.M)),
        "lastTime": float(times[-1]) if times else 0.0,
        "setUpFailures": len(setUp),
        "setUpFailure": setUp[0].strip() if setUp else "",
    }
    return st
