#!/usr/bin/env python3
# The rotated copy of the case (rotated/): the same cube, load and symmetry
# planes turned by 35 degrees about (1, 2, 3), so no tensor is diagonal and
# the exact answer is unchanged (objectivity). License: GPL-3.0-or-later
import os
import re
import shutil
import sys

import exactCompression as ex

src = sys.argv[1] if len(sys.argv) > 1 else "."
dst = sys.argv[2] if len(sys.argv) > 2 else "rotated"
R = ex.rotation()

shutil.rmtree(dst, ignore_errors=True)
for d in ("0", "constant", "system"):
    shutil.copytree(os.path.join(src, d), os.path.join(dst, d),
                    ignore=shutil.ignore_patterns("polyMesh", "C", "C?"))


def rotatePoint(m):
    p = ex.apply(R, [float(x) for x in m.group(1).split()])
    return "(%.15g %.15g %.15g)" % tuple(p)


path = os.path.join(dst, "system", "blockMeshDict")
text = open(path).read()
head, rest = text.split("vertices", 1)
verts, tail = rest.split(");", 1)
verts = re.sub(r"\(([-0-9.e ]+)\)", rotatePoint, verts)
open(path, "w").write(head + "vertices" + verts + ");" + tail)


def rotateTraction(m):
    t = ex.apply(R, [0, 0, float(m.group(1))])
    return "(1 (%.15g %.15g %.15g))" % tuple(t)


path = os.path.join(dst, "0", "D")
text = re.sub(r"\(1 \(0 0 (-[0-9.e]+)\)\)", rotateTraction, open(path).read())
open(path, "w").write(text)
