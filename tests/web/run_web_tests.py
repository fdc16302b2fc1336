#!/usr/bin/env python3
"""The web build's tests (docs/web.md), run by `./prime.sh test` after
tools/web/build.sh:

1. node: every shipped PRIME scene's graph file and companion, every Malone
   scene's PPM and every CGL scene's RLE, rendered by the WebAssembly build
   (node build/web/prime.js) and by the native build, byte for byte the same.
2. browser: headless Chromium loads the page from a local server (the same
   server ./prime.sh web runs), renders plate 2, a Malone and a CGL scene, and
   the canvas's pixels are the native --png's wherever the picture is; a
   dropped bad scene shows the error the command line prints for it.

--screenshots DIR also writes the page's screenshots there (docs/web.md's
pictures). Exit status 0 only when every check passed."""
import argparse
import base64
import concurrent.futures
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tests" / "support"))
sys.path.insert(0, str(Path(__file__).resolve().parent))
import cdp
import prime_checks

NATIVE = ROOT / "build" / "release" / "src" / "cli" / "prime"
WEB = ROOT / "build" / "web"
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what, flush=True)
    if not ok:
        failures.append(what)


def run(args, cwd):
    r = subprocess.run(args, cwd=cwd, capture_output=True, text=True, timeout=900)
    return r.returncode, r.stdout, r.stderr


# Scenes that need an option to render: the document's figures 2 and 59 as
# printed, whose comments only --lenient reads (a bullet, a bare 'vertices').
OPTIONS = {"doc-figure2.cgl": ["--lenient"], "doc-figure59.cgl": ["--lenient"]}


def node_tests(work):
    """Every shipped scene, native and WebAssembly, the same bytes."""
    node = [shutil.which("node") or "node", str(WEB / "prime.js")]
    cases = []
    for scene in sorted((ROOT / "scenes" / "prime").iterdir()):
        if (scene / "prim").is_dir():
            cases.append(("prime", scene, "graph_scr"))
    for scene in sorted((ROOT / "scenes" / "malone").glob("*.mal")):
        cases.append(("malone", scene, scene.stem + ".ppm"))
    for scene in sorted((ROOT / "scenes" / "cgl").glob("*.cgl")):
        cases.append(("cgl", scene, scene.stem + ".rle"))
    def one(case):
        system, scene, out = case
        results = {}
        for side, program in (("native", [str(NATIVE)]), ("web", node)):
            here = work / "node" / side / system / scene.stem
            here.mkdir(parents=True, exist_ok=True)
            if system == "prime":
                shutil.copytree(scene, here / scene.name, ignore=shutil.ignore_patterns(
                    "PrimFile", "List", "O[0-9]*", "Map*_[RGB].map", "graph_scr*", "prime-model.*"))
                args = program + ["trace", scene.name, "--model", "--out", out]
            else:
                args = program + ["trace", str(scene), "--out", out] + OPTIONS.get(scene.name, [])
            start = time.monotonic()
            status, _, err = run(args, here)
            companion = here / (out + ".info")
            results[side] = (status, err.strip().splitlines()[-1:] if status else [],
                             (here / out).read_bytes() if (here / out).exists() else None,
                             companion.read_bytes() if companion.exists() else None,
                             time.monotonic() - start)
        return results

    # Two scenes at a time on two CPUs: most of a node run is its start-up.
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        outcomes = list(pool.map(one, cases))
    total = {"native": 0.0, "web": 0.0}
    for (system, scene, out), results in zip(cases, outcomes):
        n, w = results["native"], results["web"]
        total["native"] += n[4]
        total["web"] += w[4]
        same = n[0] == 0 and w[0] == 0 and n[2] is not None and n[2] == w[2] and n[3] == w[3]
        check(same, f"node: {system} {scene.name}: {out} byte for byte the native build's"
              + ("" if same else f" (status native {n[0]} {n[1]}, web {w[0]} {w[1]})"))
    print(f"node: {len(cases)} scenes, native {total['native']:.1f} s, "
          f"WebAssembly under node {total['web']:.1f} s (whole processes, summed)", flush=True)


def canvas_rgb(browser):
    """The canvas's pixels as rows of RGB bytes."""
    data = browser.evaluate(
        "(() => { const c = document.getElementById('canvas');"
        " const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;"
        " const rgb = new Uint8Array(c.width * c.height * 3);"
        " for (let i = 0, j = 0; i < d.length; i += 4) { rgb[j++] = d[i]; rgb[j++] = d[i + 1];"
        " rgb[j++] = d[i + 2]; }"
        " let s = ''; for (let i = 0; i < rgb.length; i += 0x8000)"
        " s += String.fromCharCode.apply(null, rgb.subarray(i, i + 0x8000));"
        " return [c.width, c.height, btoa(s)]; })()")
    width, height, b64 = data
    raw = base64.b64decode(b64)
    return width, height, [raw[y * width * 3:(y + 1) * width * 3] for y in range(height)]


def find_picture(screen, picture, zoom):
    """Whether `picture` (rows of RGB) is in `screen` (rows of RGB, each
    picture pixel zoom x zoom): returns the offset or None."""
    ph, pw = len(picture), len(picture[0]) // 3
    small = [bytes(b for x in range(0, len(row) // 3, zoom) for b in row[3 * x:3 * x + 3])
             for row in screen[::zoom]]
    for y0 in range(0, len(small) - ph + 1):
        at = small[y0].find(picture[0])
        while at >= 0:
            if at % 3 == 0:
                x0 = at // 3
                if all(small[y0 + y][3 * x0:3 * (x0 + pw)] == picture[y] for y in range(ph)):
                    return x0, y0
            at = small[y0].find(picture[0], at + 1)
    return None


def browser_tests(work, screenshots):
    server = subprocess.Popen([sys.executable, str(ROOT / "tools" / "web" / "serve.py"), str(WEB), "0"],
                              stdout=subprocess.PIPE, text=True)
    browser = None
    try:
        url = server.stdout.readline().split(" at ")[1].split()[0]
        browser = cdp.Browser()
        start = time.monotonic()
        browser.open(url)
        while not browser.evaluate("!!(window.primePage && window.primePage.ready)"):
            if time.monotonic() - start > 60:
                raise RuntimeError("the page did not start: " + str(browser.evaluate(
                    "document.getElementById('status').textContent + ' ' + "
                    "document.getElementById('error').textContent")))
            time.sleep(0.1)
        print(f"browser: the page was ready {time.monotonic() - start:.2f} s after it was opened",
              flush=True)
        browser.evaluate("document.getElementById('keep').checked = false")
        for value, scene, native_args in (
                ("prime/plate2", ROOT / "scenes" / "prime" / "plate2", ["--png"]),
                ("malone/doc-scene.mal", ROOT / "scenes" / "malone" / "doc-scene.mal", ["--png"]),
                ("cgl/ball.cgl", ROOT / "scenes" / "cgl" / "ball.cgl", ["--png"])):
            begun = time.monotonic()
            result = browser.evaluate(
                f"(document.getElementById('scene').value = '{value}',"
                " window.primePage.render().then(() => [window.primeLast.done,"
                " window.primeLast.err.join('\\n'), window.primeLast.ms]))")
            seconds = time.monotonic() - begun
            check(result[0] == 0, f"browser: {value} rendered (status {result[0]}, "
                  f"{result[2] / 1000:.2f} s in the program, {seconds:.2f} s from the click)"
                  + ("" if result[0] == 0 else ": " + result[1]))
            width, height, screen = canvas_rgb(browser)
            here = work / "browser"
            here.mkdir(parents=True, exist_ok=True)
            png = here / (scene.stem + ".png")
            if scene.is_dir():
                shutil.copytree(scene, here / scene.name, dirs_exist_ok=True)
                args = [str(NATIVE), "trace", scene.name, "--model", "--out", "graph_scr"]
            else:
                args = [str(NATIVE), "trace", str(scene), "--out", scene.stem + ".out"]
            status, _, err = run(args + native_args + [str(png)], here)
            check(status == 0, f"browser: native {value} rendered" + ("" if status == 0 else ": " + err))
            picture = prime_checks.png_rows(png)
            zoom = max(1, min(width // 1024, height // 768))
            at = find_picture(screen, picture, zoom)
            check(at is not None, f"browser: {value}: the canvas ({width} x {height}, zoom {zoom}) "
                  f"shows the native PNG's {len(picture[0]) // 3} x {len(picture)} pixels exactly"
                  + (f", at {at[0]}, {at[1]} on the screen" if at else ""))
            if scene.is_dir():
                # The downloads: the graph file is the native one's bytes, the indexed PNG
                # the native --png's (libpng's own code, so the same bytes too).
                downloads = browser.evaluate(
                    "(() => { const b64 = (u) => { let s = ''; for (let i = 0; i < u.length;"
                    " i += 0x8000) s += String.fromCharCode.apply(null, u.subarray(i, i + 0x8000));"
                    " return btoa(s); }; const f = window.primeLast.files;"
                    " return [b64(f['/out/picture']), b64(f['/out/picture-8514.png'])]; })()")
                graph = base64.b64decode(downloads[0])
                check(graph == (here / "graph_scr").read_bytes(),
                      f"browser: {value}: the page's graph file download is the native graph file")
                page_png = here / "page.png"
                page_png.write_bytes(base64.b64decode(downloads[1]))
                check(page_png.read_bytes() == png.read_bytes(),
                      f"browser: {value}: the page's indexed PNG download is the native --png, byte for byte"
                      + ("" if page_png.read_bytes() == png.read_bytes() else
                         f" (same pixels: {prime_checks.same_pixels(str(page_png), str(png))}; "
                         f"text page {prime_checks.png_text(str(page_png))} native "
                         f"{prime_checks.png_text(str(png))})"))
            if screenshots:
                browser.screenshot(str(Path(screenshots) / f"web-{scene.stem}.png"))
        # The walk: a drag orbits the camera (the picture changes), Esc ends it.
        browser.evaluate("(document.getElementById('scene').value = 'prime/plate3',"
                         " window.walkDone = window.primePage.walk().then(() => window.primeLast.done), 1)")
        first = None
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline:
            time.sleep(0.5)
            if "frame" in browser.evaluate("document.getElementById('status').textContent"):
                first = canvas_rgb(browser)[2]
                break
        check(first is not None, "browser: the walk draws frames of plate 3")
        box = browser.evaluate("(() => { const r = canvas.getBoundingClientRect();"
                               " return [r.left + r.width / 2, r.top + r.height / 2]; })()")
        browser.call("Input.dispatchMouseEvent", type="mousePressed", x=box[0], y=box[1],
                     button="left", buttons=1, clickCount=1)
        for i in range(1, 11):
            browser.call("Input.dispatchMouseEvent", type="mouseMoved", x=box[0] + 15 * i, y=box[1],
                         button="left", buttons=1)
            time.sleep(0.05)
        browser.call("Input.dispatchMouseEvent", type="mouseReleased", x=box[0] + 150, y=box[1],
                     button="left", buttons=0, clickCount=1)
        time.sleep(4)
        check(first is not None and canvas_rgb(browser)[2] != first,
              "browser: dragging in the walk's canvas orbits the camera (the picture changes)")
        if screenshots:
            browser.screenshot(str(Path(screenshots) / "web-walk.png"))
        browser.evaluate("canvas.focus(), 1")
        browser.call("Input.dispatchKeyEvent", type="keyDown", key="Escape", code="Escape",
                     windowsVirtualKeyCode=27)
        check(browser.evaluate("window.walkDone", timeout=60) == 0, "browser: Esc ends the walk (status 0)")
        # A dropped scene with a mistake: the page shows what the command line says.
        # (Malone's document sphere with a word where a number must be, line 5.)
        lines = (ROOT / "scenes" / "malone" / "doc-sphere.mal").read_text().splitlines(True)
        lines[4] = "0 0.362164 oops\n"
        bad = "".join(lines)
        bad_path = work / "bad.mal"
        bad_path.write_text(bad)
        status, _, native_err = run([str(NATIVE), "trace", "bad.mal", "--out", "bad.ppm"], work)
        check(status != 0 and native_err.startswith("prime: bad.mal"),
              f"browser: the native build refuses bad.mal ({native_err.strip()[:120]})")
        shown = browser.evaluate(
            "window.primePage.takeScene({'bad.mal': new TextEncoder().encode("
            + json.dumps(bad) + ").buffer})"
            ".then(() => window.primePage.render()).then(() =>"
            " [window.primeLast.done, document.getElementById('error').textContent,"
            " document.getElementById('error').hidden])")
        expected = native_err.strip().replace("prime: bad.mal", "prime: /dropped/bad.mal")
        check(shown[0] != 0 and not shown[2] and shown[1].strip() == expected,
              f"browser: a dropped bad .mal shows the command line's error "
              f"(page: {shown[1].strip()[:160]!r}; native: {expected[:160]!r})")
        if screenshots:
            browser.screenshot(str(Path(screenshots) / "web-error.png"))
    finally:
        if browser:
            browser.close()
        server.kill()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--screenshots", help="write the page's screenshots into this directory")
    parser.add_argument("--only", choices=("node", "browser"))
    options = parser.parse_args()
    for need in (NATIVE, WEB / "prime.js", WEB / "index.html"):
        if not need.exists():
            sys.exit(f"run_web_tests: {need} is missing: build it first (./prime.sh build, "
                     "tools/web/build.sh)")
    work = Path(tempfile.mkdtemp(prefix="prime-web-tests-"))
    try:
        if options.only in (None, "node"):
            node_tests(work)
        if options.only in (None, "browser"):
            browser_tests(work, options.screenshots)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print(f"run_web_tests: {len(failures)} failure(s)")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
