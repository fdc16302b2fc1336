#!/usr/bin/env bash
# Regenerates every texture map under scenes/prime/ that tools/prime/mapgen.py makes (the
# others are typed by hand: 1 x 1 maps). With --check, writes nothing and
# fails if a committed map differs from what the script makes (CTest
# tools.maps_are_generated runs this).
set -euo pipefail
cd "$(dirname "$0")/../.."
check=0
[ "${1:-}" = "--check" ] && check=1
status=0

gen() {  # gen scene/map/MapN.txt mapgen-arguments...
  local target="scenes/prime/$1"
  shift
  if [ $check = 1 ]; then
    if ! python3 tools/prime/mapgen.py "$@" | cmp -s - "$target"; then
      echo "regen_maps: $target differs from: tools/prime/mapgen.py $*" >&2
      status=1
    fi
  else
    python3 tools/prime/mapgen.py --out "$target" "$@"
  fi
}

# Colour Plate 2. Map 4 is the "D.C.U. '91" lettering of the cube's outside.
gen plate2/map/Map1.txt checker --map 1 --cells 4 --a 0.05 0.05 0 --b 0.05 0 0
gen plate2/map/Map2.txt stripes --map 2 --size 8 --width 2 --a 0.05 0.05 0.05 --b 0 0.05 0
gen plate2/map/Map4.txt text --map 4 --line "D.C.U." --line "'91" --fg 0.05 0.05 0.05 --bg 0.05 0 0 \
  --margin 2 --line-gap 21
gen plate2/map/Map5.txt stripes --map 5 --size 16 --width 2 --a 0 0.05 0.05 --b 0.05 0 0.05
# Colour Plate 2 tuned for the thesis profile (scenes/prime/plate2-thesis/README.md): the same
# maps with every "on" texel 0.05 at 1, the colour the texture stands for.
gen plate2-thesis/map/Map1.txt checker --map 1 --cells 4 --a 1 1 0 --b 1 0 0
gen plate2-thesis/map/Map2.txt stripes --map 2 --size 8 --width 2 --a 1 1 1 --b 0 1 0
gen plate2-thesis/map/Map4.txt text --map 4 --line "D.C.U." --line "'91" --fg 1 1 1 --bg 1 0 0 \
  --margin 2 --line-gap 21
gen plate2-thesis/map/Map5.txt stripes --map 5 --size 16 --width 2 --a 0 1 1 --b 1 0 1
# Colour Plate 3: the chessboard.
gen plate3/map/Map1.txt checker --map 1 --cells 8 --a 0.01 1 0 --b 1 0.01 0
# Colour Plate 3 tuned for the thesis profile (scenes/prime/plate3-thesis/README.md): each square
# the colour the 1991 program showed it in (a small texel gave more light there), brightest channel 1.
gen plate3-thesis/map/Map1.txt checker --map 1 --cells 8 --a 1 0.66 0 --b 0.66 1 0
gen primitives/map/Map1.txt checker --map 1 --cells 4 --a 0.02 0.02 0 --b 0.02 0 0.02
gen glass/map/Map1.txt stripes --map 1 --size 16 --width 2 --a 0.02 0.02 0 --b 0.02 0 0.02
gen inside-maps/map/Map1.txt checker --map 1 --cells 4 --a 0.02 0.02 0 --b 0.02 0 0
gen inside-maps/map/Map2.txt stripes --map 2 --size 16 --width 2 --a 0 0.02 0.02 --b 0.02 0.02 0.02
gen inside-maps/map/Map3.txt checker --map 3 --cells 4 --a 0.02 0 0.02 --b 0.02 0.02 0.02
gen inside-maps/map/Map4.txt stripes --map 4 --size 16 --width 2 --a 0 0.02 0 --b 0.02 0.02 0
gen map-edge/map/Map1.txt bands --map 1 --width 8 --height 8 \
  --colour 0.02 0.02 0  0.02 0 0.02  0 0.02 0.02  0 0.02 0 --first 0.02 0.02 0.02 --last 0.02 0 0
exit $status
