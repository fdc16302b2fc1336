#!/usr/bin/env python3
"""Holes of prime's B-spline surfaces and of POV-Ray's bicubic_patch at equal time (CGL-D171).

Subcommands (used by bench/cgl/spline_holes.sh; plain Python, no packages):

  depth-pov IN.pov OUT.pov DISTANCES.csv [U_STEPS FLATNESS]
      IN.pov (from `prime export-pov --aalevel 0`) with every object's texture replaced by a flat
      grey that encodes the distance from the eye (the camera's location), (|P - eye| - DMIN) /
      (DMAX - DMIN) with DMIN, DMAX 0.8 and 1.25 times the reference's nearest and farthest
      distances in DISTANCES.csv, lit by the
      ambience alone (ambient 1, diffuse 0, ambient_light 1): rendered to a 16-bit PPM, each pixel
      is the distance to what POV-Ray's primary ray hit (0 = nothing). With U_STEPS and FLATNESS,
      every bicubic_patch gets `u_steps U v_steps U` and `flatness F`.
  steps IN.pov OUT.pov U_STEPS FLATNESS
      IN.pov with those subdivision settings and nothing else changed (the timing runs).
  count DISTANCES.csv [DEPTH.ppm]
      The holes against the dense reference (`prime cgl-splines --distances`): a pixel whose
      primary ray the reference hits is a hole of a renderer when the renderer's ray hits nothing
      ("missed") or hits something more than 5 % of the distance farther ("farther": a nearer
      sheet missed, the far side seen through the hole); a hit 1-5 % off is counted apart as
      "depth error" (a coarse approximation of the surface, not a hole). Without DEPTH.ppm: prime's Newton path
      (the CSV's path column); with it: POV-Ray's picture. Prints one line of key=value.
  ab RUNS SCENE.cgl PRIME_A PRIME_B...
      Two or more builds of prime on one scene (CGL-D172, CGL-D173): RUNS interleaved rounds of
      `trace SCENE --threads 1 --no-window -q --aalevel 0` (the order reversed every other round),
      CPU = user + system of the whole process; prints each build's median, its ratio to the
      first build's, and its min-max. Report the load average with it: the machine is shared.
"""
import re
import sys


def read_ppm16(path):
    data = open(path, "rb").read()
    # P6, optional comment lines, width height, maxval, one whitespace byte, then the samples.
    fields = []
    pos = 2
    while len(fields) < 3:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos) + 1
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(int(data[pos:end]))
        pos = end
    pos += 1
    width, height, maxval = fields
    size = 2 if maxval > 255 else 1
    grey = []
    step = 3 * size
    for i in range(width * height):
        at = pos + i * step  # the red sample: the grey's three channels are equal
        v = int.from_bytes(data[at:at + size], "big")
        grey.append(v / maxval)
    return width, height, grey


def depth_pov(src, dst, eye, dmin, dmax, steps=None, flatness=None):
    text = open(src).read()
    tex = ("texture { pigment { function { (sqrt(pow(x-(%r),2)+pow(y-(%r),2)+pow(z-(%r),2)) - %r) / %r }"
           " color_map { [0 rgb 0] [1 rgb 1] } } finish { ambient 1 diffuse 0 } } }"
           % (eye[0], eye[1], eye[2], dmin, dmax - dmin))
    text = re.sub(r"^texture \{.*$", tex, text, flags=re.M)
    text = re.sub(r"ambient_light rgb <[^>]*>", "ambient_light rgb 1", text)
    if steps is not None:
        text = set_steps(text, steps, flatness)
    open(dst, "w").write(text)


def set_steps(text, steps, flatness):
    return re.sub(r"flatness [0-9.eE+-]+ u_steps \d+ v_steps \d+",
                  "flatness %s u_steps %d v_steps %d" % (flatness, steps, steps), text)


def read_rows(csv_path):
    rows = []
    for line in open(csv_path).read().splitlines()[1:]:
        x, y, ref, path = line.split(",")
        rows.append((int(x), int(y), float(ref) if ref else None, float(path) if path else None))
    return rows


def distance_range(rows):
    refs = [r[2] for r in rows if r[2] is not None]
    return 0.8 * min(refs), 1.25 * max(refs)


def count(csv_path, ppm=None):
    rows = read_rows(csv_path)
    dmin, dmax = distance_range(rows)
    if ppm:
        width, height, grey = read_ppm16(ppm)
        ytop = max(r[1] for r in rows)
        xleft = min(r[0] for r in rows)
    reference = missed = farther = depth_error = extra = 0
    for x, y, ref, path in rows:
        if ppm:
            # CGL's pixel (x, y) with y up is POV-Ray's row ytop - y, column x - xleft.
            g = grey[(ytop - y) * width + (x - xleft)]
            got = dmin + g * (dmax - dmin) if g > 0 else None
        else:
            got = path
        if ref is None:
            if got is not None:
                extra += 1
            continue
        reference += 1
        if got is None:
            missed += 1
        elif got > ref * 1.05:
            farther += 1
        elif abs(got - ref) > ref * 0.01:
            depth_error += 1
    holes = missed + farther
    print("reference=%d missed=%d farther=%d holes=%d holes_pct=%.3f depth_error=%d extra=%d"
          % (reference, missed, farther, holes, 100.0 * holes / max(1, reference), depth_error, extra))


def ab(runs, scene, builds):
    import os
    import statistics
    import subprocess

    times = {b: [] for b in builds}
    for r in range(runs):
        for b in builds if r % 2 == 0 else builds[::-1]:
            args = [b, "trace", scene, "--threads", "1", "--no-window", "-q", "--aalevel", "0"]
            p = subprocess.Popen(args, stdout=subprocess.DEVNULL)
            _, status, ru = os.wait4(p.pid, 0)
            if status != 0:
                sys.exit(f"cgl_spline_holes.py ab: {b} failed on {scene}")
            times[b].append(ru.ru_utime + ru.ru_stime)
    base = statistics.median(times[builds[0]])
    for b in builds:
        m = statistics.median(times[b])
        print(f"{b}: {m:.4f} s x{m / base:.3f} ({min(times[b]):.4f}-{max(times[b]):.4f}), {runs} runs")


def main(argv):
    cmd = argv[1]
    if cmd == "depth-pov":
        m = re.search(r"location <([^>]*)>", open(argv[2]).read())
        eye = tuple(float(v) for v in m.group(1).split(","))
        dmin, dmax = distance_range(read_rows(argv[4]))
        steps = int(argv[5]) if len(argv) > 5 else None
        flatness = argv[6] if len(argv) > 6 else None
        depth_pov(argv[2], argv[3], eye, dmin, dmax, steps, flatness)
    elif cmd == "steps":
        open(argv[3], "w").write(set_steps(open(argv[2]).read(), int(argv[4]), argv[5]))
    elif cmd == "count":
        count(argv[2], argv[3] if len(argv) > 3 else None)
    elif cmd == "ab":
        ab(int(argv[2]), argv[3], argv[4:])
    else:
        sys.exit("cgl_spline_holes.py: unknown subcommand " + cmd)


if __name__ == "__main__":
    main(sys.argv)
