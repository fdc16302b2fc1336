#!/usr/bin/env bash
# PRIME against POV-Ray 3.7 on every shipped scene (issue 6, "against the
# renderer a user would pick instead").
#
# For each scenes/prime/*/ that has a Model.txt: `prime model`, `prime export-pov`,
# then RUNS paired runs of
#   prime trace DIR --threads 1                       (one ray per pixel, MaxDepth 5)
#   povray +W.. +H.. -A +WT1 (max_trace_level 6, adc_bailout 0, shadowless lights)
# at the same size, each measured as the CPU time (user + system, getrusage of
# the child process) of the whole program run. Reports the median of the
# per-pair ratios prime/POV-Ray, writes a CSV and the table in
# docs/prime/benchmarks-pov.md (between its pov_compare markers; the rest of that
# file is kept), and renders every scene once with both programs for a
# side-by-side look (OUT/<scene>_side.png, auto-levelled).
#
# Usage: bench/prime/pov_compare.sh [RUNS]          (RUNS >= 5, default 7)
# Environment: PRIME=path/to/prime (default: build/release, brought up to date),
#              OUT=output directory (default: out/pov-compare).
set -euo pipefail

cd "$(dirname "$0")/../.."
ROOT=$PWD
RUNS=${1:-7}
if ((RUNS < 5)); then
  echo "pov_compare: at least 5 paired runs (got $RUNS)" >&2
  exit 2
fi
OUT=${OUT:-$ROOT/out/pov-compare}
DOC=$ROOT/docs/prime/benchmarks-pov.md
CSV=$ROOT/docs/prime/benchmarks-pov.csv

NAME=pov_compare
source "$ROOT/bench/pov_common.sh"

rm -rf "$OUT"
mkdir -p "$OUT/scenes"

echo "scene,width,height,runs,prime_cpu_s_median,pov_cpu_s_median,ratio_median,ratio_min,ratio_max,pov_trace_cpu_s,target_met" >"$CSV"
ROWS=""
NOTES=""

for modelTxt in "$ROOT"/scenes/prime/*/Model.txt; do
  src=$(dirname "$modelTxt")
  name=$(basename "$src")
  dir=$OUT/scenes/$name
  cp -r "$src" "$dir"
  if ! "$PRIME" model "$dir" >"$OUT/$name.model.log" 2>&1; then
    echo "pov_compare: $name: prime model failed, skipped (see $OUT/$name.model.log)" >&2
    NOTES+="- \`$name\`: \`prime model\` failed; skipped."$'\n'
    continue
  fi
  "$PRIME" export-pov "$dir" "$OUT/$name.pov" >"$OUT/$name.export.log"
  size=$(grep -o '+W[0-9]* +H[0-9]*' "$OUT/$name.export.log" | head -1)
  W=$(echo "$size" | sed 's/+W\([0-9]*\) .*/\1/')
  H=$(echo "$size" | sed 's/.*+H\([0-9]*\)/\1/')
  primeCmd=("$PRIME" trace "$dir" --threads 1 --no-window -q --out "$OUT/$name.graph")
  povCmd=(povray "+I$name.pov" "+W$W" "+H$H" -A +WT1 -D -F -GA)

  # Once for the pictures (and to warm the caches).
  "$PRIME" trace "$dir" --threads 1 --no-window -q --out "$OUT/$name.graph" \
    --true-color-png "$OUT/${name}_prime.png" --png-area file
  (cd "$OUT" && povray "+I$name.pov" "+W$W" "+H$H" -A +WT1 -D File_Gamma=1.0 +FN \
    "+O${name}_pov.png" >"$name.pov.log" 2>&1)
  povTrace=$(grep -A1 'Trace Time' "$OUT/$name.pov.log" | grep -o 'with [0-9.]* CPU' | grep -o '[0-9.]*' || echo "")
  if "$PY" -c 'import PIL' 2>/dev/null; then
    "$PY" "$ROOT/bench/side_by_side.py" "$OUT/${name}_prime.png" "$OUT/${name}_pov.png" "$OUT/${name}_side.png"
  fi

  paired_runs "${primeCmd[@]}" -- "${povCmd[@]}"
  echo "$name,$W,$H,$RUNS,$pm,$qm,$rm_,$rmin,$rmax,$povTrace,$met" >>"$CSV"
  ROWS+="| \`$name\` | ${W} x ${H} | $(printf '%.3f' "$pm") | $(printf '%.3f' "$qm") | **$(printf '%.2f' "$rm_")** ($(printf '%.2f' "$rmin")-$(printf '%.2f' "$rmax")) | ${povTrace:-?} | $met |"$'\n'
  echo "$name: prime $pm s, povray $qm s, ratio $rm_ (target <= 0.5: $met)"
done

cpuModel=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')
generated=$(
  cat <<EOF
<!-- pov_compare:begin (written by bench/prime/pov_compare.sh; edit outside the markers) -->
Measured $(date -u '+%Y-%m-%d %H:%M UTC') on $(nproc) CPU(s), ${cpuModel:-unknown CPU}, $(uname -sr);
prime at commit \`$PRIME_VERSION\` (RelWithDebInfo), $POV_VERSION (Debian package).
$RUNS paired runs per scene; CPU time = user + system of the whole process (getrusage of the
child), so POV-Ray's parsing and start-up count, as PRIME's scene loading does.

| scene | size | prime CPU s (median) | POV-Ray CPU s (median) | prime / POV-Ray, median of pairs (min-max) | POV-Ray trace-only CPU s | prime <= 0.5x? |
|---|---|---|---|---|---|---|
${ROWS}
${NOTES}
Commands per scene (DIR a copy of \`scenes/<name>\`, run from \`${OUT#"$ROOT"/}\`):

\`\`\`sh
prime model DIR
prime export-pov DIR NAME.pov
prime trace DIR --threads 1 --no-window -q --out NAME.graph
povray +INAME.pov +W350 +H769 -A +WT1 -D -F -GA
\`\`\`

Rerun: \`bench/prime/pov_compare.sh\` (optionally \`bench/prime/pov_compare.sh 11\` for 11 pairs). The CSV is
[benchmarks-pov.csv](benchmarks-pov.csv).
<!-- pov_compare:end -->
EOF
)

splice_generated "$DOC" pov_compare "$generated" "PRIME against POV-Ray"
echo "wrote $CSV and $DOC; pictures in $OUT"
