"""Table of the refined and uniform bubbleObstacle runs (benchmarks/amr).

Usage: python3 report.py CASES_DIR   (CASES_DIR holds amr/ and uniform/)
"""
import re
import sys


def rows(path):
    with open(path) as f:
        return [[float(x) for x in line.split()] for line in f
                if line.strip() and not line.startswith('#')]


def summary(case):
    log = open(case + '/log.vheFoam').read()
    steps = len(re.findall(r'^Time = ', log, re.M))
    seconds = float(re.findall(r'^ExecutionTime = ([0-9.e+-]+) s', log, re.M)[-1])
    refined = [int(n) for n in re.findall(r'^Mesh refined: (\d+) cells', log, re.M)]
    owner = open(case + '/constant/polyMesh/owner', errors='replace').read()
    cells0 = int(re.search(r'nCells:\s*(\d+)', owner).group(1))
    # cells of every step: the count after the last refinement before it
    counts, n = [], cells0
    for line in log.splitlines():
        m = re.match(r'Mesh refined: (\d+) cells', line)
        if m:
            n = int(m.group(1))
        elif line.startswith('ExecutionTime'):
            counts.append(n)
    volumes = rows(case + '/postProcessing/phaseVolumes/0/volFieldValue.dat')
    drift = max(abs(r[k]/volumes[0][k] - 1) for r in volumes
                for k in range(1, len(r)) if volumes[0][k] > 0)
    ball = rows(case + '/postProcessing/solidDiagnostics/0/solidDiagnostics.dat')
    return [sum(counts)/len(counts), max([cells0] + refined), steps, seconds,
            drift, ball[-1][13]]


print('case,mean cells,max cells,steps,seconds,volume drift,ball height [m]')
for name in ('amr', 'uniform'):
    s = summary(sys.argv[1] + '/' + name)
    print('%s,%.0f,%d,%d,%.1f,%.2g,%.4f' % tuple([name] + s))
