#!/usr/bin/env bash
# Times `prime model` on a copy of scenes/prime/copies (16 databases): the
# all-or-nothing switch (M19: fsync, journal, stamp, lock) against another
# build. Interleaved pairs, CPU (user+sys) and wall medians of N runs.
# Usage: bench/prime/model_switch.sh NEW_PRIME OLD_PRIME [N]
set -euo pipefail
new=$1 old=$2 n=${3:-7}
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cp -r "$(dirname "$0")/../../scenes/prime/copies" "$work/a"; cp -r "$work/a" "$work/b"
t() { /usr/bin/time -f "%U %S %e" "$1" model -q "$2" 2>&1 >/dev/null | tail -1; }
for i in $(seq "$n"); do echo "new $(t "$new" "$work/a")"; echo "old $(t "$old" "$work/b")"; done |
  awk '{cpu[$1]=cpu[$1] " " $2+$3; wall[$1]=wall[$1] " " $4}
       END {for (k in cpu) {print k, "cpu s:" cpu[k], " wall s:" wall[k]}}'
