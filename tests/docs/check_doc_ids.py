#!/usr/bin/env python3
"""Check that every errata/decision id cited in the repository resolves inside it.

Run it from the repository root (it finds the root from its own location, so any directory works):

    python3 tests/docs/check_doc_ids.py

What it does:

1. Reads the prefix tables of docs/errata-index.md. A row whose first cell is a prefix in
   backquotes (a capital letter, or a system prefix such as CGL-E) names, in its last cell, the
   one file that defines that family: a Markdown link (relative to docs/) or a repository path
   in backquotes. The set of prefixes is taken from there, so the checker and the index cannot
   drift apart.
2. Reads the defining files. An id is defined by a Markdown table row whose first cell is the id,
   "| E57 | ...". A defining row of a family in any other Markdown file is an error (each table
   of ids lives in exactly one file), and so is a second row for the same id.
3. Scans every file git tracks (but not tests/prime/fuzz/corpus, binary files and images) for cited
   ids: in Markdown the whole text; in C and C++ the // and /* */ comments and the string
   literals (which is where the messages prime prints live); in Python the # comments and the
   docstrings; in shell, CMake and other #-comment files (scene Model.txt, CMakeLists.txt,
   dictionaries, suppression lists) the # comments. Code itself is never read, so a variable
   name cannot be mistaken for an id.
4. Every cited id must be defined by the file the index names for its prefix. Numbers compare as
   numbers, so E5 and E05 are the same id.
5. Fails on any mention, in any tracked text file but this one, of the project's shared folder
   outside the repository (the strings in FORBIDDEN below): a clone does not have it.

Not ids, although they look like them: file names (obj/D1.txt, prim/S1.txt, obj/O1), options
(+W350, -O2), a Markdown code span holding only such a token (a scene's literal text), and the few
phrases in ALLOW below, each with its reason.

With --list, every resolved citation is printed as well (file:line: id -> defining file).

Exit status 0 with the line "check_doc_ids: N ids in M files resolve" (N citations, M files
that cite at least one id); otherwise 1, with one "file:line: ..." line per problem.
Standard library only.
"""

import io
import os
import re
import subprocess
import sys
import tokenize

INDEX = "docs/errata-index.md"
SELF = "tests/docs/check_doc_ids.py"
SKIP_PARTS = ("/corpus/",)  # libFuzzer seed corpora of every system (tests/fuzz/<system>/corpus/)
IMAGE_EXTENSIONS = (".png", ".jpg", ".jpeg", ".gif", ".ppm", ".pgm", ".bmp", ".ico", ".pdf")

# Mentions of the shared folder that lives outside the repository. Built from pieces so that
# this file does not contain the strings it looks for.
FORBIDDEN = [
    re.compile(re.escape(".." + "/shared")),
    re.compile(re.escape("/work" + "/shared")),
    re.compile(re.escape("shared" + "/seeds")),
    re.compile(re.escape("shared" + "/docs")),
]

# Phrases that look like ids but are not. Keep this list short; a match inside one of these
# spans is not an id.
ALLOW = [
    (re.compile(r"\bX11\b"), "the X Window System (SDL's video driver), not errata X11"),
    (re.compile(r"\bG2 continuity\b"),
     "geometric continuity of the beta-splines, not display decision G2"),
    (re.compile(r"\bD65\b"), "the CIE standard illuminant D65 (sRGB's white), not a Difference branch"),
]

CPP_EXTENSIONS = (".c", ".cc", ".cpp", ".cxx", ".h", ".hh", ".hpp", ".hxx", ".inl", ".ipp")
HASH_EXTENSIONS = (".sh", ".bash", ".cmake", ".txt", ".dict", ".supp", ".yml", ".yaml",
                   ".toml", ".cfg", ".ini", ".gitignore", ".clang-format", ".clang-tidy")
HASH_NAMES = ("CMakeLists.txt", ".gitignore", ".clang-format", ".clang-tidy", "Makefile")


def repo_root():
    here = os.path.dirname(os.path.abspath(__file__))
    out = subprocess.run(["git", "rev-parse", "--show-toplevel"], capture_output=True, text=True,
                         cwd=here)
    if out.returncode != 0:
        sys.exit("check_doc_ids: not inside a git work tree")
    return out.stdout.strip()


def tracked_files():
    out = subprocess.run(["git", "ls-files", "-z"], capture_output=True, check=True)
    return [p for p in out.stdout.decode("utf-8", "surrogateescape").split("\0") if p]


def read_text(path):
    """The file's text, or None for a binary file, an image or a file that is not UTF-8."""
    if path.lower().endswith(IMAGE_EXTENSIONS):
        return None
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError:
        return None  # listed by git but deleted in the work tree
    if b"\0" in data[:8192]:
        return None
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        return None


# ---------------------------------------------------------------------------------------------
# The index

ROW = re.compile(r"^\|\s*`([A-Z]+(?:-[A-Z])?)`\s*\|(.*)\|\s*$")
LINK = re.compile(r"\]\(([^)#\s]+)(?:#[^)]*)?\)")
CODE_PATH = re.compile(r"`([^`\s]+\.md)`")


def read_index():
    """{prefix: defining file (repository path)} from the index's prefix tables."""
    text = read_text(INDEX)
    if text is None:
        sys.exit("check_doc_ids: cannot read " + INDEX)
    prefixes = {}
    problems = []
    base = os.path.dirname(INDEX)
    for number, line in enumerate(text.splitlines(), 1):
        m = ROW.match(line)
        if not m:
            continue
        prefix, rest = m.group(1), m.group(2)
        last = rest.split("|")[-1]
        link = LINK.search(last)
        code = CODE_PATH.search(last)
        if link:
            target = os.path.normpath(os.path.join(base, link.group(1)))
        elif code:
            target = os.path.normpath(code.group(1))
        else:
            problems.append("%s:%d: prefix %s names no defining file" % (INDEX, number, prefix))
            continue
        if prefix in prefixes:
            problems.append("%s:%d: prefix %s is listed twice" % (INDEX, number, prefix))
        prefixes[prefix] = target
    if not prefixes:
        sys.exit("check_doc_ids: no prefix table found in " + INDEX)
    return prefixes, problems


# ---------------------------------------------------------------------------------------------
# Finding ids in text

def id_pattern(single_letters):
    # A bare id: one of the index's letters and 1-3 digits, not part of a longer word, a path,
    # a file name (D1.txt), an option (+W350) or a system-prefixed id (CGL-E<n>).
    letters = "".join(sorted(single_letters))
    return re.compile(
        r"(?<![\w\\+])(?<!CGL-)(?<!MAL-)([" + letters + r"])(\d{1,3})(?![\w])(?!\.[A-Za-z0-9])")


SYSTEM_ID = re.compile(r"(?<![\w-])((?:CGL|MAL)-[A-Z])(\d+)(?![\w])")
BARE_SHAPE = re.compile(r"[A-Z]\d{1,3}$")


def slash_ok(text, start, end):
    """A slash next to an id is allowed only between two ids (K24/Q6), never in a path (obj/D1)."""
    if start > 0 and text[start - 1] == "/":
        before = re.search(r"([A-Za-z0-9_.\-]*)/$", text[:start])
        if not before or not BARE_SHAPE.match(before.group(1)):
            return False
    if end < len(text) and text[end] == "/":
        after = re.match(r"/([A-Za-z0-9_.\-]*)", text[end:])
        if not after or not BARE_SHAPE.match(after.group(1)):
            return False
    return True


def allowed_spans(text):
    spans = []
    for pattern, _reason in ALLOW:
        spans.extend(m.span() for m in pattern.finditer(text))
    return spans


def find_ids(text, bare):
    """(offset, prefix, number, spelled) for every id in text."""
    found = []
    skip = allowed_spans(text)
    inside = lambda pos: any(a <= pos < b for a, b in skip)
    for m in SYSTEM_ID.finditer(text):
        if not inside(m.start()):
            found.append((m.start(), m.group(1), int(m.group(2)), m.group(0)))
    for m in bare.finditer(text):
        if inside(m.start()) or not slash_ok(text, m.start(), m.end()):
            continue
        found.append((m.start(), m.group(1), int(m.group(2)), m.group(0)))
    return found


# ---------------------------------------------------------------------------------------------
# Which parts of a file are prose: (offset, text) chunks, offsets into the whole file

def cpp_chunks(text):
    """Comments and string literals of C or C++ source."""
    chunks = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            chunks.append((i, text[i:j]))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            chunks.append((i, text[i:j]))
            i = j
        elif text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            m = re.match(r'R"([^()\\\s]{0,16})\(', text[i:])
            if not m:
                i += 1
                continue
            close = ")" + m.group(1) + '"'
            j = text.find(close, i + m.end())
            j = n if j < 0 else j + len(close)
            chunks.append((i, text[i:j]))
            i = j
        elif c == '"':
            j = i + 1
            while j < n and text[j] != '"' and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            chunks.append((i, text[i:j + 1]))
            i = j + 1
        elif c == "'":
            # A character literal, or a digit separator (1'000) that must not start one.
            if i > 0 and text[i - 1].isalnum() and not re.match(r"'(\\.|[^\\'])'", text[i:]):
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != "'" and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            i = j + 1
        else:
            i += 1
    return chunks


def hash_chunks(text):
    """# comments of shell, CMake and text files: a # at the start of a line or after a blank."""
    chunks = []
    offset = 0
    for line in text.splitlines(True):
        m = re.search(r"(?:^|\s)(#(?!!).*)$", line.rstrip("\n"))
        if m:
            chunks.append((offset + m.start(1), m.group(1)))
        offset += len(line)
    return chunks


def python_chunks(text):
    """# comments and docstrings of Python source."""
    starts = [0]
    for line in text.splitlines(True):
        starts.append(starts[-1] + len(line))
    to_offset = lambda row, col: starts[row - 1] + col
    chunks = []
    try:
        previous = tokenize.NEWLINE
        for tok in tokenize.generate_tokens(io.StringIO(text).readline):
            if tok.type == tokenize.COMMENT:
                chunks.append((to_offset(*tok.start), tok.string))
            elif tok.type == tokenize.STRING and previous in (tokenize.NEWLINE, tokenize.INDENT,
                                                              tokenize.DEDENT):
                chunks.append((to_offset(*tok.start), tok.string))  # a docstring
            if tok.type not in (tokenize.COMMENT, tokenize.NL):
                previous = tok.type
    except (tokenize.TokenError, IndentationError, SyntaxError):
        return hash_chunks(text)
    return chunks


def prose_chunks(path, text):
    name = os.path.basename(path)
    lower = name.lower()
    if lower.endswith(".md"):
        # A code span holding nothing but an id-shaped token is literal text (the leaf `S1` that
        # must be written `S 1`), not a citation: blank it out, keeping the offsets.
        return [(0, re.sub(r"`[A-Z]\d{1,3}`", lambda m: " " * len(m.group(0)), text))]
    if lower.endswith(CPP_EXTENSIONS):
        return cpp_chunks(text)
    if lower.endswith(".py") or text.startswith("#!") and "python" in text.split("\n", 1)[0]:
        return python_chunks(text)
    if name in HASH_NAMES or lower.endswith(HASH_EXTENSIONS) or text.startswith("#!"):
        return hash_chunks(text)
    return []


# ---------------------------------------------------------------------------------------------

DEF_ROW = re.compile(r"^\|\s*((?:(?:CGL|MAL)-)?[A-Z])(\d{1,3})\s*\|", re.M)


def line_of(text, offset):
    return text.count("\n", 0, offset) + 1


def main(argv):
    listing = "--list" in argv[1:]
    os.chdir(repo_root())
    prefixes, problems = read_index()
    bare = id_pattern(p for p in prefixes if len(p) == 1)
    files = [p for p in tracked_files() if not any(part in p for part in SKIP_PARTS)]
    texts = {}
    for path in files:
        text = read_text(path)
        if text is not None:
            texts[path] = text

    # Definitions, and definition rows outside the defining file.
    defined = {}        # path -> {(prefix, number): line}
    for path in sorted(set(prefixes.values())):
        defined[path] = {}
    def_rows = set()    # (path, offset) of a defining row's first cell, not counted as citations
    for path, text in texts.items():
        if not path.lower().endswith(".md"):
            continue
        for m in DEF_ROW.finditer(text):
            prefix, number = m.group(1), int(m.group(2))
            if prefix not in prefixes:
                continue
            line = line_of(text, m.start())
            home = prefixes[prefix]
            if path != home:
                problems.append("%s:%d: %s%s is defined here, but %s defines the %s family (%s)"
                                % (path, line, prefix, m.group(2), home, prefix, INDEX))
                continue
            if (prefix, number) in defined[path]:
                problems.append("%s:%d: %s%d is defined twice (also line %d)"
                                % (path, line, prefix, number, defined[path][(prefix, number)]))
            defined[path][(prefix, number)] = line
            def_rows.add((path, m.start(1)))

    # Citations.
    citations = 0
    citing = set()
    for path in sorted(texts):
        text = texts[path]
        if path != SELF:
            for pattern in FORBIDDEN:
                for m in pattern.finditer(text):
                    problems.append("%s:%d: mentions %r, which is outside the repository; cite the "
                                    "document (author, title, institution, year) or a file in it"
                                    % (path, line_of(text, m.start()), m.group(0)))
        for start, chunk in prose_chunks(path, text):
            for offset, prefix, number, spelled in find_ids(chunk, bare):
                where = start + offset
                if (path, where) in def_rows:
                    continue
                line = line_of(text, where)
                if prefix not in prefixes:
                    problems.append("%s:%d: %s: no prefix %s in %s"
                                    % (path, line, spelled, prefix, INDEX))
                    continue
                home = prefixes[prefix]
                if home not in texts:
                    if path == INDEX:
                        continue  # an example of a reserved family whose file is not written yet
                    problems.append("%s:%d: %s: its defining file %s does not exist"
                                    % (path, line, spelled, home))
                    continue
                if (prefix, number) not in defined[home]:
                    problems.append("%s:%d: %s is not defined in %s" % (path, line, spelled, home))
                    continue
                citations += 1
                citing.add(path)
                if listing:
                    print("%s:%d: %s -> %s" % (path, line, spelled, home))

    if problems:
        def order(problem):
            path, line, _ = (problem.split(":", 2) + ["", ""])[:3]
            return (path, int(line) if line.isdigit() else 0, problem)
        for problem in sorted(set(problems), key=order):
            print(problem)
        print("check_doc_ids: %d problem(s)" % len(set(problems)))
        return 1
    print("check_doc_ids: %d ids in %d files resolve" % (citations, len(citing)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
