#!/bin/bash
# drawCost.sh DIR [CELLS]: what drawing a rigid body from its shape costs a
# step in 3D.  lightSphere.sh's case (a rigid sphere of radius 0.1 in a
# 0.6 m cube of CELLS^3 cells, 32 by default: 5.3 cells' radius) run to
# t = 0.1 with OpenFOAM's profiling on.  Prints the steps, the time loop,
# and the alpha step split into its profiled parts (the fluids' shares,
# isoAdvector) and the rest, which is the body's drawing (rigidPoses::move:
# bodyShapes::draw and the fluids' share of the difference).  About 10 s.
. "$(dirname "$0")/tank.sh"
d=$1 n=${2:-32}
lightSphereCase "$d" "$n" 0.1 || exit 1
printf 'profiling { active true; cpuInfo false; memInfo false; sysInfo false; }\n' \
    >> "$d/system/controlDict"
(run "$d" blockMesh && run "$d" setFields && run "$d" setBodies && run "$d" vheFoam) \
    || { echo "failed: $d" >&2; exit 1; }
python3 - "$d" "$n" <<'PY'
import re, sys
d, n = sys.argv[1:]
s = open(d + "/0.1/uniform/profiling").read()
t = {}
for m in re.finditer(r'description\s+"([^"]+)";\s*calls\s+(\d+);\s*totalTime\s+([\d.e+-]+);', s):
    t[m.group(1)] = (int(m.group(2)), float(m.group(3)))
steps, loop = t["time.run() " + d.rstrip("/").split("/")[-1]]
alpha = t["vheFoam::alphaEqn"][1]
parts = sum(t.get(k, (0, 0))[1] for k in ("vheMixture::fluidShares", "vheMixture::isoAdvection"))
print(f"cells {n}^3: {steps} steps, time loop {loop:.2f} s; alpha step {alpha:.2f} s, "
      f"of which drawing and the rest {alpha - parts:.2f} s ({1e3*(alpha - parts)/steps:.1f} ms a step, "
      f"{100*(alpha - parts)/loop:.0f} % of the loop)")
PY
