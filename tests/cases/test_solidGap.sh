#!/bin/bash
# A fully solid gap under a steady body force (REFERENCE.md verification 2):
# the solid comes to rest with the exact steady shear strain
# B_xy = gamma = rho f (h/2 - y) / G (0.098 at the walls for f 0.098, G 0.5).
# 32 cells, t = 30: measured max error 2.6e-3 (in the wall cells; the
# interior is exact to 1e-5), max |U| 4e-6.  Bounds: 1.2 x 2.6e-3, 1e-4.
. "$(dirname "$0")/lib.sh"

d="$WORK/gap"
channelCase "$d" cells=32 G=0.5 endTime=30 writeInterval=30 || { fail setup "$d"; finish; }
cat > "$d/system/setBodiesDict" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object setBodiesDict; }
bodies { gap { material rubber; shape box; min (0 0 0); max (1 1 1); } }
DICT
run "$d" setBodies && run "$d" vheFoam || { fail gapRun "$d"; finish; }
read -r err umax <<< "$(python3 - "$d" <<'PY'
import re, sys
d = sys.argv[1]
def cells(p):
    s = open(p).read(); i = s.index("internalField"); st = s.index("(", i)
    n = int(s[s.index(">", i) + 1:st]); body = s[st + 1:s.index("\n)\n", st)]
    x = [float(v) for v in re.findall(r"[-+]?\d+\.?\d*(?:[eE][-+]?\d+)?", body)]
    k = len(x) // n
    return [x[j * k:(j + 1) * k] for j in range(n)]
B, U, N, f, G = cells(d + "/30/Bstar"), cells(d + "/30/U"), 32, 0.098, 0.5
err = max(abs(B[j * N][1] - f * (0.5 - (j + 0.5) / N) / G) for j in range(N))
print(err, max(abs(c) for u in U for c in u))
PY
)"
check steadyStrain "$err < 1.2*2.6e-3" "max |B_xy - rho f (h/2 - y)/G| = $err (wall value 0.098)"
check solidAtRest "$umax < 1e-4" "max |U| = $umax"
finish
