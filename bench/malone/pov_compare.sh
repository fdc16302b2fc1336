#!/usr/bin/env bash
# Malone's ray tracer (this port) against POV-Ray 3.7 on every shipped scene
# (scenes/malone/*.mal), and the cost of a ray-triangle test against the
# document's "1600 triangles ... in the region of half an hour".
#
# 1. For each scene: `prime export-pov SCENE OUT.pov`, then RUNS paired runs of
#      prime trace SCENE --threads 1 --no-window -q          (--max-depth 7)
#      povray +IOUT.pov +W.. +H.. -A +WT1 -D -F -GA          (max_trace_level 7)
#    at the scene's own size (X_RES x Y_RES), each measured as the CPU time
#    (user + system, getrusage of the child) of the whole process. The two
#    programs of a pair run back to back and swap order every pair (prime
#    first in even pairs, POV-Ray first in odd ones), so a drift of the shared
#    machine's speed falls on both. Reports the median of the per-pair ratios
#    prime/POV-Ray, and how close the two pictures are (both rendered once,
#    File_Gamma=1.0, compared byte by byte).
# 2. mesh-1600.mal at 512 x 512 on one core: CPU time, median of the pairs.
# 3. A 10^6-triangle mesh (mesh_torus of tools/malone/scenes.py with 1000 x
#    500 quads, generated here, never committed) read, built and rendered at
#    512 x 512 on one core: `prime trace --timings` (median of MESH_RUNS).
# 4. ns per primitive test with the BVH (mesh-1600 at 512 x 512) and with
#    --linear-search (every primitive for every ray, as the original; at
#    LINEAR_RES x LINEAR_RES), beside the document's half hour.
# Writes docs/malone/benchmarks.csv and the generated part of
# docs/malone/benchmarks.md (between its malone_pov_compare markers; the rest
# of the file is kept).
#
# Usage: bench/malone/pov_compare.sh [RUNS]      (RUNS >= 5, default 7)
# Environment: PRIME=path/to/prime (default: build/release, brought up to date),
#              OUT=output directory (default: out/malone-pov-compare),
#              MESH_RUNS (default 5), LINEAR_RES (default 128).
set -euo pipefail

cd "$(dirname "$0")/../.."
ROOT=$PWD
RUNS=${1:-7}
if ((RUNS < 5)); then
  echo "malone_pov_compare: at least 5 paired runs (got $RUNS)" >&2
  exit 2
fi
MESH_RUNS=${MESH_RUNS:-5}
LINEAR_RES=${LINEAR_RES:-128}
OUT=${OUT:-$ROOT/out/malone-pov-compare}
DOC=$ROOT/docs/malone/benchmarks.md
CSV=$ROOT/docs/malone/benchmarks.csv

NAME=malone_pov_compare
source "$ROOT/bench/pov_common.sh"

rm -rf "$OUT"
mkdir -p "$OUT"

HAVE_PIL=no
if "$PY" -c 'import PIL, numpy' 2>/dev/null; then HAVE_PIL=yes; fi
echo "scene,width,height,runs,prime_cpu_s_median,pov_cpu_s_median,ratio_median,ratio_min,ratio_max,target_met,picture" >"$CSV"
ROWS=""
MESH1600_CPU=""

for scene in "$ROOT"/scenes/malone/*.mal; do
  name=$(basename "$scene" .mal)
  "$PRIME" export-pov "$scene" "$OUT/$name.pov" >"$OUT/$name.export.log"
  size=$(grep -o '+W[0-9]* +H[0-9]*' "$OUT/$name.export.log" | head -1)
  W=$(echo "$size" | sed 's/+W\([0-9]*\) .*/\1/')
  H=$(echo "$size" | sed 's/.*+H\([0-9]*\)/\1/')
  primeCmd=("$PRIME" trace "$scene" --threads 1 --no-window -q)
  povCmd=(povray "+I$name.pov" "+W$W" "+H$H" -A +WT1 -D -F -GA)

  # Once for the pictures (and to warm the caches).
  "$PRIME" trace "$scene" --threads 1 --no-window -q --png "$OUT/${name}_prime.png"
  (cd "$OUT" && povray "+I$name.pov" "+W$W" "+H$H" -A +WT1 -D File_Gamma=1.0 +FN \
    "+O${name}_pov.png" >"$name.pov.log" 2>&1)
  picture="?"
  if [ "$HAVE_PIL" = yes ]; then
    picture=$("$PY" "$ROOT/bench/malone_compare_images.py" "$OUT/${name}_prime.png" "$OUT/${name}_pov.png")
    "$PY" "$ROOT/bench/side_by_side.py" "$OUT/${name}_prime.png" "$OUT/${name}_pov.png" "$OUT/${name}_side.png"
  fi

  paired_runs "${primeCmd[@]}" -- "${povCmd[@]}"
  [ "$name" = mesh-1600 ] && MESH1600_CPU=$pm
  echo "$name,$W,$H,$RUNS,$pm,$qm,$rm_,$rmin,$rmax,$met,\"$picture\"" >>"$CSV"
  ROWS+="| \`$name\` | ${W} x ${H} | $(printf '%.3f' "$pm") | $(printf '%.3f' "$qm") | **$(printf '%.2f' "$rm_")** ($(printf '%.2f' "$rmin")-$(printf '%.2f' "$rmax")) | $met | $picture |"$'\n'
  echo "$name: prime $pm s, povray $qm s, ratio $rm_ (target <= 0.5: $met); picture: $picture"
done

# --- The million-triangle mesh: generated, never committed. ---
BIG=$OUT/mesh-1m.mal
"$PY" - "$ROOT/tools/malone" "$BIG" <<'PYEOF'
import sys
sys.path.insert(0, sys.argv[1])
import scenes
s = scenes.Scene()
s.viewer([0, 4.5, 7], [0, 0, 0], 45, 512, 512)   # as mesh-1600.mal
s.light([-4, 8, 6], [110, 110, 110])
s.light([5, 3, -2], [25, 25, 35])
s.ambient([0.08, 0.08, 0.08])
scenes.floor(s, -1.0)
s.default(scenes.Scene.surf([0.75, 0.75, 0.8], 0.3, 40, 0.8))
for t in scenes.mesh_torus(2.0, 0.8, 1000, 500):   # 10^6 triangles
    s.prim(5, t, None)
open(sys.argv[2], "w").write(s.text())
PYEOF
bigMB=$(du -m "$BIG" | cut -f1)
readT=() buildT=() bvhT=() renderT=() bigCpu=()
for ((i = 0; i < MESH_RUNS; i++)); do
  line=$("$PRIME" trace "$BIG" --threads 1 --no-window -q --timings | grep '^timings:')
  readT+=("$(echo "$line" | sed 's/.*read \([0-9.]*\) s.*/\1/')")
  buildT+=("$(echo "$line" | sed 's/.*build \([0-9.]*\) s (.*/\1/')")
  bvhT+=("$(echo "$line" | sed 's/.*BVH \([0-9.]*\) s.*/\1/')")
  renderT+=("$(echo "$line" | sed 's/.*render \([0-9.]*\) s.*/\1/')")
  bigCpu+=("$(cpu "$OUT" "$PRIME" trace "$BIG" --threads 1 --no-window -q)")
done
bigRead=$(median "${readT[@]}")
bigBuild=$(median "${buildT[@]}")
bigBvh=$(median "${bvhT[@]}")
bigRender=$(median "${renderT[@]}")
bigCpuM=$(median "${bigCpu[@]}")
echo "mesh-1m: read $bigRead s, build $bigBuild s (BVH $bigBvh s), render $bigRender s; whole process $bigCpuM s CPU"
rm -f "$BIG"

# --- ns per primitive test: with the BVH and with --linear-search. ---
# stats FILE ARGS...: "seconds tests rays shadow" of one single-threaded run.
stats() {
  "$PRIME" trace "$@" --threads 1 --no-window 2>/dev/null |
    awk '/^traced/ {s=$(NF-4)} /^rays:/ {
           for (i = 1; i <= NF; i++) { if ($i == "rays:") r=$(i+1); if ($i == "shadow") sh=$(i+1); if ($i == "tests") t=$(i+1) }
           gsub(/[^0-9]/, "", r); gsub(/[^0-9]/, "", sh); gsub(/[^0-9]/, "", t) }
         END {print s, t, r, sh}'
}
M1600=$ROOT/scenes/malone/mesh-1600.mal
SMALL=$OUT/mesh-1600-${LINEAR_RES}.mal
awk -v res="$LINEAR_RES" '!done && $0 == "512 512" {print res " " res; done=1; next} {print}' "$M1600" >"$SMALL"
bvhS=() linS=()
for ((i = 0; i < MESH_RUNS; i++)); do
  read -r s t r sh <<<"$(stats "$M1600")"
  bvhS+=("$s"); bvhTests=$t; bvhRays=$r; bvhShadow=$sh
  read -r s t r sh <<<"$(stats "$SMALL" --linear-search)"
  linS+=("$s"); linTests=$t; linRays=$r; linShadow=$sh
done
bvhSec=$(median "${bvhS[@]}")
linSec=$(median "${linS[@]}")
bvhNs=$(awk -v s="$bvhSec" -v t="$bvhTests" 'BEGIN {printf "%.1f", s * 1e9 / t}')
linNs=$(awk -v s="$linSec" -v t="$linTests" 'BEGIN {printf "%.2f", s * 1e9 / t}')
# The 1995 figure: 512 x 512 x 1600 x (1 + shadow rays per light) tests in 1800 s.
orig1=$(awk 'BEGIN {printf "%.3g", 512 * 512 * 1600 * 2}')
orig1Rate=$(awk 'BEGIN {printf "%.3g", 512 * 512 * 1600 * 2 / 1800}')
orig1Ns=$(awk 'BEGIN {printf "%.0f", 1800 * 1e9 / (512 * 512 * 1600 * 2)}')
orig2Ns=$(awk 'BEGIN {printf "%.0f", 1800 * 1e9 / (512 * 512 * 1600 * 3)}')
speedLin1=$(awk -v ns="$linNs" -v o="$orig1Ns" 'BEGIN {printf "%.0f", o / ns}')
speedLin2=$(awk -v ns="$linNs" -v o="$orig2Ns" 'BEGIN {printf "%.0f", o / ns}')
linFrame=$(awk -v s="$linSec" -v r="$LINEAR_RES" 'BEGIN {printf "%.2f", s * 512 * 512 / (r * r)}')
frameSpeed=$(awk -v c="$MESH1600_CPU" 'BEGIN {printf "%.0f", 1800 / c}')
echo "ns/test: BVH $bvhNs ($bvhTests tests in $bvhSec s), linear $linNs ($linTests tests in $linSec s at ${LINEAR_RES}^2)"

cpuModel=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')
generated=$(
  cat <<MDEOF
<!-- malone_pov_compare:begin (written by bench/malone/pov_compare.sh; edit outside the markers) -->
Measured $(date -u '+%Y-%m-%d %H:%M UTC') on $(nproc) CPU(s), ${cpuModel:-unknown CPU}, $(uname -sr);
prime at commit \`$PRIME_VERSION\` (release preset), $POV_VERSION (Debian package).
The machine is shared with other builds: the $RUNS pairs per scene are interleaved (prime and
POV-Ray back to back, the order swapped every pair), and the ratio is the median of the per-pair
ratios. CPU time = user + system of the whole process (getrusage of the child): POV-Ray's parsing
and start-up count, as prime's reading of the scene does.

### prime / POV-Ray per scene

| scene | size | prime CPU s (median) | POV-Ray CPU s (median) | prime / POV-Ray, median of pairs (min-max) | prime <= 0.5x? | pictures, bytes 0-255 (mean difference; pixels that differ, largest difference; within 8; off by > 32; black in one only) |
|---|---|---|---|---|---|---|
${ROWS}
Commands per scene (from \`${OUT#"$ROOT"/}\`):

\`\`\`sh
prime export-pov scenes/malone/NAME.mal NAME.pov
prime trace scenes/malone/NAME.mal --threads 1 --no-window -q
povray +INAME.pov +WX_RES +HY_RES -A +WT1 -D -F -GA
\`\`\`

### (a) mesh-1600.mal, 512 x 512, one core

CPU time of the whole \`prime trace\` process, median of the $RUNS runs above: **$(printf '%.3f' "$MESH1600_CPU") s**
(1,601 primitives: 1,600 triangles and the floor; two point lights, shadows, reflection k_s 0.3).

### (b) A 10^6-triangle mesh, 512 x 512, one core

\`mesh_torus(2.0, 0.8, 1000, 500)\` of tools/malone/scenes.py (1,000,000 triangles, the floor, the
viewer and lights of mesh-1600.mal; a ${bigMB} MB file written by the script and deleted after).
\`prime trace FILE --threads 1 --no-window -q --timings\`, median of $MESH_RUNS runs (wall seconds of
each part, one thread):

| read (parse the file) | build (scene + BVH) | of which BVH | render 512 x 512 | whole process, CPU s |
|---|---|---|---|---|
| $bigRead s | $bigBuild s | $bigBvh s | $bigRender s | $bigCpuM s |

### (c) ns per primitive test, against the document's half hour

| run | rays | shadow rays | primitive tests | render s (median of $MESH_RUNS) | ns per test |
|---|---|---|---|---|---|
| mesh-1600, 512 x 512, BVH | $bvhRays | $bvhShadow | $bvhTests | $bvhSec | $bvhNs |
| mesh-1600, ${LINEAR_RES} x ${LINEAR_RES}, \`--linear-search\` (every primitive, as the original) | $linRays | $linShadow | $linTests | $linSec | **$linNs** |

The document (section 3.3.4): "A scene of the space shuttle consisting of 1600 triangles takes in
the region of half an hour" at 512 x 512 (the machine is not stated). Derived (the document gives no count):
with no acceleration structure every ray tests every triangle: 512 x 512 x 1600 x (1 + shadow rays
per light) tests. With one light that is $orig1 tests in 1,800 s, $orig1Rate tests/s, **about
$orig1Ns ns per test**; with two lights (as mesh-1600.mal) about $orig2Ns ns. Against the linear
search here ($linNs ns per test, every ray against all 1,601 primitives): **${speedLin1}x** (one light)
to ${speedLin2}x (two lights) per test. A whole 512 x 512 frame by linear search would take about
$linFrame s here (scaled from ${LINEAR_RES} x ${LINEAR_RES}); with the BVH the frame takes $(printf '%.3f' "$MESH1600_CPU") s of CPU,
**${frameSpeed}x** less than the half hour.
<!-- malone_pov_compare:end -->
MDEOF
)

splice_generated "$DOC" malone_pov_compare "$generated" "Malone (1995) against POV-Ray 3.7"
echo "wrote $CSV and $DOC; pictures in $OUT"
