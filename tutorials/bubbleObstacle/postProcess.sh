#!/bin/bash
# Plots (gnuplot) and images (pvbatch) of a bubbleObstacle case; called by
# Allrun, can be rerun on its own.   ./postProcess.sh [amr|uniform]
cd "$(dirname "$0")" || exit 1
# the project's functions through the environment that Make/bashrc sets,
# as OpenFOAM's tutorials reach RunFunctions: a copy of this tutorial runs
# anywhere once "source <vheFoam>/Make/bashrc" is done
[ -n "${VHE_ROOT:-}" ] || [ ! -f ../common/functions.sh ] || VHE_ROOT=$(cd ../.. && pwd)
. "${VHE_ROOT:?source <vheFoam>/Make/bashrc first}/tutorials/common/functions.sh"
name=${1:-amr}
d=cases/$name
mkdir -p results

# Relative drift of each phase volume; cell count per step from the log
vhe_volume_drift "$d/postProcessing/phaseVolumes/0/volFieldValue.dat" \
    "results/volumeDrift_$name.dat" || exit 1
awk '/^Time = / {t = $3} /^Mesh refined: / {print t, $3}' "$d/log.vheFoam" \
    > "results/cells_$name.dat"
ncols=$(awk '!/^#/ {print NF; exit}' "results/volumeDrift_$name.dat")
gnuplot <<GP || exit 1
set terminal pngcairo size 1000,600 font ",12"
set output 'results/volumeDrift_$name.png'
set xlabel 't [s]'; set ylabel 'V(t)/V(0) - 1'; set grid
set title 'Phase volumes through refinement and unrefinement ($name)'
plot for [k=2:$ncols] 'results/volumeDrift_$name.dat' u 1:k w l lw 2 \
     t word("water air ball", k - 1)
GP
# the cell count, when the mesh changed
if [ -s "results/cells_$name.dat" ]; then
    gnuplot <<GP || exit 1
set terminal pngcairo size 1000,600 font ",12"
set output 'results/cells_$name.png'
set xlabel 't [s]'; set ylabel 'cells'; set grid
set title 'Cell count of the refined mesh'
plot 'results/cells_$name.dat' u 1:2 w steps lw 2 t 'dynamicRefineFvMesh'
GP
fi

vhe_pvbatch "results/log.pvbatch.$name" "$VHE_ROOT/tutorials/common/renderPhases.py" "$d/$name.foam" \
    "results/scene_$name" alpha.air,phis 0 0.5 1 1.5 || exit 1
echo "Results in $(pwd)/results: $(cd results && ls ./*"$name"* | tr '\n' ' ')"
