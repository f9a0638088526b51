#!/usr/bin/env python3
# -----------------------------------------------------------------------------
# triboFoam test runner (called by tests/Alltest, which sources etc/bashrc).
#
# Discovers tests in tests/<group>/<name>/:
#   unit test : Make/files present. Built with wmake, the executable named
#               in Make/files is run in the folder; passes when it exits 0.
#   case test : a file 'spec' (see tests/README.md) naming a tutorial or
#               the folder itself, a command, a results file and checks.
#
# License: GPL-3.0-or-later
# -----------------------------------------------------------------------------
import argparse
import math
import os
import re
import shlex
import shutil
import subprocess
import sys
import time

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "bin", "python"))
sys.path.insert(0, here)
import foamio  # noqa: E402
import processTools  # noqa: E402

projectDir = os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__))))
testsDir = os.path.join(projectDir, "tests")
resultsDir = os.path.join(testsDir, "results")
groups = ["unit", "cases", "stress"]


def discover(groupFilter, testFilter):
    found = []
    for group in groups:
        if groupFilter and group != groupFilter:
            continue
        gdir = os.path.join(testsDir, group)
        if not os.path.isdir(gdir):
            continue
        for name in sorted(os.listdir(gdir)):
            tdir = os.path.join(gdir, name)
            if testFilter and name != testFilter:
                continue
            if os.path.isfile(os.path.join(tdir, "Make", "files")):
                found.append(("unit", group, name, tdir))
            elif os.path.isfile(os.path.join(tdir, "spec")):
                found.append(("case", group, name, tdir))
    return found


def exeFromMakeFiles(tdir):
    with open(os.path.join(tdir, "Make", "files")) as f:
        for line in f:
            m = re.match(r"\s*EXE\s*=\s*(\S+)", line)
            if m:
                return os.path.expandvars(m.group(1).replace("$(", "${")
                                          .replace(")", "}"))
    return None


def runUnit(name, tdir, log):
    exe = exeFromMakeFiles(tdir)
    if exe is None:
        return False, "no EXE in Make/files"
    b = subprocess.run(["wmake", "-s"], cwd=tdir, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True)
    log.write(b.stdout)
    if b.returncode != 0 or not os.path.isfile(exe):
        return False, "build failed:\n" + b.stdout[-3000:]
    rc, out = processTools.run([exe], tdir, 1800)
    log.write(out)
    lines = [l for l in out.splitlines()
             if l.strip().startswith(("ok ", "FAILED", "FOAM FATAL"))
             or "checks passed" in l]
    if rc == processTools.TIMEOUT:
        lines.append("timed out after 1800 s")
    return rc == 0, "\n".join(lines)


class SpecError(Exception):
    pass


def parseSpec(path):
    spec = {"checks": [], "timeout": 1800, "results": "results.dat"}
    with open(path) as f:
        for lineno, raw in enumerate(f, 1):
            line = raw.strip()
            if not line or line.startswith("#"):
                continue
            words = shlex.split(line)
            key = words[0]
            if key == "check":
                # check <quantity> below|above <bound> "<source>"
                # check <quantity> near <expected> <tol> rel|abs "<source>"
                if len(words) >= 5 and words[2] in ("below", "above"):
                    spec["checks"].append(dict(
                        q=words[1], op=words[2], value=float(words[3]),
                        source=" ".join(words[4:])))
                elif len(words) >= 7 and words[2] == "near" \
                        and words[5] in ("rel", "abs"):
                    spec["checks"].append(dict(
                        q=words[1], op="near", value=float(words[3]),
                        tol=float(words[4]), kind=words[5],
                        source=" ".join(words[6:])))
                else:
                    raise SpecError("%s:%d: expected 'check <quantity> "
                                    "below|above <bound> <source>' or "
                                    "'check <quantity> near <value> <tol> "
                                    "rel|abs <source>'" % (path, lineno))
            elif key == "command":
                # the rest of the line as written: bash reads its quotes
                spec[key] = line[len(key):].strip()
            elif key in ("tutorial", "results", "timeout"):
                spec[key] = words[1]
            else:
                raise SpecError("%s:%d: unknown keyword '%s' (expected "
                                "tutorial, command, results, timeout or "
                                "check)" % (path, lineno, key))
    if "command" not in spec:
        raise SpecError("%s: keyword 'command' missing" % path)
    if not spec["checks"]:
        raise SpecError("%s: no 'check' line: a test must assert something"
                        % path)
    return spec


readResults = foamio.readResults


def evaluate(check, values):
    q = check["q"]
    if q not in values:
        return False, "FAILED  %s: not in the results file" % q
    got = values[q]
    # nan and inf are never an answer: they fail every check
    ok = math.isfinite(got)
    if check["op"] == "below":
        ok = ok and got <= check["value"]
        text = "%s: got %.6g, expected <= %.6g" % (q, got, check["value"])
    elif check["op"] == "above":
        ok = ok and got >= check["value"]
        text = "%s: got %.6g, expected >= %.6g" % (q, got, check["value"])
    else:
        tol = check["tol"] * (abs(check["value"]) if check["kind"] == "rel"
                              else 1.0)
        ok = ok and abs(got - check["value"]) <= tol
        text = "%s: expected %.6g, got %.6g, tolerance %g %s" % (
            q, check["value"], got, check["tol"], check["kind"])
    return ok, ("ok      " if ok else "FAILED  ") + text \
        + "  [" + check["source"] + "]"


def gitFiles(src, which):
    """Files under src that git tracks (which 'tracked') or that are
    untracked and not ignored ('untracked'), relative to src; None when src
    is not in a git checkout."""
    args = ["git", "-C", src, "ls-files", "-z", "--full-name"]
    if which == "untracked":
        args += ["--others", "--exclude-standard"]
    r = subprocess.run(args + ["--", "."], stdout=subprocess.PIPE,
                       stderr=subprocess.DEVNULL)
    top = subprocess.run(["git", "-C", src, "rev-parse", "--show-toplevel"],
                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                         text=True)
    if r.returncode != 0 or top.returncode != 0:
        return None
    root = top.stdout.strip()
    rel = os.path.relpath(os.path.realpath(src), os.path.realpath(root))
    prefix = "" if rel == "." else rel + "/"
    return [f[len(prefix):] for f in r.stdout.decode().split("\0")
            if f.startswith(prefix)]


def copySource(src, dst, log, skip=()):
    """Copy what git tracks of src to dst (merged into dst), the files as
    they are in the working tree: run products left in src by an earlier
    run (time directories, logs, derived cases that Allclean does not know)
    must not reach the test. Untracked files that git does not ignore are
    listed in the log and skipped ('git add' a new file to test it).
    Outside a git checkout: the whole folder, then its Allclean."""
    tracked = gitFiles(src, "tracked")
    if tracked is None:
        shutil.copytree(src, dst, symlinks=True, dirs_exist_ok=True,
                        ignore=lambda d, names: [n for n in names
                                                 if n in skip])
        if os.path.isfile(os.path.join(dst, "Allclean")):
            subprocess.run(["bash", "./Allclean"], cwd=dst,
                           stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL)
        return
    os.makedirs(dst, exist_ok=True)
    for f in tracked:
        s = os.path.join(src, f)
        if f in skip or not os.path.lexists(s):
            continue            # deleted in the working tree
        d = os.path.join(dst, f)
        os.makedirs(os.path.dirname(d), exist_ok=True)
        shutil.copy2(s, d, follow_symlinks=False)
    untracked = [f for f in gitFiles(src, "untracked") or [] if f not in skip]
    if untracked:
        log.write("runTests: %d untracked file(s) of %s not copied: %s\n"
                  % (len(untracked), src, " ".join(untracked[:20])))


def runCase(name, group, tdir, log):
    spec = parseSpec(os.path.join(tdir, "spec"))
    work = os.path.join(resultsDir, group, name)
    shutil.rmtree(work, ignore_errors=True)
    src = os.path.join(projectDir, "tutorials", spec["tutorial"]) \
        if "tutorial" in spec else tdir
    if not os.path.isdir(src):
        raise SpecError("%s/spec: tutorial folder '%s' not found"
                        % (tdir, src))
    copySource(src, work, log, skip=("spec",))
    if "tutorial" in spec:
        # the test folder's own files (scripts, dictionaries) come on top
        copySource(tdir, work, log, skip=("spec",))
    env = dict(os.environ, TRIBOFOAM_TEST="1")
    rc, out = processTools.run(["bash", "-c", spec["command"]], work,
                               float(spec["timeout"]), env)
    log.write(out)
    if rc == processTools.TIMEOUT:
        return False, "timed out after %s s (every process of the " \
            "command killed)" % spec["timeout"]
    lines = []
    ok = True
    if rc != 0:
        ok = False
        lines.append("command '%s' exited with %d:\n%s" % (
            spec["command"], rc, out[-3000:]))
    resPath = os.path.join(work, spec["results"])
    if not os.path.isfile(resPath):
        return False, "\n".join(lines + ["no results file %s" % resPath])
    values = readResults(resPath)
    for c in spec["checks"]:
        cok, text = evaluate(c, values)
        ok = ok and cok
        lines.append(text)
    return ok, "\n".join(lines)


def main():
    p = argparse.ArgumentParser(description="triboFoam test suite")
    p.add_argument("-group", choices=groups)
    p.add_argument("-test", help="run only the test of this name")
    p.add_argument("-list", action="store_true", help="list the tests")
    p.add_argument("-no-build", action="store_true",
                   help="(handled by Alltest) do not run ./Allwmake first")
    args = p.parse_args()

    tests = discover(args.group, args.test)
    if args.list:
        for kind, group, name, tdir in tests:
            print("%-6s %-5s %s" % (group, kind, name))
        return 0
    if args.test and not tests:
        print("Alltest: no test named '%s'" % args.test)
        print("0 passed, 1 failed")
        return 1

    os.makedirs(resultsDir, exist_ok=True)
    processTools.stopOnTerminate()
    nPass = nFail = 0
    failed = []
    for kind, group, name, tdir in tests:
        print("%s/%s (%s test)" % (group, name, kind), flush=True)
        t0 = time.time()
        logPath = os.path.join(resultsDir, "log.%s.%s" % (group, name))
        with open(logPath, "w") as log:
            try:
                ok, text = (runUnit if kind == "unit" else
                            lambda n, d, l: runCase(n, group, d, l))(
                                name, tdir, log)
            except (SpecError, OSError, ValueError,
                    subprocess.TimeoutExpired) as e:
                ok, text = False, "error: %s" % e
        for line in text.splitlines():
            print("    " + line)
        print("    %s in %.1f s (log: %s)" % (
            "PASSED" if ok else "FAILED", time.time() - t0,
            os.path.relpath(logPath, projectDir)), flush=True)
        if ok:
            nPass += 1
        else:
            nFail += 1
            failed.append("%s/%s" % (group, name))
    if failed:
        print("failed: " + " ".join(failed))
    print("%d passed, %d failed" % (nPass, nFail))
    return 0 if nFail == 0 and nPass > 0 else 1


if __name__ == "__main__":
    try:
        sys.exit(main())
    except KeyboardInterrupt:
        # the running test's processes are stopped (processTools.run)
        print("\nAlltest: interrupted; the running test's processes stopped")
        sys.exit(130)
