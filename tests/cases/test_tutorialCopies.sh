#!/bin/bash
# Tutorials a user can copy: each tutorial copied out of the project tree
# (to a fresh directory under /tmp) sets its cases up there with
# "./Allrun -setup" (mesh, fields, bodies) in the environment of
# Make/bashrc, as an OpenFOAM user runs a copied tutorial; without that
# environment it stops at once with a message saying what to source.
# Running a tutorial leaves the checkout clean (outputs are ignored by git).
. "$(dirname "$0")/lib.sh"

run=$(mktemp -d /tmp/vheFoamRun.XXXXXX)
trap 'rm -rf "$run"' EXIT
for t in periodicChannel damBreakSpheres floatingBlock stairs bubbleObstacle dropParticle; do
    cp -r "$VHE_ROOT/tutorials/$t" "$run/$t"
    rm -rf "$run/$t/cases" "$run/$t/results" "$run/$t"/log.*
    if (cd "$run/$t" && ./Allrun -setup > log.setup 2>&1); then
        nCases=$(ls -d "$run/$t"/cases/*/constant/polyMesh 2>/dev/null | wc -l)
        nFields=$(ls "$run/$t"/cases/*/0/alpha.* 2>/dev/null | wc -l)
        check "copy_$t" "$nCases >= 1 and $nFields >= $nCases" \
            "set up in a copy outside the tree: $nCases case(s) meshed, $nFields phase fields"
    else
        fail "copy_$t" "./Allrun -setup failed in a copy: $(tail -3 "$run/$t/log.setup" | tr '\n' ' ')"
    fi
done

# Without the environment: a clear message, not a missing file
cp -r "$VHE_ROOT/tutorials/stairs" "$run/bare"
msg=$(cd "$run/bare" && env -i PATH=/usr/bin:/bin HOME="$HOME" bash ./Allrun -setup 2>&1)
check "copyWithoutEnvironment" "'Make/bashrc' in '''$msg'''" "message: $msg"

# The checkout stays clean: what the tutorials' runs write (cases,
# results, logs; the copies above and this suite's runs) is ignored by git
dirty=$(cd "$VHE_ROOT" && git status --porcelain --untracked-files=all -- tutorials 2>/dev/null \
    | grep '^??' | head -5)
check "tutorialsLeaveCheckoutClean" "'''$dirty''' == ''" "git status of tutorials/: ${dirty:-clean}"
finish
