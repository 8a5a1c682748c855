# The surface-tension benchmarks' shared case pieces (sourced by
# staticDrop.sh, risingBubble.sh, sessileDrop.sh, capillaryWave.sh): two
# fluids, liquid and gas, with a surface tension; the same schemes and
# solvers everywhere; each case run under vheFoam and, side by side on
# the other core, under Debian's interFoam (bin/vheToInterFoam).

# st_dicts CASE TOL RELTOL RHO_L MU_L RHO_G MU_G SIGMA G_Y: fvSchemes,
# fvSolution (p_rgh and U to TOL, p_rgh's first solves to RELTOL),
# vheProperties and g (along y)
st_dicts()
{
    local c=$1 tol=$2 relTol=$3 rhoL=$4 muL=$5 rhoG=$6 muG=$7 sigma=$8 gy=$9
    local final="\$p_rgh;"
    [ "$relTol" = 0 ] || final="\$p_rgh; relTol 0;"
    cat > "$c/system/fvSchemes" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object fvSchemes; }
ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes
{
    default none;
    div(rhoPhi,U) Gauss linearUpwind grad(U);
    div(phi,alpha) Gauss vanLeer;
    div(phirb,alpha) Gauss linear;
    div((mu*dev2(T(grad(U))))) Gauss linear;
}
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
DICT
    cat > "$c/system/fvSolution" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object fvSolution; }
solvers
{
    "alpha.*" { nAlphaSubCycles 1; cAlpha 1; }
    p_rgh { solver PCG; preconditioner DIC; tolerance $tol; relTol $relTol; }
    p_rghFinal { $final }
    U { solver PBiCGStab; preconditioner DILU; tolerance $tol; relTol 0; }
    UFinal { \$U; }
}
PIMPLE { nOuterCorrectors 1; nNonOrthogonalCorrectors 0; pRefCell 0; pRefValue 0; }
DICT
    cat > "$c/constant/vheProperties" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object vheProperties; }
fluids
{
    liquid { rho [1 -3 0 0 0 0 0] $rhoL; mu [1 -1 -1 0 0 0 0] $muL; }
    gas    { rho [1 -3 0 0 0 0 0] $rhoG; mu [1 -1 -1 0 0 0 0] $muG; }
}
sigmas ( (liquid gas) [1 0 -2 0 0 0 0] $sigma );
DICT
    cat > "$c/constant/g" <<DICT
FoamFile { version 2.0; format ascii; class uniformDimensionedVectorField; object g; }
dimensions [0 1 -2 0 0 0 0]; value (0 $gy 0);
DICT
}

# st_run DIR: mesh DIR/vheFoam, make DIR/interFoam from it, run both
st_run()
{
    local c=$1/vheFoam
    (cd "$c" && blockMesh > log.blockMesh 2>&1) || return 1
    "$VHE_ROOT/bin/vheToInterFoam" "$c" "$1/interFoam" > /dev/null || return 1
    (cd "$c" && vheFoam > log.vheFoam 2>&1) &
    (cd "$1/interFoam" && interFoam > log.interFoam 2>&1) &
    wait
}
