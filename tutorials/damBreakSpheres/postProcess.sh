#!/bin/bash
# h_L files, damping table, h_L plot (gnuplot) and images (pvbatch) of the
# dam-break cases in cases/*; called by Allrun, can be rerun on its own.
cd "$(dirname "$0")" || exit 1
# the project's functions through the environment that Make/bashrc sets,
# as OpenFOAM's tutorials reach RunFunctions: a copy of this tutorial runs
# anywhere once "source <vheFoam>/Make/bashrc" is done
[ -n "${VHE_ROOT:-}" ] || [ ! -f ../common/functions.sh ] || VHE_ROOT=$(cd ../.. && pwd)
. "${VHE_ROOT:?source <vheFoam>/Make/bashrc first}/tutorials/common/functions.sh"
mkdir -p results

python3 damping.py cases results || exit 1
column -s, -t results/damping.csv

plots=""
for f in results/hL_*.dat; do
    n=$(basename "$f" .dat); n=${n#hL_}
    plots="$plots '$f' u 1:2 w l lw 2 t '$n',"
done
gnuplot <<GP || exit 1
set terminal pngcairo size 1000,600 font ",12"
set output 'results/hL.png'
set xlabel 't'; set ylabel 'h_L at x_1 = 0'; set grid
set title 'Dam break with four visco-hyperelastic spheres: liquid level on the left wall'
plot ${plots%,}
GP

# Free surface (alpha.gas = 0.5) and bodies (phi_s = 0.5)
for n in G10 G0.1; do
    d=cases/$n
    [ -d "$d" ] || continue
    vhe_pvbatch "results/log.pvbatch.$n" render.py "$d/$n.foam" "results/scene_$n" \
        0 0.5 1.5 2.0 || exit 1
done
echo "Results in $(pwd)/results: $(cd results && ls ./*.csv ./*.dat ./*.png | tr '\n' ' ')"
