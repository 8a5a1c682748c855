#!/bin/bash
# lightSphere.sh DIR [CELLS]: the light body of light.sh in 3D.  A rigid
# sphere (r 0.1, rho_s 100, a tenth of the water's) released with its
# centre at 0.15 m in water 0.35 m deep (nu 1e-2, air above) in a closed
# 0.6 m cube of CELLS^3 cells (16 by default; the floatingBlock template
# made 3D: its front and back walls, CELLS cells deep), rises through the
# surface and floats; to t = 10.  Prints the mean draft over t >= 8 (the
# water level in the corner column minus the sphere's lowest point)
# against Archimedes' spherical cap (0.03897 m), in per cent of the
# diameter, the largest relative phase volume drift, and the vertical
# velocity at the end.  About 1 min at 16 cells, 2.6 at 24, 6 at 32.
. "$(dirname "$0")/tank.sh"
d=$1 n=${2:-16}
lightSphereCase "$d" "$n" 10 || exit 1
(run "$d" blockMesh && run "$d" setFields && run "$d" setBodies && run "$d" vheFoam) \
    || { echo "failed: $d" >&2; exit 1; }
draft=$(python3 "$TESTS_DIR/floating.py" bodyDraft "$d" 0.2 8)
drift=$(python3 "$TESTS_DIR/floating.py" volumes "$d")
uy=$(awk '!/^#/ {u = $7} END {print u}' "$d/postProcessing/rigidBodies/0/poses.dat")
awk -v n="$n" -v d="$draft" -v v="$drift" -v u="$uy" 'BEGIN {
    printf "cells %d^3: draft %.5f m, Archimedes 0.03897 m, %+.2f %% of the diameter; volume drift %s; Uy at t = 10 %s m/s\n",
        n, d, 100*(d - 0.03897)/0.2, v, u}'
