#!/usr/bin/env bash
# The Waterloo CGL package's B-spline surfaces (Sweeney 1985, section 6) against
# POV-Ray 3.7's bicubic_patch: CPU time and holes at equal time (CGL-D171).
#
# For each spline scene, without anti-aliasing on either side (one primary ray
# per pixel, 512 x 512):
# 1. `prime cgl-splines SCENE --aalevel 0 --distances` traces every pixel's
#    primary ray by the dense reference (every refined knot cell boxed by the
#    convex hull of its 16 refined vertices, Newton from its centre and
#    corners; src/cgl/spline.h) and by the port's Newton path, and writes the
#    distance to the nearest spline hit of both.
# 2. `prime export-pov --aalevel 0` writes the surfaces as bicubic_patch (type
#    1), and a copy per POV-Ray subdivision setting (u_steps = v_steps = 1 .. 5
#    with flatness 0, i.e. always subdivided to the steps, and 5 with flatness
#    0.01 and 0.1). For each setting: RUNS paired runs of `prime trace SCENE
#    --aalevel 0 --threads 1` against `povray ... -A +WT1` (CPU of the whole
#    process, the order swapped every pair; bench/pov_common.sh), and one render
#    of a copy whose textures are a flat grey encoding the distance from the eye
#    (ambient only, 16-bit PPM), so that each pixel says what POV-Ray's primary
#    ray hit and how far.
# 3. A hole is a pixel the reference hits that the renderer misses or hits more
#    than 5 % of the distance farther (the far side seen through the hole);
#    hits 1-5 % off are counted apart (depth error: a coarse approximation):
#    bench/cgl/spline_holes.py count. The same rule for prime (its Newton path)
#    and for POV-Ray. "POV-Ray at equal time" is reported twice: the setting
#    whose CPU is nearest prime's, and the setting with the fewest holes (with
#    its CPU), since POV-Ray's time hardly depends on the setting here.
# Writes docs/cgl/spline-holes.csv and the generated part of
# docs/cgl/benchmarks.md between the cgl_spline_holes markers.
#
# Usage: bench/cgl/spline_holes.sh [RUNS [SCENE.cgl ...]]   (RUNS >= 5, default 5;
#        scenes default: scenes/cgl/spline-*.cgl)
# Environment: PRIME=path/to/prime (default: build/release, brought up to date),
#              OUT=output directory (default: out/cgl-spline-holes).
set -euo pipefail

cd "$(dirname "$0")/../.."
ROOT=$PWD
RUNS=${1:-5}
if ((RUNS < 5)); then
  echo "cgl_spline_holes: at least 5 paired runs (got $RUNS)" >&2
  exit 2
fi
shift || true
SCENES=("$@")
if ((${#SCENES[@]} == 0)); then SCENES=("$ROOT"/scenes/cgl/spline-*.cgl); fi
OUT=${OUT:-$ROOT/out/cgl-spline-holes}
DOC=$ROOT/docs/cgl/benchmarks.md
CSV=$ROOT/docs/cgl/spline-holes.csv
NAME=cgl_spline_holes
source "$ROOT/bench/pov_common.sh"
HOLES_PY=$ROOT/bench/cgl_spline_holes.py

mkdir -p "$OUT"
LOAD_START=$(cut -d' ' -f1-3 /proc/loadavg)
SETTINGS=("1 0" "2 0" "3 0" "4 0" "5 0" "5 0.01" "5 0.1")
echo "scene,renderer,u_steps,flatness,cpu_s_median,prime_cpu_s_median,ratio_median,ratio_min,ratio_max,reference_px,missed,farther,holes,holes_pct,depth_error,extra" >"$CSV"
ROWS=""
SUMMARY=""

kv() { sed -n "s/.*\b$1=\([^ ]*\).*/\1/p" <<<"$2"; }

for scene in "${SCENES[@]}"; do
  scene=$(realpath "$scene")
  name=$(basename "$scene" .cgl)
  "$PRIME" export-pov "$scene" "$OUT/$name.pov" --aalevel 0 >"$OUT/$name.export.log"
  povargs=$(grep -o '+W512.*File_Gamma=1.0' "$OUT/$name.export.log" | sed 's/ File_Gamma=1.0//')
  "$PRIME" cgl-splines "$scene" --aalevel 0 --distances "$OUT/$name.csv" >"$OUT/$name.splines.log"
  primeHoles=$("$PY" "$HOLES_PY" count "$OUT/$name.csv")
  primeT=()
  curve=()
  for setting in "${SETTINGS[@]}"; do
    read -r steps flat <<<"$setting"
    tag="$name-s$steps-f$flat"
    "$PY" "$HOLES_PY" steps "$OUT/$name.pov" "$OUT/$tag.pov" "$steps" "$flat"
    "$PY" "$HOLES_PY" depth-pov "$OUT/$name.pov" "$OUT/$tag-depth.pov" "$OUT/$name.csv" "$steps" "$flat"
    # shellcheck disable=SC2086
    (cd "$OUT" && povray "+I$tag-depth.pov" $povargs +WT1 -D File_Gamma=1.0 +FP16 "+O$tag-depth.ppm" \
      >"$tag-depth.log" 2>&1)
    povHoles=$("$PY" "$HOLES_PY" count "$OUT/$name.csv" "$OUT/$tag-depth.ppm")
    # shellcheck disable=SC2206
    povCmd=(povray "+I$tag.pov" $povargs +WT1 -D -F -GA)
    paired_runs "$PRIME" trace "$scene" --threads 1 --no-window -q --aalevel 0 -- "${povCmd[@]}"
    primeT+=("$pm")
    curve+=("$qm $steps $flat $(kv holes "$povHoles") $(kv holes_pct "$povHoles") $rm_")
    echo "$name,povray,$steps,$flat,$qm,$pm,$rm_,$rmin,$rmax,$(kv reference "$povHoles"),$(kv missed "$povHoles"),$(kv farther "$povHoles"),$(kv holes "$povHoles"),$(kv holes_pct "$povHoles"),$(kv depth_error "$povHoles"),$(kv extra "$povHoles")" >>"$CSV"
    ROWS+="| \`$name\` | u_steps = v_steps = $steps, flatness $flat | $(printf '%.3f' "$qm") | $(printf '%.3f' "$pm") | **$(printf '%.2f' "$rm_")** ($(printf '%.2f' "$rmin")-$(printf '%.2f' "$rmax")) | $(kv missed "$povHoles") | $(kv farther "$povHoles") | **$(kv holes "$povHoles")** ($(kv holes_pct "$povHoles") %) | $(kv depth_error "$povHoles") | $(kv extra "$povHoles") |"$'\n'
    echo "$name s$steps f$flat: povray $qm s (prime $pm s, ratio $rm_), holes: $povHoles"
  done
  pmAll=$(median "${primeT[@]}")
  echo "$name,prime,,,$pmAll,$pmAll,,,,$(kv reference "$primeHoles"),$(kv missed "$primeHoles"),$(kv farther "$primeHoles"),$(kv holes "$primeHoles"),$(kv holes_pct "$primeHoles"),$(kv depth_error "$primeHoles"),$(kv extra "$primeHoles")" >>"$CSV"
  # POV-Ray at equal time: the setting whose CPU is nearest prime's.
  eq=$(printf '%s\n' "${curve[@]}" | awk -v p="$pmAll" '{d = $1 - p; if (d < 0) d = -d; if (NR == 1 || d < best) {best = d; line = $0}} END {print line}')
  read -r eqT eqSteps eqFlat eqHoles eqPct _ <<<"$eq"
  few=$(printf '%s\n' "${curve[@]}" | sort -k4,4g -k1,1g | head -1)
  read -r fewT fewSteps fewFlat fewHoles fewPct _ <<<"$few"
  SUMMARY+="| \`$name\` | $(kv reference "$primeHoles") | $(printf '%.3f' "$pmAll") | **$(kv holes "$primeHoles")** ($(kv holes_pct "$primeHoles") %; missed $(kv missed "$primeHoles"), farther $(kv farther "$primeHoles")) | u_steps $eqSteps, flatness $eqFlat: $(printf '%.3f' "$eqT") s | **$eqHoles** ($eqPct %) | u_steps $fewSteps, flatness $fewFlat: $(printf '%.3f' "$fewT") s, $fewHoles ($fewPct %) |"$'\n'
  echo "$name: prime $pmAll s, holes $primeHoles; POV-Ray at equal time: $eq"
done

LOAD_END=$(cut -d' ' -f1-3 /proc/loadavg)
cpuModel=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')
generated=$(
  cat <<MDEOF
<!-- cgl_spline_holes:begin (written by bench/cgl/spline_holes.sh; edit outside the markers) -->
Measured $(date -u '+%Y-%m-%d %H:%M UTC') on $(nproc) CPU(s), ${cpuModel:-unknown CPU}, $(uname -sr);
prime at commit \`$PRIME_VERSION\` (release preset), $POV_VERSION. Load average (1, 5, 15 min)
at the start: $LOAD_START; at the end: $LOAD_END. $RUNS interleaved pairs per setting, CPU = user
+ system of the whole process, medians; 512 x 512, no anti-aliasing on either side.

**Holes at equal time.** prime: its Newton path against the dense reference, every pixel.
POV-Ray: the subdivision setting whose CPU time is nearest prime's.

| scene | reference pixels | prime CPU s | prime holes | POV-Ray, setting nearest prime's CPU | its holes | POV-Ray's fewest holes (setting, CPU, holes) |
|---|---|---|---|---|---|---|
${SUMMARY}
**POV-Ray's holes against its time** (each row: one bicubic_patch setting, type 1; "prime / POV-Ray"
is the median of the pairs' ratios, min-max; missed: the reference hits, POV-Ray nothing; farther:
POV-Ray's hit more than 5 % farther; depth error: 1-5 % off; extra: POV-Ray hits, the reference
not).

| scene | POV-Ray setting | POV-Ray CPU s | prime CPU s | prime / POV-Ray | missed | farther | holes | depth error | extra |
|---|---|---|---|---|---|---|---|---|---|
${ROWS}<!-- cgl_spline_holes:end -->
MDEOF
)
if ! grep -q "cgl_spline_holes:begin" "$DOC"; then
  printf '\n## B-spline surfaces: holes against POV-Ray at equal time\n\n%s\n' "$generated" >>"$DOC"
else
  splice_generated "$DOC" cgl_spline_holes "$generated" "unused"
fi
echo "wrote $CSV and $DOC; renders in $OUT"
