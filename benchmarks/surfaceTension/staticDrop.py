#!/usr/bin/env python3
"""staticDrop.py CASE DIM: the static drop's pressure jump and spurious
velocity at the last time written: prints

    dp  dp_error  Ca

dp the mean pressure of the cells wholly in the drop (alpha.liquid >
0.999) less that of the cells wholly outside (< 0.001), dp_error its
relative error against sigma/R (DIM 2) or 2 sigma/R (DIM 3), and Ca =
mu max|U|/sigma the capillary number of the largest spurious velocity
(R = 0.25, sigma = 1, mu from constant/vheProperties or
transportProperties).
"""
import os
import re
import sys

NUMBER = re.compile(r"[-+]?\d+\.?\d*(?:[eE][-+]?\d+)?")


def field(path):
    text = open(path).read()
    i = text.index("internalField")
    if text[i:i + 40].split()[1] == "uniform":
        end = text.index(";", i)
        vals = [float(x) for x in NUMBER.findall(text[i + 20:end])]
        return None, vals
    start = text.index("(", i)
    n = int(text[text.index(">", i) + 1:start])
    body = text[start + 1:text.index("\n)", start)]
    nums = [float(x) for x in NUMBER.findall(body)]
    per = len(nums)//n
    return n, [nums[k*per:(k + 1)*per] for k in range(n)]


def last_time(case):
    times = [d for d in os.listdir(case)
             if re.fullmatch(r"[\d.eE+-]+", d) and float(d) > 0]
    return max(times, key=float)


def mu_of(case):
    p = os.path.join(case, "constant/vheProperties")
    if os.path.exists(p):
        return float(re.search(r"mu\s*\[[^\]]*\]\s*([\d.eE+-]+)",
                               open(p).read()).group(1))
    t = open(os.path.join(case, "constant/transportProperties")).read()
    nu = float(re.search(r"nu\s+([\d.eE+-]+)", t).group(1))
    rho = float(re.search(r"rho\s+([\d.eE+-]+)", t).group(1))
    return nu*rho


def main(case, dim):
    t = last_time(case)
    _, a = field(f"{case}/{t}/alpha.liquid")
    _, p = field(f"{case}/{t}/p")
    nu_, u = field(f"{case}/{t}/U")
    a = [x[0] for x in a]
    p = [x[0] for x in p] if len(p) == len(a) else p*len(a)
    pin = [pi for pi, ai in zip(p, a) if ai > 0.999]
    pout = [pi for pi, ai in zip(p, a) if ai < 0.001]
    dp = sum(pin)/len(pin) - sum(pout)/len(pout)
    exact = (1 if dim == 2 else 2)*1.0/0.25
    umax = 0.0 if nu_ is None else max(sum(c*c for c in v)**0.5 for v in u)
    print(f"{dp:.6g} {(dp - exact)/exact:.4g} {mu_of(case)*umax:.4g}")


if __name__ == "__main__":
    main(sys.argv[1], int(sys.argv[2]))
