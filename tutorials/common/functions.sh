# Shared by the tutorials' Allrun/Allclean scripts (sourced).
# shellcheck disable=SC1091
. "$(dirname "${BASH_SOURCE[0]}")/../../Make/bashrc"
. "$VHE_ROOT/Make/functions.sh"

# Build what is missing (a no-op when everything is built)
vhe_build_if_missing()
{
    [ -x "$FOAM_USER_APPBIN/vheFoam" ] && [ -x "$FOAM_USER_APPBIN/setBodies" ] \
        && [ -f "$FOAM_USER_LIBBIN/libvheFoam.so" ] && return 0
    "$VHE_ROOT/Allwmake"
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

# vhe_progress LOG...: one line per running case every 20 s until all end
vhe_watch()
{
    local pids=("$@")
    while :; do
        local alive=0 p
        for p in "${pids[@]}"; do kill -0 "$p" 2>/dev/null && alive=1; done
        [ $alive = 0 ] && break
        sleep 20
        for log in cases/*/log.vheFoam; do
            [ -f "$log" ] || continue
            local last
            last=$(grep "^Progress:" "$log" | tail -1)
            [ -n "$last" ] && [ "${last#*(100%)}" = "$last" ] \
                && echo "  [$(basename "$(dirname "$log")")] $last"
        done
    done
}
