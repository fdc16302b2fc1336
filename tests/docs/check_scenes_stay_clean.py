#!/usr/bin/env python3
"""Rendering a shipped scene leaves `git status` as it was.

`prime model` and `prime trace` write into the scene's own directory, as the
listing did (the databases, graph_scr and its .info; plate1 its graph_scr;
compare its compare.png). None of those files may be tracked (a render would
rewrite it) and each must be ignored (.gitignore), or a clone that renders
its scenes shows changes it never made.

The scenes under scenes/prime/ that git tracks, with the repository's
.gitignore, are copied to a scratch git repository and added to its index;
every scene is modelled and traced (plate1 drawn by `prime plate1`), and
`compare` runs on one; then `git status --porcelain` must print nothing.

usage: check_scenes_stay_clean.py PRIME REPO
"""
import os
import shutil
import subprocess
import sys
import tempfile


def git(cwd, *args):
    return subprocess.run(["git", "-C", cwd, *args], check=True, capture_output=True,
                          text=True).stdout


def main():
    prime, repo = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    scratch = tempfile.mkdtemp(prefix="prime-scenes-clean-")
    failures = []
    try:
        tracked = [f for f in git(repo, "ls-files", "-z", "--", "scenes/prime", ".gitignore")
                   .split("\0") if f]
        copied = []
        for f in tracked:
            src = os.path.join(repo, f)
            if not os.path.isfile(src):
                continue
            copied.append(f)
            dst = os.path.join(scratch, f)
            os.makedirs(os.path.dirname(dst), exist_ok=True)
            shutil.copy2(src, dst)
        git(scratch, "init", "-q")
        # -f: a tracked file the .gitignore names (the fault this test finds) too.
        subprocess.run(["git", "-C", scratch, "add", "-f", "--pathspec-from-file=-",
                        "--pathspec-file-nul"], input="\0".join(copied), check=True, text=True)
        scenes = sorted(d for d in os.listdir(os.path.join(scratch, "scenes", "prime"))
                        if os.path.isdir(os.path.join(scratch, "scenes", "prime", d)))
        runs = []
        for s in scenes:
            d = f"scenes/prime/{s}"
            if os.path.exists(os.path.join(scratch, d, "knots.txt")):
                runs.append(["plate1", d])
            else:
                runs.append(["trace", d, "--model", "--no-window", "-q"])
        runs.append(["compare", "scenes/prime/default"])
        for args in runs:
            r = subprocess.run([prime, *args], cwd=scratch, env=env, capture_output=True,
                               text=True)
            if r.returncode != 0:
                failures.append(f"prime {' '.join(args)} exits {r.returncode}: {r.stderr[-2000:]}")
        # Against the index: a column Y other than ' ' is a change in the tree.
        status = git(scratch, "status", "--porcelain", "--untracked-files=all")
        for line in status.splitlines():
            if line.startswith("??"):
                failures.append(f"{line[3:]}: written by a render and not ignored (.gitignore)")
            elif line[1] != " ":
                failures.append(f"{line[3:]}: tracked, and a render changed it ({line[1]})")
        print(f"{len(runs)} runs over {len(scenes)} scenes of scenes/prime")
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    for f in failures:
        print("FAIL " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
