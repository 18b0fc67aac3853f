"""Helpers shared by the plot scripts of scripts/ (not a script itself).

A script imports it from its own directory:

    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import plot_tools

It reads what tribodyn writes into an output directory (CSV series,
summary.json, parameters.prm), builds the argparse parser of a script from
its docstring, and provides the few numerical helpers of the plots (running
mean, padded axis limits); ctest_tests() lists a build's tests for the
scripts that check the suite (tests/check_budget.py,
scripts/verification_audit). Only the standard library and Debian's
python3-matplotlib.
"""
import argparse
import csv
import json
import math
import os
import sys


def pyplot():
    """matplotlib.pyplot on the file-only Agg backend (no display)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def parser(doc):
    """An ArgumentParser whose --help prints the script's whole docstring
    (usage, inputs, outputs) unwrapped."""
    return argparse.ArgumentParser(
        description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)


def fail(script, message):
    """Exit with status 1 and 'SCRIPT: MESSAGE' on stderr."""
    sys.exit("%s: %s" % (script, message))


def number(text):
    """float of a CSV cell; an empty cell is NaN."""
    return float(text) if text.strip() else float("nan")


def read_csv(path):
    """Columns of a CSV file with a header line: name -> list of floats
    ({} when the file has no rows). Raises OSError and ValueError."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        return {}
    return {k: [number(r[k]) for r in rows] for k in rows[0]}


def read_summary(directory, script):
    """DIRECTORY/summary.json as a dict, or exit with a message."""
    path = os.path.join(directory, "summary.json")
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        fail(script, "cannot read the results in '%s': %s" % (directory, e))


def read_parameters(directory):
    """The parameters of a run from DIRECTORY/parameters.prm (written by
    tribodyn with every value): 'Subsection/Name' -> text, e.g.
    'Materials/Steel/Young modulus'. {} when there is no such file."""
    path = os.path.join(directory, "parameters.prm")
    if not os.path.exists(path):
        return {}
    values, section = {}, []
    with open(path) as f:
        for line in f:
            s = line.split("#", 1)[0].strip()
            if s.startswith("subsection "):
                section.append(s[len("subsection "):].strip())
            elif s == "end" and section:
                section.pop()
            elif s.startswith("set ") and "=" in s:
                name, value = s[4:].split("=", 1)
                values["/".join(section + [name.strip()])] = value.strip()
    return values


def body_material(prm):
    """'Materials/<Name>/', the prefix of the parameters of the first body's
    material (an MCA run's Geometry/Bodies ends each body with the name of
    its material), or None."""
    bodies = prm.get("Geometry/Bodies", "").split(";")[0].split()
    return "Materials/%s/" % bodies[-1].capitalize() if bodies else None


def running_mean(values, n):
    """Mean of the last N values (fewer at the start) at each index."""
    n = max(1, int(n))
    cumulative = [0.0]
    for x in values:
        cumulative.append(cumulative[-1] + x)
    return [(cumulative[i + 1] - cumulative[max(0, i + 1 - n)])
            / (i + 1 - max(0, i + 1 - n)) for i in range(len(values))]


def padded_limits(values, fraction=0.12, minimum=None):
    """(low, high) around the finite VALUES with FRACTION of their span as
    margin on both sides; a zero span (one value) gets MINIMUM, or 10 % of
    the value's magnitude (1 when it is 0), on both sides."""
    finite = [v for v in values if v is not None and math.isfinite(v)]
    if not finite:
        return -1.0, 1.0
    low, high = min(finite), max(finite)
    span = high - low
    if span > 0:
        margin = fraction * span
    elif minimum is not None:
        margin = minimum
    else:
        margin = 0.1 * abs(low) or 1.0
    return low - margin, high + margin


def label_of(directory):
    """Default legend label of a run: the name of its directory."""
    return os.path.basename(os.path.normpath(directory))


def read_vtu(path):
    """The point data and points of a .vtu file, ASCII or deal.II's
    binary (zlib-compressed, base64) format: {name: list of values} (a
    tuple per point for fields of several components), with the points
    under "points" and the cell data under their names too; the pieces of
    a file written by several ranks follow one another."""
    import base64
    import re
    import struct
    import zlib
    with open(path) as f:
        text = f.read()
    compressed = 'compressor="vtkZLibDataCompressor"' in text
    header_type = re.search(r'header_type="(\w+)"', text)
    word = "<Q" if header_type and header_type.group(1) == "UInt64" else "<I"
    size = struct.calcsize(word)
    result = {}
    for match in re.finditer(r"<DataArray([^>]*)>(.*?)</DataArray>", text, re.S):
        head, body = match.group(1), match.group(2).strip()
        name = re.search(r'Name="([^"]*)"', head)
        kind = re.search(r'type="(\w+)"', head).group(1)
        comps = re.search(r'NumberOfComponents="(\d+)"', head)
        n = int(comps.group(1)) if comps else 1
        if not body:
            values = []
        elif 'format="binary"' in head:
            code = {"Float32": "f", "Float64": "d", "Int32": "i", "UInt32": "I",
                    "Int64": "q", "UInt64": "Q", "UInt8": "B", "Int8": "b"}[kind]
            if compressed:
                # header: number of blocks, block size, last block size,
                # then the compressed size of each block; base64 of the
                # header, then of the blocks
                first = base64.b64decode(body[:((3 * size + 2) // 3) * 4])
                n_blocks = struct.unpack(word, first[:size])[0]
                header_bytes = (3 + n_blocks) * size
                header_chars = ((header_bytes + 2) // 3) * 4
                header = struct.unpack("<" + word[1] * (3 + n_blocks),
                                       base64.b64decode(body[:header_chars])[:header_bytes])
                data = base64.b64decode(body[header_chars:])
                raw, offset = b"", 0
                for b in header[3:]:
                    raw += zlib.decompress(data[offset:offset + b])
                    offset += b
            else:
                raw = base64.b64decode(body)[size:]  # after its byte count
            values = list(struct.unpack("<%d%s" % (len(raw) // struct.calcsize(code),
                                                   code), raw))
        else:
            values = [float(v) for v in body.split()]
        key = name.group(1) if name else "points"
        if key in ("connectivity", "offsets", "types"):
            continue
        result.setdefault(key, []).extend(
            tuple(values[i:i + n]) if n > 1 else values[i]
            for i in range(0, len(values), n))
    return result


def ctest_tests(build_dir, ctest="ctest"):
    """ctest's own description of the tests of BUILD_DIR (`ctest
    --show-only=json-v1`): a list of dicts with 'name', 'command' and
    'properties'. ctest is run on a copy of the build's CTestTestfile.cmake
    files in a temporary folder, because any ctest run in BUILD_DIR, even
    --show-only, replaces Testing/Temporary/LastTest.log, the log of a suite
    that may be running there (tests_budget and docs_verification_audit run
    inside the suite; scripts/verification_audit harvests that log)."""
    import shutil
    import subprocess
    import tempfile
    with tempfile.TemporaryDirectory() as copy:
        for folder, _, files in os.walk(build_dir):
            if "CTestTestfile.cmake" in files:
                target = os.path.join(copy, os.path.relpath(folder, build_dir))
                os.makedirs(target, exist_ok=True)
                shutil.copy(os.path.join(folder, "CTestTestfile.cmake"), target)
        listing = subprocess.run([ctest, "--show-only=json-v1"], cwd=copy,
                                 check=True, capture_output=True, text=True)
    return json.loads(listing.stdout)["tests"]
