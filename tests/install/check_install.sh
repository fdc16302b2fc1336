#!/usr/bin/env bash
# `cmake --install` into a temporary prefix: prime in bin/, its window module
# in lib/prime/, the man page and the bash, zsh and fish completions; the
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
