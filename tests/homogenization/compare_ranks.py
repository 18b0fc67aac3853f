"""Compare the 1-rank and 2-rank application runs (tests/homogenization):
apparent stiffnesses agree to a relative 1e-10 (CG converged to 1e-12 in
both; the partition only changes the AMG hierarchy and summation order)."""
import json
import os
import sys

build = sys.argv[1]
runs = []
for name in ["homogenization_app_1rank", "homogenization_app_2ranks"]:
    with open(os.path.join(os.path.dirname(build), name, "output", "summary.json")) as f:
        runs.append(json.load(f))
check_ok = runs[1]["n_mpi_ranks"] == 2 and runs[0]["n_mpi_ranks"] == 1
print(("PASS  " if check_ok else "FAIL  ") + "rank counts 1 and 2")
worst = 0
for bc in ["KUBC", "SUBC", "periodic"]:
    a, b = runs[0][bc]["C"], runs[1][bc]["C"]
    scale = max(abs(x) for row in a for x in row)
    d = max(abs(a[i][j] - b[i][j]) for i in range(3) for j in range(3)) / scale
    worst = max(worst, d)
    print(("PASS  " if d <= 1e-10 else "FAIL  ") + "%s C, 2 ranks vs 1 rank: relative difference %.2e (tolerance 1e-10)" % (bc, d))
sys.exit(0 if check_ok and worst <= 1e-10 else 1)
