#!/usr/bin/env python3
"""The tables of kept studies that README.md and doc/performance.md quote
are made from the data kept in the repository, byte for byte (issue #47
item 5).

    check_study_data.py SOURCE_DIR WORK_DIR

For each study kept under data/ (a folder with study.csv and PROVENANCE)
whose folder name README.md or doc/performance.md names in a marker line
'<!-- table: data/NAME (scripts/mca_study_data table data/NAME) -->',
`scripts/mca_study_data table data/NAME` must print exactly the lines that
follow the marker; `scripts/mca_study_data figures data/NAME WORK` must
draw seeds.png, mu.png and layer.png from the data alone. Also checked on
each kept study: PROVENANCE names a commit; every scene of scenes.csv has
its summary.json and its series of at most 2000 rows. A marker line
'<!-- common: data/A data/B (scripts/mca_study_data common data/A data/B)
-->' (a lever on two bases) must likewise be followed by exactly what
that command prints.
"""
import csv
import os
import re
import subprocess
import sys

source, work = sys.argv[1:3]
failures = []


def check(condition, what):
    print(("PASS  " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


script = os.path.join(source, "scripts", "mca_study_data")
# the documents that quote a kept study's table
documents = {d: open(os.path.join(source, d)).read()
             for d in ("README.md", os.path.join("doc", "performance.md"))}
markers = [(d, name) for d, text in documents.items()
           for name in re.findall(r"<!-- table: (data/[\w./-]+) "
                                  r"\(scripts/mca_study_data table \1\) -->\n",
                                  text)]
check(any(d == "README.md" for d, _ in markers),
      "README.md has a table marker: %s" % markers)
for document, name in markers:
    readme = documents[document]
    data = os.path.join(source, name)
    provenance = open(os.path.join(data, "PROVENANCE")).read()
    check(re.search(r"^commit: [0-9a-f]{40}", provenance, re.M) is not None,
          "%s/PROVENANCE names the commit" % name)
    with open(os.path.join(data, "scenes.csv")) as f:
        scenes = [r["scene"] for r in csv.DictReader(f)]
    complete = True
    for scene in scenes:
        d = os.path.join(data, "scenes", scene)
        complete = complete and os.path.exists(os.path.join(d, "summary.json"))
        for series in ("friction.csv", "layer.csv"):
            path = os.path.join(d, series)
            if os.path.exists(path):
                complete = complete and sum(1 for _ in open(path)) <= 2001
    check(complete and scenes, "%s: %d scenes with summary.json, series of "
          "at most 2000 rows" % (name, len(scenes)))
    table = subprocess.run([script, "table", data], capture_output=True,
                           text=True).stdout
    marker = "<!-- table: %s (scripts/mca_study_data table %s) -->\n" % (
        name, name)
    start = readme.index(marker) + len(marker)
    quoted = readme[start:start + len(table)]
    check(table and quoted == table,
          "%s: %s's table is what the data gives, byte for byte"
          % (name, document))
    images = os.path.join(work, os.path.basename(name))
    run = subprocess.run([script, "figures", data, images],
                         capture_output=True, text=True)
    drawn = all(os.path.getsize(os.path.join(images, f)) > 0
                for f in ("seeds.png", "mu.png", "layer.png")
                if os.path.exists(os.path.join(images, f)))
    check(run.returncode == 0 and drawn and all(
        os.path.exists(os.path.join(images, f))
        for f in ("seeds.png", "mu.png", "layer.png")),
          "%s: figures drawn from the data alone" % name)
common = [(d, a, b) for d, text in documents.items()
          for a, b in re.findall(
              r"<!-- common: (data/[\w./-]+) (data/[\w./-]+) "
              r"\(scripts/mca_study_data common \1 \2\) -->\n", text)]
for document, a, b in common:
    table = subprocess.run([script, "common", os.path.join(source, a),
                            os.path.join(source, b)], capture_output=True,
                           text=True).stdout
    marker = "<!-- common: %s %s (scripts/mca_study_data common %s %s) -->\n" \
        % (a, b, a, b)
    start = documents[document].index(marker) + len(marker)
    check(table and documents[document][start:start + len(table)] == table,
          "%s: the lever's table on %s and %s is what the data gives, byte "
          "for byte" % (document, a, b))
sys.exit(1 if failures else 0)
