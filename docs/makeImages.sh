#!/bin/bash
# Regenerates the pictures of README.md and docs/ (docs/images/) from the
# tutorials' and benchmarks' own outputs: run their Allrun first (the
# tutorials' Allrun writes results/*.png with gnuplot and pvbatch; a
# benchmark writes its plot).  Each must stay under 300 kB (the renders and
# plots are made at sizes that are); a missing source is reported and its
# old picture kept.
#   docs/makeImages.sh
cd "$(dirname "$0")" || exit 1
root=$(cd .. && pwd)
mkdir -p images
missing=0

# pick NAME SOURCE...: the last existing SOURCE (glob order) -> images/NAME
pick()
{
    local name=$1 src="" s; shift
    for s in "$@"; do [ -f "$s" ] && src=$s; done
    if [ -z "$src" ]; then
        echo "missing: $name (from $*): run that tutorial's or benchmark's Allrun"
        missing=$((missing + 1))
        return
    fi
    cp "$src" "images/$name"
    if [ "$(stat -c %s "images/$name")" -gt 300000 ]; then
        echo "too large: images/$name (over 300 kB): render $src smaller"
        missing=$((missing + 1))
    fi
    echo "images/$name <- ${src#"$root"/} ($(($(stat -c %s "images/$name") / 1024)) kB)"
}

t=$root/tutorials b=$root/benchmarks
pick periodicChannel_disks.png "$t/periodicChannel/results/disks_G0.5.png"
pick periodicChannel_flowRate.png "$t/periodicChannel/results/flowRate.png"
pick damBreakSpheres_scene.png "$t/damBreakSpheres/results/scene_G0.1_t0.5.png"
pick damBreakSpheres_hL.png "$t/damBreakSpheres/results/hL.png"
pick periodicChannel_sweep.png "$t/periodicChannel/results/sweep.png"
pick floatingBlock_scene.png "$t"/floatingBlock/results/scene_t*.png
pick floatingBodies_scene.png "$t/floatingBodies/results/scene_t1.png"
pick floatingBodies_heights.png "$t/floatingBodies/results/heights.png"
pick stairs_scene.png "$t"/stairs/results/scene_t1*.png
pick bubbleObstacle_scene.png "$t"/bubbleObstacle/results/scene_amr_t*.png
pick dropParticle_scene.png "$t/dropParticle/results/scene_t0.5.png"
pick risingBubble.png "$b/surfaceTension/results/risingBubble.png"
pick errorVsRuntime.png "$b/errorVsRuntime/errorVsRuntime.png"
pick transport.png "$b/transport/results/transport.png"
pick performance.png "$b/performance/results/performance.png"
[ "$missing" = 0 ]
