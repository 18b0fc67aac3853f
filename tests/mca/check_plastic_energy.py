"""Energy balance with plastic flow (issue #8 item 6, issue #17 item 7):
simple shear of a bonded steel slab, tests/mca/plastic_shear_energy.prm.

    check_plastic_energy.py DIR                  one run
    check_plastic_energy.py --pair SHORT TALL    the slab and its double

Each run: the integrator's bookkeeping identity (kinetic = pair work + load
work - damped, round-off only: 1e-9 of the load work); that the loads drove
the slab far into the plastic range (plastic work > half the load work, so
a missing or doubled plastic term is a residual of the order of the load
work); and the balance kinetic + elastic + plastic + switching + many-body
work = load work (no contacts, no damping, no friction here) within
TOLERANCES of the load work (below). The plastic work is what the pair sides release at their
plastic returns (doc/theory/mca.md §8.4): measured -0.008 % (slab) and
-0.017 % (twice as tall) on 2026-11-27, where the homogenized bookkeeping
of before left -3.7 % and -1.8 %, a term of the held faces' half-empty
neighbourhoods. The pair: the same for the two slabs, whose faces are the
same and whose bulk doubles: the faces' many-body work (the part of the
many-body law that is not conservative where the weights are not equal
shares) must stay within 0.1 % of the load work in both.

The physical balance (doc/theory/mca.md §8.4, "What the balance checks"):
the same with the automata's J2 dissipation by the flow rule, sum V
(sigma_y + sigma_y')/2 d eps_p over the share of it their sides hold, in
place of what the sides release; it fails on a radial return that does not
dissipate what the flow rule says, which the balance above cannot see
(tolerance and measurements: check_tools.PHYSICAL_TOLERANCE).
"""
import json
import os
import sys

from check_tools import (BOOKED_TOLERANCE, PHYSICAL_TOLERANCE, energy_stored,
                         energy_terms, finish, output_directory,
                         physical_residual, report)

# the balance's tolerance per run (issue #49: within 10x of the measured
# residual, 2026-11-30: slab -8.2e-5, twice as tall -1.66e-4); a run not
# listed: 0.1 % (the many-body work of the faces, too)
TOLERANCES = {"mca_plastic_energy": BOOKED_TOLERANCE["plastic"],
              "mca_plastic_energy_tall": 1e-3}
TOLERANCE = 0.001


def tolerance(directory):
    return TOLERANCES.get(os.path.basename(os.path.normpath(directory)),
                          TOLERANCE)


def load(directory):
    with open(os.path.join(output_directory(directory), "summary.json")) as f:
        return json.load(f)


def residual(s):
    return (s["load_work"] - energy_stored(s)) / s["load_work"]


def check_run(label, s, balance_tolerance):
    W = s["load_work"]
    report(W > 0, "%s: the loads did work: %.6g J" % (label, W))
    identity = s["kinetic_energy"] - (s["pair_work"] + W - s["damped_work"])
    report(abs(identity) <= 1e-9 * abs(W),
           "%s: kinetic = pair work + load work - damped: residual %.3g of "
           "the load work (tolerance 1e-9)" % (label, identity / W))
    share = s["plastic_work"] / W
    report(share > 0.5, "%s: plastic work %.3g of the load work (> 0.5)"
           % (label, share))
    print("      %s: %s" % (label, energy_terms(s)))
    report(abs(residual(s)) <= balance_tolerance,
           "%s: energy balance, residual %+.4f %% of the load work "
           "(tolerance %g %%)" % (label, 100 * residual(s),
                                  100 * balance_tolerance))
    # the same with the flow rule's plastic work in place of what the sides
    # release: catches a radial return that does not dissipate what the
    # flow rule says (check_tools.PHYSICAL_TOLERANCE)
    physical = physical_residual(s)
    report(abs(physical) <= PHYSICAL_TOLERANCE["plastic"],
           "%s: physical energy balance (the flow rule's plastic work "
           "%.6g J against %.6g J released), residual %+.4f %% of the load "
           "work (tolerance %g %%)"
           % (label, s["plastic_work_flow_rule"], s["plastic_work"],
              100 * physical, 100 * PHYSICAL_TOLERANCE["plastic"]))


if sys.argv[1] == "--pair":
    short, tall = load(sys.argv[2]), load(sys.argv[3])
    check_run("slab", short, tolerance(sys.argv[2]))
    check_run("double slab", tall, tolerance(sys.argv[3]))
    for label, s in (("slab", short), ("double slab", tall)):
        mb = s["many_body_work"] / s["load_work"]
        report(abs(mb) <= TOLERANCE,
               "%s: many-body work %+.4f %% of the load work (tolerance "
               "%g %%)" % (label, 100 * mb, 100 * TOLERANCE))
else:
    check_run("slab", load(sys.argv[1]), tolerance(sys.argv[1]))
finish()
