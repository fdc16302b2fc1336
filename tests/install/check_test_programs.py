#!/usr/bin/env python3
"""Every external program the tests run must come from a package prime.sh installs.

A fresh Debian machine has only what `./prime.sh test` installs (its PACKAGES
and WEB_PACKAGES arrays). This test finds the programs the tests and the scripts they call
invoke, by the ways this repository starts them:

  C++ tests     ChildProcess({"PROG", ...}), run({"PROG", ...}), onPath("PROG"),
                std::system("command -v PROG ...")
  Python        subprocess.*(["PROG", ...]), shutil.which("PROG")
  shell/CMake   command -v PROG

and fails when a program is found that PROGRAMS below does not name, or when
a named program's package is not in prime.sh's PACKAGES (nor in the base
system every Debian machine has). Where dpkg knows the program's path, it
also checks that the package named really ships it.

Run: check_test_programs.py REPO_ROOT
"""
import os
import re
import shutil
import subprocess
import sys

# program -> (Debian packages that ship it: prime.sh must install one; why).
PROGRAMS = {
    "Xvfb": (["xvfb"], "window tests: the X server"),
    "xdotool": (["xdotool"], "window tests: key presses and window ids"),
    "xwd": (["x11-apps"], "window tests: what the server shows"),
    "xwininfo": (["x11-utils"], "window tests: the window's size"),
    "readelf": (["binutils"], "the window module is not linked into prime"),
    "groff": (["groff-base"], "the man page's check"),
    "help2man": (["help2man"], "the man page"),
    "python3": (["python3", "python3-minimal"], "the docs, tools and hand-check tests"),
    "cmake": (["cmake"], "the layout tests"),
    "parallel": (["parallel"], "GNU parallel: docs/cluster.md's recipes on local cores"),
    "rsync": (["rsync"], "GNU parallel's --basefile/--return transfers (check_parallel)"),
    "munged": (["munge"], "the single-host Slurm's authentication (slurm_host.py)"),
    "slurmctld": (["slurmctld"], "the single-host Slurm's controller (slurm_host.py)"),
    "slurmd": (["slurmd"], "the single-host Slurm's node daemon (slurm_host.py)"),
    "sbatch": (["slurm-client"], "submitting docs/cluster.md's job arrays (submit.sh)"),
    "sinfo": (["slurm-client"], "the single-host Slurm's node state (slurm_host.py)"),
    "scontrol": (["slurm-client"], "the single-host Slurm's job states (slurm_host.py)"),
    "squeue": (["slurm-client"], "the single-host Slurm's queue, emptied at its teardown"),
    "scancel": (["slurm-client"], "the single-host Slurm's teardown: no job outlives it"),
    # The web build and its tests (prime.sh's WEB_PACKAGES; docs/web.md).
    "em++": (["emscripten"], "the web build: prime compiled to WebAssembly (tools/web/build.sh)"),
    "dpkg-source": (["dpkg-dev"], "the web build: Debian's sources of prime's libraries"),
    "node": (["nodejs"], "the web build's node tests: prime.js under node (tests/web)"),
    "chromium": (["chromium"], "the page's test in a real browser (tests/web)"),
}
# In every Debian root (Essential: yes) or brought by the clone itself.
BASE = {
    "bash": "Essential",
    "sh": "Essential",
    "git": "the repository is a git clone (README: 'from a clone of this repository')",
}
# Run only when present, and the test says it skipped: not installed here on
# purpose (a comparison against another ray tracer, not part of the suite).
OPTIONAL = {"povray": "POV-Ray renders of exported scenes (skipped when absent)"}

PATTERNS = [
    re.compile(r'ChildProcess(?:\s+\w+)?\(\{"([^"]+)"'),
    re.compile(r'\brun\(\{"([^"]+)"'),
    re.compile(r'onPath\("([^"]+)"\)'),
    re.compile(r'command -v ([A-Za-z0-9_.+-]+)'),
    re.compile(r'subprocess\.[a-z_]+\(\s*\["([^"]+)"'),
    re.compile(r'shutil\.which\("([^"]+)"\)'),
]
SOURCES = (".cpp", ".h", ".py", ".sh", ".cmake", ".txt")


def packages_of_prime_sh(root):
    text = open(os.path.join(root, "prime.sh"), encoding="utf-8").read()
    # The array's words, comments stripped line by line, to its closing ')'.
    code = "\n".join(line.split("#", 1)[0] for line in text.splitlines())
    # PACKAGES and WEB_PACKAGES (the web build's, which ./prime.sh test installs too).
    arrays = re.findall(r"\b(?:WEB_)?PACKAGES=\(([^)]*)\)", code)
    if not arrays:
        sys.exit("prime.sh has no PACKAGES=( ... ) array")
    return set(" ".join(arrays).split())


def invoked(root):
    found = {}
    for top in ("tests", "tools"):
        for d, _, files in os.walk(os.path.join(root, top)):
            for f in files:
                if not f.endswith(SOURCES) or f == os.path.basename(__file__):
                    continue
                path = os.path.join(d, f)
                text = open(path, encoding="utf-8", errors="replace").read()
                for p in PATTERNS:
                    for name in p.findall(text):
                        found.setdefault(name, os.path.relpath(path, root))
    return found


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else "."
    have = packages_of_prime_sh(root)
    failures = []
    found = invoked(root)
    # Words the patterns catch that are prime's own commands, not programs
    # (run({"model", ...}) runs `prime model`).
    own = {"model"}
    for name, where in sorted(found.items()):
        if name in own or name in BASE or name in OPTIONAL or name in PROGRAMS:
            continue
        failures.append(f"{where} runs '{name}', which PROGRAMS in {__file__} does not name: "
                        "add it with its Debian package, and the package to prime.sh")
    for name, (pkgs, why) in sorted(PROGRAMS.items()):
        if not any(p in have for p in pkgs):
            failures.append(f"'{name}' ({why}) comes from {' or '.join(pkgs)}, "
                            "which prime.sh's PACKAGES does not install")
        # The package named must really ship the program (where dpkg knows).
        if shutil.which("dpkg-query"):
            shipped = False
            for p in pkgs:
                r = subprocess.run(["dpkg-query", "-L", p], capture_output=True, text=True)
                if r.returncode == 0 and re.search(rf"/s?bin/{re.escape(name)}$", r.stdout, re.M):
                    shipped = True
                # An update-alternatives link (/usr/sbin/slurmd -> slurmd-wlm): the file
                # it resolves to is the package's.
                where = shutil.which(name, path=os.environ.get("PATH", "") + ":/usr/sbin:/sbin")
                if r.returncode == 0 and where and os.path.realpath(where) in r.stdout.split("\n"):
                    shipped = True
            installed = subprocess.run(["dpkg-query", "-W", "-f=${Status}", pkgs[0]],
                                       capture_output=True, text=True).stdout
            if "install ok installed" in installed and not shipped:
                failures.append(f"'{name}': none of {pkgs} ships a bin/{name}")
    for name in sorted(set(found) & set(PROGRAMS)):
        print(f"ok: {name} ({found[name]}) from {'/'.join(PROGRAMS[name][0])}")
    unused = sorted(set(PROGRAMS) - set(found) - {"python3", "cmake", "help2man", "groff"})
    for name in unused:
        failures.append(f"PROGRAMS names '{name}', which no test runs any more: drop it")
    for f in failures:
        print("FAIL: " + f)
    print(f"{len(PROGRAMS) - len(unused)} programs checked, {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
