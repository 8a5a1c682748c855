#!/usr/bin/env python3
"""risingBubble.py CASE [TIME]: Hysing et al. (2009) test case 1 figures of
a case run by risingBubble.sh, from postProcessing/bubble/0/
phaseStatistics.dat: prints

    minCircularity  tMinCirc  maxRiseVelocity  tMaxVel  yc(TIME)

(TIME default 3) and, on stderr, each against the benchmark's reference
(TP2D, the finest of the paper's groups): circularity 0.9013 at t 1.9,
rise velocity 0.2417 at t 0.921, centroid 1.0813 at t 3.
"""
import sys

REF = {"circ": 0.9013, "vel": 0.2417, "yc": 1.0813}


def main(case, tend=3.0):
    rows = []
    for line in open(f"{case}/postProcessing/bubble/0/phaseStatistics.dat"):
        if line.startswith("#"):
            continue
        v = [float(x) for x in line.split()]
        rows.append(v)  # t vol x y z Ux Uy Uz area circ
    # circularity's minimum after the start (the initial disk is 1)
    circ = min(rows, key=lambda r: r[9])
    vel = max(rows, key=lambda r: r[6])
    # centroid at tend: the last row at or before it, linearly interpolated
    yc = None
    for a, b in zip(rows, rows[1:]):
        if a[0] <= tend <= b[0]:
            w = (tend - a[0])/(b[0] - a[0]) if b[0] > a[0] else 0
            yc = a[3] + w*(b[3] - a[3])
    if yc is None:
        yc = float("nan")
    print(f"{circ[9]:.5f} {circ[0]:.3f} {vel[6]:.5f} {vel[0]:.3f} {yc:.5f}")
    for k, val in (("circ", circ[9]), ("vel", vel[6]), ("yc", yc)):
        print(f"  {k}: {val:.5f} against {REF[k]} "
              f"({100*(val - REF[k])/REF[k]:+.2f} %)", file=sys.stderr)


if __name__ == "__main__":
    main(sys.argv[1], float(sys.argv[2]) if len(sys.argv) > 2 else 3.0)
