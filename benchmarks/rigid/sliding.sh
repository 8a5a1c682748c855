#!/bin/bash
# sliding.sh DIR CELLS_PER_D [ENDTIME [RE]]: the settling disk's steady
# flow seen from the disk: a fixed cylinder (D = 0.1 m, rigid, motion
# fixed) on the axis of a channel 8 D wide (the settling channel's
# W/d), the liquid entering at U = 1 m/s and both walls sliding at U
# (fluid at rest far from the disk in the walls' frame), nu = 0.1/RE
# (RE 17.3 by default: the lower-Reynolds settling case's published
# largest Re).  The channel runs from 10 D upstream to 25 D downstream
# of the disk; outflow at p = 0.  Square cells, maxCo 0.5, to ENDTIME
# (3 s by default, 30 D/U).  postProcessing/fixedBodies/0/forces.dat;
# the steady drag coefficient Cd = 2 Fx/(rho U^2 D dz) is the one a
# disk settling at that Reynolds number meets (compare with a
# body-fitted solution: benchmarks/rigid/README.md).
. "$(dirname "$0")/../../tests/cases/lib.sh" 2>/dev/null
. "$(dirname "$0")/cylinderCase.sh"
d=$1 n=$2 tend=${3:-3} Re=${4:-17.3}
nu=$(python3 -c "print(0.1/$Re)")
nx=$((35*n)) ny=$((8*n))
rm -rf "$d"; mkdir -p "$d/0" "$d/constant" "$d/system"
cp "$VHE_ROOT/tutorials/periodicChannel/template/system/fvSchemes" "$d/system/"
cat > "$d/system/blockMeshDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
dz #eval{ 0.1/$n };
vertices ( (0 0 0) (3.5 0 0) (3.5 0.8 0) (0 0.8 0)
           (0 0 \$dz) (3.5 0 \$dz) (3.5 0.8 \$dz) (0 0.8 \$dz) );
blocks ( hex (0 1 2 3 4 5 6 7) ($nx $ny 1) simpleGrading (1 1 1) );
boundary
(
    inlet  { type patch; faces ((0 4 7 3)); }
    outlet { type patch; faces ((1 2 6 5)); }
    walls  { type wall; faces ((0 1 5 4) (3 7 6 2)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }
);
DICT
cat > "$d/system/controlDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application vheFoam; libs (vheFoam);
startFrom latestTime; startTime 0; stopAt endTime; endTime $tend;
deltaT 1e-4; writeControl adjustable; writeInterval 1; purgeWrite 0;
writeFormat ascii; writePrecision 10; timePrecision 6;
runTimeModifiable false; adjustTimeStep yes; maxCo 0.5; maxAlphaCo 0.5;
maxDeltaT 0.01;
DICT
cat > "$d/system/fvSolution" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object fvSolution; }
solvers
{
    "alpha.*" { nAlphaSubCycles 1; cAlpha 1; }
    p_rgh { solver GAMG; smoother GaussSeidel; tolerance 1e-8; relTol 0.01; }
    p_rghFinal { \$p_rgh; relTol 0; }
    U { solver PBiCGStab; preconditioner DILU; tolerance 1e-9; relTol 0; }
    UFinal { \$U; }
}
PIMPLE { nOuterCorrectors 1; nNonOrthogonalCorrectors 0; }
DICT
cylinderCase "$d" 1.0 0.4 "$nu" "motion fixed;"
cat > "$d/0/U" <<DICT
FoamFile { version 2.0; format ascii; class volVectorField; object U; }
dimensions [0 1 -1 0 0 0 0];
internalField uniform (1 0 0);
boundaryField
{
    inlet  { type fixedValue; value uniform (1 0 0); }
    outlet { type zeroGradient; }
    walls  { type fixedValue; value uniform (1 0 0); }
    frontAndBack { type empty; }
}
DICT
cat > "$d/0/p_rgh" <<DICT
FoamFile { version 2.0; format ascii; class volScalarField; object p_rgh; }
dimensions [1 -1 -2 0 0 0 0];
internalField uniform 0;
boundaryField
{
    inlet  { type zeroGradient; }
    outlet { type fixedValue; value uniform 0; }
    walls  { type zeroGradient; }
    frontAndBack { type empty; }
}
DICT
(cd "$d" && blockMesh > log.blockMesh 2>&1 && setBodies > log.setBodies 2>&1) || exit 1
(cd "$d" && vheFoam > log.vheFoam 2>&1)
