"""A band of 4d reaching a body's bottom face (size_band_at_face.prm) is
accepted, packs each size where its band is, and the graded lattice is at
rest.

Counted from the layout, not from the code: an FCC cell of edge a holds 4
automata; the block is 3 cells of 4d (a4 = 4 d sqrt 2) across in x and y
(periodic) and 3 tall. One cell layer of 4d: 3 x 3 x 4 = 36 automata; one
a4 of 2d (cells of a4 / 2): 6 x 6 x 4 x 2 = 288; one a4 of d (cells of
a4 / 4): 12 x 12 x 4 x 4 = 2304. A band placed half a cell off changes the
counts by whole half-layers (72 of 2d); shown failing with the 4d band
ending at 0.006 instead of a4 (the prm before 2026-12-01): [2304, 216, 36].

At rest: the automata of the three sizes touch at their contact distances
(r_i + r_j) across the transitions, so the block holds no elastic energy
and gains no kinetic energy over its 30 steps: both exactly 0 (measured 0
and 0; a transition packed at the wrong distance would load its pairs at
the first step). Tolerance 0: a rounding error in one pair distance gives
a nonzero energy, which this block's exact lattice does not have."""
import json
import os
import sys

from check_tools import finish, output_directory, report

folder = output_directory(sys.argv[1])
with open(os.path.join(folder, "summary.json")) as f:
    s = json.load(f)
expected = [12 * 12 * 4 * 4, 6 * 6 * 4 * 2, 3 * 3 * 4 * 1]
sizes = s.get("n_automata_per_size", [])
report(sizes == expected,
       "automata of d, 2d, 4d: %s; counted from the layout %s" % (sizes, expected))
report(s["n_automata"] == sum(expected),
       "n_automata %d = %d" % (s["n_automata"], sum(expected)))
report(s["n_steps"] >= 30, "%d steps (at least 30)" % s["n_steps"])
report(s["kinetic_energy"] == 0 and s["elastic_energy"] == 0,
       "the graded block stays at rest: kinetic %g J, elastic %g J (exactly 0)"
       % (s["kinetic_energy"], s["elastic_energy"]))
finish()
