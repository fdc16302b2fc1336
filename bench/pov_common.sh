# Sourced by bench/pov_compare.sh (PRIME) and bench/malone_pov_compare.sh
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
