# Sourced by cylinder.sh, galilean.sh, sliding.sh and faxen.sh: one rigid
# cylinder (D = 0.1 m, axis z) in one liquid of rho 1, no gravity, in a
# box of square cells.
# cylinderCase DIR X Y NU MOTION: its setBodiesDict (centre (X Y 0)),
# vheProperties (liquid and cylinder of viscosity NU; MOTION the rigid
# material's motion entries, e.g. "motion fixed;") and g
cylinderCase() {
    local d=$1 x=$2 y=$3 nu=$4 motion=$5
    cat > "$d/system/setBodiesDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object setBodiesDict; }
bodies { cylinder { material cylinder; shape cylinder; centre ($x $y 0); radius 0.05; axis (0 0 1); } }
DICT
    cat > "$d/constant/vheProperties" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object vheProperties; }
fluids { liquid { rho [1 -3 0 0 0 0 0] 1; nu [0 2 -1 0 0 0 0] $nu; } }
solids { cylinder { rho [1 -3 0 0 0 0 0] 1; rigid yes; $motion } }
DICT
    cat > "$d/constant/g" <<DICT
FoamFile { version 2.0; format ascii; class uniformDimensionedVectorField; object g; }
dimensions [0 1 -2 0 0 0 0]; value (0 0 0);
DICT
}

# cylinderSetup DIR: an empty case with the periodic channel's fvSchemes
# (its time scheme VHE_DDT's if set in the environment, e.g.
# VHE_DDT=backward)
cylinderSetup() {
    rm -rf "$1"; mkdir -p "$1/0" "$1/constant" "$1/system"
    cp "$VHE_ROOT/tutorials/periodicChannel/template/system/fvSchemes" "$1/system/"
    if [ -n "${VHE_DDT:-}" ]; then
        sed -i "s/default Euler;/default $VHE_DDT;/" "$1/system/fvSchemes"
    fi
}

# cylinderBox DIR LX LY NX NY DZ BOUNDARY: the blockMeshDict of the box
# (0 0 0) to (LX LY DZ) in NX x NY x 1 cells.  BOUNDARY: its boundary's
# entries, from the faces left (0 4 7 3), right (1 2 6 5), bottom
# (0 1 5 4), top (3 7 6 2), front and back (0 3 2 1) (4 5 6 7)
cylinderBox() {
    cat > "$1/system/blockMeshDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
dz $6;
vertices ( (0 0 0) ($2 0 0) ($2 $3 0) (0 $3 0)
           (0 0 \$dz) ($2 0 \$dz) ($2 $3 \$dz) (0 $3 \$dz) );
blocks ( hex (0 1 2 3 4 5 6 7) ($4 $5 1) simpleGrading (1 1 1) );
boundary
(
$7
);
DICT
}

# cylinderControl DIR ENDTIME DELTAT WRITEINTERVAL ADJUST: the
# controlDict; ADJUST yes: the step adjusted to Courant number 0.5 (at
# most 0.01 s), else fixed at DELTAT
cylinderControl() {
    local adjust="adjustTimeStep no; maxCo 1; maxAlphaCo 1; maxDeltaT 1;"
    [ "$5" = yes ] && adjust="adjustTimeStep yes; maxCo 0.5; maxAlphaCo 0.5;
maxDeltaT 0.01;"
    cat > "$1/system/controlDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application vheFoam; libs (vheFoam);
startFrom latestTime; startTime 0; stopAt endTime; endTime $2;
deltaT $3; writeControl adjustable; writeInterval $4; purgeWrite 0;
writeFormat ascii; writePrecision 10; timePrecision 6;
runTimeModifiable false; $adjust
DICT
}

# cylinderSolution DIR PTOL UTOL [PIMPLE]: the fvSolution, GAMG for p_rgh
# to PTOL, U to UTOL, one outer iteration; PIMPLE more PIMPLE entries, and
# those of VHE_PIMPLE in the environment (VHE_PIMPLE="coupling { solve always; }")
cylinderSolution() {
    cat > "$1/system/fvSolution" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object fvSolution; }
solvers
{
    "alpha.*" { nAlphaSubCycles 1; cAlpha 1; }
    p_rgh { solver GAMG; smoother GaussSeidel; tolerance $2; relTol 0.01; }
    p_rghFinal { \$p_rgh; relTol 0; }
    U { solver PBiCGStab; preconditioner DILU; tolerance $3; relTol 0; }
    UFinal { \$U; }
}
PIMPLE { nOuterCorrectors 1; nNonOrthogonalCorrectors 0;${4:+ $4}${VHE_PIMPLE:+ $VHE_PIMPLE} }
DICT
}

# cylinderFields DIR U0 UPATCHES PPATCHES: U (internal U0) and p_rgh
# (internal 0), UPATCHES and PPATCHES their boundary entries (one per
# line) before frontAndBack's empty one
cylinderFields() {
    cat > "$1/0/U" <<DICT
FoamFile { version 2.0; format ascii; class volVectorField; object U; }
dimensions [0 1 -1 0 0 0 0];
internalField uniform $2;
boundaryField
{
$3
    frontAndBack { type empty; }
}
DICT
    cat > "$1/0/p_rgh" <<DICT
FoamFile { version 2.0; format ascii; class volScalarField; object p_rgh; }
dimensions [1 -1 -2 0 0 0 0];
internalField uniform 0;
boundaryField
{
$4
    frontAndBack { type empty; }
}
DICT
}

# cylinderChannelFields DIR U0 INLET WALLS: the fields of a channel with
# patches inlet (U fixed to INLET), outlet (p_rgh 0) and walls (U's
# condition WALLS)
cylinderChannelFields() {
    cylinderFields "$1" "$2" "    inlet  { type fixedValue; value $3; }
    outlet { type zeroGradient; }
    walls  { $4 }" "    inlet  { type zeroGradient; }
    outlet { type fixedValue; value uniform 0; }
    walls  { type zeroGradient; }"
}

# cylinderRun DIR: mesh, bodies, run
cylinderRun() {
    (cd "$1" && blockMesh > log.blockMesh 2>&1 && setBodies > log.setBodies 2>&1) || return 1
    (cd "$1" && vheFoam > log.vheFoam 2>&1)
}
