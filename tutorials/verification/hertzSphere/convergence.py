#!/usr/bin/env python3
# Mesh-convergence table of the Hertz sphere (Allrun -refinement): per mesh
# refinement/n<N> the cells, faces in contact, wall time, Newton iterations
# per step, the errors of p0 and a against Hertz and the observed orders
# between successive meshes, log(e1/e2)/log(N2/N1) (the cell size in the
# contact zone is contactZone/N). License: GPL-3.0-or-later
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.environ["TRIBOFOAM_DIR"], "bin", "python"))
import foamio  # noqa: E402

top = sys.argv[1] if len(sys.argv) > 1 else "refinement"
rows = []
for d in os.listdir(top):
    m = re.match(r"n(\d+)$", d)
    res = os.path.join(top, d, "results.dat")
    if not m or not os.path.isfile(res):
        continue
    r = foamio.readResults(res)
    log = open(os.path.join(top, d, "log.largeStrainSolidFoam")).read()
    cells = int(re.search(r"(\d+) cells", log).group(1))
    perStep = float(re.search(r"\(([\d.]+) per step\)", log).group(1))
    wall = foamio.readResults(os.path.join(top, d, "runTime"))["elapsed"]
    rows.append((int(m.group(1)), cells, int(r["facesInContact"]), wall,
                 perStep, r["peakPressureRelError"],
                 r["contactRadiusRelError"]))
rows.sort()
print("%6s %8s %10s %9s %8s %10s %7s %10s %7s"
      % ("N", "cells", "inContact", "wall [s]", "Newton", "p0 error",
         "order", "a error", "order"))
prev = None
for row in rows:
    orders = ["%7s" % "-", "%7s" % "-"]
    if prev:
        for k, col in enumerate((5, 6)):
            if prev[col] > 0 and row[col] > 0:
                orders[k] = "%7.2f" % (math.log(prev[col]/row[col])
                                       / math.log(row[0]/prev[0]))
    print("%6d %8d %10d %9.1f %8.1f %9.2f%% %s %9.2f%% %s"
          % (row[0], row[1], row[2], row[3], row[4], 100*row[5], orders[0],
             100*row[6], orders[1]))
    prev = row
