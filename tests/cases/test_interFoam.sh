#!/bin/bash
# No solids: vheFoam reproduces Debian's interFoam (v1912) on the same
# case, the scene B dam break without spheres at 21 x 10 x 10 cells to
# t = 0.5 (liquid/gas, density ratio 1000, nu 1e-2, no surface tension,
# interFoam with MULESCorr off and one alpha corrector, tight solver
# tolerances).  Measured: the same 69 steps, max |alpha difference| 1e-8
# and max |U difference| 6e-7 of 2.9 m/s, i.e. the 8-digit write
# precision.  Bounds: 1e-7 and 1e-6 relative.
. "$(dirname "$0")/lib.sh"

vhe="$WORK/vheFoam" inter="$WORK/interFoam"
sceneCase damBreakSpheres "$vhe" n1=21 n2=10 n3=10 endTime=0.5 writeInterval=0.5 \
    nSpheres=0 || { fail setup "$vhe"; finish; }
sed -i 's/relTol          0.05;/relTol 0;/; s/tolerance       1e-7;/tolerance 1e-10;/' \
    "$vhe/system/fvSolution"
run "$vhe" setFields || { fail setup "$vhe"; finish; }

# The same case for interFoam: its phase names, dictionaries and entries
cp -r "$vhe" "$inter"
rm "$inter/constant/vheProperties" "$inter/0/alpha.gas"
sed 's/alpha.liquid/alpha.water/' "$vhe/0/alpha.liquid" > "$inter/0/alpha.water"
rm "$inter/0/alpha.liquid"
cat > "$inter/constant/transportProperties" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object transportProperties; }
phases (water air);
water { transportModel Newtonian; nu 1e-2; rho 1000; }
air   { transportModel Newtonian; nu 1e-2; rho 1; }
sigma 0;
DICT
cat > "$inter/constant/turbulenceProperties" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object turbulenceProperties; }
simulationType laminar;
DICT
python3 - "$inter" <<'PY'
import sys
d = sys.argv[1]
p = d + "/system/fvSolution"; s = open(p).read()
s = s.replace('"alpha.*"\n    {\n        nAlphaSubCycles 1;\n        cAlpha          1;\n    }',
              '"alpha.water.*"\n    {\n        nAlphaCorr 1; nAlphaSubCycles 1; cAlpha 1;\n'
              '        MULESCorr no; nLimiterIter 3;\n    }')
s = s.replace("    p_rghFinal { $p_rgh; relTol 0; }",
              "    p_rghFinal { $p_rgh; relTol 0; }\n    \"pcorr.*\" { $p_rgh; relTol 0; }")
open(p, "w").write(s)
p = d + "/system/controlDict"; s = open(p).read()
s = s.replace("application     vheFoam;", "application     interFoam;")
s = s.replace("libs            (vheFoam);", "")
s = s[:s.index("functions")] + "functions {}\n"
open(p, "w").write(s)
p = d + "/system/fvSchemes"; s = open(p).read()
s = s.replace("div((mu*dev2(T(grad(U)))))", "div(((rho*nuEff)*dev2(T(grad(U)))))")
open(p, "w").write(s)
PY

run "$vhe" vheFoam || fail vheFoamRun "$vhe/log.vheFoam"
run "$inter" interFoam || fail interFoamRun "$inter/log.interFoam"

sv=$(grep -c "^Time = " "$vhe/log.vheFoam"); si=$(grep -c "^Time = " "$inter/log.interFoam")
check sameSteps "$sv == $si" "vheFoam $sv steps, interFoam $si steps"
mv "$inter/0.5/alpha.water" "$inter/0.5/alpha.liquid"
read -r d m <<< "$(maxFieldDiff "$vhe" "$inter" 0.5 alpha.liquid)"
check sameAlpha "$d < 1e-7" "max |alpha vheFoam - interFoam| = $d at t = 0.5"
read -r d m <<< "$(maxFieldDiff "$vhe" "$inter" 0.5 U)"
check sameVelocity "$d < 1e-6*$m" "max |U vheFoam - interFoam| = $d (max |U| $m) at t = 0.5"
finish
