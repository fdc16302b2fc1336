#!/usr/bin/env python3
"""Old disks as they are: every shipped PRIME scene as a DOS copy.

For each scene of scenes/prime (with a Model.txt), against a canonical copy
modelled and traced once (512 x 384 screen):
  - a DOS copy: every name upper case (PRIM/, OBJ/COPY/, MAP/, MODEL.TXT,
    MAP1.TXT ...), every text file CR LF with a ^Z at its end, and the
    databases of the canonical run under upper-case names (PRIM/PRIMFILE,
    OBJ/O1, OBJ/LIST, MAP/MAP1_R.MAP): `prime model` twice, then `trace`
    twice: the same graph file byte for byte; the databases are written over
    the upper-case ones (no lower-case prim/, obj/ or map/ appears, no new
    file beside the old ones);
  - a fresh DOS copy of the text inputs only: `trace --model` on its first
    run gives the same graph file;
  - a copy with a 1991 Model.c (the listing's main(), its housekeeping and
    the scene's calls) instead of Model.txt: modelled and traced, the same
    graph file;
  - `prime dump` of the DOS copy's databases by their upper-case names (and
    in the wrong case), and `view`/`export` of a PNG: said to be a PNG.

Run: check_dos_copies.py PRIME_EXE REPO_ROOT
"""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../support"))
from prime_checks import Checks

PRIME, ROOT = sys.argv[1], sys.argv[2]
CHECKS = Checks(PRIME)
run, check = CHECKS.run, CHECKS.check
SCREEN = ["--screen", "512", "384", "--no-window", "-q"]
DATABASES = ("PrimFile", "List")


def is_database(name):
    return name in DATABASES or name.endswith(".map") or (name[0] == "O" and name[1:].isdigit())


def dos_copy(src, dst, with_databases):
    """Upper-case names, CR LF and ^Z text: a scene as a DOS floppy held it."""
    for root, _dirs, files in os.walk(src):
        rel = os.path.relpath(root, src)
        out = dst if rel == "." else os.path.join(dst, *[p.upper() for p in rel.split(os.sep)])
        os.makedirs(out, exist_ok=True)
        for f in files:
            data = open(os.path.join(root, f), "rb").read()
            if f.endswith(".txt"):
                data = data.replace(b"\r\n", b"\n").replace(b"\n", b"\r\n") + b"\x1a"
            elif not (with_databases and is_database(f)):
                continue  # README.md, graph files, stamps: not on the disk
            open(os.path.join(out, f.upper()), "wb").write(data)


def model_c(model_txt):
    """The listing's Model.c with the calls of a Model.txt."""
    calls = []
    for line in open(model_txt).read().splitlines():
        words = line.split("#")[0].split()
        if not words:
            continue
        name, args = words[0], words[1:]
        shown = [a if name == "AddToObjList" else '"' + a + '"' for a in args]
        calls.append(f"  {name}({', '.join(shown)});")
    return ("/* Module: Model */\n#include <stdio.h>\n"
            "extern void InitFiles(void), OpenFiles(void), CloseFiles(void),\n"
            "  AddObj(char *fileName), AddToObjList(int num),\n"
            "  CopyObj(char *srcObj, char *destObj, char *copyFile), AddMap(char *mapFile),\n"
            "  FreeAll(void), Error(char *msg), Message(char *msg);\n"
            "extern int MemoryEmpty(void);\n\nvoid main(void);\n\nvoid main(void)\n{\n"
            '  Message("Initialising Files");\n  InitFiles();\n  OpenFiles();\n'
            + "\n".join(calls) +
            '\n  CloseFiles();\n  if (!MemoryEmpty())\n  {\n    FreeAll();\n'
            '    Error("main(): Number of Mallocs != Number of Frees");\n  }\n}\n')


def graph(scene, out, *extra):
    r = run(["trace", scene, "--out", out, *SCREEN, *extra])
    if not check(r.returncode == 0, f"trace {scene} {' '.join(extra)}: {r.stderr.strip()}"):
        return None
    return open(out, "rb").read()


def names(d):
    return sorted(os.path.relpath(os.path.join(r, f), d) for r, ds, fs in os.walk(d)
                  for f in fs + ds)


scenes_dir = os.path.join(ROOT, "scenes", "prime")
scenes = sorted(s for s in os.listdir(scenes_dir)
                if os.path.isfile(os.path.join(scenes_dir, s, "Model.txt")))
check(len(scenes) >= 10, f"the shipped scenes: {scenes}")
with tempfile.TemporaryDirectory() as tmp:
    for name in scenes:
        work = os.path.join(tmp, name)
        os.makedirs(work)
        canon = os.path.join(work, "canon")
        shutil.copytree(os.path.join(scenes_dir, name), canon)
        if not check(run(["model", canon, "-q"]).returncode == 0, f"{name}: model"):
            continue
        want = graph(canon, os.path.join(work, "canon.graph"))
        if want is None:
            continue
        # A DOS copy with its databases: modelled twice, traced twice.
        dos = os.path.join(work, "DOS")
        dos_copy(canon, dos, True)
        before = names(dos)
        for k in (1, 2):
            r = run(["model", dos, "-q"])
            check(r.returncode == 0, f"{name}: model of the DOS copy ({k}): {r.stderr.strip()}")
        after = [n for n in names(dos) if not n.startswith("prime-model.")]
        check(after == before, f"{name}: the DOS copy's databases were written in place: "
              f"new {sorted(set(after) - set(before))}")
        for k in (1, 2):
            got = graph(dos, os.path.join(work, f"dos{k}.graph"))
            check(got == want, f"{name}: the DOS copy's trace {k} is the canonical picture")
        # A fresh DOS copy of the text only: trace --model, first run.
        fresh = os.path.join(work, "FRESH")
        dos_copy(os.path.join(scenes_dir, name), fresh, False)
        got = graph(fresh, os.path.join(work, "fresh.graph"), "--model")
        check(got == want, f"{name}: trace --model of a fresh DOS copy is the canonical picture")
        # A 1991 disk: Model.c, no Model.txt.
        disk = os.path.join(work, "disk")
        shutil.copytree(os.path.join(scenes_dir, name), disk)
        open(os.path.join(disk, "Model.c"), "w").write(model_c(os.path.join(disk, "Model.txt")))
        os.remove(os.path.join(disk, "Model.txt"))
        r = run(["model", disk, "-q"])
        if check(r.returncode == 0, f"{name}: model from Model.c: {r.stderr.strip()}"):
            check(graph(disk, os.path.join(work, "disk.graph")) == want,
                  f"{name}: the Model.c copy's picture is the canonical one")
        if name == "default":
            # prime dump takes the names as the disk has them, in any case.
            for typed in ("DOS/PRIM/PRIMFILE", "dos/prim/primfile", "DOS/OBJ/O1", "DOS/OBJ/LIST",
                          "DOS/MAP/MAP1_R.MAP"):
                r = run(["dump", os.path.join(work, typed)])
                check(r.returncode == 0 and r.stdout.strip(), f"dump {typed}: {r.stderr.strip()}")
            # GRAPH_SC: graph_scr as DOS's eight characters keep it.
            shutil.copyfile(os.path.join(work, "canon.graph"),
                            os.path.join(work, "DOS", "GRAPH_SC"))
            r = run(["dump", os.path.join(work, "DOS", "GRAPH_SC")])
            check(r.returncode == 0 and "graph file, graphType" in r.stdout,
                  f"dump GRAPH_SC: {r.stderr.strip()}")
            r = run(["dump", os.path.join(work, "DOS/OBJ/O99")])
            check(r.returncode == 2 and "does not exist" in r.stderr, f"dump O99: {r.stderr}")
        shutil.rmtree(work)
    # A PNG given to view or export: said to be one, not "truncated".
    png = os.path.join(ROOT, "docs", "prime", "images", "click-glass-fix-k5.png")
    for verb in (["view", png, "--no-window"], ["export", png, os.path.join(tmp, "x.png")]):
        r = run(verb)
        check(r.returncode != 0 and "found a PNG picture" in r.stderr and
              "truncated" not in r.stderr and not os.path.exists(os.path.join(tmp, "x.png")),
              f"{verb[0]} of a PNG: {r.stderr.strip()}")

sys.exit(CHECKS.report("DOS copies and Model.c"))
