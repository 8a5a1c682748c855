#!/bin/bash
# capillaryWave.sh DIR N: Prosperetti (1981)'s small capillary wave as in
# Popinet (2009): wavelength 1, box 1 x 1 (cyclic in x, slip walls top and
# bottom), interface y = 0.5 + 0.01 cos(2 pi x), both fluids rho 1,
# sigma 1, mu from La = sigma rho lambda/mu^2 = 3000, no gravity; N cells
# per wavelength (N x N), to t = 2.2 (omega0 t = 25) at the capillary step
# limit, the liquid's fraction written every 0.02.  Runs vheFoam
# (DIR/vheFoam) and interFoam (DIR/interFoam) side by side;
# capillaryWave.py compares the amplitude with prosperetti.py's.
. "$(dirname "$0")/../../tests/cases/lib.sh" 2>/dev/null
. "$(dirname "$0")/common.sh"
d=$1 n=$2
c=$d/vheFoam
rm -rf "$d"; mkdir -p "$c/0" "$c/constant" "$c/system"
read -r mu dt lz <<< "$(python3 -c "
import math
print(math.sqrt(1/3000.0), math.sqrt((1.0/$n)**3/(2*math.pi)), 1.0/$n)")"
cat > "$c/system/blockMeshDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
vertices ( (0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 $lz) (1 0 $lz) (1 1 $lz) (0 1 $lz) );
blocks ( hex (0 1 2 3 4 5 6 7) ($n $n 1) simpleGrading (1 1 1) );
boundary
(
    left { type cyclic; neighbourPatch right; faces ((0 4 7 3)); }
    right { type cyclic; neighbourPatch left; faces ((1 2 6 5)); }
    walls { type wall; faces ((0 1 5 4) (3 7 6 2)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }
);
DICT
cat > "$c/system/controlDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application vheFoam; libs (vheFoam);
startFrom startTime; startTime 0; stopAt endTime; endTime 2.2;
deltaT $dt; writeControl adjustable; writeInterval 0.02; purgeWrite 0;
writeFormat ascii; writePrecision 12; timePrecision 8;
runTimeModifiable false; adjustTimeStep yes; maxCo 0.5; maxAlphaCo 0.5;
maxDeltaT $dt;
DICT
st_dicts "$c" 1e-10 0 1 $mu 1 $mu 1 0
cat > "$c/0/U" <<DICT
FoamFile { version 2.0; format ascii; class volVectorField; object U; }
dimensions [0 1 -1 0 0 0 0];
internalField uniform (0 0 0);
boundaryField { left { type cyclic; } right { type cyclic; } walls { type slip; } frontAndBack { type empty; } }
DICT
cat > "$c/0/p_rgh" <<DICT
FoamFile { version 2.0; format ascii; class volScalarField; object p_rgh; }
dimensions [1 -1 -2 0 0 0 0];
internalField uniform 0;
boundaryField { left { type cyclic; } right { type cyclic; } walls { type fixedFluxPressure; value uniform 0; } frontAndBack { type empty; } }
DICT
for phase in liquid gas; do
    {
        echo "FoamFile { version 2.0; format ascii; class volScalarField; object alpha.$phase; }"
        echo "dimensions [0 0 0 0 0 0 0];"
        python3 -c "
import math
n = $n; d = 1.0/n; m = 64; out = []
for j in range(n):
    for i in range(n):
        f = 0.0
        for s in range(m):
            x = (i + (s + 0.5)/m)*d
            y = 0.5 + 0.01*math.cos(2*math.pi*x)
            f += min(max((y - j*d)/d, 0.0), 1.0)
        f /= m
        out.append(f if '$phase' == 'liquid' else 1 - f)
print('internalField nonuniform List<scalar> %d\n(' % len(out))
print('\n'.join('%.12g' % v for v in out))
print(');')"
        echo "boundaryField { left { type cyclic; } right { type cyclic; } walls { type zeroGradient; } frontAndBack { type empty; } }"
    } > "$c/0/alpha.$phase"
done
st_run "$d"
