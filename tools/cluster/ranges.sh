#!/bin/sh
# ranges.sh: the work of a film or of a banded picture as lines, one job a line, for
# GNU parallel (or any runner that takes a list of jobs).
#
#   tools/cluster/ranges.sh frames FIRST LAST PER   lines "A-B": chunks of PER frames
#   tools/cluster/ranges.sh bands ROWS BANDS        lines "T A-B": band T is rows A..B
#
# The same arithmetic as film-array.sbatch and bands-array.sbatch: chunk T is frames
# FIRST + T * PER .. min(that + PER - 1, LAST); band T is rows T * ROWS / BANDS ..
# (T + 1) * ROWS / BANDS - 1 (integer division: heights differ by at most one row).
#   tools/cluster/ranges.sh frames 0 9 4   ->  0-3 4-7 8-9
#   tools/cluster/ranges.sh bands 10 4     ->  0 0-1, 1 2-4, 2 5-6, 3 7-9
set -eu
usage() {
  echo "usage: $0 frames FIRST LAST PER | bands ROWS BANDS" >&2
  exit 2
}
[ $# -ge 1 ] || usage
case "$1" in
  frames)
    [ $# -eq 4 ] || usage
    A=$2 LAST=$3 PER=$4
    if [ "$PER" -lt 1 ] || [ "$A" -gt "$LAST" ]; then usage; fi
    while [ "$A" -le "$LAST" ]; do
      B=$((A + PER - 1))
      [ "$B" -le "$LAST" ] || B=$LAST
      echo "$A-$B"
      A=$((B + 1))
    done
    ;;
  bands)
    [ $# -eq 3 ] || usage
    ROWS=$2 BANDS=$3 T=0
    if [ "$BANDS" -lt 1 ] || [ "$BANDS" -gt "$ROWS" ]; then
      echo "ranges: $BANDS bands of $ROWS rows: between 1 and $ROWS bands" >&2
      exit 2
    fi
    while [ "$T" -lt "$BANDS" ]; do
      echo "$T $((T * ROWS / BANDS))-$(((T + 1) * ROWS / BANDS - 1))"
      T=$((T + 1))
    done
    ;;
  *) usage ;;
esac
