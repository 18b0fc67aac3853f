#!/usr/bin/python3
"""Test of scripts/plot_mca_seeds on a synthetic seeds.csv.

    check_plot_mca_seeds.py PATH/TO/plot_mca_seeds

The script runs through its own #! line (Debian's matplotlib), as the study
script runs it. Three seeds with relative differences -4 %, -6 %, -2 %:
mean -4 %, standard error of the mean sqrt(((0)^2 + 2^2 + 2^2) / 2 / 3)
= 1.1547 %. Checked: exit code 0, seeds.png written (non-empty), the mean
and its error printed to the printed precision; a single seed (axes
padded around it, seen on the PNG when the script was changed) is drawn
with exit code 0 and no mean printed (it needs two seeds); --help exits
with 0 and describes the input; a file without rows is refused with a
non-zero exit and a message.
"""
import os
import re
import subprocess
import sys
import tempfile

from check_tools import finish, report

script = sys.argv[1]

header = ("seed,steel_mu_steady,steel_mu_steady_stderr,"
          "steel_quasi_fluid_layer_thickness,composite_mu_steady,"
          "composite_mu_steady_stderr,composite_quasi_fluid_layer_thickness,"
          "relative_difference,relative_difference_stderr\n")
with tempfile.TemporaryDirectory() as work:
    path = os.path.join(work, "seeds.csv")
    with open(path, "w") as f:
        f.write(header)
        for seed, steel, diff in ((1, 0.50, -0.04), (2, 0.45, -0.06),
                                  (3, 0.55, -0.02)):
            f.write("%d,%r,0.005,2.2e-08,%r,0.005,2.4e-08,%r,0.015\n"
                    % (seed, steel, steel * (1 + diff), diff))
    run = subprocess.run([script, path], capture_output=True, text=True)
    report(run.returncode == 0, "exit code %d" % run.returncode)
    png = os.path.join(work, "seeds.png")
    report(os.path.exists(png) and os.path.getsize(png) > 0,
           "seeds.png written")
    match = re.search(r"over 3 seeds ([-+0-9.]+) % \+- ([0-9.]+) %",
                      run.stdout)
    report(match is not None and abs(float(match.group(1)) + 4) < 0.005
           and abs(float(match.group(2)) - 1.1547) < 0.005,
           "mean -4.00 %% +- 1.15 %% printed: %s" % run.stdout.strip())
    one = os.path.join(work, "one", "seeds.csv")
    os.makedirs(os.path.dirname(one))
    with open(one, "w") as f:
        f.write(header)
        f.write("1,0.485,0.024,2.2e-08,0.491,0.024,2.4e-08,0.013,0.011\n")
    run = subprocess.run([script, one], capture_output=True, text=True)
    png = os.path.join(work, "one", "seeds.png")
    report(run.returncode == 0 and os.path.exists(png)
           and "mean relative difference" not in run.stdout,
           "one seed: exit code %d, seeds.png written, no mean printed"
           % run.returncode)
    run = subprocess.run([script, "--help"], capture_output=True, text=True)
    report(run.returncode == 0 and "seeds_COMPARE.csv" in run.stdout
           and "relative_difference" in run.stdout
           and "--reference" in run.stdout,
           "--help exits with 0 and describes the study's seeds_COMPARE.csv "
           "and its options (exit code %d)"
           % run.returncode)
    empty = os.path.join(work, "empty.csv")
    with open(empty, "w") as f:
        f.write(header)
    run = subprocess.run([script, empty], capture_output=True, text=True)
    report(run.returncode != 0 and "no rows" in run.stderr,
           "a file without rows is refused: %s" % run.stderr.strip())
finish()
