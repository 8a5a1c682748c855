# Sourced by squareArray.sh and cubicArray.sh: scene A's channel made a
# periodic unit cell (rho 1, mu 1, body force 0.1 m/s^2 in x) holding one
# rigid body in place.
. "$(dirname "${BASH_SOURCE[0]}")/../../tests/cases/lib.sh" 2>/dev/null

# periodicCell DIR CELLS ENDTIME: the channel's walls a cyclic pair, its
# one disk's material held in place (motion fixed)
periodicCell() {
    local d=$1 n=$2 tend=$3
    rm -rf "$d"
    channelCase "$d" cells="$n" nDisks=1 rigid=yes f=0.1 mu=1 endTime="$tend" \
        writeInterval="$tend" || return 1
    python3 - "$d" <<'PY'
import sys
d = sys.argv[1]
def sub(path, old, new):
    s = open(path).read()
    if old not in s:
        sys.exit(path + ': no ' + old)
    open(path, 'w').write(s.replace(old, new))
# walls -> a cyclic pair
sub(d + '/system/blockMeshDict',
    'walls  { type wall; faces ((0 1 5 4) (3 7 6 2)); }',
    'bottom { type cyclic; neighbourPatch top; faces ((0 1 5 4)); }\n'
    '    top    { type cyclic; neighbourPatch bottom; faces ((3 7 6 2)); }')
sub(d + '/0/U', 'walls { type noSlip; }',
    'bottom { type cyclic; }\n    top { type cyclic; }')
sub(d + '/0/p_rgh', 'walls { type fixedFluxPressure; value uniform 0; }',
    'bottom { type cyclic; }\n    top { type cyclic; }')
sub(d + '/constant/vheProperties', 'rigid yes;', 'rigid yes; motion fixed;')
PY
}

# runCell DIR DT BODY: the cell's one body (BODY, a setBodiesDict entry of
# material rubber), the flow rate every step, a fixed step DT; the mesh,
# the body and the run
runCell() {
    local d=$1 dt=$2 body=$3
    cat > "$d/system/setBodiesDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object setBodiesDict; }
bodies { $body }
DICT
    (cd "$d" && foamDictionary -entry functions/flowRate/writeInterval -set 1 system/controlDict) > /dev/null
    fixedStep "$d" "$dt" || return 1
    (cd "$d" && blockMesh > log.blockMesh 2>&1 && setBodies > log.setBodies 2>&1) || return 1
    (cd "$d" && vheFoam > log.vheFoam 2>&1)
}
