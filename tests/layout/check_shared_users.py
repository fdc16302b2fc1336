#!/usr/bin/env python3
"""Shared means used by two: every header of the shared core is used by at
least two systems (directly, or through a shared unit they use), or is listed
in tests/layout/shared_single_user.txt with the reason it stays shared.

The shared core is every source under src/, legacy_io/ and palette/ whose path
names no system; a system is prime, malone or cgl, and owns the files whose
path names it (src/cgl/, legacy_io/cgl/, src/cli/cgl/, ...). The shared verbs
(src/cli/*.cpp) serve every system.

Run: check_shared_users.py REPO_ROOT
"""
import collections
import os
import re
import sys

root = sys.argv[1] if len(sys.argv) > 1 else "."
SYSTEMS = ["prime", "malone", "cgl"]


def owner(path):
    parts = path.split("/")
    for s in SYSTEMS:
        if s in parts[:-1]:
            return s
    return "shared"


files = []
for top in ("src", "legacy_io", "palette"):
    for d, _, names in os.walk(os.path.join(root, top)):
        files += [os.path.relpath(os.path.join(d, n), root) for n in names
                  if n.endswith((".h", ".cpp"))]
includers = collections.defaultdict(set)
for f in files:
    for m in re.finditer(r'#include "([^"]+)"', open(os.path.join(root, f)).read()):
        includers[m.group(1)].add(f)


def users(header, seen):
    if header in seen:
        return set()
    seen.add(header)
    out = set()
    for f in includers.get(header, ()):
        o = owner(f)
        if o != "shared":
            out.add(o)
        elif f.startswith("src/cli/") and f.count("/") == 2:
            out |= set(SYSTEMS)  # the shared verbs serve every system
        else:
            out |= users(f.rsplit(".", 1)[0] + ".h", seen)
    return out


allowed = {}
for line in open(os.path.join(root, "tests/layout/shared_single_user.txt")):
    if line.strip() and not line.startswith("#"):
        path, why = (s.strip() for s in line.split("|", 1))
        allowed[path] = why

failures = []
count = 0
for f in sorted(files):
    if owner(f) != "shared" or not f.endswith(".h") or f.startswith("src/cli/"):
        continue
    count += 1
    u = sorted(users(f, set()))
    if len(u) >= 2 and f in allowed:
        failures.append(f"{f} is used by {', '.join(u)}: remove it from shared_single_user.txt")
    elif len(u) < 2 and f not in allowed:
        failures.append(f"{f} is shared but used by {', '.join(u) or 'no system'} alone: move it "
                        "into that system, or list it in tests/layout/shared_single_user.txt "
                        "with why it stays shared")
for path in allowed:
    if path not in files:
        failures.append(f"shared_single_user.txt lists {path}, which does not exist")
for f in failures:
    print("FAIL: " + f)
print(f"{count} shared headers, {len(allowed)} listed with one user, {len(failures)} failed")
sys.exit(1 if failures else 0)
