#!/usr/bin/python3
"""Benchmarks of the explicit contact solver (issue #3); not part of ctest.

    python3 bench/contact/run.py throughput  --tribodyn build/tribodyn [--ranks 1,2]
    python3 bench/contact/run.py convergence --tribodyn build/tribodyn [--ranks 1]

throughput: DoF-steps per second (per rank) of the pin (matrix material,
  regularized friction, P = 0.5 MPa, default sample interval 20, no field
  output): small strain at h = 0.1 mm (45 522 DoFs) and h = 0.02 mm
  (1 123 602 DoFs), large deformation at h = 0.1 mm; from summary.json (time
  loop only, setup excluded).
convergence: run time against error for the elastic bar hitting the rigid
  plane (tests/contact/bar_impact.cc set-up: nu = 0, 1 mm x 8 mm, v0 = 1
  m/s, frictionless, no damping) as h and dt are refined. Errors of the
  plateau contact force (mean over [0.2, 0.8] 2L/c against rho c v0 W), of
  the contact duration (against 2L/c) and of the rebound velocity (against
  v0).
Outputs go to bench-output/contact/.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import time

OUT = os.path.join("bench-output", "contact")
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
           OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")


def run(tribodyn, ranks, name, text):
    directory = os.path.join(OUT, name)
    os.makedirs(directory, exist_ok=True)
    prm = os.path.join(directory, "run.prm")
    with open(prm, "w") as f:
        f.write("set Problem = contact\nset Output directory = %s\n"
                "set Progress interval = 60\n%s\n" % (directory, text))
    command = ([tribodyn, prm] if ranks == 1 else
               ["mpirun", "-np", str(ranks), tribodyn, prm])
    start = time.time()
    result = subprocess.run(command, env=ENV, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    wall = time.time() - start
    if result.returncode != 0:
        sys.exit("run %s failed:\n%s" % (name, result.stdout))
    with open(os.path.join(directory, "summary.json")) as f:
        return json.load(f), wall, directory


def throughput(args):
    print("| kinematics | h (mm) | DoFs | ranks | steps | time loop (s) | DoF-steps/s | per rank |")
    print("|---|---|---|---|---|---|---|---|")
    for kinematics, h, dt, end in [("small strain", 0.1e-3, 5e-9, 50e-6),
                                   ("small strain", 0.02e-3, 2e-9, 2e-6),
                                   ("large deformation", 0.1e-3, 5e-9, 20e-6)]:
        for ranks in [int(r) for r in args.ranks.split(",")]:
            s, _, _ = run(args.tribodyn, ranks, "throughput_%s_h%g_np%d" % (
                kinematics.replace(" ", "_"), h, ranks), """
subsection Geometry
  set Mesh size = %g
end
subsection Materials
  set Kinematics = %s
end
subsection Time
  set Time step = %g
  set End time = %g
end
subsection Output
  set Averaging start time = 0
  set Field interval = 0
end""" % (h, kinematics, dt, end))
            print("| %s | %g | %d | %d | %d | %.2f | %.3g | %.3g |" % (
                kinematics, h * 1e3, s["n_dofs"], ranks, s["n_steps"], s["time_loop_s"],
                s["dof_steps_per_second"], s["dof_steps_per_second_per_rank"]))
            sys.stdout.flush()


def convergence(args):
    E, rho, v0, L, W = 30e9, 1770., 1., 8e-3, 1e-3
    c = math.sqrt(E / rho)
    duration, force = 2 * L / c, rho * c * v0 * W
    mass = rho * L * W
    print("| h (mm) | dt (ns) | DoFs | steps | wall (s) | plateau force error | "
          "duration error | rebound error |")
    print("|---|---|---|---|---|---|---|---|")
    for h, dt in [(0.2e-3, 40e-9), (0.1e-3, 20e-9), (0.1e-3, 10e-9),
                  (0.05e-3, 10e-9), (0.05e-3, 5e-9), (0.025e-3, 5e-9),
                  (0.025e-3, 2.5e-9), (0.0125e-3, 1.25e-9)]:
        s, wall, d = run(args.tribodyn, int(args.ranks.split(",")[0]),
                         "bar_h%g_dt%g" % (h, dt), """
subsection Geometry
  set Width = 1e-3
  set Height = 8e-3
  set Mesh size = %g
end
subsection Materials
  subsection Matrix
    set Young modulus = 30e9
    set Poisson ratio = 0
    set Density = 1770
  end
end
subsection Loading
  set Pressure = 0
  set Top face held in x = false
  set Sliding velocity = 0
  set Initial velocity = 0, -1
end
subsection Time
  set Time step = %g
  set End time = 6e-6
  set Damping coefficient = 0
end
subsection Contact
  set Friction law = frictionless
end
subsection Output
  set Sample interval = 1
  set Averaging start time = 0
  set Field interval = 0
end""" % (h, dt))
        with open(os.path.join(d, "friction.csv")) as f:
            rows = list(csv.DictReader(f))
        plateau = [float(r["contact_normal_force"]) for r in rows
                   if 0.2 * duration < float(r["time"]) < 0.8 * duration]
        last = max(float(r["time"]) + dt for r in rows
                   if float(r["contact_normal_force"]) > 0)
        rebound = float(rows[-1]["momentum_y"]) / mass
        print("| %g | %g | %d | %d | %.2f | %.2e | %.2e | %.2e |" % (
            h * 1e3, dt * 1e9, s["n_dofs"], s["n_steps"], s["wall_time_s"],
            abs(sum(plateau) / len(plateau) / force - 1), abs(last / duration - 1),
            abs(rebound / v0 - 1)))
        sys.stdout.flush()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("what", choices=["throughput", "convergence"])
    parser.add_argument("--tribodyn", default="build/tribodyn")
    parser.add_argument("--ranks", default="1,2")
    args = parser.parse_args()
    os.makedirs(OUT, exist_ok=True)
    {"throughput": throughput, "convergence": convergence}[args.what](args)


if __name__ == "__main__":
    main()
