#!/usr/bin/env bash
# fetch_sources.sh DIR: Debian bookworm's own sources of the C libraries `prime`
# links (zlib, libpng, giflib, nettle, libimagequant, FreeType), unpacked with
# Debian's patches into DIR/<package>-<version>/, for the WebAssembly build
# (docs/web.md). Debian ships these libraries compiled for the machine only;
# the web build compiles the same sources with emscripten (tools/web/deps).
# Uses a private apt list of deb-src lines: the machine's own apt sources are
# not touched. Does nothing when DIR already holds them.
set -euo pipefail
dir=$1
packages=(zlib libpng1.6 giflib nettle libimagequant freetype)
mkdir -p "$dir"
cd "$dir"
if [ -f fetched ]; then exit 0; fi
command -v dpkg-source >/dev/null || { echo "fetch_sources.sh: no dpkg-source (Debian: dpkg-dev)" >&2; exit 1; }
state=$(mktemp -d)
trap 'rm -rf "$state"' EXIT
mkdir -p "$state/lists/partial"
echo "deb-src http://deb.debian.org/debian bookworm main" > "$state/sources.list"
apt=(apt-get -qq -o "Dir::Etc::SourceList=$state/sources.list" -o "Dir::Etc::SourceParts=/nonexistent"
     -o "Dir::State::Lists=$state/lists" -o "APT::Sandbox::User=root")
"${apt[@]}" update
"${apt[@]}" source --download-only "${packages[@]}" >/dev/null
# apt checked each file's hash against the signed Sources index; dpkg-source's
# own signature check would need debian-keyring, so its warning is dropped.
for dsc in ./*.dsc; do
  dpkg-source -x "$dsc" > "$state/unpack.log" 2>&1 || { cat "$state/unpack.log"; exit 1; }
done
touch fetched
