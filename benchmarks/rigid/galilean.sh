#!/bin/bash
# galilean.sh DIR CELLS_PER_D MODE [ENDTIME [RE]]: is a moving rigid body's drag
# Galilean invariant?  A cylinder D = 0.1 m in a doubly periodic 1 x 1 m
# box of liquid (rho 1, nu 0.1/RE: RE = 100 by default at 1 m/s), no
# gravity:
#   MODE fixed    the cylinder held at (0.5, 0.5), the liquid started at
#                 1 m/s in x around it (an impulsively started stream);
#   MODE moving   the liquid at rest, the cylinder moved at -1 m/s in x
#                 (motion prescribed) from (0.6, 0.5).
# The two are the same flow seen from frames 1 m/s apart (no walls, the
# box periodic): the fluid's force on the cylinder must agree at every
# time.  postProcessing/fixedBodies/0/forces.dat (every step);
# galilean.py compares two runs.
. "$(dirname "$0")/../../tests/cases/lib.sh" 2>/dev/null
. "$(dirname "$0")/cylinderCase.sh"
d=$1 n=$2 mode=$3 tend=${4:-0.4} Re=${5:-100}
nu=$(python3 -c "print(0.1/$Re)")
N=$((10*n))
case $mode in
    fixed)  U0="(1 0 0)" x0=0.5 motion="motion fixed;" ;;
    moving) U0="(0 0 0)" x0=0.6 motion="motion prescribed; velocity (-1 0 0);" ;;
    *) echo "MODE: fixed or moving" >&2; exit 1 ;;
esac
rm -rf "$d"; mkdir -p "$d/0" "$d/constant" "$d/system"
cp "$VHE_ROOT/tutorials/periodicChannel/template/system/fvSchemes" "$d/system/"
cat > "$d/system/blockMeshDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
dz #eval{ 1.0/$N };
vertices ( (0 0 0) (1 0 0) (1 1 0) (0 1 0)
           (0 0 \$dz) (1 0 \$dz) (1 1 \$dz) (0 1 \$dz) );
blocks ( hex (0 1 2 3 4 5 6 7) ($N $N 1) simpleGrading (1 1 1) );
boundary
(
    left   { type cyclic; neighbourPatch right; faces ((0 4 7 3)); }
    right  { type cyclic; neighbourPatch left;  faces ((1 2 6 5)); }
    bottom { type cyclic; neighbourPatch top;   faces ((0 1 5 4)); }
    top    { type cyclic; neighbourPatch bottom; faces ((3 7 6 2)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }
);
DICT
cat > "$d/system/controlDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application vheFoam; libs (vheFoam);
startFrom latestTime; startTime 0; stopAt endTime; endTime $tend;
deltaT 0.0025; writeControl adjustable; writeInterval 0.1; purgeWrite 0;
writeFormat ascii; writePrecision 10; timePrecision 6;
runTimeModifiable false; adjustTimeStep no; maxCo 1; maxAlphaCo 1; maxDeltaT 1;
DICT
cat > "$d/system/fvSolution" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object fvSolution; }
solvers
{
    "alpha.*" { nAlphaSubCycles 1; cAlpha 1; }
    p_rgh { solver GAMG; smoother GaussSeidel; tolerance 1e-9; relTol 0.01; }
    p_rghFinal { \$p_rgh; relTol 0; }
    U { solver PBiCGStab; preconditioner DILU; tolerance 1e-10; relTol 0; }
    UFinal { \$U; }
}
PIMPLE { nOuterCorrectors 1; nNonOrthogonalCorrectors 0; pRefCell 0; pRefValue 0; }
DICT
cylinderCase "$d" "$x0" 0.5 "$nu" "$motion"
for f in U p_rgh; do
    case $f in
        U) cls=volVectorField dims="[0 1 -1 0 0 0 0]" v="uniform $U0" ;;
        p_rgh) cls=volScalarField dims="[1 -1 -2 0 0 0 0]" v="uniform 0" ;;
    esac
    cat > "$d/0/$f" <<DICT
FoamFile { version 2.0; format ascii; class $cls; object $f; }
dimensions $dims;
internalField $v;
boundaryField
{
    "(left|right|bottom|top)" { type cyclic; }
    frontAndBack { type empty; }
}
DICT
done
(cd "$d" && blockMesh > log.blockMesh 2>&1 && setBodies > log.setBodies 2>&1) || exit 1
(cd "$d" && vheFoam > log.vheFoam 2>&1)
