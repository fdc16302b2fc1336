#!/usr/bin/env python3
"""Runs the command blocks of the documentation, in order, as a newcomer would.

Every ```sh block of the pages in PAGES is a runnable block, unless the line
before its fence is `<!-- not run -->` (say why after it). Blocks that only show
a session (`$ prime ...` with its output) use a ```console fence and are not
run. The blocks of a page run as one bash script (set -euo pipefail), from the
root of a scratch copy of the repository (the files git tracks), with no
DISPLAY, with `build/release/src/cli/prime` (and its window module) linked to
the executable under test and B pointing at it.

Fails when a command exits non-zero, when the commands leave a new file
anywhere but under out/ and the scene directories (scenes/*/*/, where
`prime model` and `prime trace` write the databases and graph_scr, as the
listing did), or when they change a file git tracks (a clone that runs the
docs must keep a clean `git status`).

usage: run_doc_commands.py PRIME_EXECUTABLE [--repo DIR] [--keep] [--page PAGE ...]
       run_doc_commands.py --check-names [--repo DIR] [--page PAGE ...]

--check-names runs nothing: in README.md and every page under docs/ it
refuses a command block that calls a bare `prime` (not on the path before
`cmake --install`): each ```sh block, and each `$ ` line of a session, calls
the built one as $B, and a page that does says `B=build/release/src/cli/prime`
before its first such block.
"""

import argparse
import hashlib
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

# The pages whose ```sh blocks run (docs/contributing notes in README.md).
PAGES = ["README.md"]

NOT_RUN = "<!-- not run"  # "<!-- not run -->" or "<!-- not run: why -->"


def blocks(text):
    """The runnable ```sh blocks of a page: (line number, code)."""
    out = []
    lines = text.split("\n")
    i = 0
    while i < len(lines):
        if lines[i].strip() == "```sh":
            start = i
            j = i + 1
            while j < len(lines) and lines[j].strip() != "```":
                j += 1
            previous = lines[start - 1].strip() if start > 0 else ""
            if not previous.startswith(NOT_RUN):
                out.append((start + 1, "\n".join(lines[start + 1:j])))
            i = j + 1
        else:
            i += 1
    return out


BUILT = "B=build/release/src/cli/prime"
# `prime VERB` where a command starts: at the line's start, after a shell
# operator, `do`, `$(` or `time [-f "..."]`.
COMMAND_PRIME = re.compile(
    r'(?:^\s*|[;&|(]\s*|\bdo\s+|\btime\s+(?:-f\s+"[^"]*"\s+)?|\$\(\s*)prime\s+(?=[a-z])')


def bare_prime_calls(page, text):
    """'page:line: ...' for each command line of a block that calls a bare prime,
    and for a page that uses $B without saying what it is first."""
    found, inside, fence, said = [], False, "", False
    for n, line in enumerate(text.split("\n"), 1):
        s = line.strip()
        if BUILT in line and not inside:
            said = True
        if s.startswith("```"):
            inside, fence = (not inside), s[3:]
            continue
        if not inside:
            continue
        if BUILT in line:
            said = True
        if fence == "sh":
            code = re.split(r"(?:^|\s)#", line, maxsplit=1)[0]
        elif s.startswith("$ "):
            code = s[2:]
        else:
            continue
        if COMMAND_PRIME.search(code):
            found.append(f"{page}:{n}: calls a bare prime, not on the path before installing "
                         f"(write $B, with {BUILT} said at the top of the page)")
        elif re.search(r"\$B\b", code) and not said:
            found.append(f"{page}:{n}: uses $B before the page says {BUILT}")
    return found


def check_names(repo, pages):
    if not pages:
        pages = ["README.md"] + sorted(
            os.path.relpath(os.path.join(d, f), repo)
            for d, _, names in os.walk(os.path.join(repo, "docs")) for f in names
            if f.endswith(".md"))
    failures = []
    for page in pages:
        with open(os.path.join(repo, page), encoding="utf-8") as fh:
            failures += bare_prime_calls(page, fh.read())
    for f in failures:
        print("FAIL " + f)
    print(f"{len(pages)} pages checked")
    return 1 if failures else 0


def tracked_files(repo):
    try:
        listed = subprocess.run(["git", "-C", repo, "ls-files", "-z"], check=True,
                                capture_output=True).stdout.decode()
        return [f for f in listed.split("\0") if f]
    except (OSError, subprocess.CalledProcessError):
        files = []
        for root, dirs, names in os.walk(repo):
            dirs[:] = [d for d in dirs if d not in (".git", "build", "out")]
            files += [os.path.relpath(os.path.join(root, n), repo) for n in names]
        return files


def snapshot(root):
    seen = set()
    for base, dirs, names in os.walk(root):
        for n in names:
            seen.add(os.path.relpath(os.path.join(base, n), root))
    return seen


def digest(path):
    with open(path, "rb") as fh:
        return hashlib.sha256(fh.read()).hexdigest()


def allowed(path):
    parts = path.split(os.sep)
    if parts[0] == "out":
        return True
    # scenes/<system>/<scene>/...: databases, graph_scr
    return parts[0] == "scenes" and len(parts) >= 4


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("prime", nargs="?")
    ap.add_argument("--check-names", action="store_true",
                    help="check that command blocks call the built prime ($B); run nothing")
    ap.add_argument("--repo", default=os.path.join(os.path.dirname(__file__), "..", ".."))
    ap.add_argument("--keep", action="store_true", help="keep the scratch copy")
    ap.add_argument("--page", action="append",
                    help="run these pages (relative to the repository) instead of PAGES")
    args = ap.parse_args()
    repo = os.path.abspath(args.repo)
    if args.check_names:
        return check_names(repo, args.page)
    if not args.prime:
        ap.error("the prime executable to run the blocks with is missing")
    exe = os.path.abspath(args.prime)

    scratch = tempfile.mkdtemp(prefix="prime-doc-commands-")
    failures = []
    try:
        tracked = {}
        for f in tracked_files(repo):
            src = os.path.join(repo, f)
            if not os.path.isfile(src):
                continue
            dst = os.path.join(scratch, f)
            os.makedirs(os.path.dirname(dst), exist_ok=True)
            shutil.copy2(src, dst)
            tracked[f] = digest(dst)
        bindir = os.path.join(scratch, "build", "release", "src", "cli")
        os.makedirs(bindir)
        for name in os.listdir(os.path.dirname(exe)):
            if name == os.path.basename(exe) or re.match(r"libprime_window.*\.so$", name):
                os.symlink(os.path.join(os.path.dirname(exe), name), os.path.join(bindir, name))
        before = snapshot(scratch)

        env = dict(os.environ)
        for v in ("DISPLAY", "WAYLAND_DISPLAY"):
            env.pop(v, None)
        env["B"] = "build/release/src/cli/prime"
        for page in args.page or PAGES:
            with open(os.path.join(scratch, page), encoding="utf-8") as fh:
                found = blocks(fh.read())
            for line, code in found:
                script = "set -euo pipefail\n" + code + "\n"
                t0 = time.monotonic()
                r = subprocess.run(["bash", "-c", script], cwd=scratch, env=env,
                                   capture_output=True, text=True)
                took = time.monotonic() - t0
                print(f"{page}:{line}: exit {r.returncode} in {took:.1f} s")
                if r.returncode != 0:
                    failures.append(f"{page}:{line}: the block exits {r.returncode}")
                    sys.stdout.write(r.stdout[-4000:])
                    sys.stdout.write(r.stderr[-4000:])
        stray = sorted(p for p in snapshot(scratch) - before if not allowed(p))
        for p in stray:
            failures.append(f"{p}: written outside out/ and the scene directories")
        for f, before_digest in sorted(tracked.items()):
            path = os.path.join(scratch, f)
            if not os.path.isfile(path) or digest(path) != before_digest:
                failures.append(f"{f}: a file git tracks, changed by the commands")
    finally:
        if args.keep:
            print(f"scratch copy kept: {scratch}")
        else:
            shutil.rmtree(scratch, ignore_errors=True)
    for f in failures:
        print("FAIL " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
