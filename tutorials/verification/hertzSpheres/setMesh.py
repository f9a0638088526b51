#!/usr/bin/env python3
# Set the mesh size of the two Hertz spheres: setMesh.py N [case] writes
# nContact N and what follows from it for each sphere (suffix 1: the upper,
# radius R1; 2: the lower, R2) into <case>/system/meshParameters: cell
# counts (blockMesh needs whole numbers, which #eval cannot give) and the
# expansions beyond the contact zone (bin/python/sphereMesh.py).
# License: GPL-3.0-or-later
import os
import sys

sys.path.insert(0, os.path.join(os.environ["TRIBOFOAM_DIR"], "bin", "python"))
import sphereMesh  # noqa: E402

n = int(sys.argv[1])
case = sys.argv[2] if len(sys.argv) > 2 else "."
path = os.path.join(case, "system", "meshParameters")
text = open(path).read()
text = sphereMesh.setValues(text, {"nContact": n}, path)
for s in ("1", "2"):
    values = sphereMesh.counts(
        sphereMesh.value(text, "R" + s), sphereMesh.value(text, "contactZone"),
        n, sphereMesh.value(text, "growth"),
        sphereMesh.value(text, "nInnerRatio"))
    del values["nContact"]
    text = sphereMesh.setValues(text, values, path, s)
open(path, "w").write(text)
