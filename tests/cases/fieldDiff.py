#!/usr/bin/env python3
"""Largest difference between one field of two cases at one time.

Usage: fieldDiff.py CASE_A CASE_B TIME FIELD
Prints 'maxAbsDifference maxAbsValueInA' over the internal field (ASCII
field files; uniform or nonuniform; any rank).
"""
import re
import sys

NUMBER = re.compile(r"[-+]?\d+\.?\d*(?:[eE][-+]?\d+)?")


def internal_field(path):
    text = open(path).read()
    i = text.index("internalField")
    head = text[i:i + 200]
    if head.split()[1] == "uniform":
        end = text.index(";", i)
        return None, [float(x) for x in NUMBER.findall(text[i + 20:end])]
    start = text.index("(", i)
    n = int(text[text.index(">", i) + 1:start])
    body = text[start + 1:text.index("\n)\n", start)]
    nums = [float(x) for x in NUMBER.findall(body)]
    per = len(nums) // n if n else 1
    return n, [nums[k * per:(k + 1) * per] for k in range(n)]


def main(a, b, time, field):
    na, fa = internal_field(f"{a}/{time}/{field}")
    nb, fb = internal_field(f"{b}/{time}/{field}")
    if na is None or nb is None:
        fa = [fa] if na is None else fa
        fb = [fb] if nb is None else fb
        if len(fa) != len(fb):
            fa, fb = fa * max(1, len(fb)), fb * max(1, len(fa))
    if len(fa) != len(fb):
        sys.exit(f"{field}: {len(fa)} cells in {a}, {len(fb)} in {b}")
    diff = max(abs(x - y) for u, v in zip(fa, fb) for x, y in zip(u, v))
    scale = max(abs(x) for u in fa for x in u)
    print(diff, scale)


if __name__ == "__main__":
    main(*sys.argv[1:5])
