#!/bin/bash
# Bad input: each malformed case must stop with a FOAM FATAL (IO) ERROR that
# names the file (and entry) at fault, exit non-zero and write nothing.
. "$(dirname "$0")/lib.sh"

base="$WORK/base"
channelCase "$base" cells=16 nDisks=2 endTime=0.05 || { fail setup "blockMesh"; finish; }
cat > "$base/constant/vheProperties" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object vheProperties; }
fluids { liquid { rho [1 -3 0 0 0 0 0] 1; mu [1 -1 -1 0 0 0 0] 1; } }
solids { rubber { rho [1 -3 0 0 0 0 0] 1; nu [0 2 -1 0 0 0 0] 1; G [1 -1 -2 0 0 0 0] 0.5; } }
bodyForce [0 1 -2 0 0 0 0] (0.098 0 0);
DICT
run "$base" setBodies || { fail setup "setBodies: $base/log.setBodies"; finish; }

# variant NAME: a fresh copy of the valid base case in $WORK/NAME
variant() { rm -rf "${WORK:?}/$1"; cp -r "$base" "$WORK/$1"; echo "$WORK/$1"; }

# Checksum of every file of a case but the logs
snapshot() { (cd "$1" && find . -type f ! -name 'log.*' -exec md5sum {} + | sort | md5sum); }

# expectFatal NAME DIR APP 'REGEX THE MESSAGE MUST MATCH' 'FILE IT MUST NAME'
#             [running]: found in the time loop (the function objects have
#             started their files), so writes are not checked
expectFatal() {
    local name=$1 dir=$2 app=$3 what=$4 file=$5 running=${6:-} before
    before=$(snapshot "$dir")
    if run "$dir" "$app"; then
        fail "$name" "$app succeeded on bad input ($dir)"; return
    fi
    local log="$dir/log.$app"
    if ! grep -q "FOAM FATAL" "$log"; then
        fail "$name" "no FOAM FATAL error in $log"
    elif ! grep -Eq "$what" "$log"; then
        fail "$name" "message does not say '$what': $log"
    elif ! sed -n '/FOAM FATAL/,$p' "$log" | grep -q "$file"; then
        fail "$name" "message does not name the file $file: $log"
    elif [ -z "$running" ] && [ "$before" != "$(snapshot "$dir")" ]; then
        fail "$name" "files were written: $dir"
    else
        pass "$name" "$(grep -E "$what" "$log" | head -1 | sed 's/^ *//')"
    fi
}

# setFirstCell FILE VALUE: the first cell value of a nonuniform field
setFirstCell() {
    python3 - "$1" "$2" <<'PY'
import sys
path, value = sys.argv[1:3]
lines = open(path).read().split("\n")
i = next(k for k, l in enumerate(lines) if l.startswith("internalField"))
i = lines.index("(", i)
lines[i + 1] = value
open(path, "w").write("\n".join(lines))
PY
}

setEntry() { foamDictionary -entry "$2" -set "$3" "$1" > /dev/null; }
delEntry() { foamDictionary -entry "$2" -remove "$1" > /dev/null; }
P=constant/vheProperties

# ---- vheFoam: constant/vheProperties
d=$(variant missingG); delEntry "$d/$P" solids/rubber/G
expectFatal missingG "$d" vheFoam "Entry 'G' not found" vheProperties
d=$(variant negativeG); setEntry "$d/$P" solids/rubber/G "[1 -1 -2 0 0 0 0] -1"
expectFatal negativeG "$d" vheFoam "G of rubber must be positive" vheProperties
d=$(variant hugeG); setEntry "$d/$P" solids/rubber/G "[1 -1 -2 0 0 0 0] 1e300"
expectFatal hugeG "$d" vheFoam "G of rubber is 1e\+300 Pa, above 1e\+20 Pa" vheProperties
d=$(variant rigidWithG); foamDictionary -entry solids/rubber/rigid -add yes "$d/$P" > /dev/null
expectFatal rigidWithG "$d" vheFoam "G has no meaning for the rigid material rubber" vheProperties
d=$(variant rigidWithViscosity); foamDictionary -entry solids/rubber/rigid -add yes "$d/$P" > /dev/null
delEntry "$d/$P" solids/rubber/G
expectFatal rigidWithViscosity "$d" vheFoam "(mu|nu) has no meaning for the rigid material rubber: its bodies do not shear" vheProperties
d=$(variant fixedNotRigid); foamDictionary -entry solids/rubber/motion -add fixed "$d/$P" > /dev/null
expectFatal fixedNotRigid "$d" vheFoam "motion fixed holds a rigid body to a motion: set rigid yes for rubber" vheProperties
d=$(variant unknownMotion); foamDictionary -entry solids/rubber/motion -add spinning "$d/$P" > /dev/null
expectFatal unknownMotion "$d" vheFoam "motion of rubber must be free, fixed or prescribed, got spinning" vheProperties
d=$(variant velocityNotPrescribed); foamDictionary -entry solids/rubber/angularVelocity -add "(0 0 1)" "$d/$P" > /dev/null
expectFatal velocityNotPrescribed "$d" vheFoam "angularVelocity of rubber is a prescribed motion's: set motion prescribed, or remove it" vheProperties
d=$(variant contactRange); echo "contact { range 3; }" >> "$d/$P"
expectFatal contactRange "$d" vheFoam "contact \{ range \} must lie in \[1, 2\] cells" vheProperties
d=$(variant contactStrength); echo "contact { strength -1; }" >> "$d/$P"
expectFatal contactStrength "$d" vheFoam "contact \{ strength \} must lie in \[0, 2\]" vheProperties
d=$(variant contactEntry); echo "contact { stiffness 1; }" >> "$d/$P"
expectFatal contactEntry "$d" vheFoam "Unknown entry 'stiffness' in contact" vheProperties
d=$(variant sigmaSolid); echo "sigmas ( (liquid rubber) 0.07 );" >> "$d/$P"
expectFatal sigmaSolid "$d" vheFoam "sigmas: 'rubber' is a solid; solids take no surface tension" vheProperties
d=$(variant sigmaUnknownFluid); echo "sigmas ( (liquid oil) 0.07 );" >> "$d/$P"
expectFatal sigmaUnknownFluid "$d" vheFoam "sigmas: unknown fluid 'oil'" vheProperties
d=$(variant sigmaDimensions); echo "sigmas ( (liquid air) [1 0 -1 0 0 0 0] 0.07 );" >> "$d/$P"
expectFatal sigmaDimensions "$d" vheFoam "sigmas: .* has dimensions" vheProperties
d=$(variant negativeRho); setEntry "$d/$P" fluids/liquid/rho "[1 -3 0 0 0 0 0] -1"
expectFatal negativeRho "$d" vheFoam "rho of liquid must be positive" vheProperties
d=$(variant zeroBodyDensity); setEntry "$d/$P" solids/rubber/rho "[1 -3 0 0 0 0 0] 0"
expectFatal zeroBodyDensity "$d" vheFoam "rho of rubber must be positive" vheProperties
d=$(variant missingViscosity); delEntry "$d/$P" fluids/liquid/mu
expectFatal missingViscosity "$d" vheFoam "exactly one of 'mu'" vheProperties
d=$(variant negativeNu); setEntry "$d/$P" solids/rubber/nu "[0 2 -1 0 0 0 0] -2"
expectFatal negativeNu "$d" vheFoam "must not be negative" vheProperties
d=$(variant wrongDimensionsG); setEntry "$d/$P" solids/rubber/G "[0 2 -2 0 0 0 0] 0.5"
expectFatal wrongDimensionsG "$d" vheFoam "do not match the expected dimensions" vheProperties
d=$(variant unknownPhaseEntry); setEntry "$d/$P" solids/rubber/E "[1 -1 -2 0 0 0 0] 1"
expectFatal unknownPhaseEntry "$d" vheFoam "Unknown entry 'E'" vheProperties
d=$(variant noFluids); delEntry "$d/$P" fluids
expectFatal noFluids "$d" vheFoam "No 'fluids'" vheProperties

# ---- vheFoam: fields in 0/
d=$(variant alphaSumNot1); setFirstCell "$d/0/alpha.liquid" 0.8
expectFatal alphaSumNot1 "$d" vheFoam "do not sum to 1" "$d/0"
d=$(variant alphaOutOfRange); setFirstCell "$d/0/alpha.rubber" 1.5
expectFatal alphaOutOfRange "$d" vheFoam "outside \[0, 1\]" alpha.rubber
d=$(variant unknownAlpha); cp "$d/0/alpha.rubber" "$d/0/alpha.oil"
expectFatal unknownAlpha "$d" vheFoam "names no phase" alpha.oil
d=$(variant missingAlpha); rm "$d/0/alpha.liquid"
expectFatal missingAlpha "$d" vheFoam "has no field file" alpha.liquid
d=$(variant BstarNotPSD)
setFirstCell "$d/0/Bstar" "(1 2 0 1 0 1)"
expectFatal BstarNotPSD "$d" vheFoam "not positive semi-definite" Bstar

# ---- vheFoam: constant/g, system/fvSolution
d=$(variant gWrongDimensions); sed -i 's/^dimensions .*/dimensions [0 1 -1 0 0 0 0];/' "$d/constant/g"
expectFatal gWrongDimensions "$d" vheFoam "g must have the dimensions of an acceleration" constant/g
d=$(variant noPressureReference); sed -i '/pRefCell\|pRefValue/d' "$d/system/fvSolution"
expectFatal noPressureReference "$d" vheFoam "Unable to set reference cell" fvSolution

d=$(variant unknownElasticity); sed -i 's/^    pRefValue .*/&\n    elasticity implicitish;/' "$d/system/fvSolution"
expectFatal unknownElasticity "$d" vheFoam "Unknown elasticity 'implicitish'" fvSolution
d=$(variant negativeStabilisation); sed -i 's/^    pRefValue .*/&\n    elasticStabilisation -1;/' "$d/system/fvSolution"
expectFatal negativeStabilisation "$d" vheFoam "elasticStabilisation must be >= 0" fvSolution
d=$(variant stabilisedStiff); sed -i 's/^    pRefValue .*/&\n    elasticStabilisation 0.1;/' "$d/system/fvSolution"
sed -i 's/G \[1 -1 -2 0 0 0 0\] 0.5;/G [1 -1 -2 0 0 0 0] 1e8;/' "$d/$P"
expectFatal stabilisedStiff "$d" vheFoam "elasticStabilisation \(experimental\) with a stiff body" fvSolution running
d=$(variant badSecondOrderWalls); sed -i 's/^    pRefValue .*/&\n    secondOrderWalls maybe;/' "$d/system/fvSolution"
expectFatal badSecondOrderWalls "$d" vheFoam "Expected 'true/false', 'on/off' ... found maybe" fvSolution.PIMPLE.secondOrderWalls
d=$(variant badCoupling); sed -i 's/^    pRefValue .*/&\n    coupling { tolerance -1; }/' "$d/system/fvSolution"
expectFatal badCoupling "$d" vheFoam "coupling: tolerance must be > 0" fvSolution.PIMPLE.coupling
d=$(variant badSolidTransport); sed -i "0,/nAlphaSubCycles/s/nAlphaSubCycles.*/&\n        solidTransport  isoish;/" "$d/system/fvSolution"
expectFatal badSolidTransport "$d" vheFoam "solidTransport must be geometric or MULES, got 'isoish'" fvSolution.solvers
d=$(variant unknownBTransport); sed -i 's/^    pRefValue .*/&\n    BTransport upwindish;/' "$d/system/fvSolution"
expectFatal unknownBTransport "$d" vheFoam "Unknown BTransport 'upwindish'" fvSolution
d=$(variant unknownPrescribedVelocity); sed -i 's/^    pRefValue .*/&\n    prescribedVelocity { type swirl; }/' "$d/system/fvSolution"
expectFatal unknownPrescribedVelocity "$d" vheFoam "Unknown prescribedVelocity type 'swirl'" fvSolution
d=$(variant unsupportedDdtScheme); setEntry "$d/system/fvSchemes" ddtSchemes/default CrankNicolson
expectFatal unsupportedDdtScheme "$d" vheFoam "ddt\(rho,U\) scheme 'CrankNicolson' is not supported" fvSchemes
d=$(variant nonlinearCompression); setEntry "$d/system/fvSchemes" "divSchemes/div(phirb,alpha)" "Gauss vanLeer"
expectFatal nonlinearCompression "$d" vheFoam "div\(phirb,alpha\) must be 'Gauss linear'" fvSchemes
d=$(variant backwardExplicit); setEntry "$d/system/fvSchemes" ddtSchemes/default backward
sed -i 's/^    pRefValue .*/&\n    elasticity explicit;/' "$d/system/fvSolution"
expectFatal backwardExplicit "$d" vheFoam "backward needs PIMPLE \{ elasticity semiImplicit; \}" fvSchemes

# ---- vheFoam: constant/dynamicMeshDict (run-time refinement)
# writeRefinement DIR FIELD FLUXES: a dynamicRefineFvMesh dictionary
writeRefinement() {
    cat > "$1/constant/dynamicMeshDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object dynamicMeshDict; }
dynamicFvMesh dynamicRefineFvMesh;
dynamicRefineFvMeshCoeffs
{
    refineInterval 1; field $2; lowerRefineLevel 0.01; upperRefineLevel 2;
    nBufferLayers 1; maxRefinement 1; maxCells 100000; dumpLevel false;
    correctFluxes ( $3 );
}
DICT
}
allFluxes="(phi none) (alphaPhiSolid none) (rhoPhi none) (ghf none) (accelerationFlux none)"
d=$(variant refineOnUnknownField); writeRefinement "$d" alpha.gas "$allFluxes"
expectFatal refineOnUnknownField "$d" vheFoam "field alpha.gas is not a volScalarField" dynamicMeshDict
d=$(variant refineMissingFlux); writeRefinement "$d" interfaceIndicator "(phi none)"
expectFatal refineMissingFlux "$d" vheFoam "correctFluxes does not list the fluxes" dynamicMeshDict
d=$(variant movingMesh)
cat > "$d/constant/dynamicMeshDict" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object dynamicMeshDict; }
dynamicFvMesh dynamicMotionSolverFvMesh; motionSolverLibs (fvMotionSolvers);
motionSolver solidBody; solidBodyMotionFunction linearMotion; velocity (0 0 0);
DICT
expectFatal movingMesh "$d" vheFoam "dynamicFvMesh dynamicMotionSolverFvMesh is not supported" dynamicMeshDict

# ---- setBodies: system/setBodiesDict
B=system/setBodiesDict
writeBodies() {
    cat > "$1/$B" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object setBodiesDict; }
bodies { $2 }
DICT
}
d=$(variant unknownMaterial)
writeBodies "$d" "b { material steel; shape cylinder; centre (0.5 0.5 0.5); radius 0.1; }"
expectFatal unknownMaterial "$d" setBodies "material 'steel' is not a solid" setBodiesDict
d=$(variant bodyOutsideMesh)
writeBodies "$d" "b { material rubber; shape cylinder; centre (0.5 1.5 0.5); radius 0.1; }"
expectFatal bodyOutsideMesh "$d" setBodies "outside the mesh" setBodiesDict
d=$(variant sphereIn2D)
writeBodies "$d" "b { material rubber; shape sphere; centre (0.5 0.5 0.5); radius 0.1; }"
expectFatal sphereIn2D "$d" setBodies "3D shape" setBodiesDict
d=$(variant packingCannotFit)
writeBodies "$d" "p { material rubber; packing random; count 400; radius 0.05; gap 0.01; seed 3; }"
expectFatal packingCannotFit "$d" setBodies "only [0-9]+ of 400 bodies" setBodiesDict
d=$(variant unknownShape)
writeBodies "$d" "b { material rubber; shape torus; centre (0.5 0.5 0.5); radius 0.1; }"
expectFatal unknownShape "$d" setBodies "Unknown shape 'torus'" setBodiesDict
d=$(variant negativeRadius)
writeBodies "$d" "b { material rubber; shape cylinder; centre (0.5 0.5 0.5); radius -0.1; }"
expectFatal negativeRadius "$d" setBodies "radius of b must be positive" setBodiesDict
d=$(variant overlappingBodies)
writeBodies "$d" "a { material rubber; shape cylinder; centre (0.5 0.5 0.5); radius 0.2; } b { material rubber; shape cylinder; centre (0.6 0.5 0.5); radius 0.2; }"
expectFatal overlappingBodies "$d" setBodies "Bodies overlap" setBodiesDict
finish
