// prime_micro's main: Google Benchmark's, nothing added.
#include <benchmark/benchmark.h>

BENCHMARK_MAIN();
