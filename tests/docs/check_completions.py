#!/usr/bin/env python3
"""The generated completions (tools/gen_cli_docs.py) against the CLI itself.

Every command `prime --help` lists and every option its `prime help CMD`
lists must be completed by the bash, zsh and fish scripts; a few known ones
are named here too, so that a generator that parses nothing fails; the bash
script must parse (bash -n), and offer `trace`'s options when asked.

usage: check_completions.py PRIME CLI_DOCS_DIR
"""
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
GEN = os.path.join(HERE, "..", "..", "tools", "gen_cli_docs.py")
# Known by hand (README.md): commands, and options of trace.
KNOWN = {"model", "trace", "probe", "dump", "view", "export", "diff", "check", "new", "plate1"}
KNOWN_TRACE = {"--png", "--threads", "--model", "--profile", "--palette"}


def main():
    prime, docs = sys.argv[1], sys.argv[2]
    if not os.path.exists(os.path.join(docs, "prime.bash")):
        subprocess.run([sys.executable, GEN, prime, docs], check=True)
    listed = subprocess.run([sys.executable, GEN, prime, "--list"], check=True,
                            capture_output=True, text=True).stdout.splitlines()
    table = {line.split()[0]: line.split()[1:] for line in listed}
    failures = []
    for k in sorted(KNOWN - table.keys()):
        failures.append(f"the CLI's command list lacks {k}")
    for k in sorted(KNOWN_TRACE - set(table.get("trace", []))):
        failures.append(f"trace's option list lacks {k}")
    scripts = {n: open(os.path.join(docs, n)).read() for n in ("prime.bash", "_prime", "prime.fish")}
    for cmd, opts in table.items():
        for name, text in scripts.items():
            if cmd not in text:
                failures.append(f"{name} does not complete the command {cmd}")
        for o in opts:
            if o not in scripts["prime.bash"]:
                failures.append(f"prime.bash does not complete {cmd} {o}")
            if o not in scripts["_prime"]:
                failures.append(f"_prime does not complete {cmd} {o}")
            fish = f"-l {o[2:]}" if o.startswith("--") else f"-s {o[1:]}"
            if f"__fish_seen_subcommand_from {cmd}' {fish}" not in scripts["prime.fish"]:
                failures.append(f"prime.fish does not complete {cmd} {o}")
    # bash: the script parses and completes `prime trace --pn` to --png.
    probe = (f"source {os.path.join(docs, 'prime.bash')}; COMP_WORDS=(prime trace --pn); "
             "COMP_CWORD=2; _prime; printf '%s\\n' \"${COMPREPLY[@]}\"")
    r = subprocess.run(["bash", "-c", probe], capture_output=True, text=True)
    if r.returncode != 0 or r.stdout.split() != ["--png"] and "--png" not in r.stdout.split():
        failures.append(f"bash completion of 'prime trace --pn': {r.stdout!r} {r.stderr!r}")
    for f in failures:
        print("FAIL " + f)
    print(f"{len(table)} commands, {sum(len(v) for v in table.values())} options checked")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
