#!/usr/bin/env python3
# -----------------------------------------------------------------------------
# triboFoam benchmarks: one PNG per tests/benchmarks/results/<name>.dat,
# error against wall time on log-log axes, one curve per sweep, with gnuplot.
# The .dat files are written by the benchmarks (benchTools.Report):
#   # title: ...    # ylabel: ...    # sweep: <label>   then 'wall error'
#   rows, blocks separated by two blank lines.
#
#   plot.py [name ...]     (default: every .dat in results/)
#
# License: GPL-3.0-or-later
# -----------------------------------------------------------------------------
import glob
import math
import os
import shutil
import subprocess
import sys

resultsDir = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                          "results")


def read(path):
    title, ylabel, sweeps = "", "error", []
    for line in open(path):
        if line.startswith("# title:"):
            title = line.split(":", 1)[1].strip()
        elif line.startswith("# ylabel:"):
            ylabel = line.split(":", 1)[1].strip()
        elif line.startswith("# sweep:"):
            sweeps.append((line.split(":", 1)[1].strip(), []))
        elif line.strip() and sweeps:
            x, y = line.split()[:2]
            sweeps[-1][1].append((float(x), float(y)))
    return title, ylabel, sweeps


def quote(s):
    return '"%s"' % s.replace('"', "'")


def plot(name):
    title, ylabel, sweeps = read(os.path.join(resultsDir, name + ".dat"))
    png = os.path.join(resultsDir, name + ".png")
    ys = [y for _, pts in sweeps for _, y in pts]
    lines = [
        "set terminal pngcairo size 1000,700 noenhanced font ',10'",
        "set output %s" % quote(png),
        "set title %s" % quote(title),
        "set xlabel 'wall time [s]'",
        "set ylabel %s" % quote(ylabel),
        "set logscale xy",
        "set format y '%.0e'",
        # the 1 % line always in view
        "set yrange [%g:%g]" % (10**math.floor(math.log10(min(ys + [0.01]))),
                                10**math.ceil(math.log10(max(ys + [0.02])))),
        "set grid xtics ytics mxtics mytics lc rgb '#dddddd'",
        "set key outside below",
        "set arrow from graph 0, first 0.01 to graph 1, first 0.01 nohead "
        "dt 2 lc rgb '#888888'",
        "set label '1 %' at graph 0.01, first 0.0115 tc rgb '#888888'",
    ]
    parts = ["'-' using 1:2 with linespoints lw 2 pt %d title %s"
             % (7 + i % 6, quote(label)) for i, (label, _) in enumerate(sweeps)]
    lines.append("plot " + ", ".join(parts))
    for _, pts in sweeps:
        lines += ["%.6g %.6g" % p for p in pts] + ["e"]
    subprocess.run(["gnuplot"], input="\n".join(lines) + "\n", text=True,
                   check=True)
    print("wrote %s" % os.path.relpath(png))


def main():
    if shutil.which("gnuplot") is None:
        sys.exit("plot.py: gnuplot not found (apt-get install gnuplot-nox)")
    names = sys.argv[1:] or sorted(
        os.path.basename(p)[:-4]
        for p in glob.glob(os.path.join(resultsDir, "*.dat")))
    for n in names:
        plot(n)


if __name__ == "__main__":
    main()
