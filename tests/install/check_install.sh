#!/usr/bin/env bash
# `cmake --install` into a temporary prefix: prime in bin/, its window module
# in lib/prime/, the man page, the bash, zsh and fish completions and the
# scenes (share/prime/scenes/, each rendered from there); the
# installed prime runs (--version) and finds its window module relative to
# itself (LD_DEBUG=files names the file dlopen() loaded), with no display
# server (DISPLAY names one that does not exist, so the run goes on headless).
# usage: check_install.sh BUILD_DIR SCENE_DIR
set -euo pipefail
build=$1
scene=$2
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

cmake --build "$build" --target prime prime_window_sdl prime_cli_docs >/dev/null
cmake --install "$build" --prefix "$prefix" >/dev/null
for f in bin/prime lib/prime/libprime_window_sdl.so share/man/man1/prime.1 \
         share/bash-completion/completions/prime share/zsh/site-functions/_prime \
         share/fish/vendor_completions.d/prime.fish; do
  [ -f "$prefix/$f" ] || fail "$f not installed"
done
"$prefix/bin/prime" --version | grep -q '^prime [0-9]' || fail "prime --version"

# The shipped scenes, in share/prime/scenes/, render from there: a Malone and
# a CGL scene (the document's Figure 59, its texture found in the installed
# textures/) directly, a PRIME scene from a copy (trace writes into the scene,
# README.md), and nothing a render writes is installed with them.
scenes=$prefix/share/prime/scenes
for f in malone/glass.mal cgl/checkerboard.cgl cgl/doc-figure59.cgl cgl/textures/checkerboard.rle \
         prime/plate2/Model.txt prime/plate1/knots.txt; do
  [ -f "$scenes/$f" ] || fail "share/prime/scenes/$f not installed"
done
leftovers=$(cd "$scenes" && find . -name PrimFile -o -name List -o -name 'graph_scr*' -o -name '*.png' \
            -o -name 'prime-model.*' -o -name 'Map*_[RGB].map')
[ -z "$leftovers" ] || fail "rendered files installed with the scenes: $leftovers"
(cd "$prefix" && DISPLAY= WAYLAND_DISPLAY= bin/prime trace "$scenes/malone/glass.mal" --no-window -q \
   --png glass.png && [ -s glass.png ]) || fail "the installed malone/glass.mal does not render"
(cd "$prefix" && DISPLAY= WAYLAND_DISPLAY= bin/prime trace "$scenes/cgl/doc-figure59.cgl" --lenient \
   --no-window -q --png f59.png && [ -s f59.png ]) || fail "the installed cgl/doc-figure59.cgl does not render"
cp -r "$scenes/prime/default" "$prefix/default"
(cd "$prefix" && DISPLAY= WAYLAND_DISPLAY= bin/prime trace default --model --no-window -q --png default.png &&
   [ -s default.png ]) || fail "a copy of the installed prime/default does not render"

cp -r "$scene" "$prefix/scene"
# In the ASan run, LeakSanitizer would report libdbus's allocations, which
# SDL never frees (third-party, as in the window tests: lsan-sdl.supp).
supp="$(cd "$(dirname "$0")/../support" && pwd)/lsan-sdl.supp"
err=$(cd "$prefix" && DISPLAY=:65533 WAYLAND_DISPLAY= SDL_VIDEODRIVER=x11 PRIME_WINDOW_MODULE= \
      LSAN_OPTIONS="suppressions=$supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}" \
      LD_DEBUG=files "$prefix/bin/prime" trace scene --model 2>&1 >/dev/null) ||
  fail "installed prime trace: $err"
echo "$err" | grep -q "file=$prefix/lib/prime/libprime_window_sdl.so .*dynamically loaded" ||
  fail "the window module was not loaded from $prefix/lib/prime: $(echo "$err" | grep -v '^ *[0-9]*:' | tail -5)"
echo "$err" | grep -q "cannot load the window module" && fail "cannot load the module: $err"

# The man page renders (man's own formatter, no warnings) and lists every command.
if command -v groff >/dev/null; then
  page=$(groff -man -Tutf8 -ww "$prefix/share/man/man1/prime.1" 2>&1 >/dev/null)
  [ -z "$page" ] || fail "groff warnings: $page"
  # Its footer, as man shows it at 80 columns: the source, the date of .TH and
  # PRIME(1) apart. A source as long as --version's first line ran into the
  # date ("prime 0.2.0 (PRIME 1991, Malone 1Novembere2026 CGL 1985)").
  date=$(sed -n 's/^\.TH [^"]*"[^"]*" "\([^"]*\)".*/\1/p' "$prefix/share/man/man1/prime.1")
  [ -n "$date" ] || fail "the man page has no date in .TH"
  footer=$(groff -man -Tutf8 -P-cbou -rLL=80n "$prefix/share/man/man1/prime.1" 2>/dev/null |
           grep -v '^[[:space:]]*$' | tail -1)
  [[ "$footer" =~ ^prime\ [0-9][^\ ]*\ {2,}"$date"\ {2,}PRIME\(1\)$ ]] ||
    fail "the man page's footer is not 'prime VERSION   $date   PRIME(1)': '$footer'"
fi
echo "install: ok ($prefix)"
