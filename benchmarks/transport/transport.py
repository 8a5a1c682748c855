#!/usr/bin/env python3
"""Transport verification of B (benchmarks/transport/Allrun).

  transport.py init CASE FLOW      pre-strain the disk: 0/Bstar from 0/C
  transport.py evaluate CASE FLOW SCHEME N TIME
                                   one CSV row: errors of phi_s and B at
                                   TIME against the exact answer (the
                                   initial fields: every flow returns the
                                   disk to its start), det drift, wall time

The disk carries B0 = simple shear of amount g(r) = (1 - (r/R)^2)^2 (1 at
the centre, 0 with zero slope at the rim), det B0 = 1:
    B0 = [[1 + g^2, g, 0], [g, 1, 0], [0, 0, 1]].
Errors of B over the cells with phi_s > 0.5 in both the exact and the
computed field (Frobenius norm of B - B_exact): L1 (volume mean) and max;
of phi_s: sum |phi_s - phi_s,exact| V / (disk area).
"""
import math
import os
import re
import sys

NUMBER = re.compile(r"[-+]?\d+\.?\d*(?:[eE][-+]?\d+)?")
DISKS = {  # flow: centre, radius
    "translation": ((0.5, 0.5), 0.25),
    "rotation": ((0.5, 0.7), 0.15),
    "singleVortex": ((0.5, 0.75), 0.15),
}


def read_internal(path):
    text = open(path).read()
    i = text.index("internalField")
    if text[i:i + 200].split()[1] == "uniform":
        end = text.index(";", i)
        return [[float(x) for x in NUMBER.findall(text[i + 20:end])]], text
    start = text.index("(", i)
    n = int(text[text.index(">", i) + 1:start])
    body = text[start + 1:text.index("\n)\n", start)]
    nums = [float(x) for x in NUMBER.findall(body)]
    per = len(nums) // n if n else 1
    return [nums[k * per:(k + 1) * per] for k in range(n)], text


def alpha(case, time, ncells):
    v, _ = read_internal(f"{case}/{time}/alpha.rubber")
    return [x[0] for x in v] if len(v) == ncells else [v[0][0]] * ncells


def shear(x, y, flow):
    (cx, cy), R = DISKS[flow]
    r2 = ((x - cx) ** 2 + (y - cy) ** 2) / R ** 2
    return (1 - r2) ** 2 if r2 < 1 else 0.0


def B0(x, y, flow):
    g = shear(x, y, flow)
    return [1 + g * g, g, 0.0, 1.0, 0.0, 1.0]


def init(case, flow):
    C, _ = read_internal(f"{case}/0/C")
    phis = alpha(case, 0, len(C))
    _, text = read_internal(f"{case}/0/Bstar")
    rows = []
    for (x, y, _z), p in zip(C, phis):
        b = [math.sqrt(p) * v for v in B0(x, y, flow)] if p > 1e-6 else [0.0] * 6
        rows.append("(" + " ".join("%.17g" % v for v in b) + ")")
    i = text.index("internalField")
    j = text.index(";", text.index("\n)\n", i)) if "nonuniform" in text[i:i + 60] \
        else text.index(";", i)
    field = ("internalField   nonuniform List<symmTensor> \n%d\n(\n%s\n)\n"
             % (len(rows), "\n".join(rows)))
    open(f"{case}/0/Bstar", "w").write(text[:i] + field + text[j:])


def det(b):
    xx, xy, xz, yy, yz, zz = b
    return xx * (yy * zz - yz * yz) - xy * (xy * zz - yz * xz) \
        + xz * (xy * yz - yy * xz)


def b_errors(case, time, C, p0, p1, flow, V):
    """L1 (volume mean) and max error of B over the cells with phi_s > 0.5
    in both the exact and the computed field"""
    Bs, _ = read_internal(f"{case}/{time}/Bstar")
    if len(Bs) != len(C):
        Bs = Bs * len(C)
    l1 = vol = emax = 0.0
    for (x, y, _z), a, b, bs in zip(C, p0, p1, Bs):
        if a > 0.5 and b > 0.5:
            B = [v / math.sqrt(b) for v in bs]
            E = B0(x, y, flow)
            w = [1, 2, 2, 1, 2, 1]   # off-diagonals twice: Frobenius
            e = math.sqrt(sum(k * (u - v) ** 2 for k, u, v in zip(w, B, E)))
            l1 += e * V
            vol += V
            emax = max(emax, e)
    return l1 / max(vol, 1e-300), emax


def evaluate(case, flow, scheme, n, time):
    C, _ = read_internal(f"{case}/0/C")
    nc = len(C)
    V = (1.0 / n) ** 2
    p0, p1 = alpha(case, 0, nc), alpha(case, time, nc)
    area = math.pi * DISKS[flow][1] ** 2
    ephi = sum(abs(a - b) for a, b in zip(p0, p1)) * V / area
    l1, emax = b_errors(case, time, C, p0, p1, flow, V)
    eB = f"{l1:.4e},{emax:.4e}"
    drift = 0.0
    diag = f"{case}/postProcessing/solidDiagnostics/0/solidDiagnostics.dat"
    if os.path.exists(diag):
        for line in open(diag):
            if line.strip() and not line.startswith("#"):
                drift = max(drift, float(line.split()[4]))
    log = open(f"{case}/log.vheFoam").read()
    wall = re.findall(r"ExecutionTime = (\S+) s", log)
    print(f"{flow},{scheme},{n},{ephi:.4e},{eB},"
          f"{drift:.3e},{wall[-1] if wall else ''}")


if __name__ == "__main__":
    cmd = sys.argv[1]
    if cmd == "init":
        init(*sys.argv[2:4])
    elif cmd == "evaluate":
        evaluate(sys.argv[2], sys.argv[3], sys.argv[4], int(sys.argv[5]),
                 sys.argv[6])
