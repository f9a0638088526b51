# -----------------------------------------------------------------------------
# triboFoam benchmarks (tests/benchmarks/*/run): shared helpers.
#
# A benchmark copies a tutorial into a scratch folder, changes its mesh or
# time step, runs it and records per run: wall time and CPU time of the
# solver, Newton and Krylov iterations, residual evaluations, cut-backs, peak
# resident memory, and the errors the benchmark computes. It writes
#   results/<name>.txt   the tables (what doc/performance.md quotes)
#   results/<name>.dat   error against wall time, one block per sweep, read
#                        by bin/plot.py (one PNG per benchmark)
# Timing: /usr/bin/time (GNU) when present, else a Python wrapper with
# getrusage(RUSAGE_CHILDREN). Peak memory is the largest process of the run
# (one rank for mpirun).
#
# License: GPL-3.0-or-later
# -----------------------------------------------------------------------------
import math
import os
import platform
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

projectDir = os.path.abspath(
    os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))
resultsDir = os.path.join(projectDir, "tests", "benchmarks", "results")
sys.path.insert(0, os.path.join(projectDir, "bin", "python"))
sys.path.insert(0, os.path.join(projectDir, "tests", "bin"))
import foamio  # noqa: E402
from stressTools import copyCase, edit, setEntry  # noqa: E402,F401

solver = "largeStrainSolidFoam"


# ------------------------------------------------------------- environment
def ensureEnvironment():
    """Re-run the calling script inside the project environment unless the
    solver is already on the PATH."""
    if shutil.which(solver) is None and "TRIBOFOAM_BENCH_ENV" not in os.environ:
        os.environ["TRIBOFOAM_BENCH_ENV"] = "1"
        os.execvp("bash", ["bash", "-c",
                           '. "%s/etc/bashrc" > /dev/null 2>&1; exec "$0" "$@"'
                           % projectDir, sys.executable] + sys.argv)
    if shutil.which(solver) is None:
        sys.exit("benchmark: %s not found; run ./Allwmake first" % solver)


def machine():
    """One line: date, cores, CPU model, load average at the call."""
    model = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return "%s, %d cores, %s, load average %.2f" % (
        time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), os.cpu_count(),
        model, os.getloadavg()[0])


def scratch(name):
    """A fresh scratch folder for one benchmark (removed by the caller
    unless TRIBOFOAM_BENCH_KEEP is set)."""
    return tempfile.mkdtemp(prefix="triboFoamBench-%s-" % name)


def cleanUp(path):
    if not os.environ.get("TRIBOFOAM_BENCH_KEEP"):
        shutil.rmtree(path, ignore_errors=True)
    else:
        print("kept %s" % path)


# ------------------------------------------------------------------ running
def timed(args, cwd, log, timeout=1800):
    """Run args in cwd, output to cwd/log. Returns a dict: rc, wall [s],
    cpu [s] (user + system of every process of the run), rssMB (peak
    resident memory of its largest process)."""
    timeFile = os.path.join(cwd, "time." + os.path.basename(log))
    if os.access("/usr/bin/time", os.X_OK):
        cmd = ["/usr/bin/time", "-f", "%e %U %S %M", "-o", timeFile] + args
    else:
        # a fresh interpreter, so RUSAGE_CHILDREN covers this run only
        cmd = [sys.executable, "-c", (
            "import resource, subprocess, sys, time\n"
            "t = time.time(); rc = subprocess.call(sys.argv[2:])\n"
            "r = resource.getrusage(resource.RUSAGE_CHILDREN)\n"
            "open(sys.argv[1], 'w').write('%.3f %.3f %.3f %d\\n' % ("
            "time.time() - t, r.ru_utime, r.ru_stime, r.ru_maxrss))\n"
            "sys.exit(rc)\n"), timeFile] + args
    with open(os.path.join(cwd, log), "w") as out:
        # own process group: a timeout stops mpirun's ranks too
        p = subprocess.Popen(cmd, cwd=cwd, stdout=out,
                             stderr=subprocess.STDOUT, start_new_session=True)
        try:
            rc = p.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGTERM)
            try:
                p.wait(timeout=10)
            except subprocess.TimeoutExpired:
                os.killpg(p.pid, signal.SIGKILL)
                p.wait()
            rc = "timeout"
    res = {"rc": rc, "wall": float("nan"), "cpu": float("nan"),
           "rssMB": float("nan")}
    try:
        with open(timeFile) as f:
            w = f.read().split("\n")[-2].split()
        res.update(wall=float(w[0]), cpu=float(w[1]) + float(w[2]),
                   rssMB=float(w[3])/1024)
    except (OSError, IndexError, ValueError):
        pass
    return res


def quiet(args, cwd, log):
    """Run a helper (blockMesh, postProcess, ...); it must succeed."""
    with open(os.path.join(cwd, log), "w") as out:
        rc = subprocess.call(args, cwd=cwd, stdout=out,
                             stderr=subprocess.STDOUT)
    if rc != 0:
        raise RuntimeError("%s failed in %s (see %s)" % (args[0], cwd, log))


def solverStats(case, log="log." + solver):
    """Steps, Newton, Krylov, residual evaluations and cut-backs of a run
    (the solver log's last line and postProcessing/solverPerformance.dat)."""
    st = {"steps": 0, "newton": 0, "krylov": 0, "resEvals": 0, "cutBacks": 0,
          "colours": 0, "cells": 0, "endReached": False}
    text = open(os.path.join(case, log), errors="replace").read()
    m = re.findall(r"Steps: (\d+), Newton iterations: (\d+)", text)
    if m:
        st["steps"], st["newton"] = int(m[-1][0]), int(m[-1][1])
        st["endReached"] = True
    m = re.search(r"finite-difference Jacobian, (\d+) colours", text)
    if m:
        st["colours"] = int(m.group(1))
    m = re.search(r"(\d+) cells, law", text)
    if m:
        st["cells"] = int(m.group(1))
    perf = os.path.join(case, "postProcessing", "solverPerformance.dat")
    if os.path.exists(perf):
        rows = [r.split() for r in open(perf) if r[0] != "#"]
        st["krylov"] = sum(int(r[3]) for r in rows)
        st["resEvals"] = sum(int(r[4]) for r in rows)
        st["cutBacks"] = sum(int(r[6]) for r in rows)
        if not st["steps"]:
            st["steps"] = len(rows)
            st["newton"] = sum(int(r[2]) for r in rows)
    return st


def runSolver(case, nProcs=1, args=(), timeout=1800):
    """The solver (serial or mpirun -np nProcs -parallel) under timing;
    returns timing and solverStats merged. Stops the benchmark when the
    solver fails."""
    if nProcs > 1:
        cmd = ["mpirun", "-np", str(nProcs), solver, "-parallel"] + list(args)
    else:
        cmd = [solver] + list(args)
    t = timed(cmd, case, "log." + solver, timeout)
    st = solverStats(case)
    st.update(t)
    if t["rc"] != 0 or not st["endReached"]:
        tail = open(os.path.join(case, "log." + solver),
                    errors="replace").read()[-2000:]
        raise RuntimeError("%s failed in %s (exit %s):\n%s"
                           % (solver, case, t["rc"], tail))
    return st


def best(runs):
    """The run with the smallest wall time of repeated runs."""
    return min(runs, key=lambda r: r["wall"])


def newCase(src, dst, extra=()):
    """Copy a tutorial case (0, constant, system) without mesh, results or
    cell centres; extra: further files to copy (e.g. a check script)."""
    copyCase(src, dst, mesh=False)
    for f in ("C", "Cx", "Cy", "Cz", "V"):
        p = os.path.join(dst, "0", f)
        if os.path.exists(p):
            os.remove(p)
    for f in extra:
        shutil.copy(os.path.join(src, f), dst)
    return dst


def setEntries(path, **entries):
    for k, v in entries.items():
        setEntry(path, k, v)


def mesh(case):
    quiet(["blockMesh"], case, "log.blockMesh")


def cellCentres(case):
    quiet(["postProcess", "-func", "writeCellCentres", "-time", "0"], case,
          "log.cellCentres")


def readResults(path):
    values = {}
    for line in open(path):
        w = line.split()
        if len(w) >= 2 and not w[0].startswith("#"):
            values[w[0]] = float(w[1])
    return values


# --------------------------------------------------------------- analysis
def orders(sizes, errors):
    """Observed orders between successive runs: log(e_i/e_i+1) /
    log(h_i/h_i+1); '-' where an error is missing or zero."""
    out = ["-"]
    for i in range(1, len(sizes)):
        e0, e1 = errors[i - 1], errors[i]
        if e0 and e1 and e0 > 0 and e1 > 0 and sizes[i] != sizes[i - 1]:
            out.append("%.2f" % (math.log(e0/e1)/math.log(sizes[i - 1]/sizes[i])))
        else:
            out.append("-")
    return out


def cheapest(runs, key, bound=0.01):
    """The run of smallest wall time whose error runs[key] is below bound,
    or None."""
    ok = [r for r in runs if r.get(key) is not None and r[key] < bound]
    return min(ok, key=lambda r: r["wall"]) if ok else None


# ------------------------------------------------------------------ output
class Report:
    """Lines of the results/<name>.txt file (printed as they come) and the
    sweeps of results/<name>.dat."""

    def __init__(self, name, title):
        self.name = name
        self.lines = []
        self.sweeps = []
        self.plotTitle = title
        self.yLabel = "relative error"
        self.say("# %s" % title)
        self.say("# %s" % machine())

    def say(self, line=""):
        print(line, flush=True)
        self.lines.append(line)

    def table(self, runs, columns, title=None):
        """columns: [(header, key or function(run), format)]."""
        if title:
            self.say("")
            self.say("## " + title)
        cells = []
        for r in runs:
            row = []
            for head, key, fmt in columns:
                v = key(r) if callable(key) else r.get(key)
                row.append("-" if v is None or v == "-" else
                           (fmt % v if not isinstance(v, str) else v))
            cells.append(row)
        widths = [max([len(c[0])] + [len(row[i]) for row in cells])
                  for i, c in enumerate(columns)]
        self.say("  ".join(h.rjust(w) for (h, _, _), w in zip(columns, widths)))
        for row in cells:
            self.say("  ".join(c.rjust(w) for c, w in zip(row, widths)))

    def sweep(self, label, runs, key, x="wall"):
        """A curve of the plot: error runs[key] against runs[x]."""
        pts = [(r[x], r[key]) for r in runs
               if r.get(key) is not None and r[key] > 0]
        if pts:
            self.sweeps.append((label, pts))

    def write(self):
        os.makedirs(resultsDir, exist_ok=True)
        with open(os.path.join(resultsDir, self.name + ".txt"), "w") as f:
            f.write("\n".join(self.lines) + "\n")
        if self.sweeps:
            with open(os.path.join(resultsDir, self.name + ".dat"), "w") as f:
                f.write("# title: %s\n# ylabel: %s\n"
                        % (self.plotTitle, self.yLabel))
                for label, pts in self.sweeps:
                    f.write("# sweep: %s\n" % label)
                    for xv, yv in pts:
                        f.write("%.6g %.6g\n" % (xv, yv))
                    f.write("\n\n")
