#!/bin/bash
# sessileDrop.sh DIR THETA [N] [ENDTIME]: a 2D drop spreading on a wall to
# its contact angle THETA (degrees, constantAlphaContactAngle on the
# liquid's fraction).  A half disk of radius 0.25 on the floor of a box
# 1 x 0.5 (N cells across, default 64; square cells), no gravity; both
# fluids rho 1, mu 0.02, sigma 1; to t = ENDTIME (default 3).  At rest
# the drop is the circular cap of its area with the angle THETA, whose
# centroid height sessileDrop.py compares with the drop's
# (postProcessing/drop/0/phaseStatistics.dat).  The same case runs under
# interFoam (DIR/interFoam).
. "$(dirname "$0")/../../tests/cases/lib.sh" 2>/dev/null
. "$(dirname "$0")/common.sh"
here=$(cd "$(dirname "$0")" && pwd)
d=$1 theta=$2 n=${3:-64} tend=${4:-3}
c=$d/vheFoam
rm -rf "$d"; mkdir -p "$c/0" "$c/constant" "$c/system"
lz=$(python3 -c "print(1.0/$n)")
cat > "$c/system/blockMeshDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
vertices ( (0 0 0) (1 0 0) (1 0.5 0) (0 0.5 0) (0 0 $lz) (1 0 $lz) (1 0.5 $lz) (0 0.5 $lz) );
blocks ( hex (0 1 2 3 4 5 6 7) ($n $((n/2)) 1) simpleGrading (1 1 1) );
boundary
(
    floor { type wall; faces ((0 1 5 4)); }
    walls { type wall; faces ((0 4 7 3) (1 2 6 5) (3 7 6 2)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }
);
DICT
cat > "$c/system/controlDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application vheFoam; libs (vheFoam);
startFrom latestTime; startTime 0; stopAt endTime; endTime $tend;
deltaT 1e-4; writeControl adjustable; writeInterval $tend; purgeWrite 0;
writeFormat ascii; writePrecision 10; timePrecision 6;
runTimeModifiable false; adjustTimeStep yes; maxCo 0.2; maxAlphaCo 0.2;
maxDeltaT $(python3 -c "import math; print(math.sqrt((1.0/$n)**3/(2*math.pi)))");
functions
{
    drop { type phaseStatistics; libs (vheFoam); alpha alpha.liquid;
           writeControl timeStep; writeInterval 1; }
}
DICT
st_dicts "$c" 1e-9 0 1 0.02 1 0.02 1 0
cat > "$c/0/U" <<DICT
FoamFile { version 2.0; format ascii; class volVectorField; object U; }
dimensions [0 1 -1 0 0 0 0];
internalField uniform (0 0 0);
boundaryField { floor { type noSlip; } walls { type noSlip; } frontAndBack { type empty; } }
DICT
cat > "$c/0/p_rgh" <<DICT
FoamFile { version 2.0; format ascii; class volScalarField; object p_rgh; }
dimensions [1 -1 -2 0 0 0 0];
internalField uniform 0;
boundaryField { floor { type fixedFluxPressure; value uniform 0; } walls { type fixedFluxPressure; value uniform 0; } frontAndBack { type empty; } }
DICT
for phase in liquid gas; do
    side=$([ $phase = gas ] && echo outside)
    floorBC="type zeroGradient;"
    [ $phase = liquid ] && floorBC="type constantAlphaContactAngle; theta0 $theta; limit gradient; value uniform 0;"
    {
        echo "FoamFile { version 2.0; format ascii; class volScalarField; object alpha.$phase; }"
        echo "dimensions [0 0 0 0 0 0 0];"
        python3 "$here/fraction.py" $n $((n/2)) 1 1 0.5 $lz 0.5 0 0 0.25 $side
        echo "boundaryField { floor { $floorBC } walls { type zeroGradient; } frontAndBack { type empty; } }"
    } > "$c/0/alpha.$phase"
done
st_run "$d"
