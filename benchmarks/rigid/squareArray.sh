#!/bin/bash
# squareArray.sh DIR CELLS C [ENDTIME]: Stokes flow through a square array
# of fixed cylinders (Sangani & Acrivos 1982): one cylinder of area
# fraction C (radius sqrt(C/pi)) at the centre of a unit cell, periodic in
# x and y, a rigid material held in place (motion fixed), driven by a body
# force f = 0.1 m/s^2 per unit mass in x on everything (fluid and
# cylinder, as a mean pressure gradient acts).  rho 1, mu 1: Reynolds
# number U L/nu below 0.01.  Fixed step dt = 0.01 (a viscous number of
# 0.01 CELLS^2: 41 at 64 cells), to t = 1 (40 times the slowest viscous
# time L^2/(4 pi^2 nu)).  The case is left in DIR for squareArray.py.
. "$(dirname "$0")/arrayCase.sh"
d=$1 n=$2 c=$3 tend=${4:-1}
r=$(python3 -c "import math; print(math.sqrt($c/math.pi))")
periodicCell "$d" "$n" "$tend" || exit 1
runCell "$d" "${DT:-0.01}" \
    "cylinder { material rubber; shape cylinder; centre (0.5 0.5 0.5); radius $r; axis (0 0 1); }"
