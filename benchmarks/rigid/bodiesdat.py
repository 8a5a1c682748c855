"""The rows of a case's bodies function object over restarts.

bodies_rows(CASE) yields the split data rows of every
postProcessing/bodies/<start>/bodies.dat, the start times in order; a run
restarted at time T writes a new <T> directory, whose rows replace the
earlier ones from T on."""
import os


def bodies_rows(case):
    base = os.path.join(case, 'postProcessing', 'bodies')
    starts = sorted((float(s), s) for s in os.listdir(base)
                    if os.path.isfile(os.path.join(base, s, 'bodies.dat')))
    for k, (t0, s) in enumerate(starts):
        t1 = starts[k + 1][0] if k + 1 < len(starts) else float('inf')
        for line in open(os.path.join(base, s, 'bodies.dat')):
            c = line.split()
            if line.startswith('#') or not c:
                continue
            if t0 <= float(c[0]) < t1:
                yield c
