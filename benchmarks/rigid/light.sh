#!/bin/bash
# light.sh DIR [CELLS]: light rigid bodies rising through a free surface.
# A box (0.3 x 0.1) and a disk (r 0.07) of rho_s 100, a tenth of the
# water's (nu 1e-2, air above; a 1 x 1 m tank of CELLS x CELLS cells, 40
# by default), released with their lowest point 0.2 m under the surface,
# run to t = 40.  Prints each body's mean draft over 35 <= t <= 40 (the
# water level at the wall minus its lowest point) against Archimedes'
# (the box: (rho_s - rho_air)/(rho_w - rho_air) x 0.1; the disk: the
# circular segment of that share of its area), in per cent of its
# height, and its largest tilt after t = 5 (rad; the disk's turning is
# free).  About 2 min at 40 cells, 16 at 80.
. "$(dirname "$0")/../../tests/cases/lib.sh" 2>/dev/null
d=$1 n=${2:-40}
mkdir -p "$d"
common=(nx="$n" ny="$n" depthOil=0 depthWater=0.5 nuWater=1e-2 writeInterval=5
        blockBottom=0.3 rhoSolid=100 endTime=40 rigid=yes)
printf "# %-5s %10s %12s %10s %10s\n" body draft Archimedes "error % h" tilt
for c in box disk; do
    case $c in
        box) extra=(shape=box blockWidth=0.3 blockHeight=0.1); h=0.1 ;;
        disk) extra=(shape=disk radius=0.07); h=0.14 ;;
    esac
    rm -rf "${d:?}/$c"
    sceneCase floatingBlock "$d/$c" "${common[@]}" "${extra[@]}" \
        && run "$d/$c" setFields && run "$d/$c" setBodies && run "$d/$c" vheFoam \
        || { echo "$c failed: $d/$c" >&2; continue; }
    draft=$(python3 "$TESTS_DIR/floating.py" bodyDraft "$d/$c" "$h" 35)
    tilt=$(awk '!/^#/ && $1 >= 5 {a = $12 < 0 ? -$12 : $12; if (a > m) m = a} END {print m + 0}' \
        "$d/$c/postProcessing/rigidBodies/0/poses.dat")
    python3 - "$c" "$draft" "$h" "$tilt" <<'PY'
import math, sys
c, draft, h, tilt = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
share = (100 - 1)/(1000 - 1)
if c == 'box':
    exact = share*h
else:
    r = h/2
    seg = lambda x: r*r*math.acos((r - x)/r) - (r - x)*math.sqrt(2*r*x - x*x)
    lo, hi = 0.0, 2*r
    for _ in range(100):
        mid = (lo + hi)/2
        lo, hi = (mid, hi) if seg(mid) < share*math.pi*r*r else (lo, mid)
    exact = lo
print('  %-5s %10.5f %12.5f %10.2f %10s' % (c, draft, exact, 100*(draft - exact)/h, tilt))
PY
done
