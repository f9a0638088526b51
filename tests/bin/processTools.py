# -----------------------------------------------------------------------------
# triboFoam tests: running a command with a time limit that stops everything
# it started.
#
# A test command is a shell that starts solvers, mpirun and its ranks. On a
# time-out, killing the shell alone leaves them running (and burning the
# cores the next test needs). The command is started in a session of its
# own; on a time-out every process of that session is sent SIGTERM (mpirun
# then stops its ranks), and whatever is left after a grace period SIGKILL.
# A process can leave its process group but not its session (short of
# setsid, which daemons call), so the session is what is killed. For the
# same reason the runner's own interruption (Ctrl-C, SIGTERM) does not reach
# the command: run() stops its session before passing the interruption on.
#
# License: GPL-3.0-or-later
# -----------------------------------------------------------------------------
import os
import signal
import subprocess
import time

TIMEOUT = "timeout"


def sessionProcesses(sid):
    """Process ids of the live processes of session sid (from /proc)."""
    pids = []
    for d in os.listdir("/proc"):
        if not d.isdigit():
            continue
        try:
            with open("/proc/%s/stat" % d) as f:
                stat = f.read()
        except OSError:
            continue
        # fields after the command name (which may hold spaces): state,
        # ppid, pgrp, session, ...
        rest = stat[stat.rindex(")") + 2:].split()
        if int(rest[3]) == sid and rest[0] != "Z":
            pids.append(int(d))
    return pids


def killSession(sid, grace=5.0):
    """SIGTERM to every process of session sid, SIGKILL to the rest after
    grace seconds. Returns the processes still alive (should be none)."""
    for sig, wait in ((signal.SIGTERM, grace), (signal.SIGKILL, 2.0)):
        for pid in sessionProcesses(sid):
            try:
                os.kill(pid, sig)
            except OSError:
                pass
        end = time.time() + wait
        while sessionProcesses(sid) and time.time() < end:
            time.sleep(0.1)
    return sessionProcesses(sid)


def stopOnTerminate():
    """SIGTERM raises SystemExit (status 143) in the main thread, as Ctrl-C
    raises KeyboardInterrupt, so that run() below stops the command's
    session before the runner goes: the command sits in a session of its
    own, where neither signal reaches it."""
    def terminate(signum, frame):
        raise SystemExit(128 + signum)
    signal.signal(signal.SIGTERM, terminate)


def run(args, cwd, timeout, env=None):
    """Run args (a list) in cwd, stdout and stderr together; returns
    (exit code, or TIMEOUT when the limit was hit and the session killed,
    output text). Interrupted (Ctrl-C, or SIGTERM after stopOnTerminate()),
    it stops the command's session and passes the interruption on."""
    p = subprocess.Popen(args, cwd=cwd, env=env, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, start_new_session=True)
    try:
        out, _ = p.communicate(timeout=timeout)
        rc = p.returncode
    except subprocess.TimeoutExpired:
        left = killSession(p.pid)
        out, _ = p.communicate()
        rc = TIMEOUT
        out += ("\n[timed out after %g s: every process of the command "
                "killed%s]\n" % (timeout, "" if not left else
                                 "; STILL ALIVE: %s" % left)).encode()
    except BaseException:
        killSession(p.pid, grace=2.0)
        raise
    # leftovers of a command that ended by itself (a solver sent to the
    # background and never waited for) are stopped too
    killSession(p.pid, grace=1.0)
    return rc, out.decode(errors="replace")
