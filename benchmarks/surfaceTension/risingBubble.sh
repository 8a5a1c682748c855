#!/bin/bash
# risingBubble.sh DIR N [ENDTIME]: Hysing et al. (2009)'s test case 1, a 2D
# bubble rising in a liquid: box 1 x 2, bubble radius 0.25 at (0.5, 0.5);
# liquid rho 1000, mu 10; bubble rho 100, mu 1; sigma 24.5; g 0.98
# downward; no-slip walls top and bottom, slip walls at the sides.  N
# cells per unit length (h = 1/N: N x 2N cells), to t = ENDTIME (default
# 3), the step set by maxCo 0.2 and the capillary limit (interFoam's
# maxDeltaT, since it has none of its own).  The same case
# runs under vheFoam (DIR/vheFoam) and Debian's interFoam (DIR/interFoam,
# made by bin/vheToInterFoam), side by side.  The phaseStatistics function
# object writes the bubble's centroid, rise velocity and circularity every
# step (postProcessing/bubble/0/phaseStatistics.dat); risingBubble.py
# reads them.
. "$(dirname "$0")/../../tests/cases/lib.sh" 2>/dev/null
. "$(dirname "$0")/common.sh"
here=$(cd "$(dirname "$0")" && pwd)
d=$1 n=$2 tend=${3:-3}
c=$d/vheFoam
rm -rf "$d"; mkdir -p "$c/0" "$c/constant" "$c/system"
lz=$(python3 -c "print(1.0/$n)")
# interFoam has no capillary step limit: both take Brackbill's as maxDeltaT
dtcap=$(python3 -c "import math; print(min(0.01, math.sqrt(550*(1.0/$n)**3/(2*math.pi*24.5))))")
cat > "$c/system/blockMeshDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
vertices ( (0 0 0) (1 0 0) (1 2 0) (0 2 0) (0 0 $lz) (1 0 $lz) (1 2 $lz) (0 2 $lz) );
blocks ( hex (0 1 2 3 4 5 6 7) ($n $((2*n)) 1) simpleGrading (1 1 1) );
boundary
(
    topBottom { type wall; faces ((0 1 5 4) (3 7 6 2)); }
    sides { type wall; faces ((0 4 7 3) (1 2 6 5)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }
);
DICT
cat > "$c/system/controlDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application vheFoam; libs (vheFoam);
startFrom latestTime; startTime 0; stopAt endTime; endTime $tend;
deltaT 1e-4; writeControl adjustable; writeInterval 0.5; purgeWrite 0;
writeFormat ascii; writePrecision 10; timePrecision 6;
runTimeModifiable false; adjustTimeStep yes; maxCo 0.2; maxAlphaCo 0.2;
maxDeltaT $dtcap;
functions
{
    bubble
    {
        type phaseStatistics; libs (vheFoam); alpha alpha.gas;
        writeControl timeStep; writeInterval 1;
    }
}
DICT
st_dicts "$c" 1e-9 0.01 1000 10 100 1 24.5 -0.98
cat > "$c/0/U" <<DICT
FoamFile { version 2.0; format ascii; class volVectorField; object U; }
dimensions [0 1 -1 0 0 0 0];
internalField uniform (0 0 0);
boundaryField { topBottom { type noSlip; } sides { type slip; } frontAndBack { type empty; } }
DICT
cat > "$c/0/p_rgh" <<DICT
FoamFile { version 2.0; format ascii; class volScalarField; object p_rgh; }
dimensions [1 -1 -2 0 0 0 0];
internalField uniform 0;
boundaryField { ".*" { type fixedFluxPressure; value uniform 0; } frontAndBack { type empty; } }
DICT
for phase in liquid gas; do
    side=$([ $phase = liquid ] && echo outside)
    {
        echo "FoamFile { version 2.0; format ascii; class volScalarField; object alpha.$phase; }"
        echo "dimensions [0 0 0 0 0 0 0];"
        python3 "$here/fraction.py" $n $((2*n)) 1 1 2 $lz 0.5 0.5 0 0.25 $side
        echo "boundaryField { \".*\" { type zeroGradient; } frontAndBack { type empty; } }"
    } > "$c/0/alpha.$phase"
done
st_run "$d"
