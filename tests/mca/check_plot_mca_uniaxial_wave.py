#!/usr/bin/python3
"""Test of scripts/plot_mca_uniaxial and scripts/plot_mca_wave on synthetic
run directories.

    check_plot_mca_uniaxial_wave.py PATH/TO/plot_mca_uniaxial \
        PATH/TO/plot_mca_wave

The scripts run through their own #! line (Debian's matplotlib), as users
run them. Checked:
- uniaxial: a bilinear curve (E = 200 GPa up to 800 MPa, then 20 GPa) in
  interior_strain/interior_stress with a summary.json whose
  youngs_modulus = 201.234 GPa, yield_stress = 798.765 MPa: exit code 0,
  the PNG written, E and sigma_y printed equal to summary.json's to the
  printed 6 digits; the same run with series.csv holding only the group
  forces and displacements (before the interior columns): exit 0, PNG, the
  fallback named; a summary.json without youngs_modulus is refused with a
  non-zero exit and a message;
- wave: Gaussian probe velocities peaking at 40 ps and 80 ps at probes
  230 nm apart, summary.json wave_speed = 5750 m/s: exit code 0, the PNG
  written, the arrival times and the measured c_p printed equal to
  summary.json's, c_p from E, nu, rho printed equal to
  sqrt((K + 4G/3) / rho) computed here (5810.60 m/s for the steel of
  seed 000); a series.csv without probe columns is refused.
"""
import json
import math
import os
import re
import subprocess
import sys
import tempfile

from check_tools import finish, report

STEEL = {"Young modulus": 2.06e11, "Poisson ratio": 0.28, "Density": 7800,
         "Yield stress": 8e8}


def write_prm(directory, analysis):
    with open(os.path.join(directory, "parameters.prm"), "w") as f:
        f.write("set Problem = mca\nsubsection Analysis\n")
        for name, value in analysis.items():
            f.write("  set %s = %s\n" % (name, value))
        f.write("end\nsubsection Geometry\n  set Bodies = 0 0 0 1 1 1 steel\n"
                "end\nsubsection Materials\n  subsection Steel\n")
        for name, value in STEEL.items():
            f.write("    set %s = %r\n" % (name, value))
        f.write("  end\nend\n")


def write_uniaxial(directory, interior=True, E_key=True):
    os.makedirs(directory)
    area, length = 2.8e-15, 1e-7
    columns = ["time", "top_fz", "bottom_fz", "top_uz", "bottom_uz"]
    if interior:
        columns += ["interior_strain", "interior_stress", "nominal_stress",
                    "lateral_strain"]
    with open(os.path.join(directory, "series.csv"), "w") as f:
        f.write(",".join(columns) + "\n")
        for k in range(101):
            eps = 1e-2 * k / 100
            sigma = 2e11 * eps if eps < 4e-3 else 8e8 + 2e10 * (eps - 4e-3)
            force = sigma * area  # nominal = interior here
            values = [k * 1e-11, force, -force, -eps * length / 2,
                      eps * length / 2]
            if interior:
                values += [eps, sigma, 0.9 * sigma, 0.3 * eps]
            f.write(",".join(repr(v) for v in values) + "\n")
    summary = {"yield_stress": 798.765e6, "tangent_modulus": 19.5e9,
               "poisson_ratio": 0.29876, "youngs_modulus_nominal": 180e9,
               "cross_section_area": area, "gauge_length": length}
    if E_key:
        summary["youngs_modulus"] = 201.234e9
    with open(os.path.join(directory, "summary.json"), "w") as f:
        json.dump(summary, f)
    write_prm(directory, {"Type": "uniaxial", "Axis": "z",
                          "Loaded group": "top", "Support group": "bottom",
                          "Elastic fit fraction": 0.6})


def write_pulse(directory, probes=True):
    os.makedirs(directory)
    t1, t2 = 40e-12, 80e-12
    with open(os.path.join(directory, "series.csv"), "w") as f:
        f.write("time,pulse_uz" + (",probe_1_velocity,probe_2_velocity"
                                   if probes else "") + "\n")
        for k in range(121):
            t = k * 1e-12
            values = [t, 0.0]
            if probes:
                values += [math.exp(-((t - t1) / 5e-12) ** 2),
                           0.98 * math.exp(-((t - t2) / 5e-12) ** 2)]
            f.write(",".join(repr(v) for v in values) + "\n")
    with open(os.path.join(directory, "summary.json"), "w") as f:
        json.dump({"arrival_time_1": t1, "arrival_time_2": t2,
                   "wave_speed": 5750.0,
                   "p_wave_speed_reference": reference_cp()}, f)
    write_prm(directory, {"Type": "pulse", "Axis": "z",
                          "Probe 1": "1e-7", "Probe 2": "3.3e-7"})


def reference_cp():
    E, nu, rho = (STEEL[k] for k in ("Young modulus", "Poisson ratio",
                                     "Density"))
    K, G = E / (3 * (1 - 2 * nu)), E / (2 * (1 + nu))
    return math.sqrt((K + 4 * G / 3) / rho)


def close(text, expected, digits=6):
    """TEXT (a printed %.6g number) equals EXPECTED to its digits."""
    return abs(float(text) - expected) <= 0.6 * 10 ** (1 - digits) * abs(
        expected)


def run(script, *args):
    p = subprocess.run([script] + list(args), capture_output=True, text=True)
    print(p.stdout + p.stderr)
    return p


def plotted(script, directory, png, label):
    """Run SCRIPT on DIRECTORY writing PNG: exit code 0 and a PNG of more
    than 1 kB. Returns the process (its output for the caller's checks)."""
    p = run(script, directory, "--out", png)
    report(p.returncode == 0, "%s: exit code %d" % (label, p.returncode))
    report(os.path.exists(png) and os.path.getsize(png) > 1000,
           "%s: PNG written" % label)
    return p


uniaxial, wave = sys.argv[1], sys.argv[2]
with tempfile.TemporaryDirectory() as work:
    good = os.path.join(work, "uniaxial")
    write_uniaxial(good)
    p = plotted(uniaxial, good, os.path.join(work, "uniaxial.png"),
                "uniaxial")
    m = re.search(r"E = ([0-9.e+-]+) GPa, sigma_y = ([0-9.e+-]+) MPa",
                  p.stdout)
    report(m is not None and close(m.group(1), 201.234)
           and close(m.group(2), 798.765),
           "uniaxial: E = 201.234 GPa and sigma_y = 798.765 MPa of "
           "summary.json printed")

    old = os.path.join(work, "uniaxial_old")
    write_uniaxial(old, interior=False)
    p = run(uniaxial, old)
    report(p.returncode == 0
           and os.path.exists(os.path.join(old, "uniaxial.png"))
           and "nominal stress from the group forces" in p.stdout,
           "uniaxial without interior columns: the group-force fallback")

    bad = os.path.join(work, "uniaxial_bad")
    write_uniaxial(bad, E_key=False)
    p = run(uniaxial, bad)
    report(p.returncode != 0 and "no youngs_modulus" in p.stderr,
           "uniaxial: a summary.json without youngs_modulus is refused")

    pulse = os.path.join(work, "pulse")
    write_pulse(pulse)
    p = plotted(wave, pulse, os.path.join(work, "wave.png"), "wave")
    m = re.search(r"arrival times ([0-9.e+-]+) s and ([0-9.e+-]+) s, c_p "
                  r"measured = ([0-9.e+-]+) m/s", p.stdout)
    report(m is not None and close(m.group(1), 40e-12)
           and close(m.group(2), 80e-12) and close(m.group(3), 5750.0),
           "wave: arrival times 40 ps, 80 ps and c_p = 5750 m/s of "
           "summary.json printed")
    m = re.search(r"c_p from E, nu, rho = ([0-9.e+-]+) m/s", p.stdout)
    report(m is not None and close(m.group(1), reference_cp()),
           "wave: c_p from E, nu, rho = %.6g m/s printed" % reference_cp())

    bad = os.path.join(work, "pulse_bad")
    write_pulse(bad, probes=False)
    p = run(wave, bad)
    report(p.returncode != 0 and "probe_1_velocity" in p.stderr,
           "wave: a series.csv without probe velocities is refused")
finish()
