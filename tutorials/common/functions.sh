# Shared by the tutorials' Allrun/Allclean scripts (sourced).
# shellcheck disable=SC1091
. "$(dirname "${BASH_SOURCE[0]}")/../../Make/bashrc"
. "$VHE_ROOT/Make/functions.sh"

# Build what is missing (a no-op when everything is built)
vhe_build_if_missing()
{
    [ -x "$FOAM_USER_APPBIN/vheFoam" ] && [ -x "$FOAM_USER_APPBIN/setBodies" ] \
        && [ -f "$FOAM_USER_LIBBIN/libvheFoam.so" ] \
        && [ -f "$FOAM_USER_LIBBIN/libvheCoupled.so" ] && return 0
    "$VHE_ROOT/Allwmake"
}

# vhe_scene_case SCENE DIR KEY=VALUE...: case DIR from SCENE's template/
# and parameters (SCENE: a tutorial directory), with the given entries of
# its system/parameters changed, meshed with blockMesh, or with gmsh when
# the template has a NAME.geo instead of a blockMeshDict
vhe_scene_case()
{
    local scene=$1 dir=$2 kv; shift 2
    rm -rf "$dir"
    mkdir -p "$(dirname "$dir")"
    cp -r "$scene/template" "$dir"
    cp "$scene/parameters" "$dir/system/parameters"
    for kv in "$@"; do
        foamDictionary -entry "${kv%%=*}" -set "${kv#*=}" \
            "$dir/system/parameters" > /dev/null || return 1
    done
    if [ -f "$dir/system/blockMeshDict" ]; then
        vhe_run "$dir" blockMesh
    else
        vhe_gmsh_mesh "$dir"
    fi
}

# vhe_gmsh_mesh DIR: mesh DIR/NAME.geo with gmsh (cell size: the entry dx
# of system/parameters), convert it (gmshToFoam) and give the patches their
# types (system/changeDictionaryDict)
vhe_gmsh_mesh()
{
    local dir=$1 geo dx
    geo=$(cd "$dir" && ls ./*.geo) || { echo "no blockMeshDict or .geo in $dir" >&2; return 1; }
    dx=$(foamDictionary -entry dx -value "$dir/system/parameters") || return 1
    vhe_run "$dir" gmsh -3 -setnumber dx "$dx" "$geo" -o mesh.msh || return 1
    vhe_run "$dir" gmshToFoam mesh.msh || return 1
    vhe_run "$dir" changeDictionary
}

# vhe_run CASE APP [ARGS]: run APP in CASE, log to CASE/log.APP; stop on error
vhe_run()
{
    local dir=$1 app=$2; shift 2
    ( cd "$dir" && "$app" "$@" > "log.$app" 2>&1 ) || {
        echo "$app failed in $dir: see $dir/log.$app" >&2
        tail -15 "$dir/log.$app" >&2
        return 1
    }
}

# vhe_run_pool N APP CASE...: run APP in every CASE, N at a time, printing
# each running case's progress line every 20 s; fails if any case fails
vhe_run_pool()
{
    local n=$1 app=$2; shift 2
    local queue=("$@") running=() failed=0 pid dir i tick=0
    declare -A caseOf
    while [ ${#queue[@]} -gt 0 ] || [ ${#running[@]} -gt 0 ]; do
        while [ ${#running[@]} -lt "$n" ] && [ ${#queue[@]} -gt 0 ]; do
            dir=${queue[0]}; queue=("${queue[@]:1}")
            vhe_run "$dir" "$app" &
            running+=($!); caseOf[$!]=$dir
        done
        sleep 5
        for i in "${!running[@]}"; do
            pid=${running[$i]}
            if ! kill -0 "$pid" 2>/dev/null; then
                wait "$pid" || failed=1
                echo "  [$(basename "${caseOf[$pid]}")] finished"
                unset "running[$i]"
            fi
        done
        running=("${running[@]}")
        tick=$((tick + 1))
        if [ $((tick % 4)) = 0 ]; then
            for pid in "${running[@]}"; do
                dir=${caseOf[$pid]}
                echo "  [$(basename "$dir")] $(grep "^Progress:" "$dir/log.$app" 2>/dev/null | tail -1)"
            done
        fi
    done
    return $failed
}

# vhe_pvbatch LOG SCRIPT FOAM ARG...: touches the ParaView stub FOAM and
# runs SCRIPT FOAM ARG... in pvbatch under xvfb-run (no display needed),
# its output in LOG; says where to look if it fails
vhe_pvbatch()
{
    local log=$1 script=$2 foam=$3; shift 3
    touch "$foam"
    # xvfb-run -a can pick a display whose last server is still going
    # away ("bad X server connection", seen in one of nine renders in a
    # row): a failed render is tried again, up to three times
    local try
    for try in 1 2 3; do
        xvfb-run -a pvbatch "$script" "$foam" "$@" > "$log" 2>&1 && return 0
        grep -q "bad X server connection" "$log" || break
        sleep 2
    done
    echo "pvbatch failed: $log" >&2
    return 1
}

# vhe_volume_drift DAT OUT: V(t)/V(0) - 1 for every column of a
# volFieldValue volIntegrate output (the phase volumes) into OUT; prints
# the largest drift
vhe_volume_drift()
{
    awk '!/^#/ {if (!n++) for (k = 2; k <= NF; k++) v0[k] = $k
                printf "%s", $1; for (k = 2; k <= NF; k++) printf " %.6e", $k/v0[k] - 1; print ""}' \
        "$1" > "$2" || return 1
    awk '{for (k = 2; k <= NF; k++) if ($k*$k > m) m = $k*$k}
         END {printf "Largest relative phase volume drift: %.2g\n", sqrt(m)}' "$2"
}
