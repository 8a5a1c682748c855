# Sourced by squareArray.sh, cubicArray.sh, stirrer.sh and vortex.sh: scene A's
# channel made a unit cell (rho 1, mu 1) holding one rigid body: periodic
# and driven by a body force of 0.1 m/s^2 in x (periodicCell, the body
# held in place), or a closed box (stirrer.sh).
. "$(dirname "${BASH_SOURCE[0]}")/../../tests/cases/lib.sh" 2>/dev/null

# unitCell DIR CELLS ENDTIME F: the channel with one rigid disk, mu 1,
# body force F
unitCell() {
    rm -rf "$1"
    channelCase "$1" cells="$2" nDisks=1 rigid=yes f="$4" mu=1 endTime="$3" \
        writeInterval="$3"
}

# caseEdits DIR: runs the Python on stdin with d = DIR and sub(path, old,
# new), which replaces old in the file at path and stops if it is not there
caseEdits() {
    python3 -c 'import sys
d = sys.argv[1]
def sub(path, old, new):
    s = open(path).read()
    if old not in s:
        sys.exit(path + ": no " + old)
    open(path, "w").write(s.replace(old, new))
exec(sys.stdin.read())' "$1"
}

# cyclicWalls DIR: the channel's walls a cyclic pair (periodic in x and y)
cyclicWalls() {
    caseEdits "$1" <<'PY'
sub(d + '/system/blockMeshDict',
    'walls  { type wall; faces ((0 1 5 4) (3 7 6 2)); }',
    'bottom { type cyclic; neighbourPatch top; faces ((0 1 5 4)); }\n'
    '    top    { type cyclic; neighbourPatch bottom; faces ((3 7 6 2)); }')
sub(d + '/0/U', 'walls { type noSlip; }',
    'bottom { type cyclic; }\n    top { type cyclic; }')
sub(d + '/0/p_rgh', 'walls { type fixedFluxPressure; value uniform 0; }',
    'bottom { type cyclic; }\n    top { type cyclic; }')
PY
}

# periodicCell DIR CELLS ENDTIME: the channel's walls a cyclic pair, its
# one disk's material held in place (motion fixed)
periodicCell() {
    local d=$1
    unitCell "$d" "$2" "$3" 0.1 && cyclicWalls "$d" || return 1
    caseEdits "$d" <<'PY'
sub(d + '/constant/vheProperties', 'rigid yes;', 'rigid yes; motion fixed;')
PY
}

# runBody DIR DT BODY: the cell's one body (BODY, a setBodiesDict entry of
# material rubber), a fixed step DT (none: the case's adjustable step); the
# mesh, the body and the run
runBody() {
    local d=$1 dt=$2 body=$3
    cat > "$d/system/setBodiesDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object setBodiesDict; }
bodies { $body }
DICT
    [ -z "$dt" ] || fixedStep "$d" "$dt" || return 1
    (cd "$d" && blockMesh > log.blockMesh 2>&1 && setBodies > log.setBodies 2>&1) || return 1
    (cd "$d" && vheFoam > log.vheFoam 2>&1)
}

# runCell DIR DT BODY: runBody with the flow rate written every step
runCell() {
    (cd "$1" && foamDictionary -entry functions/flowRate/writeInterval -set 1 system/controlDict) > /dev/null
    runBody "$@"
}
