#!/usr/bin/env bash
# The thesis renderer's speed targets (issue "what the thesis describes",
# section "Fast"), on every shipped PRIME scene at 4x the listing's linear
# size (--screen 4096 3072: the listing's 350 x 769 window becomes 1394 x 3073):
#
#   1. prime trace --profile thesis (shadow rays on) against POV-Ray 3.7 with
#      its shadows on (the scene exported by `prime export-pov --shadows`),
#      one thread each: CPU time (user + system of the whole process), RUNS
#      paired runs, the two programs back to back, order swapped every pair.
#      Target: prime / POV-Ray <= 0.5.
#   2. prime trace --profile thesis on one thread against two: WALL time of
#      the whole command, RUNS paired runs. Target: >= 1.9x.
#   3. prime trace --profile modern against --profile 1991 (no shadows in
#      either), one thread, CPU time, RUNS paired runs. Target: <= 1.3x.
#
# Writes docs/prime/benchmarks-thesis.csv and the generated part of
# docs/prime/benchmarks-thesis.md (between its thesis_pov_compare markers).
#
# Usage: bench/prime/thesis_pov_compare.sh [RUNS] [SCENE...]   (RUNS >= 5, default 5;
#        all scenes with a Model.txt when none is named)
# Environment: PRIME=path/to/prime (default: build/release, brought up to date),
#              OUT=output directory (default: out/thesis-pov-compare).
set -euo pipefail

cd "$(dirname "$0")/../.."
ROOT=$PWD
RUNS=${1:-5}
shift || true
if ((RUNS < 5)); then
  echo "thesis_pov_compare: at least 5 paired runs (got $RUNS)" >&2
  exit 2
fi
OUT=${OUT:-$ROOT/out/thesis-pov-compare}
DOC=$ROOT/docs/prime/benchmarks-thesis.md
CSV=$ROOT/docs/prime/benchmarks-thesis.csv
SCREEN=(4096 3072)

NAME=thesis_pov_compare
source "$ROOT/bench/pov_common.sh"

rm -rf "$OUT"
mkdir -p "$OUT/scenes"
loadStart=$(cut -d' ' -f1-3 /proc/loadavg)

scenes=("$@")
if ((${#scenes[@]} == 0)); then
  for modelTxt in "$ROOT"/scenes/prime/*/Model.txt; do scenes+=("$(basename "$(dirname "$modelTxt")")"); done
fi

echo "scene,width,height,runs,thesis_cpu_s,pov_cpu_s,thesis_over_pov,pov_target_met,one_thread_wall_s,two_threads_wall_s,speedup,speedup_target_met,profile1991_cpu_s,modern_cpu_s,modern_over_1991,modern_target_met" >"$CSV"
ROWS=""
for name in "${scenes[@]}"; do
  src=$ROOT/scenes/prime/$name
  dir=$OUT/scenes/$name
  cp -r "$src" "$dir"
  "$PRIME" model "$dir" -q 2>"$OUT/$name.model.log"
  "$PRIME" export-pov "$dir" "$OUT/$name.pov" --shadows --screen "${SCREEN[@]}" >"$OUT/$name.export.log"
  size=$(grep -o '+W[0-9]* +H[0-9]*' "$OUT/$name.export.log" | head -1)
  W=$(echo "$size" | sed 's/+W\([0-9]*\) .*/\1/')
  H=$(echo "$size" | sed 's/.*+H\([0-9]*\)/\1/')
  trace=("$PRIME" trace "$dir" --screen "${SCREEN[@]}" --no-window -q --out "$OUT/$name.graph")
  povCmd=(povray "+I$name.pov" "+W$W" "+H$H" -A +WT1 -D -F -GA)

  "${trace[@]}" --profile thesis --threads 1 --true-color-png "$OUT/${name}_thesis.png"  # warm-up, picture

  paired cpu "${trace[@]}" --profile thesis --threads 1 -- "${povCmd[@]}"
  thesis=$am pov=$bm
  povRatio=$ratio
  povRange="$(printf '%.2f' "$rmin")-$(printf '%.2f' "$rmax")"
  povMet=$(awk -v r="$povRatio" 'BEGIN {print (r <= 0.5) ? "yes" : "no"}')

  paired wall "${trace[@]}" --profile thesis --threads 1 -- "${trace[@]}" --profile thesis --threads 2
  one=$am two=$bm
  speedup=$ratio
  speedupRange="$(printf '%.2f' "$rmin")-$(printf '%.2f' "$rmax")"
  speedupMet=$(awk -v r="$speedup" 'BEGIN {print (r >= 1.9) ? "yes" : "no"}')

  paired cpu "${trace[@]}" --profile modern --threads 1 -- "${trace[@]}" --profile 1991 --threads 1
  modern=$am p1991=$bm
  modernRatio=$ratio
  modernRange="$(printf '%.2f' "$rmin")-$(printf '%.2f' "$rmax")"
  modernMet=$(awk -v r="$modernRatio" 'BEGIN {print (r <= 1.3) ? "yes" : "no"}')

  echo "$name,$W,$H,$RUNS,$thesis,$pov,$povRatio,$povMet,$one,$two,$speedup,$speedupMet,$p1991,$modern,$modernRatio,$modernMet" >>"$CSV"
  ROWS+="| \`$name\` | $(printf '%.3f' "$thesis") | $(printf '%.3f' "$pov") | **$(printf '%.2f' "$povRatio")** ($povRange) $povMet | $(printf '%.3f' "$one") | $(printf '%.3f' "$two") | **$(printf '%.2f' "$speedup")** ($speedupRange) $speedupMet | $(printf '%.3f' "$p1991") | $(printf '%.3f' "$modern") | **$(printf '%.2f' "$modernRatio")** ($modernRange) $modernMet |"$'\n'
  echo "$name: thesis/POV $povRatio ($povMet), 1->2 threads $speedup ($speedupMet), modern/1991 $modernRatio ($modernMet)"
done

cpuModel=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')
loadEnd=$(cut -d' ' -f1-3 /proc/loadavg)
generated=$(
  cat <<EOF
<!-- thesis_pov_compare:begin (written by bench/prime/thesis_pov_compare.sh; edit outside the markers) -->
Measured $(date -u '+%Y-%m-%d %H:%M UTC') on $(nproc) CPU(s), ${cpuModel:-unknown CPU}, $(uname -sr);
prime at commit \`$PRIME_VERSION\` (release preset), $POV_VERSION (Debian package). Load average
(1, 5, 15 min) at the start: $loadStart; at the end: $loadEnd. $RUNS paired runs per cell, the two
commands back to back and their order swapped every pair; medians, and the median of the per-pair
ratios with its range. Every scene at \`--screen ${SCREEN[*]}\` (4x the listing's linear size: ${W} x ${H}
for the listing's window).

| scene | thesis CPU s | POV-Ray CPU s (shadows) | thesis / POV-Ray (<= 0.5?) | 1 thread wall s | 2 threads wall s | speed-up (>= 1.9?) | 1991 CPU s | modern CPU s | modern / 1991 (<= 1.3?) |
|---|---|---|---|---|---|---|---|---|---|
${ROWS}
Commands per scene (DIR a copy of \`scenes/prime/<name>\`, run from \`${OUT#"$ROOT"/}\`):

\`\`\`sh
prime model DIR
prime export-pov DIR NAME.pov --shadows --screen ${SCREEN[*]}
prime trace DIR --screen ${SCREEN[*]} --no-window -q --out NAME.graph --profile thesis --threads 1   # and --threads 2
povray +INAME.pov +W${W} +H${H} -A +WT1 -D -F -GA
prime trace DIR --screen ${SCREEN[*]} --no-window -q --out NAME.graph --profile 1991 --threads 1      # and --profile modern
\`\`\`

Rerun: \`bench/prime/thesis_pov_compare.sh\` (\`bench/prime/thesis_pov_compare.sh 7 plate2 plate3\` for 7 pairs on
two scenes). The CSV is [benchmarks-thesis.csv](benchmarks-thesis.csv).
<!-- thesis_pov_compare:end -->
EOF
)

splice_generated "$DOC" thesis_pov_compare "$generated" "The thesis renderer's speed"
echo "wrote $CSV and $DOC; pictures in $OUT"
