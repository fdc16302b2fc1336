#!/usr/bin/env python3
"""Hostile command lines and scenes, every system (issue 37's classes).

For each class, the systems that have it; each case runs the real `prime` and
checks the exit status, that the message names the file and what was expected
and found, that nothing is left half-written, and that it ends quickly:
  - writers: an empty output name, two outputs naming one file (also by hard
    link), a render with no output named (says so), `-o -q` (a flag taken as
    the output's name);
  - the command line: options of several values followed by the scene (they
    took it), the system of `-o existing.rle scene.cgl`, a file no system
    reads, a 309-digit range in a message;
  - unbounded work from a small file: a CGL DAG of 2^60 paths, a chain of
    6,000 CGL nodes, a CGL spline refined to 5.3 GiB, a Malone viewer of
    16384 x 16384, 200 Malone sampled lights of 100,000 samples each, Ctrl-C
    inside a pixel of such lights, Malone's --max-depth beyond 64;
  - hostile bytes: control bytes in a CGL scene are shown escaped.

Run: check_hostile.py PRIME_EXE REPO_ROOT
"""
import math
import os
import re
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time

PRIME, ROOT = sys.argv[1], sys.argv[2]
failures = []
CASES = 0


def run(args, cwd, timeout=120):
    env = dict(os.environ, DISPLAY="", WAYLAND_DISPLAY="")
    start = time.monotonic()
    r = subprocess.run([PRIME] + args, capture_output=True, text=True, cwd=cwd, env=env,
                       timeout=timeout, errors="replace")
    r.seconds = time.monotonic() - start
    r.out = r.stdout + r.stderr
    return r


def check(ok, what, r=None):
    global CASES
    CASES += 1
    if not ok:
        failures.append(what + ("" if r is None else f"\n    exit {r.returncode}: {r.out[-600:]}"))


def refused(r, status, *needles, seconds=10.0):
    """Refused with `status`, the message holding every needle, within `seconds`."""
    return (r.returncode == status and all(n in r.out for n in needles)
            and r.seconds < seconds and "bad_alloc" not in r.out and "terminate" not in r.out)


with tempfile.TemporaryDirectory() as tmp:
    def path(name):
        return os.path.join(tmp, name)

    def write(name, text):
        with open(path(name), "w") as f:
            f.write(text)
        return path(name)

    malone = os.path.join(ROOT, "scenes/malone/doc-sphere.mal")
    cgl = os.path.join(ROOT, "scenes/cgl/ball.cgl")
    prime = path("default")  # a copy: `--model` writes its databases
    shutil.copytree(os.path.join(ROOT, "scenes/prime/default"), prime)
    scenes = {"malone": malone, "cgl": cgl}

    # ---- writers -------------------------------------------------------------
    for system, scene in scenes.items():
        r = run(["trace", scene, "--no-window", "--png", ""], tmp)
        check(refused(r, 2, "--png", "empty file name"), f"{system}: --png '' is refused", r)
        r = run(["trace", scene, "--no-window", "-q", "--png", "same.png",
                 "--true-color-png", "same.png"], tmp)
        check(refused(r, 1, "same.png", "--png and --true-color-png name the same file")
              and not os.path.exists(path("same.png")),
              f"{system}: two outputs naming one file are refused before the render", r)
        write("a.png", "")
        if os.path.exists(path("b.png")):
            os.remove(path("b.png"))
        os.link(path("a.png"), path("b.png"))
        r = run(["trace", scene, "--no-window", "-q", "--png", "a.png", "--png-8514", "b.png"],
                tmp)
        check(refused(r, 1, "name the same file") and os.path.getsize(path("a.png")) == 0,
              f"{system}: two outputs that are one file by a hard link are refused", r)
        r = run(["trace", scene, "--no-window"], tmp)
        check(r.returncode == 0 and "no output named, so the picture will not be written"
              in r.stderr and "wrote nothing" in r.stdout,
              f"{system}: a trace with no output says it writes nothing", r)
    r = run(["trace", prime, "--model", "--no-window", "-q", "--out", "x.gr", "--png", "x.gr"],
            tmp)
    check(refused(r, 1, "--out and --png name the same file"),
          "prime: --out and --png naming one file are refused", r)
    r = run(["trace", "-o", "-q", cgl, "--no-window"], tmp)
    check(refused(r, 2, "-o", "expected a path name", "'-q'")
          and not os.path.exists(path("--quiet")),
          "cgl call statement: -o -q is refused, no file named --quiet", r)

    # ---- the command line ----------------------------------------------------
    r = run(["trace", "--background", "10", "20", "30", cgl, "--no-window", "-q",
             "--png", "bg.png"], tmp)
    check(r.returncode == 0 and os.path.exists(path("bg.png")),
          "cgl: --background R G B before the scene leaves the scene to be the scene", r)
    r = run(["trace", "-b", "10", "20", "30", cgl, "--no-window", "-q", "--png", "b3.png"], tmp)
    check(r.returncode == 0 and os.path.exists(path("b3.png")),
          "cgl call statement: -b r g b before the scene", r)
    os.makedirs(path("tex"), exist_ok=True)
    r = run(["trace", "--textures", path("tex"), cgl, "--no-window", "-q", "--png", "t.png"], tmp)
    check(r.returncode == 0 and os.path.exists(path("t.png")),
          "cgl: --textures DIR before the scene (a list takes one value a flag)", r)
    with open(path("pic.rle"), "wb") as f:  # an existing picture named by -o
        f.write(b"\x00\x01\x02\x03 not a scene")
    r = run(["trace", "-o", "pic.rle", cgl, "--no-window", "-q"], tmp)
    check(r.returncode == 0 and os.path.getsize(path("pic.rle")) > 20,
          "cgl: -o existing.rle scene.cgl is CGL's (the scene is the file CGL reads)", r)
    r = run(["trace", "--light-radius", "0.1", prime, "--profile", "thesis", "--model",
             "--no-window", "-q", "--out", "lr.gr"], tmp)
    check(r.returncode == 0 and os.path.exists(path("lr.gr")),
          "prime: --light-radius N before the scene directory (a run of numbers, then the scene)",
          r)
    notes = write("notes.txt", "Dear reader, this is a letter.\n")
    r = run(["trace", notes, "--no-window"], tmp)
    check(refused(r, 2, "notes.txt", "no system reads as its scene", "--format")
          and "Directory is actually a file" not in r.out,
          "a text file no system reads: the message says so", r)
    r = run(["compare", prime, "--threads", "-1"], tmp)
    check(refused(r, 2, "--threads", "-1") and len(r.out) < 300,
          "compare --threads -1: a short message (no 309-digit range)", r)
    r = run(["dump", "--help"], tmp)
    check(r.returncode == 0, "dump --help", r)

    # ---- unbounded work from a small file -------------------------------------
    head = "0 0 0 1 1 {nodes} 1\n"
    surface = open(cgl).read().split("* surface 1")[1].split("* scene nodes")[0]
    body = "* surface 1" + surface + "* scene nodes\n"
    n = 60  # each dummy node shares the next by both pointers: 2^60 paths, no object
    dag = head.format(nodes=n) + body + "".join(
        f"{k} dummy {k + 1:02d} {k + 1:02d}\n" for k in range(1, n)) + f"{n} dummy 00 00\n"
    r = run(["trace", write("dag.cgl", dag), "--no-window", "-q", "--png", "dag.png"], tmp)
    check(refused(r, 1, "dag.cgl", "node visits") and not os.path.exists(path("dag.png")),
          "cgl: a DAG of 2^60 paths is refused at its node-visit limit, quickly", r)
    n = 6000
    chain = head.format(nodes=n) + body + "".join(
        f"{k} dummy {k + 1:02d} 00\n" for k in range(1, n)) + \
        f"{n} sphere 00 00 1 0.0 0.0 0.0 0.3 x y\n"
    r = run(["trace", write("chain.cgl", chain), "--no-window", "-q", "--png", "chain.png"], tmp,
            timeout=300)
    check(r.returncode == 0 and os.path.exists(path("chain.png")),
          "cgl: a chain of 6,000 nodes renders (no recursion per node)", r)
    tube = open(os.path.join(ROOT, "scenes/cgl/doc-spline-tube.cgl")).read()
    # One spline of 60 x 60 control vertices at 64 divisions (the reader's
    # most, CGL-Q9): 3,907 x 3,907 refined points, 5.3 GiB with its box tree,
    # asked by a 60 KB file. (A mesh shared along many paths adds up the same
    # way: CglPreprocess.SplineMeshesAddUpAlongEveryPath.)
    n = 60
    head_lines = tube.split("* scene nodes\n")[0].replace("0 2 0 1 1 4 1", "0 2 0 1 1 1 1", 1)
    controls = "".join(f"{i + 1} {0.3 * math.cos(2 * math.pi * i / n):.4f} {j / n:.4f} "
                       f"{0.3 * math.sin(2 * math.pi * i / n):.4f}\n"
                       for j in range(n) for i in range(n))
    huge = head_lines + "* scene nodes\n" + f"1 spline 00 00 1 {n} closed {n} double 64 0.6\n" \
        + controls
    r = run(["trace", write("spline.cgl", huge), "--no-window", "-q", "--png", "sp.png"], tmp)
    check(refused(r, 1, "spline.cgl", "divisions", "3907 x 3907 points", "2048 MiB"),
          "cgl: a spline refined beyond the memory limit is refused before it is made", r)
    text = open(malone).read()
    big = text.replace("256 256", "16384 16384", 1)
    r = run(["trace", write("big.mal", big), "--no-window", "-q", "--png", "big.png"], tmp)
    check(refused(r, 1, "big.mal", "16384 x 16384", "GiB"),
          "malone: a 16384 x 16384 viewer is refused before allocating, naming what it needs", r)
    lights = text.replace("101\n4 4 6\n60 60 60\n",
                          "105\n100000\n4 4 6\n0.5\n60 60 60\n" * 200, 1)
    check(lights != text, "doc-sphere.mal's light is where this test expects it")
    r = run(["trace", write("lights.mal", lights), "--no-window", "-q", "--png", "l.png"], tmp)
    check(refused(r, 1, "lights.mal", "at most 1000000 samples of sampled lights"),
          "malone: 200 lights of 100,000 samples are refused at the samples limit", r)
    # Ctrl-C inside one pixel: two facing perfect mirrors and --max-depth
    # 10000 make every pixel 10,000 shading points, each sending a shadow ray
    # to every one of ten lights' 100,000 samples (the limit): hours a pixel,
    # so only a check inside the pixel can end the run.
    light = "105\n100000\n0 1 0\n0.5\n60 60 60\n"
    mirror = "100\n0.9 0.9 0.9\n1 200\n0 0 0\n"
    mirrors = ("102\n0 0 0\n1 0 0\n0 0 0.1\n0 0.1 0\n4 4\n" + light * 10 +
               "2\n1.5\n1 0 0\n" + mirror + "2\n-1.5\n1 0 0\n" + mirror)
    env = dict(os.environ, DISPLAY="", WAYLAND_DISPLAY="")
    p = subprocess.Popen([PRIME, "trace", write("slow.mal", mirrors), "--no-window",
                          "--max-depth", "10000", "--min-weight", "0", "--threads", "1",
                          "--png", "slow.png"], cwd=tmp, env=env, stdout=subprocess.DEVNULL,
                         stderr=subprocess.PIPE, text=True)
    started = False
    for line in p.stderr:  # the render has begun once the run says it is headless
        if "running headless" in line:
            started = True
            break
    time.sleep(1.0)
    running = started and p.poll() is None
    p.send_signal(signal.SIGINT)
    start = time.monotonic()
    try:
        p.communicate(timeout=10)
    except subprocess.TimeoutExpired:
        p.kill()
        p.communicate()
    waited = time.monotonic() - start
    check(running and p.returncode == 130 and waited < 1.0 and not os.path.exists(path("slow.png")),
          f"malone: Ctrl-C inside a pixel of hours (10,000 bounces, 1,000,000 light samples) "
          f"ends the run in {waited:.2f} s with {p.returncode} (want 130 within 1 s), no picture")
    corridor = os.path.join(ROOT, "scenes/malone/mirror-corridor.mal")
    r = run(["trace", corridor, "--max-depth", "200", "--min-weight", "0", "--size", "64",
             "48", "--no-window", "-q", "--png", "deep.png"], tmp)
    check(r.returncode == 0 and os.path.exists(path("deep.png")),
          "malone: --max-depth 200, past the old cap of 64 (the document's MIN_WEIGHT is what bounds depth)", r)

    # ---- failures nobody foresaw name the file and the step ------------------------
    tube_path = os.path.join(ROOT, "scenes/cgl/doc-spline-tube.cgl")
    r = run(["cgl-splines", tube_path, "--distances", path("no such dir/d.csv")], tmp)
    check(refused(r, 1, "no such dir/d.csv", "does not exist"),
          "cgl-splines --distances into a missing directory: a message, not SIGABRT", r)

    def limited(mib):
        def apply():
            resource.setrlimit(resource.RLIMIT_AS, (mib << 20, mib << 20))
        return apply

    env = dict(os.environ, DISPLAY="", WAYLAND_DISPLAY="")
    probe = subprocess.run([PRIME, "--version"], capture_output=True, preexec_fn=limited(400),
                           env=env)
    if probe.returncode != 0:  # AddressSanitizer reserves terabytes: no address-space limit
        print("check_hostile: out-of-memory case skipped: this build cannot run under a 400 MiB "
              "address-space limit (a sanitizer's shadow memory)")
    else:
        big = open(malone).read().replace("256 256", "6000 6000", 1)  # 1 GiB of picture
        oom = subprocess.run([PRIME, "trace", write("oom.mal", big), "--no-window", "-q",
                              "--png", "oom.png"], capture_output=True, text=True, cwd=tmp,
                             env=env, preexec_fn=limited(400), timeout=120)
        check(oom.returncode == 1 and "out of memory while" in oom.stderr
              and "oom.mal" in oom.stderr and "bad_alloc" not in oom.stderr
              and not os.path.exists(path("oom.png")),
              "out of memory names the step and the scene, not a bare std::bad_alloc:\n    "
              + oom.stderr[-400:])

    # ---- hostile bytes ---------------------------------------------------------
    with open(path("ctl.cgl"), "wb") as f:
        f.write(b"* a scene with control bytes\n0 0 0 1 1 1 1\n1 ph\x00ng\x1b[31m normal 0 0 0\n")
    r = run(["trace", path("ctl.cgl"), "--no-window", "-q"], tmp)
    check(r.returncode == 1 and "\\x00" in r.out and "\x1b" not in r.out and "ctl.cgl" in r.out,
          "cgl: control bytes of a scene are shown escaped, a NUL does not cut the message", r)

    # Nothing half-written anywhere.
    left = [f for f in os.listdir(tmp) if ".prime-tmp." in f]
    check(not left, f"no temporaries left behind: {left}")

for f in failures:
    print("FAIL:", f)
print(f"check_hostile: {CASES - len(failures)} of {CASES} checks pass")
sys.exit(1 if failures else 0)
