#!/usr/bin/env python3
"""Compare two bodies.dat files (the bodies function object) row by row.

Usage: bodiesDiff.py A B
Prints the number of rows of each, whether time, id, material and colour
agree on every row, and the largest absolute difference of each other
column over all rows.  Exit 1 when the rows or their keys differ."""
import sys


def rows(path):
    out = []
    with open(path) as f:
        for line in f:
            if line.startswith('#') or not line.strip():
                continue
            out.append([float(v) for v in line.split()])
    return out


def main():
    a, b = rows(sys.argv[1]), rows(sys.argv[2])
    print(f"rows {len(a)} {len(b)}")
    if len(a) != len(b) or not a:
        return 1
    keys = all(x[:4] == y[:4] for x, y in zip(a, b))
    print(f"keys {'equal' if keys else 'differ'}")
    names = ["volume", "centroid_x", "centroid_y", "centroid_z", "U_x", "U_y",
             "U_z", "omega_x", "omega_y", "omega_z", "D", "axis_x", "axis_y",
             "axis_z", "maxDevB", "gap"]
    for k, name in enumerate(names, start=4):
        print(f"{name} {max(abs(x[k] - y[k]) for x, y in zip(a, b)):.3e}")
    return 0 if keys else 1


if __name__ == "__main__":
    sys.exit(main())
