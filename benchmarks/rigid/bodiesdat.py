"""The rows of a case's function-object files over restarts.

function_rows(CASE, NAME, FILE) yields the split data rows of every
postProcessing/NAME/<start>/FILE, the start times in order; a run
restarted at time T writes a new <T> directory, whose rows replace the
earlier ones from T on.  bodies_rows(CASE): the bodies function object's
(bodies/<start>/bodies.dat)."""
import os


def function_rows(case, name, file):
    base = os.path.join(case, 'postProcessing', name)
    starts = sorted((float(s), s) for s in os.listdir(base)
                    if os.path.isfile(os.path.join(base, s, file)))
    for k, (t0, s) in enumerate(starts):
        t1 = starts[k + 1][0] if k + 1 < len(starts) else float('inf')
        for line in open(os.path.join(base, s, file)):
            c = line.split()
            if line.startswith('#') or not c:
                continue
            if t0 <= float(c[0]) < t1:
                yield c


def bodies_rows(case):
    return function_rows(case, 'bodies', 'bodies.dat')
