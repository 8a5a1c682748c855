#!/bin/bash
# cylinder.sh DIR CELLS_PER_D [ENDTIME]: Schaefer & Turek (1996)'s 2D-2
# benchmark, the laminar flow past a fixed cylinder at Re = 100: channel
# 2.2 x 0.41 m, cylinder D = 0.1 m at (0.2, 0.2) (a rigid material with
# motion fixed), nu 1e-3, rho 1, parabolic inflow of peak 1.5 m/s (mean
# U = 1), outflow at p = 0, no-slip walls.  Square cells, CELLS_PER_D
# across the cylinder; maxCo 0.5; to t = ENDTIME (default 10).  The
# fluid's force on the cylinder is postProcessing/fixedBodies/0/
# forces.dat (every step); cylinder.py reads it.
. "$(dirname "$0")/../../tests/cases/lib.sh" 2>/dev/null
. "$(dirname "$0")/cylinderCase.sh"
d=$1 n=$2 tend=${3:-10}
nx=$((22*n)) ny=$(python3 -c "print(round(4.1*$n))")
rm -rf "$d"; mkdir -p "$d/0" "$d/constant" "$d/system"
cp "$VHE_ROOT/tutorials/periodicChannel/template/system/fvSchemes" "$d/system/"
cat > "$d/system/blockMeshDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
dz #eval{ 0.1/$n };
vertices ( (0 0 0) (2.2 0 0) (2.2 0.41 0) (0 0.41 0)
           (0 0 \$dz) (2.2 0 \$dz) (2.2 0.41 \$dz) (0 0.41 \$dz) );
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
cylinderCase "$d" 0.2 0.2 1e-3 "motion fixed;"
inflow=$(python3 -c "
H = 0.41; n = $ny
print(' '.join('(%.12g 0 0)' % (6*(j + 0.5)*H/n*(H - (j + 0.5)*H/n)/H**2) for j in range(n)))")
cat > "$d/0/U" <<DICT
FoamFile { version 2.0; format ascii; class volVectorField; object U; }
dimensions [0 1 -1 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    inlet  { type fixedValue; value nonuniform List<vector> $ny ($inflow); }
    outlet { type zeroGradient; }
    walls  { type noSlip; }
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
