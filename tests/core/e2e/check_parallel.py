#!/usr/bin/env python3
"""A walk becomes a film, and a picture is cut into bands, through GNU parallel.

The recipes of docs/cluster.md, run as separate `prime` processes by GNU
parallel (`parallel -j2`), each compared byte for byte with one process:
  (a) films: for every system (PRIME's plate 2, a Malone and a CGL scene), the
      frames of a small orbit, in chunks (tools/cluster/ranges.sh frames), the
      same bytes as one `prime trace --frames` of them all; `prime film` of
      either set of PNGs gives the same GIF;
  (b) bands: for every system, the picture cut into bands of rows
      (tools/cluster/ranges.sh bands) rendered with different --threads each
      (one PRIME picture of many rows), stitched by `prime stitch`, the same
      bytes as one process's render; PNG pieces too; and `prime stitch`
      refuses a gap, an overlap, a piece of another render and a piece whose
      bytes changed after its record, writing nothing;
  (c) resume: a film's parallel run killed (SIGTERM to parallel) once its
      first frames are done, then run again as written: the frames done before
      the kill are not rendered again (same inode and mtime), the others are,
      and the film is the same bytes as one process's;
  (d) the other machines' recipes, the hosts played by a stand-in ssh that
      runs parallel's wrapped command here: --sshlogin 1/host1,1/host2
      --workdir DIR on a shared filesystem, and without one (--basefile the
      scene and path, --return each frame and its record, --cleanup, by
      rsync): the same frames as one process.

Sizes are tiny so that the whole runs in a few seconds in a release build and
under AddressSanitizer within its timeout.

Run: check_parallel.py PRIME_EXE REPO_ROOT
"""
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../support"))
from prime_checks import Checks

PRIME, ROOT = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
RANGES = os.path.join(ROOT, "tools/cluster/ranges.sh")
CHECKS = Checks(PRIME)
run, check = CHECKS.run, CHECKS.check
ENV = dict(os.environ, DISPLAY="", WAYLAND_DISPLAY="")
FRAMES = 4  # frames of each system's film

# system -> scene, --out extension, size of the film's frames, of the banded picture
SYSTEMS = {
    "prime": {"scene": os.path.join(ROOT, "scenes/prime/plate2"), "ext": ".scr",
              "film": (24, 18), "bands": (40, 769), "n": 7},
    "malone": {"scene": os.path.join(ROOT, "scenes/malone/doc-sphere.mal"), "ext": ".ppm",
               "film": (24, 18), "bands": (32, 24), "n": 4},
    "cgl": {"scene": os.path.join(ROOT, "scenes/cgl/ball.cgl"), "ext": ".rle",
            "film": (24, 18), "bands": (32, 24), "n": 3},
}
def sh(args, **kw):
    kw.setdefault("capture_output", True)
    kw.setdefault("text", True)
    return subprocess.run(args, env=ENV, **kw)


def same_dirs(one, many, what, skip=("film.gif",)):
    """Every file one process wrote in ONE (pictures, companions, .render records) is in MANY
    with the same bytes, and MANY holds nothing else."""
    a = sorted(set(os.listdir(one)) - set(skip))
    b = sorted(set(os.listdir(many)) - set(skip))
    if not check(a == b, f"{what}: files {b} where one process wrote {a}"):
        return False
    for n in a:
        if not check(open(os.path.join(one, n), "rb").read() ==
                     open(os.path.join(many, n), "rb").read(),
                     f"{what}: {n} differs from one process's"):
            return False
    return True


def camera_path(scene, path, frames=FRAMES):
    """An orbit of FRAMES frames about the scene (prime path --orbit)."""
    r = run(["path", scene, "--orbit", str(frames), "--out", path])
    return check(r.returncode == 0 and os.path.isfile(path), f"prime path {scene}: {r.stderr}")


def parallel(args, lines, **kw):
    """GNU parallel on local cores, the jobs' arguments on its standard input."""
    return sh(["parallel", "-j2", "--halt", "now,fail=1"] + args, input="".join(lines), **kw)


def ranges(*args):
    r = sh([RANGES] + [str(a) for a in args])
    check(r.returncode == 0, f"ranges.sh {args}: {r.stderr}")
    return r.stdout.splitlines(keepends=True)


def films(tmp, scenes):
    started = time.monotonic()
    for system, s in SYSTEMS.items():
        scene, ext = scenes[system], s["ext"]
        path = os.path.join(tmp, f"{system}.path")
        if not camera_path(scene, path):
            continue
        one, many = os.path.join(tmp, f"{system}-film-one"), os.path.join(tmp, f"{system}-film-par")
        os.mkdir(one)
        os.mkdir(many)
        size = [str(v) for v in s["film"]]
        common = ["--camera-path", path, "--size"] + size + ["-q", "--no-window"]
        r = run(["trace", scene, "--frames", f"0-{FRAMES - 1}", "--out", f"{one}/f%04d{ext}",
                 "--png", f"{one}/f%04d.png", "--threads", "2"] + common)
        if not check(r.returncode == 0, f"(a) {system}: one process's frames: {r.stderr}"):
            continue
        # The recipe: chunks of two frames, one process each, two at a time.
        r = parallel([PRIME, "trace", scene, "--frames", "{}", "--out", f"{many}/f%04d{ext}",
                      "--png", f"{many}/f%04d.png", "--threads", "1"] + common,
                     ranges("frames", 0, FRAMES - 1, 2))
        if not check(r.returncode == 0, f"(a) {system}: parallel: {r.stdout}{r.stderr}"):
            continue
        same_dirs(one, many, f"(a) {system} film")
        gifs = []
        for d in (one, many):
            gif = os.path.join(d, "film.gif")
            pngs = [os.path.join(d, f"f{i:04d}.png") for i in range(FRAMES)]
            r = run(["film", gif] + pngs + ["--fps", "4"])
            check(r.returncode == 0 and os.path.isfile(gif), f"(a) {system}: prime film: {r.stderr}")
            gifs.append(gif)
        if all(os.path.isfile(g) for g in gifs):
            check(open(gifs[0], "rb").read() == open(gifs[1], "rb").read(),
                  f"(a) {system}: the GIF of the parallel frames differs")
    return time.monotonic() - started


# Plate 2 at 4x the listing's linear size (the benchmarks' --screen 4096 3072:
# 1394 x 3073 pixels through the listing's camera), in 8 bands.
PLATE_4X = {"ext": ".scr", "args": ["--screen", "4096", "3072"], "rows": 3073, "n": 8}


def bands(tmp, scenes):
    started = time.monotonic()
    for system, s in list(SYSTEMS.items()) + [("prime 4x", PLATE_4X)]:
        scene, ext, n = scenes[system.split()[0]], s["ext"], s["n"]
        if "args" in s:
            rows, h = s["rows"], s["rows"]
            size = s["args"] + ["-q", "--no-window"]
        else:
            w, h = s["bands"]
            rows = 512 if system == "cgl" else h  # CGL's picture is its 512 x 512 frame buffer
            size = ["--size", str(w), str(h), "-q", "--no-window"]
        d = os.path.join(tmp, f"{system.replace(' ', '-')}-bands")
        os.mkdir(d)
        whole, whole_png = os.path.join(d, "whole" + ext), os.path.join(d, "whole.png")
        r = run(["trace", scene, "--out", whole, "--png", whole_png, "--threads", "2"] + size)
        if not check(r.returncode == 0, f"(b) {system}: one process's render: {r.stderr}"):
            continue
        # The recipe, each band with its own --threads (1, 2, 1, ...): the bytes must not care.
        jobs = [f"{line.strip()} {1 + i % 2}\n" for i, line in enumerate(ranges("bands", rows, n))]
        r = parallel(["--colsep", " ", PRIME, "trace", scene, "--rows", "{2}",
                      "--out", f"{d}/piece-{{1}}{ext}", "--png", f"{d}/piece-{{1}}.png",
                      "--threads", "{3}"] + size, jobs)
        if not check(r.returncode == 0, f"(b) {system}: parallel: {r.stdout}{r.stderr}"):
            continue
        pieces = [os.path.join(d, f"piece-{i}{ext}") for i in range(n)]
        for kind, parts, ref in (("", pieces, whole),
                                 (" (PNG)", [p[:-len(ext)] + ".png" for p in pieces], whole_png)):
            out = os.path.join(d, "stitched" + os.path.splitext(ref)[1])
            r = run(["stitch", out] + parts)
            if check(r.returncode == 0 and os.path.isfile(out),
                     f"(b) {system}{kind}: prime stitch: {r.stderr}"):
                check(open(out, "rb").read() == open(ref, "rb").read(),
                      f"(b) {system}{kind}: {n} bands stitched differ from one process's render")
                if os.path.exists(ref + ".info"):  # a PRIME graph file's companion
                    check(os.path.exists(out + ".info") and
                          open(out + ".info", "rb").read() == open(ref + ".info", "rb").read(),
                          f"(b) {system}{kind}: the stitched graph file's companion differs")
        if system != "malone":
            continue
        # What `prime stitch` refuses, so that a seam cannot pass unseen (Malone: cheapest).
        refused = os.path.join(d, "refused" + ext)
        r = run(["stitch", refused] + pieces[:1] + pieces[2:])
        check(r.returncode != 0 and not os.path.exists(refused),
              f"(b) stitch of bands with a gap (no band 1): exit {r.returncode}, {r.stderr}")
        a, b = os.path.join(d, "over-a" + ext), os.path.join(d, "over-b" + ext)
        half = h // 2
        ra = run(["trace", scene, "--rows", f"0-{half}", "--out", a] + size)
        rb = run(["trace", scene, "--rows", f"{half - 1}-{h - 1}", "--out", b] + size)
        if check(ra.returncode == 0 and rb.returncode == 0, f"(b) overlap pieces: {ra.stderr}{rb.stderr}"):
            r = run(["stitch", refused, a, b])
            check(r.returncode != 0 and not os.path.exists(refused),
                  f"(b) stitch of overlapping bands: exit {r.returncode}, {r.stderr}")
        other = os.path.join(d, "other" + ext)
        first = ranges("bands", rows, n)[1].split()[1]  # band 1's rows, of another render
        r = run(["trace", scene, "--rows", first, "--out", other, "--max-depth", "2"] + size)
        if check(r.returncode == 0, f"(b) a piece of another render: {r.stderr}"):
            r = run(["stitch", refused, pieces[0], other] + pieces[2:])
            check(r.returncode != 0 and not os.path.exists(refused),
                  f"(b) stitch of a piece of another render (--max-depth 2): exit "
                  f"{r.returncode}, {r.stderr}")
        changed = os.path.join(d, "changed" + ext)  # band 1, its bytes changed after the fact
        shutil.copy(pieces[1], changed)
        shutil.copy(pieces[1] + ".render", changed + ".render")
        data = bytearray(open(changed, "rb").read())
        data[len(data) // 2] ^= 0xFF
        open(changed, "wb").write(bytes(data))
        r = run(["stitch", refused, pieces[0], changed] + pieces[2:])
        check(r.returncode != 0 and not os.path.exists(refused),
              f"(b) stitch of a piece changed after its record: exit {r.returncode}, {r.stderr}")
    return time.monotonic() - started


def resume(tmp, scenes):
    """(c): kill GNU parallel once frames are done, rerun the same command."""
    started = time.monotonic()
    scene, ext, n = scenes["prime"], ".scr", 8
    path = os.path.join(tmp, "resume.path")
    if not camera_path(scene, path, n):
        return time.monotonic() - started
    one, d = os.path.join(tmp, "resume-one"), os.path.join(tmp, "resume")
    os.mkdir(one)
    os.mkdir(d)
    common = ["--camera-path", path, "--size", "480", "360", "--threads", "1", "--no-window"]
    r = run(["trace", scene, "--frames", f"0-{n - 1}", "--out", f"{one}/f%04d{ext}",
             "--png", f"{one}/f%04d.png", "-q"] + common)
    if not check(r.returncode == 0, f"(c) one process's frames: {r.stderr}"):
        return time.monotonic() - started
    command = ["parallel", "-j2", PRIME, "trace", scene, "--frames", "{}",
               "--out", f"{d}/f%04d{ext}", "--png", f"{d}/f%04d.png"] + common
    jobs = "".join(ranges("frames", 0, n - 1, 4))  # two jobs of four frames
    p = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True, env=ENV)
    p.stdin.write(jobs)
    p.stdin.close()
    end = time.monotonic() + 120
    def frame_done():  # a frame is done when each of its outputs has its record (written last)
        names = set(os.listdir(d))
        return any(f"f{i:04d}{ext}.render" in names and f"f{i:04d}.png.render" in names
                   for i in range(n))
    while not frame_done() and p.poll() is None and time.monotonic() < end:
        time.sleep(0.02)
    p.send_signal(signal.SIGTERM)
    first_out = p.stdout.read()
    p.wait()
    done = {}
    for i in range(n):
        files = [f"f{i:04d}{ext}", f"f{i:04d}.png"]
        if all(os.path.exists(os.path.join(d, f + ".render")) for f in files):
            done[i] = {f: os.stat(os.path.join(d, f)) for f in files}
    if not check(0 < len(done) < n, f"(c) the kill came after {len(done)} of {n} frames "
                 f"(parallel exit {p.returncode}): the test needs some frames done and some "
                 f"not\n{first_out}"):
        return time.monotonic() - started
    r = sh(command, input=jobs)
    check(r.returncode == 0, f"(c) the rerun: exit {r.returncode}: {r.stdout}{r.stderr}")
    for i, files in sorted(done.items()):
        for f, st in files.items():
            now = os.stat(os.path.join(d, f))
            check((now.st_ino, now.st_mtime_ns) == (st.st_ino, st.st_mtime_ns),
                  f"(c) {f}, done before the kill, was written again by the rerun")
    # Each process's summary: "frames A-B of PATH: R rendered, S done already (skipped)".
    counts = [re.search(r"(\d+) rendered, (\d+) done already", line)
              for line in r.stdout.splitlines()]
    rendered = sum(int(m.group(1)) for m in counts if m)
    skipped = sum(int(m.group(2)) for m in counts if m)
    check((rendered, skipped) == (n - len(done), len(done)),
          f"(c) the rerun rendered {rendered} and skipped {skipped} frames; {len(done)} of {n} "
          f"were done: {r.stdout}")
    # Everything one process writes, nothing else (no temporary file the kill left).
    same_dirs(one, d, "(c) the resumed film")
    print(f"check_parallel: (c) killed with {len(done)} of {n} frames done (parallel exit "
          f"{p.returncode}); the rerun rendered {rendered}, skipped {skipped}")
    return time.monotonic() - started


# ssh as GNU parallel calls it (`ssh [OPTIONS] HOST -- COMMAND`), running COMMAND here:
# the remote recipe's command line, through parallel's wrapping for another host.
FAKE_SSH = """#!/bin/sh
while [ $# -gt 0 ]; do case "$1" in -*) shift ;; *) break ;; esac; done
echo "$1" >> "$0.hosts"
# Each host its own home (a login's directory): what one host removes
# (--cleanup of the basefiles) is not another's.
home="$0-home-$1"
mkdir -p "$home" && cd "$home" && export HOME="$home"
# A login sets SHELL to the user's shell; parallel's remote wrapper runs the job
# with $SHELL, and without one ran nothing and still exited 0 (seen in CI, whose
# environment has no SHELL).
export SHELL=/bin/sh
shift
[ "${1:-}" = -- ] && shift
exec sh -c "$*"
"""


def remote(tmp, scenes):
    """(d) the --sshlogin --workdir recipe (a shared filesystem), hosts played by a stand-in ssh."""
    started = time.monotonic()
    ssh = os.path.join(tmp, "ssh")
    with open(ssh, "w") as f:
        f.write(FAKE_SSH)
    os.chmod(ssh, 0o755)
    s, one = SYSTEMS["malone"], os.path.join(tmp, "malone-film-one")
    d = os.path.join(tmp, "remote")
    os.mkdir(d)
    size = [str(v) for v in s["film"]]
    r = parallel(["--ssh", ssh, "--sshlogin", "1/host1,1/host2", "--workdir", d,
                  PRIME, "trace", scenes["malone"], "--camera-path",
                  os.path.join(tmp, "malone.path"), "--frames", "{}", "--size"] + size +
                 ["--threads", "1", "-q", "--no-window", "--out", "f%04d.ppm",
                  "--png", "f%04d.png"], ranges("frames", 0, FRAMES - 1, 1))
    if check(r.returncode == 0, f"(d) parallel --sshlogin: {r.stdout}{r.stderr}"):
        same_dirs(one, d, "(d) frames through --sshlogin")
        hosts = set(open(ssh + ".hosts").read().split()) if os.path.exists(ssh + ".hosts") else set()
        check(hosts == {"host1", "host2"}, f"(d) jobs went to {hosts}, not host1 and host2")
    # Without a shared filesystem: the scene and the path sent (--basefile, by rsync over
    # ssh) to a work directory on each host, one frame a job, its picture and record
    # brought back (--return) and removed there (--cleanup).
    if not check(shutil.which("rsync") is not None,
                 "(d) rsync is not installed (GNU parallel's transfers; prime.sh installs it)"):
        return time.monotonic() - started
    d = os.path.join(tmp, "transfer")
    os.mkdir(d)
    shutil.copy(scenes["malone"], d)
    shutil.copy(os.path.join(tmp, "malone.path"), d)
    # A work directory in each host's home: two hosts share no files (with one
    # shared directory, the first host's --cleanup removed the basefiles from
    # under the other's jobs).
    work = "prime-work"
    r = parallel(["--ssh", ssh, "--sshlogin", "1/host1,1/host2", "--workdir", work,
                  "--basefile", os.path.basename(scenes["malone"]), "--basefile", "malone.path",
                  "--return", 'f{=$_=sprintf("%04d",$_)=}.ppm',
                  "--return", 'f{=$_=sprintf("%04d",$_)=}.ppm.render', "--cleanup",
                  PRIME, "trace", os.path.basename(scenes["malone"]), "--camera-path",
                  "malone.path", "--frames", "{}", "--size"] + size +
                 ["--threads", "1", "-q", "--no-window", "--out", "f%04d.ppm"],
                 [f"{i}\n" for i in range(FRAMES)], cwd=d)
    if check(r.returncode == 0, f"(d) parallel --basefile --return: {r.stdout}{r.stderr}"):
        for i in range(FRAMES):
            for f in (f"f{i:04d}.ppm", f"f{i:04d}.ppm.render"):
                a, b = os.path.join(one, f), os.path.join(d, f)
                check(os.path.isfile(b) and open(a, "rb").read() == open(b, "rb").read(),
                      f"(d) {f} returned by --return differs from one process's (or is missing)")
        for host in ("host1", "host2"):
            w = os.path.join(f"{ssh}-home-{host}", work)
            left = os.listdir(w) if os.path.isdir(w) else []
            check(not left, f"(d) --cleanup left {left} in {host}'s work directory")
    return time.monotonic() - started


def main():
    if shutil.which("parallel") is None:
        print("FAIL: GNU parallel is not installed (Debian: apt-get install parallel; "
              "prime.sh's PACKAGES has it)")
        return 1
    with tempfile.TemporaryDirectory() as tmp:
        scenes = {k: v["scene"] for k, v in SYSTEMS.items()}
        scratch = os.path.join(tmp, "plate2")
        shutil.copytree(scenes["prime"], scratch)
        scenes["prime"] = scratch
        r = run(["model", scratch])
        if not check(r.returncode == 0, f"model plate 2: {r.stderr}"):
            return CHECKS.report("film and bands through GNU parallel")
        ta = films(tmp, scenes)
        tb = bands(tmp, scenes)
        tc = resume(tmp, scenes)
        td = remote(tmp, scenes)
        print(f"check_parallel: (a) films {ta:.1f} s, (b) bands {tb:.1f} s, (c) resume "
              f"{tc:.1f} s, (d) --sshlogin {td:.1f} s")
    return CHECKS.report("film and bands through GNU parallel")


if __name__ == "__main__":
    sys.exit(main())
