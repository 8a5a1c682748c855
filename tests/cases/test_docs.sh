#!/bin/bash
# The front page and the manual: every relative link and image of
# README.md and docs/ resolves; README.md is at most 300 lines and shows at
# least four pictures of scenes; every picture in docs/images/ is under
# 300 kB (docs/makeImages.sh makes them).
. "$(dirname "$0")/lib.sh"

out=$(python3 "$TESTS_DIR/docLinks.py" "$VHE_ROOT")
nBroken=$(echo "$out" | grep -c "^broken:")
check docLinks "$nBroken == 0" "$(echo "$out" | tail -1)$(echo "$out" | grep '^broken:' | head -3 | tr '\n' ' ')"

lines=$(wc -l < "$VHE_ROOT/README.md")
check readmeLength "$lines <= 300" "README.md: $lines lines"
scenes=$(grep -oE '!\[[^]]*\]\(docs/images/(periodicChannel|damBreakSpheres|floatingBlock|stairs|bubbleObstacle)_[^)]*\)' \
    "$VHE_ROOT/README.md" | sort -u | wc -l)
check readmeScenePictures "$scenes >= 4" "$scenes pictures of scenes in README.md"

big=$(find "$VHE_ROOT/docs/images" -name '*.png' -size +300k | wc -l)
n=$(find "$VHE_ROOT/docs/images" -name '*.png' | wc -l)
check imagesSmall "$n >= 4 and $big == 0" "$n pictures in docs/images, $big over 300 kB"
finish
