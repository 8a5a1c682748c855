#!/bin/bash
# bodyFitted.sh DIR RE [H0]: a body-fitted reference for the settling
# disk's drag, independent of vheFoam: the steady, symmetric laminar flow
# past a cylinder (d = 1) on the axis of a channel 8 d wide whose walls
# slide at the stream's velocity U = 1 (the settling disk's frame: the
# liquid at rest far from it in the walls' frame), Reynolds number RE
# (nu = 1/RE), from 10 d upstream to 40 d downstream; the half above the
# axis, with a symmetry plane on it.  gmsh's triangles-made-quads, H0 d
# at the surface (0.006 by default: 260 cells around the half circle),
# simpleFoam (Debian's OpenFOAM) to a steady state.  Prints the drag
# coefficient Cd = 2 Fx/(rho U^2 d) of the whole cylinder.
. "$(dirname "$0")/../../tests/cases/lib.sh" 2>/dev/null
d=$1 Re=$2 h0=${3:-0.006}
# SIMPLE's relaxation of U: 0.9 converges in about 600 iterations at Re
# below 100; the long wakes of Re several hundred need 0.7
relax=$(python3 -c "print(0.9 if $Re < 100 else 0.7)")
rm -rf "$d"; mkdir -p "$d/0" "$d/constant" "$d/system"
cat > "$d/half.geo" <<GEO
h0 = $h0; h1 = 0.25;
Point(1) = {-10, 0, 0, h1}; Point(2) = {-0.5, 0, 0, h0}; Point(3) = {0, 0, 0, h0};
Point(4) = {0, 0.5, 0, h0}; Point(5) = {0.5, 0, 0, h0}; Point(6) = {40, 0, 0, h1};
Point(7) = {40, 4, 0, h1}; Point(8) = {-10, 4, 0, h1};
Line(1) = {1, 2}; Circle(2) = {2, 3, 4}; Circle(3) = {4, 3, 5}; Line(4) = {5, 6};
Line(5) = {6, 7}; Line(6) = {7, 8}; Line(7) = {8, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7};
Plane Surface(1) = {1};
Field[1] = Distance; Field[1].CurvesList = {2, 3};
Field[2] = Threshold; Field[2].InField = 1; Field[2].SizeMin = h0;
Field[2].SizeMax = h1; Field[2].DistMin = 0.03; Field[2].DistMax = 8;
Field[3] = Box; Field[3].VIn = 5*h0; Field[3].VOut = h1;
Field[3].XMin = -1; Field[3].XMax = 8; Field[3].YMin = 0; Field[3].YMax = 1.2;
Field[4] = Box; Field[4].VIn = 0.08; Field[4].VOut = h1;
Field[4].XMin = -2; Field[4].XMax = 30; Field[4].YMin = 0; Field[4].YMax = 2;
Field[5] = Min; Field[5].FieldsList = {2, 3, 4};
Background Field = 5;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.Algorithm = 6;
Recombine Surface{1};
ex[] = Extrude {0, 0, 0.1} { Surface{1}; Layers{1}; Recombine; };
Physical Surface("frontAndBack") = {1, ex[0]};
Physical Volume("fluid") = {ex[1]};
Physical Surface("axis") = {ex[2], ex[5]};
Physical Surface("cylinder") = {ex[3], ex[4]};
Physical Surface("outlet") = {ex[6]};
Physical Surface("top") = {ex[7]};
Physical Surface("inlet") = {ex[8]};
GEO
cat > "$d/system/controlDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application simpleFoam; startFrom latestTime; startTime 0; stopAt endTime;
endTime 8000; deltaT 1; writeControl timeStep; writeInterval 8000;
writeFormat ascii; writePrecision 8;
functions
{
    forces
    {
        type forceCoeffs; libs (forces); writeControl timeStep;
        writeInterval 10; patches (cylinder); rho rhoInf; rhoInf 1;
        CofR (0 0 0); liftDir (0 1 0); dragDir (1 0 0); pitchAxis (0 0 1);
        magUInf 1; lRef 1; Aref 0.05;
    }
}
DICT
cat > "$d/system/fvSchemes" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object fvSchemes; }
ddtSchemes { default steadyState; }
gradSchemes { default Gauss linear; }
divSchemes { default none; div(phi,U) bounded Gauss linearUpwind grad(U);
             div((nuEff*dev2(T(grad(U))))) Gauss linear; }
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
DICT
cat > "$d/system/fvSolution" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object fvSolution; }
solvers
{
    p { solver GAMG; smoother GaussSeidel; tolerance 1e-9; relTol 0.05; }
    U { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-10; relTol 0.1; }
}
SIMPLE { nNonOrthogonalCorrectors 1; consistent yes;
         residualControl { p 1e-6; U 1e-7; } }
relaxationFactors { equations { U $relax; } fields { p 1; } }
DICT
cat > "$d/constant/transportProperties" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object transportProperties; }
transportModel Newtonian; nu $(python3 -c "print(1/$Re)");
DICT
cat > "$d/constant/turbulenceProperties" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object turbulenceProperties; }
simulationType laminar;
DICT
cat > "$d/0/U" <<DICT
FoamFile { version 2.0; format ascii; class volVectorField; object U; }
dimensions [0 1 -1 0 0 0 0]; internalField uniform (1 0 0);
boundaryField
{
    "(inlet|top)" { type fixedValue; value uniform (1 0 0); }
    outlet { type zeroGradient; }
    axis { type symmetryPlane; }
    cylinder { type noSlip; }
    frontAndBack { type empty; }
}
DICT
cat > "$d/0/p" <<DICT
FoamFile { version 2.0; format ascii; class volScalarField; object p; }
dimensions [0 2 -2 0 0 0 0]; internalField uniform 0;
boundaryField
{
    "(inlet|top|cylinder)" { type zeroGradient; }
    outlet { type fixedValue; value uniform 0; }
    axis { type symmetryPlane; }
    frontAndBack { type empty; }
}
DICT
(
    cd "$d" || exit 1
    gmsh -3 half.geo -format msh2 -o half.msh > log.gmsh 2>&1 || exit 1
    gmshToFoam half.msh > log.gmshToFoam 2>&1 || exit 1
    python3 - <<'PY' || exit 1
import re
p = 'constant/polyMesh/boundary'
s = open(p).read()
for patch, kind in (('frontAndBack', 'empty'), ('cylinder', 'wall'),
                    ('axis', 'symmetryPlane')):
    s = re.sub(r'(%s\s*\{\s*type\s+)patch' % patch, r'\g<1>' + kind, s)
open(p, 'w').write(s)
PY
    simpleFoam > log.simpleFoam 2>&1 || exit 1
    tail -1 postProcessing/forces/0/coefficient.dat \
        | awk -v re="$Re" '{printf "Re %s: Cd %.4f after %d iterations\n", re, $2, $1}'
)
