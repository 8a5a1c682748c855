#!/bin/bash
# Plots (gnuplot) and images (pvbatch) of the floating-bodies case; called
# by Allrun, can be rerun on its own.
cd "$(dirname "$0")" || exit 1
# the project's functions through the environment that Make/bashrc sets,
# as OpenFOAM's tutorials reach RunFunctions: a copy of this tutorial runs
# anywhere once "source <vheFoam>/Make/bashrc" is done
[ -n "${VHE_ROOT:-}" ] || [ ! -f ../common/functions.sh ] || VHE_ROOT=$(cd ../.. && pwd)
. "${VHE_ROOT:?source <vheFoam>/Make/bashrc first}/tutorials/common/functions.sh"
d=cases/bodies
dat=$d/postProcessing/bodies/0/bodies.dat
mkdir -p results

# Per body: count, volume drift, smallest gap; the water's volume drift
python3 - "$dat" "$d/postProcessing/phaseVolumes/0/volFieldValue.dat" \
    > results/summary.txt <<'PY' || exit 1
import sys
rows = [l.split() for l in open(sys.argv[1]) if not l.startswith("#")]
times = sorted({float(r[0]) for r in rows})
per = {t: [r for r in rows if float(r[0]) == t] for t in times}
v0 = {}
drift = gap = 0.0
gap = min(float(r[-1]) for r in rows if float(r[-1]) >= 0)
for r in rows:
    v0.setdefault(r[1], float(r[4]))
    drift = max(drift, abs(float(r[4]) / v0[r[1]] - 1))
vol = [l.split() for l in open(sys.argv[2]) if not l.startswith("#")]
w = max(abs(float(v[1]) / float(vol[0][1]) - 1) for v in vol)
print(f"bodies per write: {min(len(p) for p in per.values())} to "
      f"{max(len(p) for p in per.values())} over {len(times)} writes")
print(f"largest relative volume drift of a body: {drift:.2e}")
print(f"smallest gap between bodies: {gap:.4f} m")
print(f"relative drift of the water volume: {w:.2e}")
PY
cat results/summary.txt

# one file per body id: t, x, y of its centroid
rm -rf results/tracks; mkdir -p results/tracks
awk '!/^#/ {print $1, $6, $7 > ("results/tracks/" $2 ".dat")}' "$dat"
depth=$(foamDictionary -entry depthWater -value "$d/system/parameters")
W=$(foamDictionary -entry W -value "$d/system/parameters")
gnuplot <<GP || exit 1
set terminal pngcairo size 1000,600 font ",12"
set output 'results/heights.png'
set xlabel 't [s]'; set ylabel 'centroid height [m]'; set grid
set title 'Rigid bodies (rho 600) rising in water: heights (one line per body id)'
stats '$dat' u 2 nooutput
plot for [i=0:int(STATS_max)] sprintf('results/tracks/%d.dat', i) u 1:3 w l lw 2 t sprintf('body %d', i), \
     $depth w l dt 2 lc rgb 'black' t 'water level at rest'
set output 'results/tracks.png'
set size ratio -1
set xlabel 'x [m]'; set ylabel 'y [m]'; set xrange [0:$W]; set yrange [0:*]
set title 'Tracks of the body centroids'
plot for [i=0:int(STATS_max)] sprintf('results/tracks/%d.dat', i) u 2:3 w lp pt 7 ps 0.4 lw 1.5 t sprintf('body %d', i), \
     $depth w l dt 2 lc rgb 'black' t 'water level at rest'
GP

fields=alpha.water,alpha.wood
for f in "$d"/0/alpha.wood.*; do
    [ -f "$f" ] && fields="$fields,$(basename "$f")"
done
vhe_pvbatch results/log.pvbatch "$VHE_ROOT/tutorials/common/renderPhases.py" "$d/bodies.foam" results/scene \
    "$fields" 0 0.5 1 3 || exit 1
echo "Results in $(pwd)/results: $(ls results | tr '\n' ' ')"
