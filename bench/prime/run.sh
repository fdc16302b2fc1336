#!/usr/bin/env bash
# bench/prime/run.sh [OUT]: rerun every measurement of docs/prime/benchmarks.md (except the
# POV-Ray comparison, bench/prime/pov_compare.sh) into OUT (default docs/prime/benchmarks):
#   bench.csv, bench.md, time_error.png      prime bench, every scenes/prime/*/
#   scale.csv, scale.md, scale_*.png         the scale study (1 .. 10,000 objects)
#   micro.csv                                prime_micro, 9 repetitions (mean, median, stddev, cv)
# Takes about 15 minutes on 2 cores. Run it on a quiet machine: `uptime` first.
set -euo pipefail
cd "$(dirname "$0")/../.."
OUT=${1:-docs/benchmarks}
./prime.sh build
B=build/release
mkdir -p "$OUT"
uptime
"$B/src/cli/prime" bench --runs 5 --scale --out "$OUT"
"$B/bench/micro/prime_micro" --benchmark_repetitions=9 --benchmark_report_aggregates_only=true \
  --benchmark_format=csv >"$OUT/micro.csv"
uptime
echo "bench/prime/run.sh: results in $OUT"
