#!/bin/bash
# Restart: a run stopped at a written time and restarted from it ends where
# the continuous run ends (disks in the channel, semi-implicit elasticity,
# B*, alpha and U compared at the end).  The cases write 17 digits, so the
# restart must continue exactly: bound 1e-12 of the field scale (measured
# 1.7e-14 for B*, 1e-17 for U).  (With 8 digits B* differs by 2.5e-6 of
# its scale at t = 0.6: the limiters of the transport are not smooth
# functions of their input, and cells of little solid amplify it.)  The
# same for six rigid disks, drawn from their poses (rigidPoses).
. "$(dirname "$0")/lib.sh"

cont="$WORK/continuous" rest="$WORK/restarted"
channelCase "$cont" cells=32 nDisks=6 G=0.5 endTime=0.6 writeInterval=0.3 \
    || { fail setup blockMesh; finish; }
sed -i 's/relTol          0.01;/relTol 0;/' "$cont/system/fvSolution"
sed -i 's/^writePrecision .*/writePrecision  17;/' "$cont/system/controlDict"
run "$cont" setBodies || { fail setup setBodies; finish; }
cp -r "$cont" "$rest"
run "$cont" vheFoam || fail continuousRun "$cont/log.vheFoam"

# stop at the first written time, then restart from it (startFrom latestTime)
foamDictionary -entry endTime -set 0.3 "$rest/system/parameters" > /dev/null
run "$rest" vheFoam || fail firstPart "$rest/log.vheFoam"
foamDictionary -entry endTime -set 0.6 "$rest/system/parameters" > /dev/null
run "$rest" vheFoam || fail secondPart "$rest/log.vheFoam"

for f in U Bstar alpha.rubber; do
    read -r d m <<< "$(maxFieldDiff "$cont" "$rest" 0.6 "$f")"
    check "restart_$f" "$d <= 1e-12*$m" "max |$f continuous - restarted| = $d at t = 0.6 (scale $m)"
done

# Rigid disks: their poses and the fixed point's history
# (<time>/uniform/rigidBodies, 17 digits) carry on too, so the restarted
# run draws and holds them as the continuous one does.  The first step
# after the restart differs by round-off (8.5e-14 of the scale in U) and
# the bodies' fixed point carries it on: 1.1e-11 at t = 0.6, so the bound
# is 1e-10 (without the history kept: 2.6e-6)
rcont="$WORK/rigidContinuous" rrest="$WORK/rigidRestarted"
channelCase "$rcont" cells=32 nDisks=6 rigid=yes endTime=0.6 \
    writeInterval=0.3 || { fail setupRigid blockMesh; finish; }
sed -i 's/relTol          0.01;/relTol 0;/' "$rcont/system/fvSolution"
sed -i 's/^writePrecision .*/writePrecision  17;/' "$rcont/system/controlDict"
run "$rcont" setBodies || { fail setupRigid setBodies; finish; }
cp -r "$rcont" "$rrest"
run "$rcont" vheFoam || fail rigidContinuousRun "$rcont/log.vheFoam"
foamDictionary -entry endTime -set 0.3 "$rrest/system/parameters" > /dev/null
run "$rrest" vheFoam || fail rigidFirstPart "$rrest/log.vheFoam"
foamDictionary -entry endTime -set 0.6 "$rrest/system/parameters" > /dev/null
run "$rrest" vheFoam || fail rigidSecondPart "$rrest/log.vheFoam"
for f in U alpha.rubber; do
    read -r d m <<< "$(maxFieldDiff "$rcont" "$rrest" 0.6 "$f")"
    check "restartRigid_$f" "$d <= 1e-10*$m" "rigid disks: max |$f continuous - restarted| = $d at t = 0.6 (scale $m)"
done
finish
