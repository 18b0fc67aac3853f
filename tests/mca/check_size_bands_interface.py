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
Arguments: the tribodyn binary, the prm/mca folder, a scratch directory."""
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
for prm, n in (("friction_tall_graded.prm", 6), ("friction_tall_graded_far.prm", 8)):
    expected = ((8 + 2 * n) * 1024, 2048, (96 - 8 - 2 * n - 16) * 16)
    got = counts(open(f"{folder}/{prm}").read(), prm)
    report(got == expected, f"{prm}: {got} automata of d, 2d, 4d; counted from "
           f"the layout {expected}")
finish()
