#!/usr/bin/env python3
"""The generated completions (tools/gen_cli_docs.py) against the CLI itself.

Every command `prime --help` lists and every option its `prime help CMD`
lists must be completed by the bash, zsh and fish scripts; a few known ones
are named here too, so that a generator that parses nothing fails; the bash
script must parse (bash -n), and offer `trace`'s options when asked. Every
option whose help shows a fixed set of values completes to exactly that set
(bash, as asked; zsh and fish, in their scripts), a few known sets named here;
and bash completes the build tree's build/release/src/cli/prime as it does
`prime`.

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
# Known sets by hand (the user guide): command, option, values.
KNOWN_VALUES = {("trace", "--format"): {"prime", "malone", "cgl"},
                ("trace", "--profile"): {"1991", "modern", "thesis", "document"},  # CGL: document, modern
                ("trace", "--png-area"): {"image", "screen", "file"},
                ("trace", "--quantize"): {"popularity", "median-cut", "octree"},
                ("quantize", "--method"): {"popularity", "median-cut", "octree", "listing",
                                           "libimagequant"},
                ("export", "--area"): {"image", "screen", "file"}}


def bash_complete(script, words, name="prime"):
    """What the bash script offers for the last word of `name words...`."""
    quoted = " ".join(f"'{w}'" for w in [name, *words])
    probe = (f"source {script}; COMP_WORDS=({quoted}); COMP_CWORD={len(words)}; "
             f"$(complete -p {name} | sed -E 's/.* -F ([^ ]+) .*/\\1/'); "
             "printf '%s\\n' \"${COMPREPLY[@]}\"")
    r = subprocess.run(["bash", "-c", probe], capture_output=True, text=True)
    return r.returncode, r.stdout.split(), r.stderr


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
    # Values: every fixed set the help shows, as bash completes it.
    listed = subprocess.run([sys.executable, GEN, prime, "--list-values"], check=True,
                            capture_output=True, text=True).stdout.splitlines()
    values = {(line.split()[0], line.split()[1]): line.split()[2:] for line in listed}
    for key, want in sorted(KNOWN_VALUES.items()):
        if set(values.get(key, [])) != want:
            failures.append(f"the values of {' '.join(key)} read from the help: "
                            f"{values.get(key)}, not {sorted(want)}")
    bash_script = os.path.join(docs, "prime.bash")
    for (cmd, opt), want in sorted(values.items()):
        status, got, err = bash_complete(bash_script, [cmd, opt, ""])
        if status != 0 or got != want:
            failures.append(f"bash completes 'prime {cmd} {opt} ' to {got}, not {want} {err}")
        zsh = f"'{opt}:value:({' '.join(want)})'"
        if zsh not in scripts["_prime"]:
            failures.append(f"_prime does not offer {zsh} for {cmd}")
        fish = f"__fish_seen_subcommand_from {cmd}' -l {opt[2:]} -x -a '{' '.join(want)}'"
        if opt.startswith("--") and fish not in scripts["prime.fish"]:
            failures.append(f"prime.fish does not offer the values of {cmd} {opt}")
    status, got, err = bash_complete(bash_script, ["trace", "--format", "ma"])
    if got != ["malone"]:
        failures.append(f"bash completion of 'prime trace --format ma': {got} {err}")
    # The build tree's command, as README.md and the docs call it.
    for name in ("build/release/src/cli/prime", "./build/release/src/cli/prime"):
        status, got, err = bash_complete(bash_script, ["trace", "--png-a"], name)
        if got != ["--png-area"]:
            failures.append(f"bash completion of '{name} trace --png-a': {got} {err}")
    # bash: the script parses and completes `prime trace --pn` to --png.
    probe = (f"source {os.path.join(docs, 'prime.bash')}; COMP_WORDS=(prime trace --pn); "
             "COMP_CWORD=2; _prime; printf '%s\\n' \"${COMPREPLY[@]}\"")
    r = subprocess.run(["bash", "-c", probe], capture_output=True, text=True)
    if r.returncode != 0 or r.stdout.split() != ["--png"] and "--png" not in r.stdout.split():
        failures.append(f"bash completion of 'prime trace --pn': {r.stdout!r} {r.stderr!r}")
    for f in failures:
        print("FAIL " + f)
    print(f"{len(table)} commands, {sum(len(v) for v in table.values())} options, "
          f"{len(values)} value sets checked")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
