#!/usr/bin/env python3
"""CPU time of `prime trace --profile thesis` against `--profile modern` on a
scene, by interleaved paired runs (modern, thesis, modern, thesis, ...), one
thread each, so that load drifting on a shared machine hits both alike.
Prints each profile's median CPU seconds and the median of the per-pair
ratios thesis / modern.

  python3 bench/prime/thesis_vs_modern.py [--prime build/release/src/cli/prime]
      [--scene scenes/prime/plate2] [--runs 7] [-- extra trace options...]

The scene must be modelled (`prime model SCENE`) first. Pictures go to a
temporary directory."""
import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile


def cpu_of(cmd):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--prime", default="build/release/src/cli/prime")
    ap.add_argument("--scene", default="scenes/prime/plate2")
    ap.add_argument("--runs", type=int, default=7)
    ap.add_argument("extra", nargs="*", help="options for both traces (after --)")
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        def cmd(profile):
            return [a.prime, "trace", a.scene, "--profile", profile, "--threads", "1", "-q",
                    "--out", os.path.join(tmp, "graph_" + profile)] + a.extra
        times = {"modern": [], "thesis": []}
        ratios = []
        for _ in range(a.runs):
            m = cpu_of(cmd("modern"))
            t = cpu_of(cmd("thesis"))
            times["modern"].append(m)
            times["thesis"].append(t)
            ratios.append(t / m)
    for p, v in times.items():
        print(f"{p}: median CPU {statistics.median(v):.3f} s over {len(v)} runs "
              f"(min {min(v):.3f}, max {max(v):.3f})")
    print(f"thesis / modern: median of paired ratios {statistics.median(ratios):.2f} "
          f"(min {min(ratios):.2f}, max {max(ratios):.2f})")
    print(f"load average: {os.getloadavg()}")


if __name__ == "__main__":
    sys.exit(main())
