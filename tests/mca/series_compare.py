"""Shared by compare_ranks.py and compare_partitions.py: the largest
difference between two series.csv tables, relative to each column's largest
magnitude in the first; the components of a group's force or displacement
(<group>_fx, _fy, _fz; _ux, _uy, _uz) relative to the largest of the three,
so that a component that vanishes by symmetry (rounding noise, ~1e-16 of
the others) is judged at the scale of its vector, not of its own noise; and
the energies and works (*_energy, *_work) relative to the largest of them,
the scale of the energy balance (the switching and many-body work of an
elastic block are rounding noise of its elastic energy)."""

import re


def column_scale(header, columns, c):
    """Largest magnitude of column c, or of its vector's three columns."""
    m = re.match(r"(.*)_([fu])[xyz]$", header[c])
    members = [c]
    if re.search(r"_(energy|work)$", header[c]):
        members = [k for k, h in enumerate(header)
                   if re.search(r"_(energy|work)$", h)]
    elif m:
        members = [k for k, h in enumerate(header)
                   if re.fullmatch(re.escape(m.group(1)) + "_" + m.group(2) + "[xyz]", h)]
    return max(max(max(abs(x) for x in columns[k]) for k in members), 1e-300)


def largest_relative_difference(a, b):
    """a, b: rows of two CSV files (header first). Returns (difference,
    column name)."""
    worst, name = 0.0, ""
    columns = [[float(r[c]) for r in a[1:]] for c in range(len(a[0]))]
    for c in range(len(a[0])):
        col_a = columns[c]
        col_b = [float(r[c]) for r in b[1:]]
        scale = column_scale(a[0], columns, c)
        d = max(abs(x - y) for x, y in zip(col_a, col_b)) / scale
        if d > worst:
            worst, name = d, a[0][c]
    return worst, name
