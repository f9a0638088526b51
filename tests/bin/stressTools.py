# -----------------------------------------------------------------------------
# triboFoam stress tests (tests/stress/*/run*): shared helpers.
#
# A stress test runs many variants of a small case. Each variant ends in one
# of three outcomes:
#   converged-correct  exit 0, endTime reached, no nan/inf in any written
#                      file, and every physical check of the variant holds;
#   stopped-cleanly    the solver's own stop and nothing else: non-zero exit
#                      with its FOAM FATAL ERROR message 'The step to time
#                      .. did not converge after .. cut-backs .. The last
#                      converged time, T, is written'; T is the latest time
#                      directory, its fields are finite and no file holds
#                      nan/inf;
#   FAIL               anything else: nan/inf on disk, a crash (signal), a
#                      hang (timeout; every process of the run is killed),
#                      a wrong answer, a run that stopped without a message
#                      or with any other fatal error (a dictionary or
#                      set-up error included), or a variant that must
#                      converge and did not.
# classify() decides; Matrix prints the variant x outcome table into the
# test log and writes the counts to results.dat. The checks on the contact
# state are in contactChecks.py.
#
# License: GPL-3.0-or-later
# -----------------------------------------------------------------------------
import math
import os
import re
import shutil
import sys

projectDir = os.environ.get("TRIBOFOAM_DIR") or os.path.abspath(
    os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(projectDir, "bin", "python"))
import foamio  # noqa: E402
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import processTools  # noqa: E402

CONVERGED = "converged-correct"
STOPPED = "stopped-cleanly"
FAIL = "FAIL"


# ------------------------------------------------------------------ running
def run(args, cwd, log, timeout=120):
    """Run an OpenFOAM command in cwd, output (stdout + stderr) to log.
    Returns (exit code or 'timeout', output); on a time-out every process
    the command started is stopped (processTools)."""
    if shutil.which(args[0]) is None:
        # not started by tests/Alltest: set the project environment up
        args = ["bash", "-c", '. "%s/etc/bashrc" > /dev/null 2>&1; '
                'exec "$0" "$@"' % projectDir] + list(args)
    rc, out = processTools.run(args, cwd, timeout)
    with open(os.path.join(cwd, log), "a") as f:
        f.write(out)
    return rc, out


def copyCase(src, dst, mesh=True):
    """0, constant (with the mesh unless mesh=False) and system of src."""
    shutil.rmtree(dst, ignore_errors=True)
    os.makedirs(dst)
    for d in ("0", "constant", "system"):
        shutil.copytree(os.path.join(src, d), os.path.join(dst, d),
                        symlinks=True)
    if not mesh:
        shutil.rmtree(os.path.join(dst, "constant", "polyMesh"),
                      ignore_errors=True)
    return dst


def edit(path, pattern, repl, flags=re.M):
    """One regular-expression substitution in a file; it must match."""
    with open(path) as f:
        text = f.read()
    new, n = re.subn(pattern, repl, text, flags=flags)
    if n == 0:
        raise RuntimeError("pattern %r not found in %s" % (pattern, path))
    with open(path, "w") as f:
        f.write(new)


def setEntry(path, key, value):
    """Set a top-level 'key value;' entry of a dictionary (replace or add)."""
    with open(path) as f:
        text = f.read()
    pat = re.compile(r"^(%s)\s+[^;\n]*;" % re.escape(key), re.M)
    if pat.search(text):
        text = pat.sub(lambda m: "%-15s %s;" % (key, value), text)
    else:
        text += "\n%-15s %s;\n" % (key, value)
    with open(path, "w") as f:
        f.write(text)


# --------------------------------------------------------------- inspecting
numberToken = re.compile(
    r"(?<![A-Za-z0-9_])[-+]?(nan|inf|infinity)(?![A-Za-z0-9_])", re.I)


def nanFiles(case):
    """Files of the case (logs excepted) holding a nan or inf token."""
    bad = []
    for root, dirs, files in os.walk(case):
        for f in files:
            if f.startswith("log."):
                continue
            p = os.path.join(root, f)
            with open(p, errors="replace") as fh:
                if numberToken.search(fh.read()):
                    bad.append(os.path.relpath(p, case))
    return bad


timeDirs = foamio.timeValues


def finiteDir(path):
    """Every field file of a time directory parses and is finite."""
    for f in os.listdir(path):
        p = os.path.join(path, f)
        if not os.path.isfile(p):
            continue
        with open(p, errors="replace") as fh:
            text = fh.read()
        if numberToken.search(text):
            return False
        if "internalField" in text:
            try:
                vals = foamio.readInternalField(p, 1)
            except (ValueError, OSError):
                return False
            flat = [x for v in vals
                    for x in (v if isinstance(v, tuple) else (v,))]
            if not all(math.isfinite(x) for x in flat):
                return False
    return True


# The solver's own stop (solidTimeLoop.C): a step that does not
# converge after the allowed cut-backs, the last converged time written
cleanStop = re.compile(
    r"^FOAM FATAL ERROR\b[^\n]*\n(?:.*\n)*?The step to time \S+ did not "
    r"converge after \d+ cut-backs[^\n]*\n(?:.*\n)*?The last converged "
    r"time, (\S+?), is written", re.M)


def fatalMessage(out):
    i = out.find("FOAM FATAL")
    return out[i:] if i >= 0 else ""


def steps(out):
    """Converged steps, failed attempts and cut-backs of a solver log."""
    converged, failed = [], 0
    current = None
    for line in out.splitlines():
        m = re.match(r"Time = (\S+), deltaT", line)
        if m:
            current = m.group(1)
        elif current and "step not converged" in line:
            failed += 1
        elif current and line.strip().startswith("converged:"):
            converged.append(current)
    cutBacks = out.count("cutting the time step back")
    return converged, failed, cutBacks


def classify(case, rc, out, endTime, errors, mustConverge=False):
    """Outcome of one run and a short reason. errors: the failed physical
    checks of the run (list of strings; checked by the caller on the
    written results, empty when all hold)."""
    nans = nanFiles(case)
    dirs = timeDirs(case)
    latestT, latest = dirs[-1]
    if rc == "timeout":
        return FAIL, "hang (timeout)"
    if nans:
        return FAIL, "nan/inf on disk: " + " ".join(nans[:3])
    if rc != 0:
        fatal = fatalMessage(out)
        if not fatal:
            return FAIL, "crash: exit %s without a FOAM FATAL message" % rc
        stop = cleanStop.search(fatal)
        if not stop:
            # a dictionary, set-up or any other fatal error is a failure,
            # whatever the variant
            lines = [l.strip() for l in fatal.splitlines()[1:] if l.strip()]
            return FAIL, "fatal error, not the solver's clean stop: %s" % (
                lines[0][:110] if lines else fatal[:110])
        lastT = float(stop.group(1))
        if abs(lastT - latestT) > 1e-9*max(1, latestT):
            return FAIL, ("reported last converged time %s is not the "
                          "latest directory %s" % (stop.group(1), latest))
        if not finiteDir(os.path.join(case, latest)):
            return FAIL, "latest time %s not finite" % latest
        if mustConverge:
            return FAIL, "must converge; stopped at %s" % latest
        if errors:
            return FAIL, "wrong answer before it stopped: " + "; ".join(
                errors)
        return STOPPED, "at t = %s: %s" % (latest, next(
            l for l in stop.group(0).splitlines()
            if l.startswith("The step"))[:110])
    if abs(latestT - endTime) > 1e-9*max(1, endTime):
        return FAIL, "exit 0 but the latest time is %s" % latest
    if errors:
        return FAIL, "wrong answer: " + "; ".join(errors)
    return CONVERGED, ""


class Matrix:
    """The variant x outcome table of a stress test."""

    def __init__(self, title):
        self.title = title
        self.rows = []

    def add(self, name, outcome, reason, info=""):
        self.rows.append((name, outcome, reason, info))
        print("%-28s %-18s %s %s" % (name, outcome, info, reason),
              flush=True)

    def count(self, outcome):
        return sum(r[1] == outcome for r in self.rows)

    def print(self):
        print("\n%s: variant x outcome" % self.title)
        w = max([len(r[0]) for r in self.rows] + [7])
        fmt = "    %%-%ds  %%-18s %%s" % w
        head = fmt % ("variant", "outcome", "details")
        print(head)
        print("    " + "-"*(len(head) - 4))
        for name, outcome, reason, info in self.rows:
            print(fmt % (name, outcome, (info + "  " + reason).strip()))
        print("    %d variants: %d converged-correct, %d stopped-cleanly, "
              "%d FAIL\n" % (len(self.rows), self.count(CONVERGED),
                             self.count(STOPPED), self.count(FAIL)))

    def results(self):
        return {"variants": len(self.rows),
                "convergedCorrect": self.count(CONVERGED),
                "stoppedCleanly": self.count(STOPPED),
                "failures": self.count(FAIL)}


readResults = foamio.readResults


def writeResults(path, values):
    with open(path, "w") as f:
        for k, v in values.items():
            f.write("%s %.10g\n" % (k, v))
