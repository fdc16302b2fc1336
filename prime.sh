#!/usr/bin/env bash
# prime.sh: set up a fresh Debian machine, build, and run PRIME.
#   ./prime.sh demo    install what is missing, build, model + trace the default scene
#   ./prime.sh test    install what is missing, build, run every test (plain and ASan+UBSan),
#                      then fuzz every reader for a bounded time (clang + libFuzzer, tests/fuzz)
#   ./prime.sh build   install what is missing and build the release preset only
set -euo pipefail
cd "$(dirname "$0")"

# Debian packages the build and the tests need.
PACKAGES=(cmake ninja-build g++ pkg-config libcli11-dev libgtest-dev libgmock-dev
          libbenchmark-dev libsdl2-dev libpng-dev clang libclang-rt-14-dev
          xvfb xauth x11-apps xdotool)  # window tests: an X server, xwd (x11-apps), key presses

setup() {
  local missing=()
  for p in "${PACKAGES[@]}"; do
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

build() {  # build PRESET
  cmake --preset "$1" >/dev/null
  cmake --build --preset "$1" -j "$(nproc)"
}

case "${1:-}" in
  demo)
    setup
    build release
    mkdir -p out
    ./build/release/src/cli/prime trace scenes/prime/default --model --png out/default.png
    echo "prime.sh: the screen image is out/default.png"
    ;;
  test)
    setup
    build release
    ctest --preset release -j "$(nproc)"
    build asan
    ctest --preset asan -j "$(nproc)"
    build fuzz   # only the fuzz targets; each fuzz.<name> test fuzzes for 20 s
    ctest --preset fuzz -j "$(nproc)"
    ;;
  build)
    setup
    build release
    ;;
  *)
    echo "usage: $0 demo|test|build" >&2
    exit 2
    ;;
esac
