#!/bin/bash
# Plots (gnuplot) and images (pvbatch) of the stairs case; called by
# Allrun, can be rerun on its own.
cd "$(dirname "$0")" || exit 1
# the project's functions through the environment that Make/bashrc sets,
# as OpenFOAM's tutorials reach RunFunctions: a copy of this tutorial runs
# anywhere once "source <vheFoam>/Make/bashrc" is done
[ -n "${VHE_ROOT:-}" ] || [ ! -f ../common/functions.sh ] || VHE_ROOT=$(cd ../.. && pwd)
. "${VHE_ROOT:?source <vheFoam>/Make/bashrc first}/tutorials/common/functions.sh"
d=cases/stairs
mkdir -p results

vhe_volume_drift "$d/postProcessing/phaseVolumes/0/volFieldValue.dat" \
    results/volumeDrift.dat || exit 1
cp "$d/postProcessing/stepLevels/0/liquidLevel.dat" results/stepLevels.dat
gnuplot <<GP || exit 1
set terminal pngcairo size 1000,600 font ",12"
set output 'results/stepLevels.png'
set xlabel 't [s]'; set ylabel 'water depth [m]'; set grid
set title 'Water falling down stairs: depth on each step (step 1 at the top)'
plot for [k=2:5] 'results/stepLevels.dat' u 1:k w l lw 2 t sprintf('step %d', k - 1)
set output 'results/volumeDrift.png'
set ylabel 'V(t)/V(0) - 1'; set title 'Phase volumes: relative drift'
plot for [k=2:3] 'results/volumeDrift.dat' u 1:k w l lw 2 t word("water air", k - 1)
GP

vhe_pvbatch results/log.pvbatch "$VHE_ROOT/tutorials/common/renderPhases.py" "$d/stairs.foam" results/scene \
    alpha.water 0 0.5 1 2 3 || exit 1
echo "Results in $(pwd)/results: $(cd results && ls ./*.dat ./*.png | tr '\n' ' ')"
