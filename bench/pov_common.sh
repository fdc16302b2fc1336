# Sourced by bench/prime/pov_compare.sh (PRIME) and bench/malone/pov_compare.sh
# (Malone): what a paired prime / POV-Ray timing needs, written once.
#   NAME   the calling script's name, for messages (set before sourcing)
#   ROOT   the repository root
# Sets PY, PRIME (unless given), POV_VERSION, PRIME_VERSION; defines
# cpu DIR CMD... and median VALUES...

as_root() { if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi; }

if ! command -v povray >/dev/null; then
  echo "$NAME: installing povray (Debian package)" >&2
  as_root apt-get update -qq
  DEBIAN_FRONTEND=noninteractive as_root apt-get install -y -qq povray >/dev/null
fi
PY=/usr/bin/python3
[ -x "$PY" ] || PY=python3

if [ -z "${PRIME:-}" ]; then
  echo "$NAME: building prime (cmake --preset release)" >&2
  cmake --preset release >/dev/null
  cmake --build --preset release --target prime >/dev/null
  PRIME=$ROOT/build/release/src/cli/prime
fi

# cpu DIR CMD...: runs CMD in DIR with its output discarded and prints the
# CPU seconds (user + system) it used, to the microsecond.
cpu() {
  "$PY" - "$@" <<'PYEOF'
import resource, subprocess, sys
subprocess.run(sys.argv[2:], cwd=sys.argv[1], check=True,
               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
r = resource.getrusage(resource.RUSAGE_CHILDREN)
print(f"{r.ru_utime + r.ru_stime:.6f}")
PYEOF
}

median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR%2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }

POV_VERSION=$(povray --version 2>&1 | grep -m1 -o 'POV-Ray [0-9.][^ ]*' || echo "POV-Ray (version unknown)")
PRIME_VERSION=$(git -C "$ROOT" describe --always --dirty 2>/dev/null || echo unknown)

# wall DIR CMD...: the wall-clock seconds of CMD run in DIR, output discarded.
wall() {
  "$PY" - "$@" <<'PYEOF'
import subprocess, sys, time
t = time.perf_counter()
subprocess.run(sys.argv[2:], cwd=sys.argv[1], check=True,
               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
print(f"{time.perf_counter() - t:.6f}")
PYEOF
}

# paired MEASURE A... -- B...: RUNS pairs in $OUT measured with MEASURE (cpu
# or wall), the two commands back to back and their order swapped every
# pair, so a drift of the shared machine's speed falls on both. Sets am, bm
# (median seconds of A and B) and ratio, rmin, rmax (A / B: the median of the
# per-pair ratios, least, most).
paired() {
  local measure=$1 a=() b=() ta=() tb=() rs=() x y i
  shift
  while [ "$1" != -- ]; do a+=("$1"); shift; done
  shift
  b=("$@")
  for ((i = 0; i < RUNS; i++)); do
    if ((i % 2 == 0)); then
      x=$("$measure" "$OUT" "${a[@]}")
      y=$("$measure" "$OUT" "${b[@]}")
    else
      y=$("$measure" "$OUT" "${b[@]}")
      x=$("$measure" "$OUT" "${a[@]}")
    fi
    ta+=("$x")
    tb+=("$y")
    rs+=("$(awk -v p="$x" -v q="$y" 'BEGIN {printf "%.4f", p / q}')")
  done
  am=$(median "${ta[@]}")
  bm=$(median "${tb[@]}")
  ratio=$(median "${rs[@]}")
  rmin=$(printf '%s\n' "${rs[@]}" | sort -g | head -1)
  rmax=$(printf '%s\n' "${rs[@]}" | sort -g | tail -1)
}

# paired_runs PRIME_CMD... -- POV_CMD...: paired CPU times of prime and
# POV-Ray. Sets pm, qm (median CPU seconds of prime and POV-Ray), rm_, rmin,
# rmax (the ratio prime / POV-Ray: median of the pairs, least, most) and met
# (yes when rm_ <= 0.5).
paired_runs() {
  paired cpu "$@"
  pm=$am
  qm=$bm
  rm_=$ratio
  met=$(awk -v r="$rm_" 'BEGIN {print (r <= 0.5) ? "yes" : "no"}')
}

# splice_generated DOC MARKER TEXT TITLE: puts TEXT (which holds the lines
# "<!-- MARKER:begin ..." and "<!-- MARKER:end -->") in place of the part of
# DOC between those markers, keeping the rest of DOC; a DOC without them is
# written as TITLE and TEXT.
splice_generated() {
  local doc=$1 marker=$2 text=$3 title=$4
  if [ -f "$doc" ] && grep -q "$marker:begin" "$doc"; then
    "$PY" - "$doc" "$marker" "$text" <<'PYEOF'
import re, sys
path, marker, new = sys.argv[1], sys.argv[2], sys.argv[3]
text = open(path).read()
text = re.sub(r"<!-- " + re.escape(marker) + r":begin.*?<!-- " + re.escape(marker) + r":end -->",
              lambda m: new, text, flags=re.S)
open(path, "w").write(text)
PYEOF
  else
    printf '# %s\n\n%s\n' "$title" "$text" >"$doc"
  fi
}
