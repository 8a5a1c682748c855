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

# The sweep (Allrun -sweep): nu_m/nu0 against the area fraction per
# material, with the dilute limit 1 + 2 phi of rigid disks
if ls -d cases/phi* > /dev/null 2>&1; then
    python3 sweep.py results/summary.csv results || exit 1
    sweeps=""
    for f in results/sweep_*.dat; do
        g=${f#results/sweep_}; g=${g%.dat}
        if [ "$g" = rigid ]; then t="rigid"; else t="G = $g Pa"; fi
        sweeps="$sweeps '$f' u 1:2 w lp lw 2 pt 7 t '$t',"
    done
    gnuplot <<GP || exit 1
set terminal pngcairo size 900,600 font ",12"
set output 'results/sweep.png'
set xlabel 'area fraction of the disks'; set ylabel 'nu_m / nu_0'; set grid
set title 'Effective viscosity of the suspension (Q_{th} / Q), $(foamDictionary -entry cells -value parameters) cells'
set key top left; set xrange [0:0.35]
plot ${sweeps} 1 + 2*x dt 2 lc rgb 'black' t 'dilute rigid disks, 1 + 2 phi'
GP
fi

# Per-body trajectories: each disk's height across the channel over time
for d in cases/*/; do
    dat="$d/postProcessing/bodies/0/bodies.dat"
    [ -f "$dat" ] || continue
    n=$(basename "$d")
    # one file per body id: t, x, y of its centroid
    tracks=results/tracks_$n
    rm -rf "$tracks"; mkdir -p "$tracks"
    awk -v o="$tracks" '!/^#/ {print $1, $6, $7 > (o "/" $2 ".dat")}' "$dat"
    gnuplot <<GP || exit 1
set terminal pngcairo size 900,600 font ",12"
set output 'results/trajectories_$n.png'
set xlabel 't [s]'; set ylabel 'centroid x_2 [m]'; set grid
set title 'Disk trajectories across the channel, $n (one line per body id)' noenhanced
stats '$dat' u 2 nooutput
set yrange [0:$(foamDictionary -entry L -value parameters)]
plot for [i=0:int(STATS_max)] sprintf('$tracks/%d.dat', i) u 1:3 w l lw 1.5 notitle
GP
done

# phi_s = 0.5 contours over vorticity at the final time (ParaView)
for d in cases/*/; do
    [ -f "$d/0/alpha.rubber" ] || continue
    n=$(basename "$d")
    vhe_pvbatch "results/log.pvbatch.$n" render.py "$d/$n.foam" \
        "results/disks_$n.png" || exit 1
done
echo "Results in $(pwd)/results: $(cd results && ls ./*.csv ./*.png | tr '\n' ' ')"
