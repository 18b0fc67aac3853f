"""A band of 4d reaching a body's bottom face (size_band_at_face.prm) is
accepted and packs all three sizes: summary.json's n_automata_per_size
has automata of d, 2d and 4d, summing to n_automata. Before the fix the
run was refused ('the size jumps from 1d to 4d' at the body's face, where
no automata are below)."""
import json
import os
import sys

from check_tools import finish, output_directory, report

folder = output_directory(sys.argv[1])
with open(os.path.join(folder, "summary.json")) as f:
    s = json.load(f)
sizes = s.get("n_automata_per_size", [])
report(len(sizes) == 3 and all(n > 0 for n in sizes),
       "automata of d, 2d and 4d: %s" % sizes)
report(sum(sizes) == s["n_automata"],
       "they sum to n_automata (%d)" % s["n_automata"])
finish()
