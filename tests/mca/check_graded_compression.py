"""A graded block under uniaxial strain has the modulus of the uniform
block (issue #18, item 2): tests/mca/uniaxial_strain_uniform.prm and
uniaxial_strain_graded.prm (4 x 4 x 10 FCC cells of d, periodic in x and y,
the graded one with 2d automata in its lower and upper fifth) are
compressed alike; the fitted P-wave moduli must agree within 5e-5 and the
yield stresses within 0.5 %. Measured 2026-11-25: M 262.998 against
262.967 GPa (+0.012 %), sigma_y +0.13 %; 2026-11-30 (since the background
mesh and the moment arms of issue #48): M -8.6e-6, sigma_y +0.134 %. With the pair forces of the
transitional automata on the line of centres instead of their face
centroids the cells turn under load: M -0.65 %, sigma_y +1.0 % (fails). The graded
run's summary.json gives the automata per size and its particles their
size. Arguments: the tribodyn binary, the tests/mca folder."""
import json
import os
import subprocess
import sys
import tempfile

from check_tools import finish, report, report_relative

tribodyn, folder = sys.argv[1], sys.argv[2]
results = {}
with tempfile.TemporaryDirectory() as work:
    for kind in ("uniform", "graded"):
        prm = os.path.join(folder, f"uniaxial_strain_{kind}.prm")
        run = subprocess.run([tribodyn, prm], cwd=work, capture_output=True,
                             text=True)
        report(run.returncode == 0, f"{kind} block ran")
        out = os.path.join(work, "output", "mca", f"uniaxial_strain_{kind}")
        path = os.path.join(out, "summary.json")
        results[kind] = json.load(open(path)) if os.path.exists(path) else {}
    g = results["graded"]
    report(sum(g.get("n_automata_per_size", [])) == g.get("n_automata")
           and g.get("n_automata_per_size", [0, 0])[1] > 0,
           f"graded automata per size {g.get('n_automata_per_size')} sum to "
           f"{g.get('n_automata')}")
    vtu = os.path.join(work, "output", "mca", "uniaxial_strain_graded",
                       "particles_0000.0.vtu")
    report(os.path.exists(vtu) and 'Name="size"' in open(vtu).read(),
           "graded particles carry their size")
u = results["uniform"]
report_relative(g, u, (("youngs_modulus", 5e-5), ("yield_stress", 5e-3)))
finish()
