# -----------------------------------------------------------------------------
# The sliding blocks' written data for check.py and checkLubricated.py: the
# contact and force tables, patch fields, and the slip of the slave faces
# relative to the master surface, derived from the displacements.
#
# License: GPL-3.0-or-later
# -----------------------------------------------------------------------------
import os
import sys

sys.path.insert(0, os.path.join(os.environ["TRIBOFOAM_DIR"], "bin", "python"))
import foamio  # noqa: E402


def rows(case, path):
    """A postProcessing table as {time: row}."""
    return {round(r[0], 9): r for r in (
        [float(v) for v in l.split()] for l in open(os.path.join(case, path))
        if l[0] != "#")}


def field(case, time, name, patch, n):
    return foamio.readPatchField(os.path.join(case, time, name), patch, n)


def relativeSlips(case, slave, master, nS, nM, t0, t1):
    """Slip of each slave face over [t0, t1] in x: its displacement
    increment less that of the master surface under it (interpolated
    between the master face centres)."""
    Cs = field(case, "0", "C", slave, nS)
    xm = [c[0] for c in field(case, "0", "C", master, nM)]

    def increment(patch, n):
        return [a[0] - b[0] for a, b in zip(field(case, t1, "D", patch, n),
                                            field(case, t0, "D", patch, n))]

    dS, dM = increment(slave, nS), increment(master, nM)

    def masterAt(x):
        for k in range(len(xm) - 1):
            if xm[k] <= x <= xm[k + 1]:
                w = (x - xm[k])/(xm[k + 1] - xm[k])
                return (1 - w)*dM[k] + w*dM[k + 1]
        return dM[0] if x < xm[0] else dM[-1]

    return [d - masterAt(c[0]) for d, c in zip(dS, Cs)]
