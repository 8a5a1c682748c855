# Sourced by settling.sh and dkt.sh: a tank of the floatingBodies template
# full of water (rho 1000, nu 1e-6), rigid bodies of material "wood",
# decomposed in y for 2 ranks.  And by lightSphere.sh, drawCost.sh,
# tenCate.sh and sphereDrag.sh: sphereTank, the floatingBlock template made
# 3D with a sphere, lightSphereCase, the light sphere's case, and
# tenCateSphere, ten Cate's sphere in a closed box of oil.
. "$(dirname "${BASH_SOURCE[0]}")/../../tests/cases/lib.sh" 2>/dev/null

# tankCase DIR W H NX NY RHO_BODY ENDTIME MAXDELTAT BODIES [NU]: the case
# in DIR, the water 0.01 m above the top; BODIES is the setBodiesDict's
# bodies entries, NU the water's viscosity (1e-6 by default)
tankCase() {
    local d=$1 W=$2 H=$3 nx=$4 ny=$5 rho=$6 tend=$7 dtmax=$8 bodies=$9 nu=${10:-1e-6}
    rm -rf "$d"
    sceneCase floatingBodies "$d" W="$W" H="$H" nx="$nx" ny="$ny" \
        depthWater="$(python3 -c "print(round($H + 0.01, 9))")" rhoWater=1000 \
        nuWater="$nu" nuAir="$nu" rhoWood="$rho" \
        endTime="$tend" writeInterval=0.01 maxDeltaT="$dtmax" || return 1
    cat > "$d/system/setBodiesDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object setBodiesDict; }
bodies { $bodies }
DICT
    sed -i 's/n (2 1 1)/n (1 2 1)/' "$d/system/decomposeParDict"
}

# tankGAMG DIR: GAMG for the pressure (the template's PCG takes hundreds of
# iterations a step on a few hundred thousand cells)
tankGAMG() {
    python3 - "$1/system/fvSolution" <<'PY'
import re, sys
p = sys.argv[1]
s = open(p).read()
s, n = re.subn(r'(p_rgh\s*\{\s*)solver\s+PCG;\s*preconditioner\s+DIC;',
              r'\1solver GAMG; smoother GaussSeidel;', s)
if n != 1:
    sys.exit(p + ': no PCG p_rgh to set to GAMG')
open(p, 'w').write(s)
PY
}

# tankRun DIR: set the fields and bodies, decompose, run on 2 ranks
tankRun() {
    (cd "$1" && setFields > log.setFields 2>&1 && setBodies > log.setBodies 2>&1 \
        && decomposePar > log.decomposePar 2>&1) || return 1
    (cd "$1" && mpirun -np 2 vheFoam -parallel > log.vheFoam 2>&1)
}

# lightSphereCase DIR CELLS ENDTIME: lightSphere.sh's case (a rigid sphere
# of r 0.1 and rho_s 100 centred at 0.15 m in water 0.35 m deep, nu 1e-2,
# air above, in a closed 0.6 m cube of CELLS^3 cells), written at ENDTIME
lightSphereCase() {
    local d=$1 n=$2 tend=$3
    rm -rf "${d:?}"
    sceneCase floatingBlock "$d" W=0.6 H=0.6 nx="$n" ny="$n" depthOil=0 \
        depthWater=0.35 shape=disk radius=0.1 blockBottom=0.05 nuWater=1e-2 \
        rhoSolid=100 rigid=yes endTime="$tend" writeInterval="$tend" || return 1
    sphereTank "$d" 0.6 "$n" "0.3 0.15 0.3"
}

# sphereTank DIR THICKNESS NZ CENTRE: the floatingBlock case in DIR (its
# shape disk) made 3D: THICKNESS deep in z on NZ cells, its front and back
# the side walls' conditions, the disk a sphere centred at CENTRE ("x y z")
sphereTank() {
    local d=$1 depth=$2 nz=$3 centre=$4 f w
    sed -i "s/^thickness .*/thickness $depth;/" "$d/system/parameters"
    sed -i "s/(\$nx \$ny 1)/(\$nx \$ny $nz)/; s/frontAndBack { type empty;/frontAndBack { type wall;/" \
        "$d/system/blockMeshDict"
    for f in "$d"/0/*; do      # the front and back walls as the side walls
        w=$(grep -o "walls *{[^}]*}" "$f" | sed 's/walls//')
        sed -i "s|frontAndBack *{ *type empty; *}|frontAndBack $w|" "$f"
    done
    sed -i "s/shape    disk;/shape    sphere;/; s|centre   (.*);|centre ($centre);|" \
        "$d/system/setBodiesDict"
    grep -q "shape    sphere" "$d/system/setBodiesDict" && grep -q "type wall; faces ((0 3 2 1)" \
        "$d/system/blockMeshDict" || { echo "could not make $d 3D" >&2; return 1; }
}

# tenCateSphere DIR W H CELLS_PER_D RHO MU Y ENDTIME: ten Cate et al.'s
# sphere (d 15 mm, rho_s 1120, rigid) at height Y on the axis of a W x H x
# W box (y up) full of one liquid (RHO kg/m^3, MU Pa s), CELLS_PER_D cells
# across the sphere, no-slip walls all round (the top too), maxDeltaT
# 0.005 s, to ENDTIME.  Euler and one outer iteration, as the template,
# unless VHE_DDT (e.g. backward) or VHE_NOUTER (e.g. 2) are set in the
# environment: a moving body's drag carries both steps' errors (README)
tenCateSphere() {
    local d=$1 W=$2 H=$3 n=$4 rho=$5 mu=$6 y=$7 tEnd=$8 nx ny
    read -r nx ny <<< "$(python3 -c "n = $n; print(round($W*1000/15*n), round($H*1000/15*n))")"
    rm -rf "${d:?}"
    sceneCase floatingBlock "$d" W="$W" H="$H" nx="$nx" ny="$ny" depthOil=0 depthWater="$H" \
        rhoWater="$rho" nuWater="$(python3 -c "print($mu/$rho)")" shape=disk radius=0.0075 \
        blockBottom=0.12 rhoSolid=1120 rigid=yes endTime="$tEnd" writeInterval="$tEnd" \
        maxDeltaT=0.005 || return 1
    sphereTank "$d" "$W" "$nx" "$(python3 -c "print($W/2, $y, $W/2)")" || return 1
    sed -i 's/top   { type slip; }/top   { type noSlip; }/' "$d/0/U"
    grep -q "top   { type noSlip; }" "$d/0/U" || { echo "could not close $d's top" >&2; return 1; }
    if [ -n "${VHE_DDT:-}" ]; then
        sed -i "s/default Euler;/default $VHE_DDT;/" "$d/system/fvSchemes"
        grep -q "default $VHE_DDT;" "$d/system/fvSchemes" || { echo "could not set $d's time scheme" >&2; return 1; }
    fi
    if [ -n "${VHE_NOUTER:-}" ]; then
        sed -i "s/nOuterCorrectors    1;/nOuterCorrectors    $VHE_NOUTER;/" "$d/system/fvSolution"
        grep -q "nOuterCorrectors    $VHE_NOUTER;" "$d/system/fvSolution" || { echo "could not set $d's outer iterations" >&2; return 1; }
    fi
}
