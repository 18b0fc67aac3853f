"""Shared by compare_ranks.py and compare_partitions.py: the largest
difference between two series.csv tables, relative to each column's largest
magnitude in the first."""


def largest_relative_difference(a, b):
    """a, b: rows of two CSV files (header first). Returns (difference,
    column name)."""
    worst, name = 0.0, ""
    for c in range(len(a[0])):
        col_a = [float(r[c]) for r in a[1:]]
        col_b = [float(r[c]) for r in b[1:]]
        scale = max(max(abs(x) for x in col_a), 1e-300)
        d = max(abs(x - y) for x, y in zip(col_a, col_b)) / scale
        if d > worst:
            worst, name = d, a[0][c]
    return worst, name
