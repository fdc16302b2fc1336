#!/bin/sh
# Frames per second of `prime walk` (docs/prime/walk-and-compare.md): every
# shipped scene that walk can show (all of scenes/prime but plate1, a
# wireframe), at 350 x 769 and 1024 x 768, each profile, N frames along an
# orbit (medians). The scenes are modelled first.
# Usage: bench/prime/walk_fps.sh [PRIME] [FRAMES] [THREADS]
set -eu
PRIME=${1:-build/release/src/cli/prime}
FRAMES=${2:-9}
THREADS=${3:-0}
SCENES=$(cd scenes/prime && ls -d */ | tr -d / | grep -v '^plate1$')
for scene in $SCENES; do
  "$PRIME" model "scenes/prime/$scene" >/dev/null
done
for size in "350 769" "1024 768"; do
  for profile in 1991 modern; do
    for scene in $SCENES; do
      # shellcheck disable=SC2086  # $size is two numbers
      "$PRIME" walk "scenes/prime/$scene" --bench "$FRAMES" --size $size --threads "$THREADS" \
        --profile "$profile" | sed -n '2,4p' | sed "s|^|$scene $profile $size: |"
    done
  done
done
