# Shared by the case tests (sourced).  A test prints one line per check,
# "PASS <name>: <figures>" or "FAIL <name>: <why>", which ./Alltest counts.
# shellcheck disable=SC1091
. "$(dirname "${BASH_SOURCE[0]}")/../../tutorials/common/functions.sh"

TESTS_DIR="$VHE_ROOT/tests/cases"
WORK="$VHE_ROOT/build/tests/$(basename "$0" .sh)"
rm -rf "$WORK"
mkdir -p "$WORK"

nfail=0
pass() { echo "PASS $1: ${2:-}"; }
fail() { echo "FAIL $1: ${2:-}"; nfail=$((nfail + 1)); }
finish() { exit $((nfail > 0)); }

# check NAME CONDITION(python expression) DETAILS
check() {
    if python3 -c "import math, sys; sys.exit(0 if ($2) else 1)"; then
        pass "$1" "$3"
    else
        fail "$1" "$3 (wanted $2)"
    fi
}

# checkKnown NAME PASS_CONDITION KNOWN_CONDITION DETAILS WHY: PASS when
# the first condition holds; else KNOWN (a documented limitation, not
# counted as a failure) when the looser second one holds, with WHY; else FAIL
checkKnown() {
    if python3 -c "import math, sys; sys.exit(0 if ($2) else 1)"; then
        pass "$1" "$4"
    elif python3 -c "import math, sys; sys.exit(0 if ($3) else 1)"; then
        echo "KNOWN $1: $4 (wanted $2; $5)"
    else
        fail "$1" "$4 (wanted $2, at least $3)"
    fi
}

# sceneCase SCENE DIR KEY=VALUE...: a case from tutorials/SCENE (its
# template with the given parameters changed), meshed with blockMesh
sceneCase() { vhe_scene_case "$VHE_ROOT/tutorials/$1" "${@:2}"; }

# channelCase DIR KEY=VALUE...: the periodic channel (scene A)
channelCase() { sceneCase periodicChannel "$@"; }

# couetteWalls DIR N: the channel's walls (N x N cells) moving at -1
# (bottom) and +1 m/s (top) in x: plane Couette flow.  blockMesh lists the
# bottom wall's faces first, then the top's
couetteWalls() {
    python3 - "$1" "$2" <<'PY'
import sys
d, n = sys.argv[1], int(sys.argv[2])
p = d + '/0/U'
vals = ' '.join(['(-1 0 0)']*n + ['(1 0 0)']*n)
s = open(p).read()
if 'walls { type noSlip; }' not in s:
    sys.exit(p + ': no noSlip walls to set moving')
s = s.replace('walls { type noSlip; }',
    'walls { type fixedValue; value nonuniform List<vector> %d (%s); }' % (2*n, vals))
open(p, 'w').write(s)
PY
}

# fixedStep DIR DT: a fixed step DT and writes at run times (controlDict)
fixedStep() {
    local e
    for e in "adjustTimeStep no" "deltaT $2" "writeControl runTime"; do
        (cd "$1" && foamDictionary -entry ${e% *} -set "${e#* }" system/controlDict) \
            > /dev/null || return 1
    done
}

# tightSolvers DIR TOL: every solver of DIR/system/fvSolution to tolerance
# TOL and relTol 0, so that two runs (serial and parallel, vheFoam and
# interFoam) differ by the solvers' tolerance rather than by their relTol
tightSolvers() {
    sed -i -E "s/relTol[[:space:]]+[0-9.eE+-]+;/relTol 0;/g; s/tolerance[[:space:]]+[0-9.eE+-]+;/tolerance $2;/g" \
        "$1/system/fvSolution"
}

# run DIR APP ARGS...: run in DIR, log to DIR/log.APP, return its status
run() {
    local dir=$1 app=$2; shift 2
    (cd "$dir" && "$app" "$@" > "log.$app" 2>&1)
}

# Mean flow rate per unit depth over t >= T0 from the flowRate output
flowRate() {
    awk -v t0="$2" '!/^#/ && $1 >= t0 {s += -$2; n++} END {printf "%.8g\n", s/n}' \
        "$1/postProcessing/flowRate/0/surfaceFieldValue.dat"
}

# Smallest and largest phase fraction over every step of a vheFoam log
# ("Phase <name> volume V  fraction min, max = a b" lines): prints "lo hi"
alphaRange() {
    grep "^Phase .* fraction min, max" "$1" \
        | awk 'NR == 1 {lo = $9; hi = $10} {if ($9 < lo) lo = $9; if ($10 > hi) hi = $10}
               END {print lo, hi}'
}

# maxFieldDiff CASE_A CASE_B TIME FIELD: prints "maxAbsDifference maxAbsValue"
maxFieldDiff() { python3 "$TESTS_DIR/fieldDiff.py" "$@"; }
