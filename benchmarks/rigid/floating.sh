#!/bin/bash
# floating.sh DIR [CELLS [ENDTIME]]: does a floating box's draft depend on
# its stiffness?  test_floating's Archimedes box (0.3 x 0.1, rho_s 500 in
# water of nu 1e-2 under air, released at half its draft, a 1 x 1 m tank of
# CELLS x CELLS cells, 40 by default) run to ENDTIME (8 s by default:
# the heave has died out by t = 5) as a rigid body and as elastic bodies of
# G/rho_s = 10 and 100 m^2/s^2.  Prints, per case, the mean draft over the
# last 2 s against Archimedes' (rho_s - rho_air)/(rho_w - rho_air) x 0.1,
# in per cent of the height (negative: floats high), and the submerged
# area at the end against Archimedes' (from the written fractions), and for
# the elastic boxes the vertical elastic traction through the box's
# outline at the end (edgeTraction.py).  About 2 min at 40 cells.
. "$(dirname "$0")/../../tests/cases/lib.sh" 2>/dev/null
d=$1 n=${2:-40} tend=${3:-8}
mkdir -p "$d"
box=(nx="$n" ny="$n" depthOil=0 depthWater=0.5 shape=box blockWidth=0.3
     blockHeight=0.1 nuWater=1e-2 writeInterval=1 blockBottom=0.475
     rhoSolid=500 endTime="$tend")
printf "# %-8s %12s %12s %14s\n" case draft "error % h" "submerged/A"
for c in rigid G10 G100; do
    case $c in
        rigid) extra=(rigid=yes) ;;
        G10) extra=(GperRho=10) ;;
        G100) extra=(GperRho=100) ;;
    esac
    rm -rf "${d:?}/$c"
    sceneCase floatingBlock "$d/$c" "${box[@]}" "${extra[@]}" \
        && run "$d/$c" setFields && run "$d/$c" setBodies && run "$d/$c" vheFoam \
        || { echo "$c failed: $d/$c" >&2; continue; }
    # the draft over the last 2 s: of the rigid body's centroid at the
    # writes, of the elastic one's every step
    how=draft; [ "$c" = rigid ] && how=bodyDraft
    draft=$(python3 "$TESTS_DIR/floating.py" $how "$d/$c" 0.1 \
        "$(awk -v t="$tend" 'BEGIN {print t - 2}')")
    sub=$(python3 "$TESTS_DIR/floating.py" submerged "$d/$c" "$tend")
    awk -v c="$c" -v d="$draft" -v s="$sub" 'BEGIN {
        printf "  %-8s %12.5f %12.2f %14.4f\n", c, d, 100*(d - 499/999*0.1)/0.1, s}'
    [ "$c" = rigid ] || python3 "$(dirname "$0")/edgeTraction.py" "$d/$c" "$tend"
done
