#!/usr/bin/env bash
# The Waterloo CGL package (this port) against POV-Ray 3.7 on every shipped
# scene (scenes/cgl/*.cgl), against the VAX 11/780 times of the document's
# figures, and Table 5's costs per operation (Sweeney 1985, sections 11 and 13).
#
# 1. For each scene that renders (the verbatim OCR copies doc-*.cgl are the
#    checkerboard again and are skipped; a scene the port refuses, e.g. one
#    with a Cook-Torrance surface, is listed as skipped): `prime export-pov`,
#    then RUNS paired runs of
#      prime trace SCENE --threads 1 --no-window -q
#      povray +IOUT.pov <the export's options> +WT1 -D -F -GA
#    at 512 x 512 with the scene's window (+SC/+EC/+SR/+ER), the same depth
#    (max_trace_level = depth + 1) and comparable anti-aliasing (the scene's
#    aalevel against POV-Ray's method 1 with +R(aalevel + 1) and threshold
#    aathreshold/255), each measured as the CPU time (user + system,
#    getrusage of the child) of the whole process; the two programs of a pair
#    run back to back and swap order every pair. The same again without
#    anti-aliasing on either side (--aalevel 0 against -A). Reports medians
#    and the median of the per-pair ratios, and how close the pictures are.
# 2. The document's figures: checkerboard (Figure 5/59, 18:30 on the VAX),
#    ball at no anti-aliasing and aalevel 1, 2, 4, 8 (Figure 45: 1:01, 1:06,
#    1:33, 1:55, 2:33), illumination models (Figure 46, 9:04; without its Cook
#    sphere): CPU seconds of `prime trace --threads 1`, median of RUNS.
# 3. Table 5 by prime_micro (bench/micro/cgl_bench.cpp), medians of 5
#    repetitions, beside the VAX's milliseconds.
# Writes docs/cgl/benchmarks.csv and the generated part of
# docs/cgl/benchmarks.md (between its cgl_pov_compare markers).
#
# Usage: bench/cgl/pov_compare.sh [RUNS]      (RUNS >= 5, default 7)
# Environment: PRIME=path/to/prime (default: build/release, brought up to
#              date), MICRO=path/to/prime_micro (default: build/release),
#              OUT=output directory (default: out/cgl-pov-compare).
set -euo pipefail

cd "$(dirname "$0")/../.."
ROOT=$PWD
RUNS=${1:-7}
if ((RUNS < 5)); then
  echo "cgl_pov_compare: at least 5 paired runs (got $RUNS)" >&2
  exit 2
fi
OUT=${OUT:-$ROOT/out/cgl-pov-compare}
DOC=$ROOT/docs/cgl/benchmarks.md
CSV=$ROOT/docs/cgl/benchmarks.csv

NAME=cgl_pov_compare
source "$ROOT/bench/pov_common.sh"
if [ -z "${MICRO:-}" ]; then
  cmake --build --preset release --target prime_micro >/dev/null
  MICRO=$ROOT/build/release/bench/micro/prime_micro
fi

rm -rf "$OUT"
mkdir -p "$OUT"
LOAD_START=$(cut -d' ' -f1-3 /proc/loadavg)

HAVE_PIL=no
if "$PY" -c 'import PIL, numpy' 2>/dev/null; then HAVE_PIL=yes; fi
echo "scene,mode,runs,prime_cpu_s_median,pov_cpu_s_median,ratio_median,ratio_min,ratio_max,target_met,pov_options,picture" >"$CSV"
ROWS=""
SKIPPED=""

# pair MODE NAME SCENE POVFILE POVARGS PRIMEARGS...: RUNS paired runs; sets
# pm qm rm_ rmin rmax met.
pair() {
  local mode=$1 name=$2 scene=$3 pov=$4 povargs=$5
  shift 5
  local primeCmd=("$PRIME" trace "$scene" --threads 1 --no-window -q "$@")
  # shellcheck disable=SC2206
  local povCmd=(povray "+I$pov" $povargs +WT1 -D -F -GA)
  paired_runs "${primeCmd[@]}" -- "${povCmd[@]}"
}

for scene in "$ROOT"/scenes/cgl/*.cgl; do
  name=$(basename "$scene" .cgl)
  case $name in doc-*) continue ;; esac
  if ! "$PRIME" export-pov "$scene" "$OUT/$name.pov" >"$OUT/$name.export.log" 2>&1; then
    SKIPPED+="- \`$name\`: $(tail -1 "$OUT/$name.export.log" | sed 's/|/\//g')"$'\n'
    echo "$name: skipped ($(tail -1 "$OUT/$name.export.log"))"
    continue
  fi
  povargs=$(grep -o '+W512.*File_Gamma=1.0' "$OUT/$name.export.log" | sed 's/ File_Gamma=1.0//')
  "$PRIME" export-pov "$scene" "$OUT/${name}-noaa.pov" --aalevel 0 >"$OUT/$name.export-noaa.log"
  povargs0=$(grep -o '+W512.*File_Gamma=1.0' "$OUT/$name.export-noaa.log" | sed 's/ File_Gamma=1.0//')

  # Once for the pictures (and to warm the caches).
  "$PRIME" trace "$scene" --threads 1 --no-window -q --png "$OUT/${name}_prime.png"
  # shellcheck disable=SC2086
  (cd "$OUT" && povray "+I$name.pov" $povargs +WT1 -D File_Gamma=1.0 +FN "+O${name}_pov.png" \
    >"$name.pov.log" 2>&1)
  picture="?"
  if [ "$HAVE_PIL" = yes ]; then
    picture=$("$PY" "$ROOT/bench/malone_compare_images.py" "$OUT/${name}_prime.png" "$OUT/${name}_pov.png")
    "$PY" "$ROOT/bench/side_by_side.py" "$OUT/${name}_prime.png" "$OUT/${name}_pov.png" "$OUT/${name}_side.png"
  fi

  pair aa "$name" "$scene" "$name.pov" "$povargs"
  echo "$name,scene aalevel,$RUNS,$pm,$qm,$rm_,$rmin,$rmax,$met,$povargs,\"$picture\"" >>"$CSV"
  ROWS+="| \`$name\` | as the scene (\`${povargs#+W512 +H512 }\`) | $(printf '%.3f' "$pm") | $(printf '%.3f' "$qm") | **$(printf '%.2f' "$rm_")** ($(printf '%.2f' "$rmin")-$(printf '%.2f' "$rmax")) | $met | $picture |"$'\n'
  echo "$name (AA): prime $pm s, povray $qm s, ratio $rm_ (target <= 0.5: $met); picture: $picture"

  pair noaa "$name" "$scene" "${name}-noaa.pov" "$povargs0" --aalevel 0
  echo "$name,no anti-aliasing,$RUNS,$pm,$qm,$rm_,$rmin,$rmax,$met,$povargs0," >>"$CSV"
  ROWS+="| \`$name\` | none (\`--aalevel 0\` / \`-A\`) | $(printf '%.3f' "$pm") | $(printf '%.3f' "$qm") | **$(printf '%.2f' "$rm_")** ($(printf '%.2f' "$rmin")-$(printf '%.2f' "$rmax")) | $met | |"$'\n'
  echo "$name (no AA): prime $pm s, povray $qm s, ratio $rm_ (target <= 0.5: $met)"
done

# --- The document's figures against their captions. ---
# fig LABEL VAX_SECONDS SCENE ARGS...: the whole process's CPU (median of
# RUNS), and the render alone by `prime bench` (CPU, one thread, median).
FIGROWS=""
fig() {
  local label=$1 vax=$2 scene=$3
  shift 3
  local t=() i
  for ((i = 0; i < RUNS; i++)); do
    t+=("$(cpu "$OUT" "$PRIME" trace "$ROOT/scenes/cgl/$scene" --threads 1 --no-window -q "$@")")
  done
  local m
  m=$(median "${t[@]}")
  "$PRIME" bench "$ROOT/scenes/cgl/$scene" --threads 1 --runs "$RUNS" --csv "$OUT/fig.csv" "$@" >/dev/null 2>&1
  local render rays
  render=$(awk -F, 'NR == 2 {print $7}' "$OUT/fig.csv")
  rays=$(awk -F, 'NR == 2 {print $9}' "$OUT/fig.csv")
  FIGROWS+="| $label | $(awk -v s="$vax" 'BEGIN {printf "%d:%02d (%d s)", s / 60, s % 60, s}') | \`$scene $*\` | $rays | $(printf '%.4f' "$render") | **$(awk -v v="$vax" -v m="$render" 'BEGIN {printf "%.0f", v / m}')x** | $(printf '%.4f' "$m") | $(awk -v v="$vax" -v m="$m" 'BEGIN {printf "%.0f", v / m}')x |"$'\n'
  echo "figure $label: VAX $vax s, prime render $render s, whole process $m s"
  echo "figure $label,$*,$RUNS,$m,,,,,,vax_s=$vax render_cpu_s=$render rays=$rays," >>"$CSV"
}
fig "5/59 checkerboard" 1110 checkerboard.cgl
fig "45 ball, no anti-aliasing" 61 ball.cgl --aalevel 0
fig "45 ball, aalevel 1" 66 ball.cgl --aalevel 1
fig "45 ball, aalevel 2" 93 ball.cgl --aalevel 2
fig "45 ball, aalevel 4" 115 ball.cgl --aalevel 4
fig "45 ball, aalevel 8" 153 ball.cgl --aalevel 8
fig "46 illumination models" 544 illumination-models.cgl

# --- Table 5: prime_micro, medians of 5 repetitions. ---
"$MICRO" --benchmark_filter='^cgl/' --benchmark_repetitions=5 \
  --benchmark_report_aggregates_only=true --benchmark_format=csv 2>/dev/null >"$OUT/micro.csv"
TABLE5=$("$PY" - "$OUT/micro.csv" <<'PYEOF'
import csv, sys
ns = {}
for row in csv.reader(open(sys.argv[1])):
    if len(row) > 3 and row[0].endswith("_median"):
        ns[row[0][: -len("_median")].strip('"')] = float(row[3])  # cpu_time, ns
def cell(v):
    return "%.1f" % v
rows = [("intersect sphere", 1.31, "intersect_sphere"), ("intersect cylinder", 1.30, "intersect_cylinder"),
        ("intersect rectangle", 0.25, "intersect_rectangle"), ("intersect super-box", 0.09, "intersect_super_box")]
out = []
for label, ms, key in rows:
    h, m, a = (ns["cgl/%s/%s" % (key, k)] for k in ("hit", "miss", "alternate"))
    out.append("| %s | %.2f | %s | %s | %s | **%.0f** |" % (label, ms, cell(h), cell(m), cell(a), ms * 1e6 / a))
i = ns["cgl/trace_intersect_only"]
for label, ms, key in (("shade ray (lamberts law)", 2.99, "lambert"), ("shade ray (phong)", 4.45, "phong"),
                       ("shade ray (cook-torrance)", 3.81, "cook")):
    t = ns["cgl/trace_shade/" + key]
    out.append("| %s | %.2f | trace %s - intersect %s = %s | | | **%.0f** |" % (label, ms, cell(t), cell(i), cell(t - i), ms * 1e6 / (t - i)))
for label, ms, where in (("intersect fractal (6 subdivisions)", 12.43, "rendering.md, Fractal surfaces"),
                         ("intersect spline (bump)", 83.85, "splines.md, Table 6")):
    out.append("| %s | %.2f | not in prime_micro: per call from `prime trace`'s counts in %s | | | |" % (label, ms, where))
print("\n".join(out))
PYEOF
)
echo "$TABLE5"

LOAD_END=$(cut -d' ' -f1-3 /proc/loadavg)
cpuModel=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')
generated=$(
  cat <<MDEOF
<!-- cgl_pov_compare:begin (written by bench/cgl/pov_compare.sh; edit outside the markers) -->
Measured $(date -u '+%Y-%m-%d %H:%M UTC') on $(nproc) CPU(s), ${cpuModel:-unknown CPU}, $(uname -sr);
prime at commit \`$PRIME_VERSION\` (release preset), $POV_VERSION (Debian package). Load average
(1, 5, 15 min) at the start: $LOAD_START; at the end: $LOAD_END. The machine is shared with
other builds: the $RUNS pairs per scene are interleaved (prime and POV-Ray back to back, the
order swapped every pair) and the ratio is the median of the per-pair ratios. CPU time = user +
system of the whole process (getrusage of the child): POV-Ray's parsing and start-up count, as
prime's reading of the scene and its texture maps do.

### prime / POV-Ray per scene

| scene | anti-aliasing (POV-Ray options) | prime CPU s (median) | POV-Ray CPU s (median) | prime / POV-Ray, median of pairs (min-max) | prime <= 0.5x? | pictures, bytes 0-255 (mean difference; pixels that differ, largest difference; within 8; off by > 32; black in one only) |
|---|---|---|---|---|---|---|
${ROWS}
${SKIPPED:+Skipped (the port refuses them):
$SKIPPED}
Commands per scene (from \`${OUT#"$ROOT"/}\`):

\`\`\`sh
prime export-pov scenes/cgl/NAME.cgl NAME.pov            # prints the POV-Ray options
prime trace scenes/cgl/NAME.cgl --threads 1 --no-window -q
povray +INAME.pov <options> +WT1 -D -F -GA
prime export-pov scenes/cgl/NAME.cgl NAME-noaa.pov --aalevel 0
prime trace scenes/cgl/NAME.cgl --threads 1 --no-window -q --aalevel 0
povray +INAME-noaa.pov +W512 +H512 [window] -A +WT1 -D -F -GA
\`\`\`

### The document's figures against their captions (VAX 11/780)

The captions' times are render times of the package on the VAX at 512 x 512 with the picture
bounded by the program parameters (section 11). Here: the render alone (\`prime bench SCENE
--threads 1 --runs $RUNS\`, CPU seconds of \`render\`, median), and the whole \`prime trace SCENE
--threads 1 --no-window -q\` process (CPU, median of $RUNS; reading, Preprocess with its texture
maps, the 512 x 512 buffers and the start-up included).

| figure | VAX 11/780 | prime trace | rays | render CPU s | VAX / render | whole process CPU s | VAX / process |
|---|---|---|---|---|---|---|---|
${FIGROWS}
### Table 5: milliseconds per operation on the VAX, nanoseconds here

\`prime_micro --benchmark_filter=^cgl/ --benchmark_repetitions=5\`, CPU time per operation,
median of the repetitions (bench/micro/cgl_bench.cpp). Hit: a ray through the object; miss: a
ray 3 units beside it; alternate: the two in turn (Table 5 does not say which rays it timed).
Shade: \`Tracer::trace\` of a ray that hits a one-sphere scene (one light at infinity, no
shadows, depth 0: the intersect, the hit point and normal, and Shade in 33 samples) less
\`Tracer::intersect\` of the same ray (Shade is private to the tracer). The last column is the
VAX's time over the port's (alternate rays; shade: the difference).

| operation | VAX ms | port ns, hit | miss | alternate | VAX / port |
|---|---|---|---|---|---|
${TABLE5}
<!-- cgl_pov_compare:end -->
MDEOF
)

splice_generated "$DOC" cgl_pov_compare "$generated" "Waterloo CGL (1985) against POV-Ray 3.7 and the VAX 11/780"
echo "wrote $CSV and $DOC; pictures in $OUT"
