#!/usr/bin/env python3
"""faxen.py DIR...: F/(mu U) of each faxen.sh case at its last step (the
fluid's force on the disk, postProcessing/fixedBodies/0/forces.dat,
over the cell depth D/CELLS_PER_D; mu 1, U 0.01) against Faxen's 10.558.
Prints: dir, F/(mu U), relative error.
"""
import math
import sys

a_l = 1/8.0
ref = 4*math.pi/(math.log(1/a_l) - 0.9157 + 1.7244*a_l**2 - 1.7302*a_l**4
                 + 2.4056*a_l**6 - 4.5913*a_l**8)
for d in sys.argv[1:]:
    fy = None
    for line in open(d + '/postProcessing/fixedBodies/0/forces.dat'):
        if not line.startswith('#') and line.split():
            fy = float(line.split()[3])
    dz = None
    for line in open(d + '/system/blockMeshDict'):
        if line.startswith('dz'):
            n = float(line.split('/')[1].split('}')[0])
            dz = 0.1/n
    k = fy/dz/(1.0*0.01)
    print('%s %.4f %+.4f' % (d, k, k/ref - 1))
