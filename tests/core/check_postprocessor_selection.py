"""The user's list of outputs, 'Output/Postprocessors', in the three engines
and 'RVE study/Outputs' in the RVE study
(issue #52 item 2: a postprocessor is chosen from a user list in the prm;
core/plugin_registry.h). For each engine a short run with 'all' (the
default) and one with a list:

- the listed outputs are exactly the ones made: their files exist, the
  others' do not (automata: series.csv has the listed outputs' columns only;
  contact: friction.csv without point_M.csv, contact_status.csv,
  fields.pvd or spectrum.csv; homogenization: effective_properties.csv without
  morphology.vtu, morphology.txt or the fields' VTU);
- an output does not change what is computed: the listed run's figures
  equal the 'all' run's bit for bit (the uniaxial E and nu, the pin's mean
  mu and energy balance, the apparent stiffnesses);
- a name that is not an output of the engine, and a listed output that does
  not apply to the run (friction in a uniaxial scene), are refused with exit
  code 2 and a message naming 'Output/Postprocessors' and the outputs.

Arguments: the tribodyn binary, the source directory, a scratch directory."""
import csv
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "mca"))
from check_tools import finish, report  # noqa: E402

tribodyn, source, scratch = (os.path.abspath(a) for a in sys.argv[1:4])
os.makedirs(scratch, exist_ok=True)


def run(name, base, text, selection=None):
    """Run BASE (a prm of the source tree) with TEXT and the list SELECTION
    appended; return (exit code, output, output directory)."""
    out = os.path.join(scratch, name)
    path = out + ".prm"
    with open(path, "w") as f:
        f.write(f"include {os.path.join(source, base)}\n"
                f"set Output directory = {out}\n{text}\n")
        if selection is not None:
            f.write(f"subsection Output\n  set Postprocessors = {selection}\nend\n")
    p = subprocess.run([tribodyn, path], capture_output=True, text=True,
                       cwd=os.path.dirname(os.path.join(source, base)))
    return p.returncode, p.stdout + p.stderr, out


def summary(out):
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def exists(out, name):
    return os.path.exists(os.path.join(out, name))


# --- automata: the uniaxial scene, 8 steps
short = "subsection Time\n  set End time = 2e-12\nend\n"
code_all, _, all_out = run("mca_all", "prm/mca/uniaxial_steel.prm", short)
code, _, out = run("mca_list", "prm/mca/uniaxial_steel.prm", short,
                   "energies, uniaxial")
report(code_all == 0 and code == 0, f"automata: both runs finish ({code_all}, {code})")
if code_all == 0 and code == 0:
    with open(os.path.join(out, "series.csv")) as f:
        columns = next(csv.reader(f))
    with open(os.path.join(all_out, "series.csv")) as f:
        all_columns = next(csv.reader(f))
    report("kinetic_energy" in columns and "interior_stress" in columns
           and not any(c.startswith("loaded_") or c.startswith("support_")
                       for c in columns)
           and len(columns) < len(all_columns),
           f"automata: series.csv has {len(columns)} columns (energies and "
           f"uniaxial) against {len(all_columns)} with 'all' (no boundary "
           "group columns)")
    report(not exists(out, "particles.pvd") and exists(all_out, "particles.pvd"),
           "automata: no particles.pvd without 'visualization' (written with 'all')")
    a, b = summary(all_out), summary(out)
    same = [k for k in ("kinetic_energy", "elastic_energy", "load_work")
            if k in a and a[k] == b.get(k)]
    report(len(same) == 3,
           f"automata: the energies at the end equal the 'all' run's bit for bit ({same})")
for name, selection, words in (
        ("mca_unknown", "energies, fiction", "'fiction', which is not one of"),
        ("mca_not_applying", "friction", "it applies when Analysis/Type = friction")):
    code, text, out = run(name, "prm/mca/uniaxial_steel.prm", short, selection)
    report(code == 2 and "'Output/Postprocessors'" in text and words in text,
           f"automata: '{selection}' refused (exit {code}): {words}")

# --- contact: the short pin of the tests, 10 us
code_all, _, all_out = run("contact_all", "tests/contact/short_pin.prm", "")
code, _, out = run("contact_list", "tests/contact/short_pin.prm", "", "friction")
report(code_all == 0 and code == 0, f"contact: both runs finish ({code_all}, {code})")
if code_all == 0 and code == 0:
    report(exists(out, "friction.csv") and not exists(out, "point_M.csv")
           and not exists(out, "contact_status.csv") and not exists(out, "fields.pvd")
           and not exists(out, "spectrum.csv")
           and exists(all_out, "point_M.csv") and exists(all_out, "fields.pvd")
           and exists(all_out, "spectrum.csv"),
           "contact: friction.csv only (point_M.csv, contact_status.csv, "
           "fields.pvd and spectrum.csv with 'all')")
    a, b = summary(all_out), summary(out)
    keys = ("mu_global_mean", "energy_balance_error", "stick_fraction",
            "dominant_frequency_hz")
    report(all(a[k] == b[k] for k in keys),
           f"contact: {', '.join(keys)} equal the 'all' run's "
           f"({[b[k] for k in keys]})")
code, text, _ = run("contact_unknown", "tests/contact/short_pin.prm", "", "spectra")
report(code == 2 and "'Output/Postprocessors'" in text,
       f"contact: an unknown name refused (exit {code})")

# --- homogenization: the small random cell of the tests
code_all, _, all_out = run("homogenization_all",
                           "tests/homogenization/small_random.prm", "")
code, _, out = run("homogenization_list", "tests/homogenization/small_random.prm",
                   "", "effective properties, Huet ordering")
report(code_all == 0 and code == 0,
       f"homogenization: both runs finish ({code_all}, {code})")
if code_all == 0 and code == 0:
    report(exists(out, "effective_properties.csv")
           and not exists(out, "morphology.vtu") and not exists(out, "morphology.txt")
           and not any(f.startswith("fields_") for f in os.listdir(out))
           and exists(all_out, "morphology.vtu")
           and exists(all_out, "fields_periodic.pvd"),
           "homogenization: effective_properties.csv without the morphology "
           "map and the fields (both written with 'all')")
    def numbers(value, path=""):
        """The numbers of a summary by their key paths (run times left out)."""
        if isinstance(value, dict):
            return {k: v for key, item in value.items()
                    if not key.endswith("_s") and "time" not in key
                    and "memory" not in key
                    for k, v in numbers(item, f"{path}/{key}").items()}
        if isinstance(value, list):
            return {k: v for i, item in enumerate(value)
                    for k, v in numbers(item, f"{path}[{i}]").items()}
        return {path: value} if isinstance(value, (int, float)) else {}
    a, b = numbers(summary(all_out)), numbers(summary(out))
    common = [k for k in b if k in a]
    differing = [k for k in common if a[k] != b[k]]
    report(not differing and len(common) >= 20,
           f"homogenization: the {len(common)} numbers both summaries hold "
           f"agree bit for bit (differing: {differing[:5]})")
code, text, _ = run("homogenization_unknown", "tests/homogenization/small_random.prm",
                    "", "effective properties, huet ordering")
report(code == 2 and "'huet ordering'" in text and "Huet ordering" in text,
       f"homogenization: a misspelt name refused naming the right one (exit {code})")
# --- the RVE study (its outputs, 'RVE study/Outputs'): the small study
def run_rve(name, outputs=None):
    out = os.path.join(scratch, name)
    path = out + ".prm"
    with open(path, "w") as f:
        f.write(f"include {os.path.join(source, 'tests/homogenization/rve_small.prm')}\n"
                f"set Output directory = {out}\n"
                "subsection RVE study\n  set Plot script = none\n")
        if outputs is not None:
            f.write(f"  set Outputs = {outputs}\n")
        f.write("end\n")
    p = subprocess.run([tribodyn, path], capture_output=True, text=True,
                       cwd=os.path.join(source, "tests/homogenization"))
    return p.returncode, p.stdout + p.stderr, out


code_all, _, all_out = run_rve("rve_all")
code, _, out = run_rve("rve_list", "table")
report(code_all == 0 and code == 0, f"rve: both runs finish ({code_all}, {code})")
if code_all == 0 and code == 0:
    report(exists(out, "rve.csv") and not exists(out, "rve.md")
           and exists(all_out, "rve.md") and not exists(all_out, "rve.png"),
           "rve: 'table' writes rve.csv and no rve.md; 'all' writes rve.md and, "
           "with 'Plot script = none', no rve.png")
    with open(os.path.join(out, "rve.csv")) as f, \
            open(os.path.join(all_out, "rve.csv")) as g:
        report(f.read() == g.read(), "rve: rve.csv the same with either list")
code, text, _ = run_rve("rve_unknown", "table, plots")
report(code == 2 and "'plots'" in text and "RVE study/Outputs" in text,
       f"rve: an unknown output refused naming 'RVE study/Outputs' (exit {code})")
code, text, _ = run_rve("rve_plot", "plot")
report(code == 2 and "Plot script" in text,
       f"rve: 'plot' with 'Plot script = none' refused (exit {code})")
finish()
