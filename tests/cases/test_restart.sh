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

# restartPair CONT REST ENTRIES...: the channel (32 cells, six disks, to
# t = 0.6, written at 0.3 with 17 digits, relTol 0) with the given
# parameters, run through in CONT and in REST stopped at the first written
# time and restarted from it (startFrom latestTime)
restartPair() {
    local cont=$1 rest=$2 tag; shift 2
    tag=$(basename "$rest")
    channelCase "$cont" cells=32 nDisks=6 endTime=0.6 writeInterval=0.3 "$@" \
        || { fail "${tag}Setup" blockMesh; return 1; }
    sed -i 's/relTol          0.01;/relTol 0;/' "$cont/system/fvSolution"
    sed -i 's/^writePrecision .*/writePrecision  17;/' "$cont/system/controlDict"
    run "$cont" setBodies || { fail "${tag}Setup" setBodies; return 1; }
    cp -r "$cont" "$rest"
    run "$cont" vheFoam || fail "${tag}ContinuousRun" "$cont/log.vheFoam"
    foamDictionary -entry endTime -set 0.3 "$rest/system/parameters" > /dev/null
    run "$rest" vheFoam || fail "${tag}FirstPart" "$rest/log.vheFoam"
    foamDictionary -entry endTime -set 0.6 "$rest/system/parameters" > /dev/null
    run "$rest" vheFoam || fail "${tag}SecondPart" "$rest/log.vheFoam"
}

cont="$WORK/continuous" rest="$WORK/restarted"
restartPair "$cont" "$rest" G=0.5 || finish
for f in U Bstar alpha.rubber; do
    read -r d m <<< "$(maxFieldDiff "$cont" "$rest" 0.6 "$f")"
    check "restart_$f" "$d <= 1e-12*$m" "max |$f continuous - restarted| = $d at t = 0.6 (scale $m)"
done

# Rigid disks: their poses and the fixed point's history
# (<time>/uniform/rigidBodies, 17 digits) carry on too, so the restarted
# run draws and holds them as the continuous one does.  The first step
# after the restart differs by round-off (8.5e-14 of the scale in U) and
# the bodies' fixed point carries it on: 1.7e-11 at t = 0.6, so the bound
# is 1e-10 (without the history kept: 2.6e-6)
rcont="$WORK/rigidContinuous" rrest="$WORK/rigidRestarted"
restartPair "$rcont" "$rrest" rigid=yes || finish
for f in U alpha.rubber; do
    read -r d m <<< "$(maxFieldDiff "$rcont" "$rrest" 0.6 "$f")"
    check "restartRigid_$f" "$d <= 1e-10*$m" "rigid disks: max |$f continuous - restarted| = $d at t = 0.6 (scale $m)"
done
finish
