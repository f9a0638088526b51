#!/usr/bin/env python3
# Set the mesh size of the Hertz sphere: setMesh.py N [case] writes nContact
# N and what follows from it into <case>/system/meshParameters: cell counts
# (blockMesh needs whole numbers, which #eval cannot give) and the
# expansions beyond the contact zone, where the cells grow geometrically
# from the zone's size h = contactZone/N, by at most 'growth' per cell, so
# that no cell is much larger than its neighbour (bin/python/sphereMesh.py).
# License: GPL-3.0-or-later
import os
import sys

sys.path.insert(0, os.path.join(os.environ["TRIBOFOAM_DIR"], "bin", "python"))
import sphereMesh  # noqa: E402

R = 0.01            # sphere radius [m] (blockMeshDict)

n = int(sys.argv[1])
case = sys.argv[2] if len(sys.argv) > 2 else "."
path = os.path.join(case, "system", "meshParameters")
text = open(path).read()
values = sphereMesh.counts(
    R, sphereMesh.value(text, "contactZone"), n,
    sphereMesh.value(text, "growth"), sphereMesh.value(text, "nInnerRatio"))
open(path, "w").write(sphereMesh.setValues(text, values, path))
