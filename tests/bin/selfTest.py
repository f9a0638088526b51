#!/usr/bin/env python3
# -----------------------------------------------------------------------------
# triboFoam tests: the test machinery tested (run by tests/cases/testTools).
#
#   runTests.evaluate   nan, +inf and -inf fail every kind of check (below,
#                       above, near); a missing quantity fails; finite
#                       values on the right and wrong side of a bound;
#   runTests.parseSpec  a spec without a check line is refused; the command
#                       is kept as written, quotes included;
#   processTools.run    on a time-out every process of the command is
#                       stopped: a shell's background children, and
#                       mpirun with its ranks (which sit in process groups
#                       of their own); a background process left by a
#                       command that ended is stopped too; the runner
#                       stopped by Ctrl-C or SIGTERM stops the command's
#                       processes;
#   runTests.copySource only what git tracks reaches the test copy: an
#                       ignored time directory and an untracked derived
#                       case left by an earlier run are not copied (and the
#                       untracked one is named in the log), a tracked file
#                       is copied as it is in the working tree;
#   stressTools.classify the solver's own stop (its message, the last
#                       converged time written and latest) is
#                       stopped-cleanly; a dictionary error, a stop naming
#                       another time, a crash without a message, nan on
#                       disk, a stop of a variant that must converge are
#                       FAIL; a complete run is converged-correct.
# Each check prints one line; writes results.dat (selfTestChecks,
# selfTestFailures).
#
# License: GPL-3.0-or-later
# -----------------------------------------------------------------------------
import io
import math
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
import processTools  # noqa: E402
import runTests  # noqa: E402
import stressTools  # noqa: E402

checks = []


def check(name, ok, detail=""):
    checks.append(bool(ok))
    print("%s %s%s" % ("ok     " if ok else "FAILED ", name,
                       (": " + detail) if detail else ""), flush=True)


# ------------------------------------------------------------- evaluate
def testEvaluate():
    below = dict(q="x", op="below", value=1.0, source="s")
    above = dict(q="x", op="above", value=1.0, source="s")
    near = dict(q="x", op="near", value=1.0, tol=0.1, kind="rel", source="s")
    for v in (math.nan, math.inf, -math.inf):
        for c in (below, above, near):
            ok, text = runTests.evaluate(c, {"x": v})
            check("evaluate: %s %s fails" % (v, c["op"]), not ok, text)
    for c, v, expect in ((below, 0.5, True), (below, 1.5, False),
                         (above, 1.5, True), (above, 0.5, False),
                         (near, 1.05, True), (near, 1.2, False)):
        ok, text = runTests.evaluate(c, {"x": v})
        check("evaluate: %g %s %g %s" % (v, c["op"], c["value"],
                                         "passes" if expect else "fails"),
              ok == expect, text)
    ok, text = runTests.evaluate(below, {})
    check("evaluate: a missing quantity fails", not ok, text)


def testParseSpec(tmp):
    path = os.path.join(tmp, "spec")
    with open(path, "w") as f:
        f.write("command ./Allrun\n")
    try:
        runTests.parseSpec(path)
        check("parseSpec: a spec without checks is refused", False)
    except runTests.SpecError as e:
        check("parseSpec: a spec without checks is refused", True, str(e))
    command = './Allrun -cases "a b" -np 1'
    with open(path, "w") as f:
        f.write("command  %s\ncheck x below 1 \"source\"\n" % command)
    spec = runTests.parseSpec(path)
    check("parseSpec: the command is kept as written (quotes included)",
          spec["command"] == command, spec["command"])


# ------------------------------------------------------------- time-outs
def testTimeout(tmp):
    def leftovers(marker):
        """Processes whose command line holds marker (a unique sleep
        length: no one else's process)."""
        out = []
        for d in os.listdir("/proc"):
            if d.isdigit():
                try:
                    with open("/proc/%s/cmdline" % d, "rb") as f:
                        cmd = f.read().replace(b"\0", b" ").decode()
                except OSError:
                    continue
                if marker in cmd and "bash" not in cmd:
                    out.append(int(d))
        return out

    t0 = time.time()
    rc, out = processTools.run(
        ["bash", "-c", "sleep 731.5 & sleep 731.5 & wait"], tmp, 2)
    time.sleep(0.5)
    check("time-out: the command is reported timed out",
          rc == processTools.TIMEOUT, "rc %s after %.1f s"
          % (rc, time.time() - t0))
    left = leftovers("731.5")
    check("time-out: the shell's background children are stopped",
          not left, "left: %s" % left)

    if shutil.which("mpirun"):
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
                   OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        rc, out = processTools.run(
            ["bash", "-c", "mpirun -np 2 --oversubscribe sleep 732.5"],
            tmp, 4, env)
        time.sleep(0.5)
        left = leftovers("732.5")
        check("time-out: mpirun and its ranks are stopped",
              rc == processTools.TIMEOUT and not left,
              "rc %s, left: %s" % (rc, left))
    else:
        check("time-out: mpirun found to test", False, "no mpirun")

    rc, out = processTools.run(["bash", "-c", "sleep 733.5 > /dev/null 2>&1 &"],
                               tmp, 10)
    time.sleep(0.5)
    left = leftovers("733.5")
    check("a background process left by a finished command is stopped",
          rc == 0 and not left, "rc %s, left: %s" % (rc, left))

    # The runner interrupted (Ctrl-C, SIGTERM) while a command runs: the
    # command's session is stopped with it, though neither signal reaches
    # that session by itself
    # (a shell that starts jobs in the background, as a CI may, hands
    # them SIGINT ignored: the child takes Ctrl-C's default back, as a
    # runner started from a terminal has it)
    runner = ("import signal, sys; sys.path.insert(0, %r); "
              "signal.signal(signal.SIGINT, signal.default_int_handler); "
              "import processTools; processTools.stopOnTerminate(); "
              "processTools.run(['bash', '-c', "
              "'sleep %%s & sleep %%s & wait'], %r, 60)" % (here, tmp))
    for sig, name, marker in ((signal.SIGINT, "Ctrl-C", "734.5"),
                              (signal.SIGTERM, "SIGTERM", "735.5")):
        r = subprocess.Popen([sys.executable, "-c",
                              runner.replace("%s", marker)],
                             stdout=subprocess.DEVNULL,
                             stderr=subprocess.DEVNULL)
        end = time.time() + 10
        while len(leftovers(marker)) < 2 and time.time() < end:
            time.sleep(0.1)
        started = len(leftovers(marker))
        r.send_signal(sig)
        try:
            r.wait(timeout=15)
        except subprocess.TimeoutExpired:
            r.kill()
        time.sleep(0.5)
        left = leftovers(marker)
        check("runner stopped by %s: the running command's processes are "
              "stopped" % name, started == 2 and not left,
              "started %d, left: %s" % (started, left))
        for pid in left:
            os.kill(pid, signal.SIGKILL)


# ------------------------------------------------------------- copies
def testCopy(tmp):
    repo = os.path.join(tmp, "repo")
    tut = os.path.join(repo, "tutorials", "demo")

    def write(rel, text):
        p = os.path.join(repo, rel)
        os.makedirs(os.path.dirname(p), exist_ok=True)
        with open(p, "w") as f:
            f.write(text)

    write(".gitignore", "/tutorials/**/[1-9]*/\nlog.*\n")
    write("tutorials/demo/Allrun", "#!/bin/sh\n")
    write("tutorials/demo/case/0/D", "tracked\n")
    git = ["git", "-C", repo, "-c", "user.name=t", "-c", "user.email=t@t"]
    r = subprocess.run(["git", "init", "-q", repo], stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT)
    r2 = subprocess.run(git + ["add", "-A"], stdout=subprocess.PIPE,
                        stderr=subprocess.STDOUT)
    r3 = subprocess.run(git + ["commit", "-q", "-m", "x"],
                        stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    if r.returncode or r2.returncode or r3.returncode:
        check("copy: a scratch git repository", False,
              (r.stdout + r2.stdout + r3.stdout).decode()[-300:])
        return
    # an earlier run's leftovers, and a tracked file edited since
    write("tutorials/demo/case/1/D", "ignored time directory\n")
    write("tutorials/demo/case/log.solver", "ignored log\n")
    write("tutorials/demo/derived/0/D", "untracked derived case\n")
    write("tutorials/demo/case/0/D", "tracked, edited\n")
    dst = os.path.join(tmp, "copy")
    log = io.StringIO()
    runTests.copySource(tut, dst, log)
    present = lambda rel: os.path.exists(os.path.join(dst, rel))
    check("copy: tracked files copied",
          present("Allrun") and present("case/0/D"))
    check("copy: a tracked file as in the working tree",
          open(os.path.join(dst, "case/0/D")).read() == "tracked, edited\n")
    check("copy: an ignored time directory and log are not copied",
          not present("case/1") and not present("case/log.solver"))
    check("copy: an untracked derived case is not copied, and is named",
          not present("derived") and "derived/0/D" in log.getvalue(),
          log.getvalue().strip())


# ------------------------------------------------------------- classify
stopMessage = """
--> FOAM FATAL ERROR: 
The step to time 1.5 did not converge after 3 cut-backs of the time step \
(last deltaT 0.0125 s, reason: Newton iterations exhausted).
The last converged time, %s, is written; check the loading, the boundary \
conditions and the solid controls in system/fvSolution

    From function int main(int, char**)
    in file largeStrainSolidFoam.C at line 143.

FOAM exiting
"""

ioError = """
--> FOAM FATAL IO ERROR: (openfoam-1912)
Entry 'E' not found in dictionary "constant/mechanicalProperties/mechanicalLaw"

file: constant/mechanicalProperties/mechanicalLaw from line 12 to line 16.

FOAM exiting
"""

field = """FoamFile { version 2.0; format ascii; class volScalarField; \
object p; }
dimensions [0 0 0 0 0 0 0];
internalField nonuniform List<scalar> 2 (%s 2);
boundaryField { }
"""


def testClassify(tmp):
    def case(name, times, value="1"):
        c = os.path.join(tmp, "classify", name)
        for t in times:
            os.makedirs(os.path.join(c, t))
            with open(os.path.join(c, t, "p"), "w") as f:
                f.write(field % value)
        return c

    cls = stressTools.classify
    for name, args, expect in [
        ("clean stop", (case("stop", ["0", "1"]), 1, stopMessage % "1",
                        3.0, []), stressTools.STOPPED),
        ("clean stop at the start time",
         (case("stop0", ["0"]), 1, stopMessage % "0", 3.0, []),
         stressTools.STOPPED),
        ("dictionary error", (case("io", ["0"]), 1, ioError, 3.0, []),
         stressTools.FAIL),
        ("stop naming a time that is not the latest",
         (case("other", ["0", "1", "1.25"]), 1, stopMessage % "1", 3.0, []),
         stressTools.FAIL),
        ("crash without a message", (case("crash", ["0", "1"]), -11,
                                     "Segmentation fault\n", 3.0, []),
         stressTools.FAIL),
        ("nan on disk", (case("nan", ["0", "3"], "nan"), 0, "End\n", 3.0,
                         []), stressTools.FAIL),
        ("complete run", (case("done", ["0", "3"]), 0, "End\n", 3.0, []),
         stressTools.CONVERGED),
        ("complete run, wrong answer", (case("wrong", ["0", "3"]), 0,
                                        "End\n", 3.0, ["off by 1"]),
         stressTools.FAIL),
        ("time-out", (case("hang", ["0", "1"]), processTools.TIMEOUT,
                      "", 3.0, []), stressTools.FAIL),
    ]:
        outcome, reason = cls(*args)
        check("classify: %s -> %s" % (name, expect), outcome == expect,
              "%s (%s)" % (outcome, reason))
    outcome, reason = cls(case("must", ["0", "1"]), 1, stopMessage % "1",
                          3.0, [], mustConverge=True)
    check("classify: a clean stop of a variant that must converge -> FAIL",
          outcome == stressTools.FAIL, "%s (%s)" % (outcome, reason))


def main():
    tmp = tempfile.mkdtemp(prefix="triboFoamSelfTest.")
    try:
        testEvaluate()
        testParseSpec(tmp)
        testTimeout(tmp)
        testCopy(tmp)
        testClassify(tmp)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    nFail = checks.count(False)
    print("%d of %d self-test checks passed" % (len(checks) - nFail,
                                                len(checks)))
    with open("results.dat", "w") as f:
        f.write("selfTestChecks %d\nselfTestFailures %d\n"
                % (len(checks), nFail))
    return 0


if __name__ == "__main__":
    sys.exit(main())
