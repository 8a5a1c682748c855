#!/bin/bash
# Plots (gnuplot) and images (pvbatch) of the drop-and-particle case;
# called by Allrun, can be rerun on its own.
cd "$(dirname "$0")" || exit 1
# the project's functions through the environment that Make/bashrc sets,
# as OpenFOAM's tutorials reach RunFunctions: a copy of this tutorial runs
# anywhere once "source <vheFoam>/Make/bashrc" is done
[ -n "${VHE_ROOT:-}" ] || [ ! -f ../common/functions.sh ] || VHE_ROOT=$(cd ../.. && pwd)
. "${VHE_ROOT:?source <vheFoam>/Make/bashrc first}/tutorials/common/functions.sh"
d=cases/drop
mkdir -p results

# time, centroid height and circularity of the drop; the particle's height
awk '!/^#/ {print $1, $4, $10, $2}' "$d/postProcessing/drop/0/phaseStatistics.dat" \
    > results/drop.dat
awk '!/^#/ {print $1, $4, $2}' "$d/postProcessing/particle/0/phaseStatistics.dat" \
    > results/particle.dat
gnuplot <<GP || exit 1
set terminal pngcairo size 1000,600 font ",12"
set output 'results/heights.png'
set xlabel 't [s]'; set ylabel 'centroid height [mm]'; set grid
set title 'Water drop (radius 2.5 mm) carrying a gel particle through oil'
plot 'results/drop.dat' u 1:(1000*\$2) w l lw 2 t 'drop', \
     'results/particle.dat' u 1:(1000*\$2) w l lw 2 t 'particle'
set output 'results/circularity.png'
set ylabel 'circularity of the drop'
set title 'Surface tension keeps the drop round (1: a circle)'
plot 'results/drop.dat' u 1:3 w l lw 2 t 'drop'
GP

vhe_pvbatch results/log.pvbatch "$VHE_ROOT/tutorials/common/renderPhases.py" "$d/drop.foam" results/scene \
    alpha.water,alpha.oil,alpha.gel 0 0.2 0.5 1 || exit 1
echo "Results in $(pwd)/results: $(cd results && ls ./*.dat ./*.png | tr '\n' ' ')"
