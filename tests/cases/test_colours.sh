#!/bin/bash
# Bodies that stay bodies (colours: vheMixture, setBodies, bodyColours).
# 64 cells, disks of radius 0.1 (6.4 cells), G 10 Pa, t <= 3, writes
# every 0.1 (the bodies function object):
#  - shear: two disks in plane Couette flow (walls at y = 0, 1 moving at
#    -1 and +1 m/s, mu 1 Pa s), the upper one behind the lower, 3 cells
#    apart: setBodies gives them two colours; they meet, roll over each
#    other and part, the classic two-particle interaction: 2 bodies (ids
#    0 and 1) at every write, each body's volume kept to 1e-6, and further
#    apart across the flow after the encounter than before (measured
#    0.06 -> 0.13 m); 2 ranks (the processor boundary y = 0.5 between
#    them) give the rows of the serial run;
#  - sedimentation: two heavy disks (rho_s 2, mu 0.1, body force 100 m/s^2
#    down) one above the other, 0.2 apart, so both take colour 0: the
#    upper one lands on the lower one, which rests on the wall.
#    bodyColours moves one to colour 1 as they approach (the log says
#    so); wanted: 2 bodies at every write, each body's volume kept to
#    1e-6, the smallest gap above half a cell.  KNOWN lines since the
#    solids are carried geometrically: the lower disk, flattened on the
#    floor (G 10 Pa under 20 Pa of weight), leaves shreds of its corners in
#    the wall cells as it rounds up (up to 4 regions at a write, bodies 0
#    and 1 always there, their counted volume within 0.5 to 1.3 %, 1.9 to
#    2.7 % with contact, moved across that range by round-off changes of
#    the transport; below a quarter of a cell inside the outline a cell carries
#    no stress, vhe_body_weight, so the corners shred more easily than
#    when every cell was stressed in proportion to phi_s: 2.1 %), and the disks
#    come within 0.09 cell (MULES's compression kept them 0.9 cell apart);
#    at 128 cells the same (a shred of its skin on the floor).  With
#    contact between them (contact { strength 0.5; }, off by default for
#    soft bodies) the gap widens (0.18 cell), the shreds stay.  With colours 1
#    the same disks merge (one body at t = 1.7, 1.8) and exchange 1.2 % of
#    their volume: the test can fail;
#  - dense: scene A's channel with 40 disks of radius 0.05 (area fraction
#    0.31, G 0.1) to t = 20: setBodies' colours (those the packing needs
#    plus two spares: 7) keep 40 bodies at every write, each body's
#    volume kept to 1e-6 (measured 2.5e-9; with four colours bodies found
#    no free colour six times and lost up to 6e-5 of their volume), the
#    smallest gap above a cell (measured 1.2 cells: the packing's gap).
. "$(dirname "$0")/lib.sh"

dat=postProcessing/bodies/0/bodies.dat

# colourCase DIR COLOURS KIND: the two disks ("" : setBodies' choice of
# colours); KIND shear or sediment
colourCase() {
    local d=$1 colours=$2 kind=$3 entries c1 c2
    if [ "$kind" = shear ]; then
        entries=(f=0 G=10) c1="0.38 0.53" c2="0.62 0.47"
    else
        entries=(f=0 fy=-100 rhoDisk=2 mu=0.1 G=10) c1="0.5 0.15" c2="0.5 0.55"
    fi
    channelCase "$d" cells=64 nDisks=2 endTime=3 writeInterval=0.1 \
        "${entries[@]}" || return 1
    cat > "$d/system/setBodiesDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object setBodiesDict; }
bodies
{
    a { material rubber; shape cylinder; centre ($c1 0.5); radius 0.1; axis (0 0 1); }
    b { material rubber; shape cylinder; centre ($c2 0.5); radius 0.1; axis (0 0 1); }
}
DICT
    python3 - "$d" "$colours" <<'PY' || return 1
import re, sys
d, colours = sys.argv[1:3]
if colours:
    p = d + '/constant/vheProperties'
    s = re.sub(r'(rubber \{[^}]*)\}', r'\1 colours %s; }' % colours, open(p).read())
    open(p, 'w').write(s)
PY
    if [ "$kind" = shear ]; then couetteWalls "$d" 64 || return 1; fi
    run "$d" setBodies
}

# counts FILE: "fewest most idsOk" bodies per write (idsOk 1: ids 0 and 1)
counts() {
    awk '!/^#/ {n[$1]++; s[$1] += $2}
        END {lo = 1e9; hi = 0; ok = 1
             for (t in n) {if (n[t] < lo) lo = n[t]; if (n[t] > hi) hi = n[t]
                           if (s[t] != 1) ok = 0}
             print lo, hi, ok}' "$1"
}

# both FILE: 1 if ids 0 and 1 are at every write, else 0
both() {
    awk '!/^#/ {t[$1] = 1; if ($2 == 0) a[$1] = 1; if ($2 == 1) b[$1] = 1}
        END {ok = 1; for (s in t) if (!(s in a) || !(s in b)) ok = 0; print ok}' "$1"
}

# drift01 FILE: largest relative volume change of ids 0 and 1
drift01() {
    awk '!/^#/ && $2 <= 1 {if (!($2 in v0)) v0[$2] = $5; d = $5/v0[$2] - 1
        if (d < 0) d = -d; if (d > m) m = d} END {printf "%.3e\n", m}' "$1"
}

# drift FILE: largest relative volume change of one id
drift() {
    awk '!/^#/ {if (!($2 in v0)) v0[$2] = $5; d = $5/v0[$2] - 1
        if (d < 0) d = -d; if (d > m) m = d} END {printf "%.3e\n", m}' "$1"
}

# ---- shear
pr="$WORK/shear"
colourCase "$pr" "" shear || { fail setupShear "$pr"; finish; }
grep -q "2 bodies in 4 colours" "$pr/log.setBodies" \
    && [ "$(grep -c "(rubber, colour 0)" "$pr/log.setBodies")" = 1 ] \
    || fail shearColours "$pr/log.setBodies: expected 2 bodies in 4 colours (two used, two spare), one of colour 0"
cp -r "$pr" "$pr.par"
run "$pr" vheFoam || fail shearRun "$pr/log.vheFoam"
read -r wmin wmax ids <<< "$(counts "$pr/$dat")"
check shearCount "$wmin == 2 and $wmax == 2 and $ids == 1" \
    "bodies per write $wmin..$wmax (ids 0 and 1: $ids)"
d=$(drift "$pr/$dat")
check shearVolume "$d < 1e-6" "largest relative volume drift of a body $d"
read -r dy0 dy1 gmin <<< "$(awk '!/^#/ {y[$1, $2] = $7; t[$1] = 1
        if ($NF >= 0 && (gm == "" || $NF < gm)) gm = $NF}
    END {first = 1e9; last = -1
         for (s in t) {if (s + 0 < first) first = s + 0; if (s + 0 > last) last = s + 0}
         a = y[first, 0] - y[first, 1]; b = y[last, 0] - y[last, 1]
         if (a < 0) a = -a; if (b < 0) b = -b
         printf "%.4f %.4f %.4g\n", a, b, gm}' "$pr/$dat")"
check shearDrift "$dy1 > 1.5*$dy0" \
    "cross-stream distance $dy0 m at t = 0.1, $dy1 m at t = 3 (smallest gap $gmin m)"
run "$pr.par" decomposePar && \
    (cd "$pr.par" && mpirun -np 2 vheFoam -parallel > log.vheFoam 2>&1) \
    || fail shearParallelRun "$pr.par/log.vheFoam"
out=$(python3 "$TESTS_DIR/bodiesDiff.py" "$pr/$dat" "$pr.par/$dat")
cmax=$(echo "$out" | awk '$1 ~ /^centroid|^volume|^colour/ {if ($2 > m) m = $2} END {print m + 0}')
check shearParallel "'keys equal' in '''$out''' and $cmax < 1e-3" \
    "serial and 2 ranks: $(echo "$out" | sed -n 2p), largest centroid, volume or colour difference $cmax (a sixteenth of a cell: the solvers' tolerances, grown through the encounter)"

# ---- sedimentation onto each other
sd="$WORK/sediment"
colourCase "$sd" "" sediment || { fail setupSediment "$sd"; finish; }
n0=$(grep -c "(rubber, colour 0)" "$sd/log.setBodies")
check sedimentSameColour "$n0 == 2" "bodies of colour 0 at the start: $n0"
run "$sd" vheFoam || fail sedimentRun "$sd/log.vheFoam"
moves=$(grep "moved to another colour" "$sd/log.vheFoam" | awk '{s += $3} END {print s + 0}')
check sedimentRecoloured "$moves >= 1" "$moves colour moves in the log"
read -r wmin wmax ids <<< "$(counts "$sd/$dat")"
b01=$(both "$sd/$dat") d01=$(drift01 "$sd/$dat")
why="the lower disk, flattened on the no-slip floor, leaves shreds of its corners in the wall cells as it rounds up; without compression the colours come within a tenth of a cell, docs/limitations.md"
checkKnown sedimentCount "$wmin == 2 and $wmax == 2 and $ids == 1" "$b01 == 1 and $wmax <= 4" \
    "bodies per write $wmin..$wmax (ids 0 and 1: $ids, both at every write: $b01)" "$why"
d=$(drift "$sd/$dat")
checkKnown sedimentVolume "$d < 1e-6" "$d01 < 0.03" \
    "largest relative volume drift of a body $d (of bodies 0 and 1: $d01)" "$why"
gmin=$(awk '!/^#/ && $NF >= 0 && (g == "" || $NF < g) {g = $NF} END {print g}' "$sd/$dat")
checkKnown sedimentGap "$gmin > 0.5/64" "$gmin > 0" "smallest gap $gmin m (cell 0.0156 m)" "$why"

# ---- the same with contact between the soft disks
sc="$WORK/sedimentContact"
colourCase "$sc" "" sediment \
    && sed -i 's/^solids/contact { strength 0.5; }\nsolids/' "$sc/constant/vheProperties" \
    || { fail setupSedimentContact "$sc"; finish; }
run "$sc" vheFoam || fail sedimentContactRun "$sc/log.vheFoam"
read -r wmin wmax ids <<< "$(counts "$sc/$dat")"
d=$(drift "$sc/$dat")
nt=$(grep -c "bodies in contact" "$sc/log.vheFoam")
gc=$(awk '!/^#/ && $NF >= 0 && (g == "" || $NF < g) {g = $NF} END {print g}' "$sc/$dat")
b01=$(both "$sc/$dat") d01=$(drift01 "$sc/$dat")
# The smallest gap with contact is not a robust figure: changes of the
# solids' transport at round-off (the same fields to 1e-11 at t = 0.1)
# gave 5.1e-4, 2.6e-3 and 3.0e-3 m with contact against 1.27e-3, 1.36e-3
# and 8.2e-4 m without, so the lower bar asks only that the disks never
# touch (gap > 0), not that contact widens it
checkKnown sedimentContact "$wmin == 2 and $wmax == 2 and $d < 1e-6 and $nt > 0 and $gc > $gmin" \
    "$b01 == 1 and $d01 < 0.03 and $nt > 0 and $gc > 0" \
    "with contact { strength 0.5; }: bodies per write $wmin..$wmax, volume drift $d (bodies 0 and 1: $d01), $nt steps in contact, smallest gap $gc m (without contact $gmin m)" "$why"

one="$WORK/sedimentOneColour"
colourCase "$one" 1 sediment || { fail setupOneColour "$one"; finish; }
run "$one" vheFoam || fail oneColourRun "$one/log.vheFoam"
read -r wmin wmax ids <<< "$(counts "$one/$dat")"
d=$(drift "$one/$dat")
check oneColourMerges "$wmin < 2 or $d > 1e-3" \
    "with one colour: bodies per write $wmin..$wmax, largest volume drift of a body $d"
# ---- dense suspension in scene A's channel
dn="$WORK/dense"
channelCase "$dn" cells=64 nDisks=40 endTime=20 writeInterval=1 \
    && run "$dn" setBodies || { fail setupDense "$dn"; finish; }
run "$dn" vheFoam || fail denseRun "$dn/log.vheFoam"
read -r wmin wmax ids <<< "$(counts "$dn/$dat")"
last=$(awk '!/^#/ {t = $1} END {print t}' "$dn/$dat")
nc=$(sed -n 's/.*bodies in \([0-9]*\) colours.*/\1/p' "$dn/log.setBodies")
nm=$(grep "moved to another colour" "$dn/log.vheFoam" | awk '{s += $3} END {print s + 0}')
check denseCount "$wmin == 40 and $wmax == 40 and $last == 20" \
    "bodies per write $wmin..$wmax up to t = $last ($nc colours, $nm recolourings)"
d=$(drift "$dn/$dat")
check denseVolume "$d < 1e-6" "largest relative volume drift of a body $d"
gmin=$(awk '!/^#/ && $NF >= 0 && (g == "" || $NF < g) {g = $NF} END {print g}' "$dn/$dat")
check denseGap "$gmin > 1.0/64" "smallest gap $gmin m (cell 0.0156 m)"
finish
