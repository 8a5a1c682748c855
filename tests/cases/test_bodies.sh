#!/bin/bash
# The bodies function object (per-body output) in prescribed motions with
# exact answers, and in scene A's channel:
#  - translation U = (1, 0, 0) of a disk of radius 0.15 that starts across
#    the periodic boundary (centre x = 0.95) for one period, on 32 cells,
#    serial and on 2 ranks (the processor boundary y = 0.5 cuts the disk):
#    one body with id 0 at every write, its centroid where the flow puts it
#    (x0 + t, wrapped; bound 1e-3 m, a thirtieth of a cell), its volume
#    that of the disk (1e-6 relative drift; the transport conserves it),
#    omega 0, and serial == 2 ranks (1e-8);
#  - solid rotation at omega = 2 pi about (0.5, 0.5) of a disk at
#    (0.5, 0.7) for one turn on 64 cells: omega_z within 1 % of 2 pi
#    (measured 4.5e-10), the centroid on its circle and D near 0 within
#    1.2 x what the phase fraction's transport leaves at 64 cells
#    (measured 4.8e-3 m, a third of a cell, and 0.0385);
#  - scene A's channel (64 cells, 16 disks, t = 2): 16 bodies with ids
#    0..15 at every write, each id's centroid moving by less than a
#    radius between writes, serial == 2 ranks.
. "$(dirname "$0")/lib.sh"

# prescribed DIR FLOW CENTRE N DT: one disk (r 0.15) in a prescribed flow
prescribed() {
    local d=$1 flow=$2 centre=$3 n=$4 dt=$5
    channelCase "$d" cells="$n" nDisks=1 f=0 endTime=1 writeInterval=0.125 \
        || return 1
    cat > "$d/system/setBodiesDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object setBodiesDict; }
bodies { disk { material rubber; shape cylinder; centre $centre; radius 0.15; axis (0 0 1); } }
DICT
    run "$d" setBodies || return 1
    sed -i "s/^adjustTimeStep .*/adjustTimeStep  no;/; s/^deltaT .*/deltaT          $dt;/" \
        "$d/system/controlDict"
    sed -i "s/^    pRefValue .*/&\n    prescribedVelocity { $flow }/" "$d/system/fvSolution"
}

dat=postProcessing/bodies/0/bodies.dat

# ---- translation across the periodic boundary, serial and 2 ranks
tr="$WORK/translation"
prescribed "$tr" "type translation; U (1 0 0);" "(0.95 0.5 0.5)" 32 0.015625 \
    || { fail setupTranslation "$tr"; finish; }
cp -r "$tr" "$tr.par"
run "$tr" vheFoam || fail translationRun "$tr/log.vheFoam"
run "$tr.par" decomposePar && \
    (cd "$tr.par" && mpirun -np 2 vheFoam -parallel > log.vheFoam 2>&1) \
    || fail translationParallelRun "$tr.par/log.vheFoam"
read -r nrow ids cerr verr wmax <<< "$(awk '!/^#/ {
        n++; if ($2 != 0) ids++
        x = 0.95 + $1; x -= int(x); dx = $6 - x; if (dx < 0) dx = -dx
        if (dx > 0.5) dx = 1 - dx; dy = $7 - 0.5; if (dy < 0) dy = -dy
        if (dx > c) c = dx; if (dy > c) c = dy
        if (!v0) v0 = $5; dv = $5/v0 - 1; if (dv < 0) dv = -dv; if (dv > v) v = dv
        w = $14; if (w < 0) w = -w; if (w > wm) wm = w
    } END {printf "%d %d %.3e %.3e %.3e\n", n, ids, c, v, wm}' "$tr/$dat")"
check translationOneBody "$nrow == 8 and $ids == 0" \
    "$nrow rows (8 writes), $ids rows with another id than 0"
check translationCentroid "$cerr < 1e-3" \
    "largest centroid error $cerr m (32 cells, across the periodic boundary)"
check translationVolume "$verr < 1e-6" "largest volume drift $verr"
check translationNoRotation "$wmax < 1e-6" "largest |omega_z| $wmax rad/s"
out=$(python3 "$TESTS_DIR/bodiesDiff.py" "$tr/$dat" "$tr.par/$dat")
dmax=$(echo "$out" | awk 'NR > 2 {if ($2 > m) m = $2} END {print m + 0}')
check translationParallel "'keys equal' in '''$out''' and $dmax < 1e-8" \
    "serial and 2 ranks: $(echo "$out" | sed -n 2p), largest column difference $dmax"

# ---- solid rotation
ro="$WORK/rotation"
prescribed "$ro" "type rotation; omega 6.283185307179586; origin (0.5 0.5 0);" \
    "(0.5 0.7 0.5)" 64 0.00125 || { fail setupRotation "$ro"; finish; }
run "$ro" vheFoam || fail rotationRun "$ro/log.vheFoam"
read -r werr rerr dmax <<< "$(awk '!/^#/ {
        w = $14/6.283185307179586 - 1; if (w < 0) w = -w; if (w > we) we = w
        r = sqrt(($6 - 0.5)^2 + ($7 - 0.5)^2) - 0.2; if (r < 0) r = -r; if (r > re) re = r
        if ($15 > dm) dm = $15
    } END {printf "%.3e %.3e %.3e\n", we, re, dm}' "$ro/$dat")"
check rotationOmega "$werr < 0.01" "largest relative error of omega_z $werr"
check rotationCentroid "$rerr < 1.2*4.8e-3" "largest distance from the circle $rerr m"
check rotationShape "$dmax < 1.2*0.0385" "largest Taylor deformation $dmax"

# ---- scene A's channel: 16 disks keep their ids
ch="$WORK/channel"
channelCase "$ch" cells=64 endTime=2 writeInterval=0.5 || { fail setupChannel "$ch"; finish; }
run "$ch" setBodies || fail setupChannel "$ch/log.setBodies"
cp -r "$ch" "$ch.par"
run "$ch" vheFoam || fail channelRun "$ch/log.vheFoam"
run "$ch.par" decomposePar && \
    (cd "$ch.par" && mpirun -np 2 vheFoam -parallel > log.vheFoam 2>&1) \
    || fail channelParallelRun "$ch.par/log.vheFoam"
read -r writes bad jump <<< "$(awk '!/^#/ {
        t[$1] = 1; n[$1]++; if ($2 < 0 || $2 > 15) bad++
        if ($2 in x) { dx = $6 - x[$2]; if (dx < 0) dx = -dx; if (dx > 0.5) dx = 1 - dx
                       dy = $7 - y[$2]; if (dy < 0) dy = -dy; d = sqrt(dx*dx + dy*dy)
                       if (d > j) j = d }
        x[$2] = $6; y[$2] = $7
    } END {w = 0; for (k in t) { w++; if (n[k] != 16) bad++ }; printf "%d %d %.3e\n", w, bad + 0, j}' "$ch/$dat")"
check channelSixteenBodies "$writes == 4 and $bad == 0" \
    "$writes writes of 16 bodies with ids 0..15 ($bad rows or writes otherwise)"
check channelIdsFollow "$jump < 0.05" "largest move of one id between writes $jump m (radius 0.05)"
out=$(python3 "$TESTS_DIR/bodiesDiff.py" "$ch/$dat" "$ch.par/$dat")
dmax=$(echo "$out" | awk 'NR > 2 && $1 !~ /^axis/ {if ($2 > m) m = $2} END {print m + 0}')
check channelParallel "'keys equal' in '''$out''' and $dmax < 1e-7" \
    "serial and 2 ranks: $(echo "$out" | sed -n 2p), largest difference but the axis $dmax"
finish
