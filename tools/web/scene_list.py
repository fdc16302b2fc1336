#!/usr/bin/env python3
"""scene_list.py SCENES OUT: copies the shipped scenes the page offers into OUT
and writes OUT/scenes.json, the page's list of them (docs/web.md):
{"prime": [{"name", "target", "files"}], "malone": [...], "cgl": [...]}, the
files relative to OUT/<system>/ and the target the path `prime trace` is given.
Only the scenes' own inputs are copied: not what `prime model` and `prime
trace` write into a PRIME scene (the names .gitignore leaves out)."""
import json
import re
import shutil
import sys
from pathlib import Path

GENERATED = re.compile(r"^(PrimFile|List|O[0-9]+|Map.*_[RGB]\.map|graph_scr.*|prime-model\..*|.*\.png)$")


def main():
    source, out = Path(sys.argv[1]), Path(sys.argv[2])
    listing = {"prime": [], "malone": [], "cgl": []}
    for scene in sorted((source / "prime").iterdir()):
        # plate1 is a wireframe (`prime plate1`), not a scene to trace.
        if not scene.is_dir() or not (scene / "prim").is_dir():
            continue
        files = [p.relative_to(source / "prime").as_posix() for p in sorted(scene.rglob("*"))
                 if p.is_file() and not GENERATED.match(p.name)]
        listing["prime"].append({"name": scene.name, "target": scene.name, "files": files})
    for system, suffix in (("malone", ".mal"), ("cgl", ".cgl")):
        # What a scene may read beside it: textures, reflectance tables.
        extra = [p.relative_to(source / system).as_posix()
                 for p in sorted((source / system).rglob("*"))
                 if p.is_file() and p.suffix not in (suffix, ".md")]
        for scene in sorted((source / system).glob("*" + suffix)):
            listing[system].append({"name": scene.name, "target": scene.name,
                                    "files": [scene.name] + extra})
    for system, scenes in listing.items():
        for s in scenes:
            for f in s["files"]:
                target = out / system / f
                target.parent.mkdir(parents=True, exist_ok=True)
                shutil.copyfile(source / system / f, target)
    (out / "scenes.json").write_text(json.dumps(listing, indent=1) + "\n")


if __name__ == "__main__":
    main()
