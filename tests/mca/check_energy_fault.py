"""The physical energy balance catches a wrong stress update (issue #49
item 5; doc/theory/mca.md Sec. 8.4, "What the balance checks").

DIR is the output of tests/mca/faulted_run.cc (tribodyn with a fault
injected into one update, TRIBODYN_FAULT) on a scene whose balances the
tests mca_plastic_energy or mca_friction_energy check: the radial return's
M 0.1 % low on the plastic slab, the Coulomb limit 10 % low on the elastic
friction scene. The booked balance, whose events book what they release,
still closes within its own test's tolerance: it cannot see the fault. The
physical one, with the dissipation the laws prescribe, must exceed its
tolerance (check_tools.PHYSICAL_TOLERANCE): this test fails if it does not.
Measured (2026-11-30): the return -0.135 of the load work (tolerance 5e-3;
correct -1.8e-3), the limit +0.027 (tolerance 1.5e-2; correct -6.8e-3).
"""
import json
import os
import sys

from check_tools import (BOOKED_TOLERANCE, PHYSICAL_TOLERANCE, energy_stored,
                         finish, output_directory, physical_residual, report)

out = output_directory(sys.argv[1])
with open(os.path.join(out, "summary.json")) as f:
    s = json.load(f)
kind = "plastic" if "plastic" in os.path.basename(
    os.path.normpath(sys.argv[1])) else "friction"
booked_tolerance = BOOKED_TOLERANCE[kind]
W = s["load_work"]
booked = (energy_stored(s) - W) / W
report(abs(booked) <= booked_tolerance,
       "booked energy balance still closes with the fault: residual %.3g "
       "of the load work (tolerance %g)" % (booked, booked_tolerance))
physical = physical_residual(s)
report(abs(physical) > PHYSICAL_TOLERANCE[kind],
       "physical energy balance catches the fault: residual %.3g of the "
       "load work (beyond its tolerance %g)"
       % (physical, PHYSICAL_TOLERANCE[kind]))
finish()
