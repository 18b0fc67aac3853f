"""The step limit of the stiffest automaton (issue #47; doc/stability.md,
"The step limit at changes of size and material"). Each automaton's highest
frequency against fixed neighbours (its springs and relative-rotation
moments over its mass and moment of inertia) is held at or below that of an
automaton in the uniform lattice at Courant 0.5; summary.json's
courant_limit is the Courant factor that does it, and a larger step is
refused naming the parameter.

Checked against the runs that measured where the graded scenes are stable
(doc/performance.md, "The time step at the seed's heights"):
- a uniform lattice of one material, and the laptop composite (steel with
  carbon cylinders), whose stiffest automaton is a carbon one bonded to steel
  but at 0.5 d/c_p,max (set by the carbon) below the steel lattice's level:
  limit 0.5, as the runs at 0.5 found stable (the lever studies, 16 ns each);
- the graded seed-heights steel scene (band 'interface 8 16'): at 0.5 it
  left its mirrored state after 3.5 ns and ejected an automaton at 5.1 ns; at
  0.42 it stayed mirrored to 7 ns, and at 0.47 to 10 ns. Its limit must lie
  in [0.42, 0.5): 0.5 refused (exit 2, naming 'Time/Courant factor', a
  given 'Time/Time step' above it likewise), the limit itself accepted;
- the same scene without the relative-rotation moments
  (Interaction/Relative rotation stiffness = 0), which stayed mirrored at
  0.5 to 5 ns: limit 0.5 (the moments are what the changes of size make
  stiffer; shown failing with the moments counted in the lattice but not in
  the automata: the graded limit became 0.5).
Arguments: the tribodyn binary, the prm/mca folder, a scratch directory."""
import json
import os
import re
import subprocess
import sys

from check_tools import finish, report

tribodyn, folder, scratch = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(scratch, exist_ok=True)


def run(name, scene, settings):
    """Run SCENE (a prm of FOLDER) for two steps with SETTINGS (prm text)
    appended; return (exit code, output, summary or None)."""
    out = os.path.join(scratch, name)
    path = out + ".prm"
    with open(path, "w") as f:
        f.write(f"include {os.path.abspath(os.path.join(folder, scene))}\n"
                f"set Output directory = {out}\n"
                f"subsection Time\n  set End time = 1e-12\nend\n{settings}\n")
    p = subprocess.run([tribodyn, path], capture_output=True, text=True)
    summary = None
    if p.returncode == 0:
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
    return p.returncode, p.stdout + p.stderr, summary


def courant(value):
    return f"subsection Time\n  set Courant factor = {value}\nend\n"


for scene in ("friction_steel.prm", "friction_composite.prm"):
    code, text, s = run(scene.replace(".prm", ""), scene, courant(0.5))
    report(code == 0 and s["courant_limit"] == 0.5,
           f"{scene} at Courant 0.5: runs, courant_limit "
           f"{s['courant_limit'] if s else None} (0.5: stable at 0.5)")

graded = "friction_seed_heights_steel.prm"
band = "subsection Geometry\n  set Size bands = interface 8 16\nend\n"
code, text, _ = run("graded_050", graded, band + courant(0.5))
m = re.search(r"allows a Courant factor of ([0-9.]+)", text)
limit = float(m.group(1)) if m else None
report(code == 2 and "'Time/Courant factor' = 0.5" in text and m is not None,
       f"graded seed-heights scene at Courant 0.5: refused (exit {code}), "
       f"naming the parameter and the limit {limit}")
report(limit is not None and 0.42 <= limit < 0.5,
       f"its limit {limit} within [0.42, 0.5): below the factor where it "
       "became unstable, at or above one where it stayed stable")
if limit is not None:
    code, text, s = run("graded_limit", graded, band + courant(limit))
    report(code == 0 and s["courant_limit"] == limit,
           f"at Courant {limit}: runs, summary courant_limit "
           f"{s['courant_limit'] if s else None}")
    critical = s["critical_dt"] if s else 1.29e-12
    step = f"subsection Time\n  set Time step = {1.001 * limit * critical!r}\nend\n"
    code, text, _ = run("graded_step", graded, band + step)
    report(code == 2 and "'Time/Time step'" in text,
           f"a given time step 0.1 % above the limit: refused (exit {code}) "
           "naming 'Time/Time step'")
code, text, s = run("graded_no_moments", graded, band + courant(0.5) +
                    "subsection Interaction\n"
                    "  set Relative rotation stiffness = 0\nend\n")
report(code == 0 and s["courant_limit"] == 0.5,
       "graded scene without the relative-rotation moments at 0.5: runs, "
       f"courant_limit {s['courant_limit'] if s else None} (stable at 0.5)")
finish()
