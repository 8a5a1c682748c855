#!/bin/bash
# Plots (gnuplot) and images (pvbatch) of the floating-disk case; called by
# Allrun, can be rerun on its own.
cd "$(dirname "$0")" || exit 1
# the project's functions through the environment that Make/bashrc sets,
# as OpenFOAM's tutorials reach RunFunctions: a copy of this tutorial runs
# anywhere once "source <vheFoam>/Make/bashrc" is done
[ -n "${VHE_ROOT:-}" ] || [ ! -f ../common/functions.sh ] || VHE_ROOT=$(cd ../.. && pwd)
. "${VHE_ROOT:?source <vheFoam>/Make/bashrc first}/tutorials/common/functions.sh"
d=cases/disk
mkdir -p results

# Relative drift of each phase volume, and the disk's height against the
# oil/water interface of the undisturbed layers
vhe_volume_drift "$d/postProcessing/phaseVolumes/0/volFieldValue.dat" \
    results/volumeDrift.dat || exit 1
awk '!/^#/ {print $1, $13}' "$d/postProcessing/solidDiagnostics/0/solidDiagnostics.dat" \
    > results/diskHeight.dat
interface=$(foamDictionary -entry depthWater -value "$d/system/parameters")
gnuplot <<GP || exit 1
set terminal pngcairo size 1000,600 font ",12"
set output 'results/volumeDrift.png'
set xlabel 't [s]'; set ylabel 'V(t)/V(0) - 1'; set grid
set title 'Phase volumes: relative drift (seed 003: every volume conserved)'
plot for [k=2:5] 'results/volumeDrift.dat' u 1:k w l lw 2 \
     t word("water oil air disk", k - 1)
set output 'results/diskHeight.png'
set ylabel 'height of the disk centre [m]'
set title 'Soft disk (rho 900) sinking through oil (800) onto water (1000)'
plot 'results/diskHeight.dat' u 1:2 w l lw 2 t 'vheFoam', \
     $interface w l dt 2 lw 2 t 'oil/water interface at rest'
GP

vhe_pvbatch results/log.pvbatch "$VHE_ROOT/tutorials/common/renderPhases.py" "$d/disk.foam" results/scene \
    alpha.water,alpha.oil,alpha.block 0 1 2 5 || exit 1
echo "Results in $(pwd)/results: $(cd results && ls ./*.dat ./*.png | tr '\n' ' ')"
