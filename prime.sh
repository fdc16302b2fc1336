#!/usr/bin/env bash
# prime.sh: set up a fresh Debian machine, build, and run PRIME.
#   ./prime.sh demo    install what is missing, build prime, model + trace Colour Plate 2
#   ./prime.sh test    install what is missing, build, run every test (plain and ASan+UBSan),
#                      then fuzz every reader for a bounded time (clang + libFuzzer, tests/fuzz),
#                      then build the web page and test it under node and Chromium (tests/web)
#   ./prime.sh build   install what is missing and build the release preset only
#   ./prime.sh web [--build-only]
#                      install what is missing, build the page into build/web/ (prime compiled
#                      to WebAssembly, docs/web.md) and serve it on localhost
set -euo pipefail
cd "$(dirname "$0")"

# Debian packages the build and the tests need.
PACKAGES=(cmake ninja-build g++ binutils pkg-config libcli11-dev libgtest-dev libgmock-dev
          libbenchmark-dev libsdl2-dev libpng-dev libimagequant-dev libxxhash-dev nettle-dev clang libclang-rt-14-dev
          libfreetype-dev libfontconfig-dev fonts-dejavu-core   # the probe's text panel (palette/text)
          libgif-dev                    # prime film's animated GIFs (palette/gif_film); its
                                        # videos need ffmpeg, which is not installed here
          xvfb xauth x11-apps x11-utils xdotool   # window tests: an X server, xwd (x11-apps),
                                                  # xwininfo (x11-utils), key presses
          python3                       # the docs, tools and hand-check tests
          parallel rsync                # GNU parallel: docs/cluster.md's recipes (check_parallel);
                                        # rsync: its transfers to hosts without a shared filesystem
          munge slurmctld slurmd slurm-client   # a single-host Slurm for docs/cluster.md's job
                                        # arrays (check_slurm; Debian's slurm-wlm is these three)
          help2man groff-base)          # the man page (generated from the CLI) and its check
# What the web build and its tests add (./prime.sh web, ./prime.sh test; docs/web.md).
WEB_PACKAGES=(emscripten dpkg-dev   # emscripten compiles prime and Debian's sources of the
                                    # libraries it links (unpacked by dpkg-source)
              nodejs                # runs emscripten, and prime.js in the node tests
              chromium)             # the page's test in a real browser (tests/web)
# tests/install/check_test_programs.py fails when a program the tests run is
# not provided by a package above.

setup() {  # setup [PACKAGE...]: those (default: PACKAGES) that are missing
  local missing=() wanted=("$@")
  [ ${#wanted[@]} -eq 0 ] && wanted=("${PACKAGES[@]}")
  for p in "${wanted[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    echo "prime.sh: installing ${missing[*]}"
    local sudo=""
    [ "$(id -u)" -ne 0 ] && sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  fi
}

# stage NAME COMMAND...: runs a stage of the test command and prints its time.
stage() {
  local name=$1 start=$SECONDS
  shift
  echo "prime.sh: stage $name"
  "$@"
  echo "prime.sh: stage $name took $((SECONDS - start)) s"
}

build() {  # build PRESET [TARGET...]
  local preset=$1
  shift
  cmake --preset "$preset" >/dev/null
  if [ $# -gt 0 ]; then
    cmake --build --preset "$preset" -j "$(nproc)" --target "$@"
  else
    cmake --build --preset "$preset" -j "$(nproc)"
  fi
}

case "${1:-}" in
  demo)
    setup
    build release prime prime_window_sdl   # only what the demo runs, not the tests
    mkdir -p out
    ./build/release/src/cli/prime trace scenes/prime/plate2 --model --png out/plate2.png \
      --true-color-png out/plate2-true.png
    echo "prime.sh: out/plate2.png is Colour Plate 2 of the 1991 thesis as its IBM 8514/A showed it:"
    echo "  three CSG objects with texture maps (the D.C.U. '91 cube on the right), in the 256"
    echo "  fixed colours of the listing's palette; out/plate2-true.png is the same render before"
    echo "  those 256 colours. Next: README.md, docs/user-guide.md."
    ;;
  test)
    total=$SECONDS
    stage setup setup
    stage "build release" build release
    stage "test release" ctest --preset release -j "$(nproc)"
    stage "build asan" build asan
    stage "test asan" ctest --preset asan -j "$(nproc)"
    stage "build fuzz" build fuzz   # only the fuzz targets; each fuzz.<name> test fuzzes for 20 s
    stage "test fuzz" ctest --preset fuzz -j "$(nproc)"
    stage "setup web" setup "${WEB_PACKAGES[@]}"
    stage "build web" tools/web/build.sh
    stage "test web" python3 tests/web/run_web_tests.py
    echo "prime.sh: test took $((SECONDS - total)) s in all"
    ;;
  build)
    setup
    build release
    ;;
  web)
    setup
    setup "${WEB_PACKAGES[@]}"
    tools/web/build.sh
    if [ "${2:-}" != "--build-only" ]; then
      exec python3 tools/web/serve.py build/web "${PRIME_WEB_PORT:-8000}"
    fi
    ;;
  *)
    echo "usage: $0 demo|test|build|web [--build-only]" >&2
    exit 2
    ;;
esac
