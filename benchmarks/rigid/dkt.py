#!/usr/bin/env python3
"""dkt.py DIR [PNG]: the two disks of a dkt.sh case per write (bodies function
object, by body id): t, the centre (x, y) of the disk that started below
and of the one above, their gap in diameters; then the tumbling time (the
first write where the disk that started below is the higher; -1: never)
and the kissing time, the write of their smallest gap before it (contact
keeps them about 1.5 cells apart, so the gap does not close).  With PNG,
a gnuplot figure of both heights and the gap against time."""
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bodiesdat import bodies_rows  # noqa: E402

d = sys.argv[1]
dia = 2e-3
rows = {}
for c in bodies_rows(d):
    rows.setdefault(float(c[0]), {})[int(c[1])] = (float(c[5]), float(c[6]))
times = sorted(rows)
ids = sorted(rows[times[0]], key=lambda i: rows[times[0]][i][1])[:2]
tumble = -1
gaps = []
table = []
for t in times:
    if not all(i in rows[t] for i in ids):
        print('%.2f a disk is missing' % t)
        continue
    (xl, yl), (xh, yh) = rows[t][ids[0]], rows[t][ids[1]]
    gap = ((xl - xh)**2 + (yl - yh)**2)**0.5/dia - 1
    line = '%.2f %.5f %.5f %.5f %.5f %.3f' % (t, xl, yl, xh, yh, gap)
    print(line)
    table.append(line)
    if tumble < 0:
        gaps.append((gap, t))
        if yl > yh:
            tumble = t
gmin, kiss = min(gaps)
print('# kissing at t = %g s (smallest gap %.3f d), tumbling at t = %g s'
      % (kiss, gmin, tumble))

if len(sys.argv) > 2:
    png = sys.argv[2]
    dat = png[:-4] + '.dat'
    open(dat, 'w').write('# t x_low y_low x_high y_high gap/d\n' + '\n'.join(table) + '\n')
    subprocess.run(['gnuplot'], check=True, text=True, input=f"""
set terminal pngcairo size 900,500
set output '{png}'
set xlabel 't [s]'
set ylabel 'height of the centre [cm]'
set y2label 'gap [diameters]'
set y2tics
set ytics nomirror
set key top right
set title 'Drafting, kissing, tumbling: kissing {kiss:g} s, tumbling {tumble:g} s'
plot '{dat}' u 1:($3*100) w l lw 2 t 'disk released below', \
     '' u 1:($5*100) w l lw 2 t 'disk released above', \
     '' u 1:6 axes x1y2 w l dt 2 t 'gap'
""")
