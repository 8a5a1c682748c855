#!/bin/bash
# staticDrop.sh DIR CELLS_PER_D [STEPS] [DIM]: a static drop, radius
# R = 0.25 at the centre of a unit box (square in 2D, cube with DIM 3),
# walls all round, no gravity; both fluids rho 1, sigma 1, and mu from the
# Laplace number La = sigma rho D/mu^2 = 12000 (Popinet 2009's test).
# CELLS_PER_D cells across the drop, 2 CELLS_PER_D across the box.  The
# same case runs under vheFoam (DIR/vheFoam) and Debian's interFoam
# (DIR/interFoam, made by bin/vheToInterFoam) for STEPS (default 1000)
# steps of the capillary step limit sqrt(rho dx^3/(2 pi sigma)).
# staticDrop.py reads the pressure jump and the spurious velocity.
. "$(dirname "$0")/../../tests/cases/lib.sh" 2>/dev/null
. "$(dirname "$0")/common.sh"
here=$(cd "$(dirname "$0")" && pwd)
d=$1 n=$2 steps=${3:-1000} dim=${4:-2}
N=$((2*n))
read -r mu dt <<< "$(python3 -c "
import math
sigma, rho, D, La = 1.0, 1.0, 0.5, 12000.0
dx = 1.0/$N
print(math.sqrt(sigma*rho*D/La), math.sqrt(rho*dx**3/(2*math.pi*sigma)))")"
endTime=$(python3 -c "print(repr($steps*$dt))")
c=$d/vheFoam
rm -rf "$d"; mkdir -p "$c/0" "$c/constant" "$c/system"
# 3D: the front and back are walls too
if [ "$dim" = 3 ]; then
    nz=$N lz=1 cz=0.5 front=wall fU=noSlip fp=fixedFluxPressure fa=zeroGradient
else
    nz=1 lz=$(python3 -c "print(1.0/$N)") cz=0 front=empty fU=empty fp=empty fa=empty
fi
cat > "$c/system/blockMeshDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
vertices ( (0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 $lz) (1 0 $lz) (1 1 $lz) (0 1 $lz) );
blocks ( hex (0 1 2 3 4 5 6 7) ($N $N $nz) simpleGrading (1 1 1) );
boundary
(
    walls { type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2)); }
    frontAndBack { type $front; faces ((0 3 2 1) (4 5 6 7)); }
);
DICT
cat > "$c/system/controlDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application vheFoam; libs (vheFoam);
startFrom startTime; startTime 0; stopAt endTime; endTime $endTime;
deltaT $dt; writeControl timeStep; writeInterval $steps; purgeWrite 0;
writeFormat ascii; writePrecision 12; timePrecision 12;
runTimeModifiable false; adjustTimeStep no; maxCo 1; maxAlphaCo 1;
DICT
st_dicts "$c" 1e-10 0 1 $mu 1 $mu 1 0
cat > "$c/0/U" <<DICT
FoamFile { version 2.0; format ascii; class volVectorField; object U; }
dimensions [0 1 -1 0 0 0 0];
internalField uniform (0 0 0);
boundaryField { walls { type noSlip; } frontAndBack { type $fU; } }
DICT
cat > "$c/0/p_rgh" <<DICT
FoamFile { version 2.0; format ascii; class volScalarField; object p_rgh; }
dimensions [1 -1 -2 0 0 0 0];
internalField uniform 0;
boundaryField { walls { type fixedFluxPressure; value uniform 0; } frontAndBack { type $fp; value uniform 0; } }
DICT
for phase in liquid gas; do
    side=$([ $phase = gas ] && echo outside)
    {
        echo "FoamFile { version 2.0; format ascii; class volScalarField; object alpha.$phase; }"
        echo "dimensions [0 0 0 0 0 0 0];"
        python3 "$here/fraction.py" $N $N $nz 1 1 $lz 0.5 0.5 $cz 0.25 $side
        echo "boundaryField { walls { type zeroGradient; } frontAndBack { type $fa; } }"
    } > "$c/0/alpha.$phase"
done
st_run "$d"
