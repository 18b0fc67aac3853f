"""Geometry/Size bands = 'interface N' (issue #47 item 2, the narrowed fine
band): the layout of the graded friction scenes generated from the bodies
and the rough interface. Checked by counting: the seed-heights scene is 16 x
16 periodic FCC cells of a = d sqrt 2 across and 404 cells tall (the
interface at 202); a cell layer of height a holds 1024 automata of d, 128
of 2d (8 times fewer) or 16 of 4d (64 times fewer). 'interface N' puts d in
2N cells at the interface and the 2 x 4 outer cells, 2d in M cells on each
side of the fine band (4 if not given) and in two 4-cell transitions next to
the outer cells, 4d in the rest, so --partition-report must print exactly
(8 + 2N) 1024 of d, (2M + 8) 128 of 2d and (404 - 8 - 2N - 2M - 8) 16 of 4d. For N = 23
the generated bands are the ones the seed-heights scene had written out by
hand before (BY_HAND below): the same counts (a shifted or misplaced band
changes them by whole cell layers: 1024 automata; shown failing with the
hand-written 2d band moved down by one cell). The tall graded scenes
(96 cells, interface at 48) are counted the same way: (8 + 2N) 1024,
2048 and (96 - 8 - 2N - 16) 16.

'interface N M O' makes the outer cells (the loading layers) of 2^O d:
O = 1 puts 2d in the 4 outer cells and drops the transitions, 2N 1024 of
d, (2M + 8) 128 of 2d, (404 - 8 - 2N - 2M) 16 of 4d; O = 2 runs the 4d to
the faces: 2N 1024, 2M 128, (404 - 2N - 2M) 16. Its loading layers are
counted in layers of the outer automata (4 times the fine spacing for 4d):
a short run of the approach must move the top and bottom layers as mirror
images (top_uz = -bottom_uz, not zero: before 2026-12-01 the top layer
was looked for on the fine lattice's top plane, 1.5 a above the highest
4d plane, and held no automaton, top_uz = 0), with the damping of the seed's
criterion c_p / (2 h) for the layers' thickness h, a quarter of the fine
scene's (exact: h is 4 times as thick).
Arguments: the tribodyn binary, the prm/mca folder, a scratch directory."""
import csv
import json
import os
import re
import subprocess
import sys

from check_tools import finish, report

tribodyn, folder, scratch = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(scratch, exist_ok=True)
base = open(f"{folder}/friction_seed_heights_steel.prm").read()
BY_HAND = ("4.24264068712e-08 8.48528137424e-08 1; 8.48528137424e-08 1.85615530061e-06 2; "
           "1.85615530061e-06 1.89858170749e-06 1; 2.3864853865e-06 2.42891179338e-06 1; "
           "2.42891179338e-06 4.20021428025e-06 2; 4.20021428025e-06 4.24264068712e-06 1")


def counts(prm_text, name):
    path = os.path.join(scratch, name)
    with open(path, "w") as f:
        f.write(prm_text)
    p = subprocess.run([tribodyn, "--partition-report", "1", path],
                       capture_output=True, text=True)
    m = re.search(r"automata per size: (\d+) of d, (\d+) of 2d, (\d+) of 4d", p.stdout)
    if p.returncode != 0 or not m:
        print(p.stdout, p.stderr)
        return None
    return tuple(int(x) for x in m.groups())


def with_bands(text):
    return re.sub(r"(?m)^  set Size bands .*$", f"  set Size bands = {text}", base)


by_hand = counts(with_bands(BY_HAND), "by_hand.prm")
report(by_hand == counts(with_bands("interface 23"), "interface_23.prm"),
       f"'interface 23' packs as the hand-written bands of the seed-heights "
       f"scene: {by_hand}")
for n, m in ((7, None), (8, None), (12, None), (8, 16), (7, 9)):
    words = f"interface {n}" + (f" {m}" if m else "")
    m = m or 4
    expected = ((8 + 2 * n) * 1024, (2 * m + 8) * 128, (404 - 8 - 2 * n - 2 * m - 8) * 16)
    got = counts(with_bands(words), words.replace(" ", "_") + ".prm")
    report(got == expected, f"'{words}': {got} automata of d, 2d, 4d; "
           f"counted from the layout {expected}")
for n, m, o in ((8, 16, 1), (8, 16, 2), (6, 18, 2)):
    words = f"interface {n} {m} {o}"
    outer = 8 if o == 1 else 0
    expected = (2 * n * 1024, (2 * m + outer) * 128, (404 - outer - 2 * n - 2 * m) * 16)
    got = counts(with_bands(words), words.replace(" ", "_") + ".prm")
    report(got == expected, f"'{words}': {got} automata of d, 2d, 4d; "
           f"counted from the layout {expected}")


def approach(words):
    """A 20-ps run of the approach with Size bands = WORDS: its summary and
    the last row of its series."""
    name = "approach_" + words.replace(" ", "_")
    text = with_bands(words).replace("set End time       = 16e-9", "set End time = 2e-11")
    text = re.sub(r"(?m)^set Output directory = .*$",
                  f"set Output directory = {os.path.join(scratch, name)}", text)
    path = os.path.join(scratch, name + ".prm")
    with open(path, "w") as f:
        f.write(text)
    p = subprocess.run([tribodyn, path], capture_output=True, text=True)
    if p.returncode != 0:
        print(p.stdout, p.stderr)
        return None, None
    out = os.path.join(scratch, name)
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    with open(os.path.join(out, "series.csv")) as f:
        rows = list(csv.DictReader(f))
    return summary, rows[-1]


fine, fine_last = approach("interface 8 16")
coarse, last = approach("interface 8 16 2")
if coarse is None or fine is None:
    report(False, "the two approach runs")
else:
    top, bottom = float(last["top_uz"]), float(last["bottom_uz"])
    report(top < 0 and abs(top + bottom) <= 1e-12 * abs(top),
           f"4d loading layers: top_uz {top:.6e} m = -bottom_uz {bottom:.6e} m "
           f"(1e-12 relative: both prescribed, the same arithmetic)")
    report(abs(top - float(fine_last["top_uz"])) <= 1e-12 * abs(top),
           f"and as the fine layers' {float(fine_last['top_uz']):.6e} m")
    ratio = fine["loading_damping"] / coarse["loading_damping"]
    report(ratio == 4, f"damping of the loading layers: fine "
           f"{fine['loading_damping']:.6e} 1/s, 4d {coarse['loading_damping']:.6e} "
           f"1/s, ratio {ratio} (exactly 4)")
for prm, n in (("friction_tall_graded.prm", 6), ("friction_tall_graded_far.prm", 8)):
    expected = ((8 + 2 * n) * 1024, 2048, (96 - 8 - 2 * n - 16) * 16)
    got = counts(open(f"{folder}/{prm}").read(), prm)
    report(got == expected, f"{prm}: {got} automata of d, 2d, 4d; counted from "
           f"the layout {expected}")
finish()
