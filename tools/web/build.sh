#!/usr/bin/env bash
# build.sh: the web build (docs/web.md) into build/web/: `prime` compiled to
# WebAssembly twice from the same objects' sources (prime.js for node,
# prime-page.js for the page), the page (web/), and the shipped scenes with
# their listing (scenes/scenes.json). The C libraries come from Debian's
# sources (fetch_sources.sh), compiled with emscripten (tools/web/deps).
# ./prime.sh web calls it after installing the packages it needs.
set -euo pipefail
cd "$(dirname "$0")/../.."
# Emscripten's tools run on node and need Debian's acorn (node-acorn), which a
# node that is not Debian's does not look for.
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}
command -v em++ >/dev/null || { echo "build.sh: no em++ (Debian: emscripten)" >&2; exit 1; }
tools/web/fetch_sources.sh build/web-sources
cmake --preset web >/dev/null
cmake --build --preset web -j "$(nproc)"
out=build/web
rm -rf "$out.new"
mkdir -p "$out.new"
from=build/web-build/src/cli
cp "$from/prime.js" "$from/prime.worker.js" "$from/prime-page.js" "$from/prime-page.wasm" \
   "$from/prime-page.worker.js" "$out.new/"
cp web/index.html web/app.js web/worker.js web/style.css "$out.new/"
python3 tools/web/scene_list.py scenes "$out.new/scenes"
rm -rf "$out"
mv "$out.new" "$out"
du -sb "$out"/prime-page.wasm "$out"/prime-page.js "$out"/scenes "$out" | \
  awk '{printf "%-32s %8.1f KiB\n", $2, $1 / 1024}'
