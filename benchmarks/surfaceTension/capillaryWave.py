#!/usr/bin/env python3
"""capillaryWave.py CASE N: the amplitude of the capillary wave of a case
run by capillaryWave.sh (N cells per wavelength) at each written time,
from the first Fourier mode of the columns' liquid heights (corrected for
the cell average of the cosine), against Prosperetti's solution
(prosperetti.py).  Prints the RMS of (a - a_exact)/a0 over the written
times, and writes CASE/amplitude.dat (t, a/a0, exact).
"""
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from prosperetti import amplitude  # noqa: E402
from staticDrop import field  # noqa: E402


def main(case, n):
    n = int(n)
    d = 1.0/n
    k = 2*math.pi
    nu = math.sqrt(1/3000.0)
    sinc = math.sin(k*d/2)/(k*d/2)
    times = sorted((t for t in os.listdir(case)
                    if re.fullmatch(r"[\d.eE+-]+", t)), key=float)
    rows, err2 = [], 0.0
    for t in times:
        _, a = field(f"{case}/{t}/alpha.liquid")
        if _ is None:
            continue
        H = [sum(a[j*n + i][0] for j in range(n))*d for i in range(n)]
        A = 2.0/n*sum((H[i] - 0.5)*math.cos(k*(i + 0.5)*d)
                      for i in range(n))/sinc/0.01
        ex = amplitude(float(t), k, nu, 1.0, 1.0) if float(t) > 0 else 1.0
        rows.append((float(t), A, ex))
        err2 += (A - ex)**2
    with open(f"{case}/amplitude.dat", "w") as f:
        for r in rows:
            f.write("%g %.6f %.6f\n" % r)
    print(f"{math.sqrt(err2/len(rows)):.4g}")


if __name__ == "__main__":
    main(*sys.argv[1:3])
