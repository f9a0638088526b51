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
import os
import re
import shlex
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "bin", "python"))
import foamio  # noqa: E402

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
    r = subprocess.run([exe], cwd=tdir, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True, timeout=1800)
    log.write(r.stdout)
    lines = [l for l in r.stdout.splitlines()
             if l.strip().startswith(("ok ", "FAILED", "FOAM FATAL"))
             or "checks passed" in l]
    return r.returncode == 0, "\n".join(lines)


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
            elif key in ("tutorial", "command", "results", "timeout"):
                spec[key] = " ".join(words[1:]) if key == "command" \
                    else words[1]
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
    ok = got == got  # not NaN
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


def runCase(name, group, tdir, log):
    spec = parseSpec(os.path.join(tdir, "spec"))
    work = os.path.join(resultsDir, group, name)
    shutil.rmtree(work, ignore_errors=True)
    src = os.path.join(projectDir, "tutorials", spec["tutorial"]) \
        if "tutorial" in spec else tdir
    if not os.path.isdir(src):
        raise SpecError("%s/spec: tutorial folder '%s' not found"
                        % (tdir, src))
    shutil.copytree(src, work, symlinks=True)
    if os.path.isfile(os.path.join(work, "Allclean")):
        # start from a clean tutorial, whatever was run in the source tree
        subprocess.run(["bash", "./Allclean"], cwd=work,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    if "tutorial" in spec:
        # the test folder's own files (scripts, dictionaries) come on top
        for f in os.listdir(tdir):
            if f != "spec":
                s = os.path.join(tdir, f)
                d = os.path.join(work, f)
                if os.path.isdir(s):
                    shutil.copytree(s, d, symlinks=True, dirs_exist_ok=True)
                else:
                    shutil.copy2(s, d)
    env = dict(os.environ, TRIBOFOAM_TEST="1")
    try:
        r = subprocess.run(["bash", "-c", spec["command"]], cwd=work,
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           text=True, timeout=float(spec["timeout"]), env=env)
    except subprocess.TimeoutExpired:
        return False, "timed out after %s s" % spec["timeout"]
    log.write(r.stdout)
    lines = []
    ok = True
    if r.returncode != 0:
        ok = False
        lines.append("command '%s' exited with %d:\n%s" % (
            spec["command"], r.returncode, r.stdout[-3000:]))
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
    sys.exit(main())
