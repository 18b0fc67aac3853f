"""The shipped automata studies run (issue #49 item 2), cut short:
prm/study/mca_laptop.prm, mca_seed_heights.prm, mca_seed_heights_12.prm,
mca_seed_heights_044.prm, its 48-ns campaign mca_seed_heights_044_48ns.prm,
mca_fibre_content.prm, mca_time_step_lever.prm, mca_automaton_order.prm,
mca_time_step_lever_composite.prm and the two seed-heights levers
mca_time_step_lever_seed_heights(_composite).prm and the coarse layout's
mca_coarse_lever_seed_heights(_composite).prm and its campaign
mca_seed_heights_coarse.prm, the outer layout's
mca_outer_lever_seed_heights(_composite).prm and the inclusion-seed lever
mca_inclusion_seed_lever.prm (its roughness seed 1 with inclusion seed 2:
the scene composite_044_seed1_inclusions2, tagged with both seeds), each
with an
override block appended (as a user continues a prm: later entries win; the
shipped text is not edited) for one roughness seed, 2e-11 s (the bodies
are still approaching) and an output directory of the test's; the bases
made absolute, as the study reads them relative to its own file.

    check_shipped_mca_studies.py TRIBODYN PRM_STUDY_DIR SCRATCH

Checked: the study runs (exit 0) and writes its tables, one scene per base
with its factors named in summary.json; each scene holds the automata its
prm documents (the laptop scene: 16 x 16 x 12 FCC cells = 12 288; the seed
heights with the fine band at 8 cells and 16 of 2d: 35 136, the count
mca_size_bands_interface derives from the layout; the coarse layout
'interface 6 18 2': 22 592, the outer one 'interface 8 16 2': 26 176), and
the seed-heights scenes really run the study's setting or their base's
(their parameters.prm reads 'interface 8 16', the coarse bases 'interface 6
18 2', the outer ones 'interface 8 16 2'), the order study's scenes the
order of their base ('Morton curve' or 'slabs'); the time-step levers' two bases differ in dt by the
ratio of their Courant factors, 0.5/0.35 or 0.44/0.35 (the same d and c_p:
to 1e-12)."""
import csv
import json
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "mca"))
from check_tools import finish, report  # noqa: E402

tribodyn, folder, scratch = sys.argv[1], os.path.abspath(sys.argv[2]), sys.argv[3]
# a fresh scratch: scenes left by an earlier run (of another version) would
# be reused, resumed or re-analysed instead of run
shutil.rmtree(scratch, ignore_errors=True)
os.makedirs(scratch)
AUTOMATA = {"mca_laptop": 12288, "mca_seed_heights": 35136,
            "mca_seed_heights_12": 35136, "mca_seed_heights_044": 35136,
            "mca_seed_heights_044_48ns": 35136,
            "mca_fibre_content": 12288, "mca_time_step_lever": 12288,
            "mca_automaton_order": 12288,
            "mca_time_step_lever_composite": 12288,
            "mca_time_step_lever_seed_heights": 35136,
            "mca_time_step_lever_seed_heights_composite": 35136,
            "mca_coarse_lever_seed_heights": {"steel_044": 35136, "steel_coarse": 22592},
            "mca_coarse_lever_seed_heights_composite":
                {"composite_044": 35136, "composite_coarse": 22592},
            "mca_seed_heights_coarse": 22592,
            "mca_inclusion_seed_lever": 35136,
            "mca_outer_lever_seed_heights": {"steel_044": 35136, "steel_outer": 26176},
            "mca_outer_lever_seed_heights_composite":
                {"composite_044": 35136, "composite_outer": 26176}}
# the inclusion seed a study's cut keeps with roughness seed 1 (the others:
# each equal to its roughness seed)
INCLUSION_SEEDS = {"mca_inclusion_seed_lever": 2}
# the layout each seed-heights scene must run: the study's setting or its
# base's (the coarse lever's bases), 'interface 8 16' unless named here
BANDS = {"steel_coarse": "interface 6 18 2", "composite_coarse": "interface 6 18 2",
         "steel_outer": "interface 8 16 2", "composite_outer": "interface 8 16 2"}
# the two bases of each time-step lever and the ratio of their Courant
# factors (0.35 against 0.5 or 0.44)
LEVERS = {"mca_time_step_lever": ("courant_035", "courant_050", 0.5 / 0.35),
          "mca_time_step_lever_composite": ("composite_035", "composite_050",
                                            0.5 / 0.35),
          "mca_time_step_lever_seed_heights": ("steel", "steel_044", 0.44 / 0.35),
          "mca_time_step_lever_seed_heights_composite":
              ("composite", "composite_044", 0.44 / 0.35)}
# the generated fibres' share of each contacting part's box (the set-up's
# 'Inclusions:' line), per base of the fibre-content study: the 4 % base
# reads friction_composite.prm through an include beside it, run from the
# test's directory
FIBRES = {"composite": 1.90895, "composite_4": 3.8179}


def bases(text):
    """Study/Bases of a study prm: the entry with its continuation lines."""
    joined = text.replace("\\\n", " ")
    for line in joined.splitlines():
        words = line.split("#", 1)[0].strip()
        if words.startswith("set Bases") and "=" in words:
            return [b.split(":", 1) for b in words.split("=", 1)[1].split(",")]
    return []


for name, n_automata in AUTOMATA.items():
    shipped = os.path.join(folder, name + ".prm")
    text = open(shipped).read()
    out = os.path.join(scratch, name)
    absolute = ", ".join(f"{b.strip()}: {os.path.join(folder, f.strip())}"
                         for b, f in bases(text))
    wrapper = os.path.join(scratch, name + ".prm")
    with open(wrapper, "w") as f:
        f.write(text + f"""
# --- appended by the test: one seed, cut short ---
set Output directory = {out}
subsection Time
  set End time = 2e-11
end
subsection Study
  set Bases           = {absolute}
  set Roughness seeds = 1
""" + (f"  set Inclusion seeds = {INCLUSION_SEEDS[name]}\n"
       if name in INCLUSION_SEEDS else "") + "end\n")
    run = subprocess.run([tribodyn, wrapper], capture_output=True, text=True)
    print(run.stdout[-1500:], run.stderr[-1500:])
    report(run.returncode == 0, f"{name}: the study ran (exit {run.returncode})")
    if run.returncode != 0:
        continue
    with open(os.path.join(out, "scenes.csv")) as f:
        scenes = list(csv.DictReader(f))
    bases_run = [b.strip() for b, _ in bases(text)]
    report(len(scenes) == len(bases_run) and os.path.exists(os.path.join(out, "study.csv")),
           f"{name}: scenes.csv with the {len(bases_run)} bases' scenes, study.csv written")
    inclusions = INCLUSION_SEEDS.get(name, 1)
    suffix = f"_inclusions{inclusions}" if inclusions != 1 else ""
    for base in bases_run:
        scene = os.path.join(out, "scenes", f"{base}_seed1{suffix}")
        with open(os.path.join(scene, "summary.json")) as f:
            summary = json.load(f)
        tag = summary.get("study_scene", {})
        expected = n_automata[base] if isinstance(n_automata, dict) else n_automata
        report(tag.get("base") == base and summary.get("n_automata") == expected
               and tag.get("roughness_seed") == 1
               and tag.get("inclusion_seed") == inclusions,
               f"{name} {base}: {summary.get('n_automata')} automata "
               f"(documented {expected}), scene tagged {tag}")
        if name == "mca_automaton_order":
            prm = open(os.path.join(scene, "parameters.prm")).read()
            order = "slabs" if base == "slabs" else "Morton curve"
            report(re.search(rf"set Automaton order += {order}\n", prm)
                   is not None,
                   f"{name} {base}: the order '{order}' reached the scene")
        if "seed_heights" in name:
            prm = open(os.path.join(scene, "parameters.prm")).read()
            bands = BANDS.get(base, "interface 8 16")
            report(f"= {bands}\n" in prm,
                   f"{name} {base}: the Size bands '{bands}' reached the scene")
        if name == "mca_fibre_content" and base in FIBRES:
            fraction = summary.get("inclusion_volume_fraction_generated", 0) * 100
            report(abs(fraction - FIBRES[base]) < 1e-3,
                   f"{name} {base}: fibres {fraction:.5f} % of the part's box "
                   f"(the generator's {FIBRES[base]} %)")
    if name in LEVERS:
        dts = {}
        for base in bases_run:
            with open(os.path.join(out, "scenes", f"{base}_seed1",
                                   "summary.json")) as f:
                dts[base] = json.load(f)["dt"]
        small, large, factors = LEVERS[name]
        ratio = dts[large] / dts[small]
        report(abs(ratio / factors - 1) < 1e-12,
               f"{name}: dt ratio {ratio:.15f} = {factors:.15f} (Courant factors)")
finish()
