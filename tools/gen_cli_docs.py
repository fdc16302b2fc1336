#!/usr/bin/env python3
"""The man page and the shell completions of `prime`, from the CLI definitions.

Everything is read from the built executable itself (`prime --help`, `prime help
CMD`), so neither can drift from the commands and options: the man page is
help2man's page of `prime --help` with one COMMANDS subsection per command
(its full help), and the bash, zsh and fish completions complete the command
names, each command's options and the values of the options that take one of
a fixed set (the set CLI11 shows in the help: `--format TEXT:{prime,cgl,malone}`),
for `prime` and for the build tree's build/release/src/cli/prime.

usage: gen_cli_docs.py PRIME OUTDIR          writes OUTDIR/prime.1, prime.bash, _prime, prime.fish
       gen_cli_docs.py PRIME --list          prints "command option option ..." lines (for tests)
       gen_cli_docs.py PRIME --list-values   prints "command option value value ..." lines: the
                                             options whose help shows a fixed set (CLI11's {a,b})
"""

import os
import re
import shutil
import subprocess
import sys


def run(prime, *args):
    env = dict(os.environ)
    env.pop("DISPLAY", None)
    env.pop("WAYLAND_DISPLAY", None)
    r = subprocess.run([prime, *args], capture_output=True, text=True, env=env)
    if r.returncode != 0:
        sys.exit(f"gen_cli_docs: {prime} {' '.join(args)} exited {r.returncode}: {r.stderr}")
    # CLI11 shows argv[0]: the page shows the command's name.
    return r.stdout.replace(prime + " ", "prime ")


# Commands that serve several systems: the scene picks the system, and each
# system's options (`prime trace --format malone --help`) complete too.
SYSTEMS = {"trace": ["malone", "cgl"], "probe": ["malone", "cgl"], "bench": ["malone", "cgl"],
           "export-pov": ["malone", "cgl"], "export": ["rle"], "view": ["rle"]}


def section(text, title):
    """The lines of a CLI11 help section ("Subcommands:", "Options:")."""
    out, inside = [], False
    for line in text.splitlines():
        if re.match(r"^[A-Z][A-Za-z ]*:\s*$", line):
            inside = line.strip() == title
            continue
        if inside:
            out.append(line)
    return out


def commands(prime):
    """(name, description) of every visible command, in the order --help lists them."""
    found = []
    for line in section(run(prime, "--help"), "Subcommands:"):
        m = re.match(r"^  (\S+)\s+(.*)$", line)
        if m:
            found.append((m.group(1), m.group(2).strip()))
        elif found and line.strip():
            found[-1] = (found[-1][0], found[-1][1] + " " + line.strip())
    return found


def options(help_text):
    """Every option name (-x, --long) of a command's help."""
    names = []
    for line in section(help_text, "Options:"):
        m = re.match(r"^  (-\S+(?:, ?-\S+)*)", line)
        if not m:
            continue
        for name in re.split(r",\s*", m.group(1)):
            name = name.split("=")[0]
            if name.startswith("-") and name not in names:
                names.append(name)
    return names


def option_values(help_text):
    """{option: [value, ...]} for the options whose help shows a fixed set
    (CLI11's `--format TEXT:{prime,cgl,malone}`)."""
    found = {}
    for line in section(help_text, "Options:"):
        m = re.match(r"^  (-\S+(?:, ?-\S+)*)\s+[A-Z]+:\{([^}]*)\}", line)
        if not m:
            continue
        values = [v.strip() for v in m.group(2).split(",") if v.strip()]
        for name in re.split(r",\s*", m.group(1)):
            name = name.split("=")[0]
            if name.startswith("-"):
                found.setdefault(name, [])
                found[name] += [v for v in values if v not in found[name]]
    return found


def roff(text):
    lines = []
    for line in text.splitlines():
        line = line.replace("\\", "\\e")
        if line.startswith((".", "'")):
            line = "\\&" + line
        lines.append(line)
    return "\n".join(lines)


def help_roff(text, description):
    """A command's CLI11 help as man-page markup: each option a tagged
    paragraph (.TP), so that man wraps its description to the terminal's
    width, instead of one preformatted block hundreds of columns wide. The
    command's description (the help's first line, and again before each other
    system's options) is left out: the subsection's heading says it."""
    lines = [l for l in text.splitlines() if l.strip() != description.strip()]
    out = []
    i = 0
    while i < len(lines):
        line = lines[i].rstrip()
        i += 1
        if not line.strip():
            continue
        if re.match(r"^\S.*:$", line):  # Positionals:, Options:, Subcommands:
            out += [".PP", "\\fB" + roff(line) + "\\fR"]
            continue
        m = re.match(r"^ {1,4}(\S.*?)(?: {2,}(\S.*))?$", line)
        if m and (m.group(1).startswith("-") or m.group(2) is not None or
                  (i < len(lines) and re.match(r"^ {10,}\S", lines[i]))):
            desc = m.group(2) or ""
            while i < len(lines) and re.match(r"^ {10,}\S", lines[i]):
                desc += (" " if desc else "") + lines[i].strip()
                i += 1
            out += [".TP", "\\fB" + roff(m.group(1)) + "\\fR"] + ([roff(desc)] if desc else [])
            continue
        out += [".PP", roff(line.strip())]
    return "\n".join(out)


# The names completion is registered for: the installed command, and the
# build tree's, as README.md and the docs call it (bash looks a path up as
# written, and older versions do not fall back to its last component).
BUILD_NAMES = ["build/release/src/cli/prime", "./build/release/src/cli/prime"]


def bash(table, values):
    cases = "\n".join(f"    {c}) opts=\"{' '.join(o)}\" ;;" for c, o in table.items())
    value_cases = "\n".join(f"    '{c} {o}') vals=\"{' '.join(v)}\" ;;"
                             for c, opts in values.items() for o, v in opts.items())
    return f"""# bash completion for prime (generated by tools/gen_cli_docs.py from the CLI; do not edit)
# From a build tree, before installing: source build/release/src/cli/cli-docs/prime.bash
_prime() {{
  local cur=${{COMP_WORDS[COMP_CWORD]}} cmd=${{COMP_WORDS[1]}} prev= opts vals=
  [ "$COMP_CWORD" -ge 1 ] && prev=${{COMP_WORDS[COMP_CWORD-1]}}
  # An option that takes one of a fixed set of values: those values.
  case "$cmd $prev" in
{value_cases}
  esac
  if [ -n "$vals" ]; then
    COMPREPLY=($(compgen -W "$vals" -- "$cur"))
    return
  fi
  if [ "$COMP_CWORD" -eq 1 ]; then
    COMPREPLY=($(compgen -W "{' '.join(table)} help --help --version" -- "$cur"))
    return
  fi
  case "$cmd" in
{cases}
    help) COMPREPLY=($(compgen -W "{' '.join(table)}" -- "$cur")); return ;;
    *) opts="" ;;
  esac
  if [[ "$cur" == -* ]]; then
    COMPREPLY=($(compgen -W "$opts" -- "$cur"))
  else
    COMPREPLY=($(compgen -f -- "$cur"))
  fi
}}
complete -o filenames -F _prime prime {' '.join(BUILD_NAMES)}
"""


def zsh(table, descriptions, values):
    names = "\n".join(
        f"    '{c}:{descriptions[c][:70].replace(chr(39), '')}'" for c in table)

    def spec(c, o):
        v = values.get(c, {}).get(o)
        return f"'{o}:value:({' '.join(v)})'" if v else repr(o)

    cases = "\n".join(f"    {c}) _arguments '*:file:_files' {' '.join(spec(c, o) for o in opts)} ;;"
                      for c, opts in table.items())
    return f"""#compdef prime {' '.join(BUILD_NAMES)}
# zsh completion for prime (generated by tools/gen_cli_docs.py from the CLI; do not edit)
_prime() {{
  local -a commands
  commands=(
{names}
  )
  if (( CURRENT == 2 )); then
    _describe 'command' commands
    return
  fi
  case "$words[2]" in
{cases}
    *) _files ;;
  esac
}}
_prime "$@"
"""


def fish(table, descriptions, values):
    lines = ["# fish completion for prime (generated by tools/gen_cli_docs.py from the CLI; do not edit)",
             "complete -c prime -f -n __fish_use_subcommand -l version -d 'Print the version'"]
    for c in table:
        d = descriptions[c][:70].replace("'", "")
        lines.append(f"complete -c prime -f -n __fish_use_subcommand -a {c} -d '{d}'")
    for c, opts in table.items():
        for o in opts:
            flag = f"-l {o[2:]}" if o.startswith("--") else f"-s {o[1:]}"
            v = values.get(c, {}).get(o)
            if v:
                flag += f" -x -a '{' '.join(v)}'"
            lines.append(f"complete -c prime -n '__fish_seen_subcommand_from {c}' {flag}")
    return "\n".join(lines) + "\n"


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    prime, out = os.path.abspath(sys.argv[1]), sys.argv[2]
    cmds = commands(prime)
    helps = {c: run(prime, "help", c) for c, _ in cmds}
    table = {c: options(helps[c]) for c, _ in cmds}
    values = {c: option_values(helps[c]) for c, _ in cmds}
    for c, formats in SYSTEMS.items():
        if c not in helps:
            continue
        for f in formats:
            other = run(prime, c, "--format", f, "--help")
            helps[c] += f"\n(--format {f}, or a scene that is one)\n" + other
            table[c] += [o for o in options(other) if o not in table[c]]
            for o, v in option_values(other).items():
                values[c].setdefault(o, [])
                values[c][o] += [x for x in v if x not in values[c][o]]
    if out == "--list":
        for c, opts in table.items():
            print(" ".join([c, *opts]))
        return 0
    if out == "--list-values":
        for c, opts in values.items():
            for o, v in opts.items():
                print(" ".join([c, o, *v]))
        return 0
    os.makedirs(out, exist_ok=True)
    descriptions = dict(cmds)
    with open(os.path.join(out, "prime.bash"), "w") as f:
        f.write(bash(table, values))
    with open(os.path.join(out, "_prime"), "w") as f:
        f.write(zsh(table, descriptions, values))
    with open(os.path.join(out, "prime.fish"), "w") as f:
        f.write(fish(table, descriptions, values))

    include = os.path.join(out, "prime.h2m")
    with open(include, "w") as f:
        f.write("[COMMANDS]\nEach command's own help (also `prime help COMMAND`).\n")
        for c, d in cmds:
            f.write(f'.SS "prime {c}"\n{roff(d)}\n{help_roff(helps[c], d)}\n')
        f.write("[FILES]\nThe window module libprime_window_sdl.so is loaded from beside the "
                "executable, or from ../lib/prime/ relative to it (an installed prime).\n")
        f.write("[SEE ALSO]\nREADME.md and docs/ in the source tree: the user guide, the "
                "file formats, the listing errata and the deviations.\n")
    help2man = shutil.which("help2man")
    if help2man is None:
        sys.exit("gen_cli_docs: help2man is not installed (apt-get install help2man)")
    env = dict(os.environ)
    env.pop("DISPLAY", None)
    # The page's footer is .TH's source, date and title on one line: the whole
    # first line of --version ("prime 0.2.0 (PRIME 1991, ...)") as the source
    # runs into the date at 80 columns ("Malone 1Novembere2026"); the name and
    # version alone fit.
    version = run(prime, "--version").splitlines()[0]
    m = re.match(r"^(\S+) (\d\S*)", version)
    if not m:
        sys.exit(f"gen_cli_docs: no version in the first line of prime --version: {version!r}")
    subprocess.run([help2man, "--no-info", "--no-discard-stderr", "--section", "1",
                    "--version-string", f"{m.group(1)} {m.group(2)}",
                    "--name", "replay historical ray tracers (PRIME 1991, Malone 1995, "
                    "Waterloo CGL 1985)", "--include", include, "--output",
                    os.path.join(out, "prime.1"), prime], check=True, env=env)
    os.remove(include)
    return 0


if __name__ == "__main__":
    sys.exit(main())
