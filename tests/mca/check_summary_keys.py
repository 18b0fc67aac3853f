"""Check that an MCA run wrote summary.json with the documented keys
(n_automata, n_steps, dt, critical_dt, wall_time_s,
automaton_steps_per_second, tribodyn_version, n_mpi_ranks) and series.csv."""
import json
import os
import sys

# The run's output directory is wherever its summary.json is (the prm
# chooses it, relative to the test's working directory).
dirs = sorted(root for root, _, files in os.walk(sys.argv[1]) if "summary.json" in files)
ok = len(dirs) == 1
print(("PASS  " if ok else "FAIL  ") + "one output directory: %s" % dirs)
if ok:
    with open(os.path.join(dirs[0], "summary.json")) as f:
        s = json.load(f)
    for key in ["n_automata", "n_steps", "dt", "critical_dt", "wall_time_s",
                "automaton_steps_per_second", "tribodyn_version", "n_mpi_ranks"]:
        good = key in s
        ok = ok and good
        print(("PASS  " if good else "FAIL  ") + "summary.json has " + key)
    good = os.path.exists(os.path.join(dirs[0], "series.csv"))
    ok = ok and good
    print(("PASS  " if good else "FAIL  ") + "series.csv exists")
sys.exit(0 if ok else 1)
