#!/usr/bin/env python3
# Mesh-convergence table of the Hertz sphere tutorials (hertzSphere,
# hertzSpheres: Allrun -refinement):
#   hertzConvergence.py [-results FILE] <case> <case> ...
# per case (each run and checked) the mesh size N (nContact), cells, faces
# in contact, wall time, Newton iterations per step, the errors of p0 and a
# against Hertz and the observed orders between successive meshes,
# log(e1/e2)/log(N2/N1) (the cell size in the contact zone is
# contactZone/N). With -results, appends the two finest meshes' orders
# (p0Order, aOrder) to FILE. License: GPL-3.0-or-later
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.environ["TRIBOFOAM_DIR"], "bin", "python"))
import foamio  # noqa: E402

args = sys.argv[1:]
results = None
if args[:1] == ["-results"]:
    results, args = args[1], args[2:]
rows = {}
for case in args:
    r = foamio.readResults(os.path.join(case, "results.dat"))
    n = int(re.search(r"^nContact\s+(\d+);", open(os.path.join(
        case, "system", "meshParameters")).read(), re.M).group(1))
    log = open(os.path.join(case, "log.largeStrainSolidFoam")).read()
    cells = int(re.search(r"-D, (\d+) cells", log).group(1))
    perStep = float(re.search(r"\(([\d.]+) per step\)", log).group(1))
    rt = os.path.join(case, "runTime")
    wall = foamio.readResults(rt)["elapsed"] if os.path.isfile(rt) \
        else float("nan")
    rows[n] = (n, cells, int(r["facesInContact"]), wall, perStep,
               r["peakPressureRelError"], r["contactRadiusRelError"])
print("%6s %8s %10s %9s %8s %10s %7s %10s %7s"
      % ("N", "cells", "inContact", "wall [s]", "Newton", "p0 error",
         "order", "a error", "order"))
prev = None
orders = [float("nan"), float("nan")]
for n in sorted(rows):
    row = rows[n]
    text = ["%7s" % "-", "%7s" % "-"]
    if prev:
        for k, col in enumerate((5, 6)):
            orders[k] = math.log(prev[col]/row[col])/math.log(row[0]/prev[0]) \
                if prev[col] > 0 and row[col] > 0 else float("nan")
            text[k] = "%7.2f" % orders[k]
    print("%6d %8d %10d %9.1f %8.1f %9.2f%% %s %9.2f%% %s"
          % (row[0], row[1], row[2], row[3], row[4], 100*row[5], text[0],
             100*row[6], text[1]))
    prev = row
if results:
    with open(results, "a") as f:
        f.write("p0Order %.10g\naOrder %.10g\n" % tuple(orders))
