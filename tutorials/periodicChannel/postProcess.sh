#!/bin/bash
# Summary table, plots (gnuplot) and images (pvbatch) of the periodic
# channel cases in cases/*; called by Allrun, can be rerun on its own.
cd "$(dirname "$0")" || exit 1
# the project's functions through the environment that Make/bashrc sets,
# as OpenFOAM's tutorials reach RunFunctions: a copy of this tutorial runs
# anywhere once "source <vheFoam>/Make/bashrc" is done
[ -n "${VHE_ROOT:-}" ] || [ ! -f ../common/functions.sh ] || VHE_ROOT=$(cd ../.. && pwd)
. "${VHE_ROOT:?source <vheFoam>/Make/bashrc first}/tutorials/common/functions.sh"
mkdir -p results

python3 summary.py cases results || exit 1
column -s, -t results/summary.csv

# Q/Q_th over time and u1 profiles, all cases on one plot each
plots=""
for d in cases/*/; do
    n=$(basename "$d")
    plots="$plots '$d/postProcessing/flowRate/0/surfaceFieldValue.dat'"
    plots="$plots u 1:(-\$2/Qth) w l lw 2 t '$n',"
done
Qth=$(awk -F, 'NR==2{print $7}' results/summary.csv)
gnuplot <<GP || exit 1
set terminal pngcairo size 900,600 font ",12"
set output 'results/flowRate.png'
set xlabel 't [s]'; set ylabel 'Q / Q_{th}'; set grid
set title 'Periodic channel with deformable disks: flow rate'
set key bottom left
Qth = $Qth
plot ${plots%,}, 1 dt 2 lc rgb 'black' t 'no disks, exact'
GP

profiles=""
for d in cases/*/; do
    n=$(basename "$d")
    last=$(cd "$d/postProcessing/profile" && ls | sort -g | tail -1)
    profiles="$profiles '$d/postProcessing/profile/$last/midChannel_U.xy' u 1:2 w l lw 2 t '$n',"
done
f=$(foamDictionary -entry f -value parameters)
mu=$(foamDictionary -entry mu -value parameters)
L=$(foamDictionary -entry L -value parameters)
gnuplot <<GP || exit 1
set terminal pngcairo size 900,600 font ",12"
set output 'results/profiles.png'
set xlabel 'x_2 [m]'; set ylabel 'u_1 at x_1 = L/2, final time [m/s]'; set grid
set title 'Velocity profiles across the channel'
set key bottom center
plot $profiles \
     $f/(2*$mu)*x*($L - x) dt 2 lc rgb 'black' t 'Poiseuille, no disks'
GP

# phi_s = 0.5 contours over vorticity at the final time (ParaView)
for d in cases/*/; do
    [ -f "$d/0/alpha.rubber" ] || continue
    n=$(basename "$d")
    vhe_pvbatch "results/log.pvbatch.$n" render.py "$d/$n.foam" \
        "results/disks_$n.png" || exit 1
done
echo "Results in $(pwd)/results: $(cd results && ls ./*.csv ./*.png | tr '\n' ' ')"
