#!/usr/bin/env python3
"""The camera hand-off: one set of camera flags for every system.

For each system's scene (a copy of PRIME's default scene directory, a Malone
and a CGL scene file), runs the real `prime` and checks:
  - `trace` and `probe` take --eye --look-at --up --fov --size --camera;
  - the five flags move the picture: the PNG differs from the scene's own
    camera's, and has the --size asked (CGL: the 512 x 512 frame buffer with
    a W x H window in its middle, the rest black);
  - `--camera FILE` holding those flags (after a comment and an older camera:
    the last camera in the file counts) gives the same bytes as the flags;
  - flags given beside --camera win over the file's;
  - a camera file that is not one is refused naming the file and line (exit 1),
    a bad flag value as a usage error (exit 2), writing nothing;
  - CGL refuses a --size larger than its 512 x 512 screen.

Run: check_cameras.py PRIME_EXE REPO_ROOT
"""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../support"))
from prime_checks import Checks, png_rows, png_size

PRIME, ROOT = sys.argv[1], sys.argv[2]
SCENES = {
    "prime": os.path.join(ROOT, "scenes/prime/default"),
    "malone": os.path.join(ROOT, "scenes/malone/doc-sphere.mal"),
    "cgl": os.path.join(ROOT, "scenes/cgl/ball.cgl"),
}
# A camera each scene shows something in, off its own.
CAMERAS = {
    "prime": "--eye 900 700 -1200 --look-at 500 450 200 --up 0 1 0 --fov 42 --size 96 64",
    "malone": "--eye 1.5 1 4 --look-at 0 0 0 --up 0 1 0 --fov 35 --size 80 60",
    "cgl": "--eye 0.8 0.5 3 --look-at 0 0 0 --up 0 1 0 --fov 12 --size 200 150",
}
OLDER = "--eye 1 2 3 --look-at 0 0 0 --up 0 1 0 --fov 50 --size 32 32"

CHECKS = Checks(PRIME)
run, check, failures = CHECKS.run, CHECKS.check, CHECKS.failures


with tempfile.TemporaryDirectory() as tmp:
    scratch = os.path.join(tmp, "default")
    shutil.copytree(SCENES["prime"], scratch)
    SCENES["prime"] = scratch
    r = run(["model", scratch])
    check(r.returncode == 0, f"model the default scene: {r.stderr}")
    for system, scene in SCENES.items():
        for verb in ("trace", "probe"):
            r = run([verb, scene, "--help"])
            for flag in ("--eye", "--look-at", "--up", "--fov", "--size", "--camera"):
                check(f" {flag} " in r.stdout or f" {flag}," in r.stdout,
                      f"{verb} {system} --help lists {flag}")
        out = lambda name: os.path.join(tmp, f"{system}-{name}.png")
        flags = CAMERAS[system].split()
        own = run(["trace", scene, "--true-color-png", out("own"), "-q", "--no-window"])
        by_flags = run(["trace", scene] + flags + ["--true-color-png", out("flags"), "-q",
                                                   "--no-window"])
        cam_file = os.path.join(tmp, f"{system}-cameras.txt")
        with open(cam_file, "w") as f:
            f.write(f"# an older camera\n{OLDER}\n\n# prime walk {system}\n{CAMERAS[system]}\n")
        by_file = run(["trace", scene, "--camera", cam_file, "--true-color-png", out("file"), "-q",
                       "--no-window"])
        if not (check(own.returncode == 0, f"{system}: own camera: {own.stderr}") and
                check(by_flags.returncode == 0, f"{system}: the flags: {by_flags.stderr}") and
                check(by_file.returncode == 0, f"{system}: --camera: {by_file.stderr}")):
            continue
        a, b = open(out("flags"), "rb").read(), open(out("file"), "rb").read()
        check(a == b, f"{system}: --camera FILE gives other bytes than the flags")
        check(a != open(out("own"), "rb").read(), f"{system}: the flags changed nothing")
        w, h = (int(v) for v in CAMERAS[system].split("--size")[1].split())
        if system == "cgl":
            check(png_size(out("flags")) == (512, 512), f"cgl: the frame is 512 x 512")
            rows = png_rows(out("flags"))
            x0, y0 = 256 - w // 2, 256 - h // 2  # the window, in screen coordinates
            top, bottom = 511 - (y0 + h - 1), 511 - y0  # as image rows
            outside = [rows[y][3 * x:3 * x + 3] for y in (top - 1, bottom + 1)
                       for x in range(0, 512, 7)]
            outside += [rows[y][3 * x:3 * x + 3] for y in range(0, 512, 7)
                        for x in (x0 - 1, x0 + w)]
            check(all(p == b"\0\0\0" for p in outside), "cgl: outside the --size window is black")
            inside = [rows[y][3 * x:3 * x + 3] for y in range(top, bottom + 1)
                      for x in range(x0, x0 + w)]
            check(any(p != b"\0\0\0" for p in inside), "cgl: the window shows the ball")
        else:
            check(png_size(out("flags")) == (w, h), f"{system}: --size {w} {h}")
        # A flag beside the file wins over the file's.
        r = run(["trace", scene, "--camera", cam_file, "--fov", "20", "--true-color-png",
                 out("mixed"), "-q", "--no-window"])
        check(r.returncode == 0 and open(out("mixed"), "rb").read() != a,
              f"{system}: --fov beside --camera is used: {r.stderr}")
        # probe takes the same camera: the pixel at the centre of the picture
        # trace writes (CGL's: the frame buffer's), which shows the scene.
        px = (256, 256) if system == "cgl" else (w // 2, h // 2)
        r = run(["probe", scene, "--camera", cam_file, "--pixel", str(px[0]), str(px[1])])
        check(r.returncode == 0 and "hit" in r.stdout and "nothing" not in r.stdout.split("\n")[1],
              f"{system}: probe --camera sees the scene at the picture's centre: {r.stderr}"
              f"{r.stdout[:300]}")
        # Not a camera file: the file and line named, exit 1, nothing written.
        bad = os.path.join(tmp, f"{system}-bad.txt")
        with open(bad, "w") as f:
            f.write("# fine\n--eye 1 2 3 --look-at 0 0 0 --zoom 2\n")
        r = run(["trace", scene, "--camera", bad, "--true-color-png", out("bad"), "-q",
                 "--no-window"])
        check(r.returncode == 1 and f"{bad}:2:" in r.stderr and "--zoom" in r.stderr,
              f"{system}: a bad camera file is refused naming it, line 2 and the word: "
              f"exit {r.returncode}: {r.stderr.strip()}")
        check(not os.path.exists(out("bad")), f"{system}: a refused camera wrote a picture")
        r = run(["trace", scene, "--fov", "180", "--true-color-png", out("bad"), "-q",
                 "--no-window"])
        check(r.returncode == 2 and "--fov" in r.stderr,
              f"{system}: --fov 180 is a usage error: exit {r.returncode}: {r.stderr.strip()}")
        r = run(["trace", scene, "--eye", "0", "0", "0", "--look-at", "0", "0", "0",
                 "--true-color-png", out("bad"), "-q", "--no-window"])
        check(r.returncode == 2 and "look-at" in r.stderr,
              f"{system}: the eye at the look-at point is refused: {r.stderr.strip()}")
        check(not os.path.exists(out("bad")), f"{system}: a refused camera wrote a picture")
    r = run(["trace", SCENES["cgl"], "--size", "640", "480", "-q", "--no-window"])
    check(r.returncode == 2 and "512 x 512" in r.stderr,
          f"cgl: --size 640 480 is refused naming its screen: {r.stderr.strip()}")

for f in failures:
    print("FAIL:", f)
print(f"camera hand-off: {len(failures)} failure(s)")
sys.exit(1 if failures else 0)
