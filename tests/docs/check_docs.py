#!/usr/bin/env python3
"""Checks README.md and docs/*.md against the checkout and the built programs.

- every relative link and image resolves to a file, and every #anchor to a heading of the Markdown page it names;
- every command in a fenced code block that runs specula (or specula-view, specula-path, specula-load) uses only
  flags that the program's `--help` for that (sub)command lists;
- the generated benchmark tables (docs/tools/bench_tables.py) match bench-results/.

Usage: check_docs.py --repository DIR --specula BIN --specula-view BIN --specula-path BIN --specula-load BIN
Prints one line per problem and exits 1 if there is any.
"""
import argparse
import functools
import importlib.util
import pathlib
import re
import shlex
import subprocess
import sys

FENCE = re.compile(r"^ {0,3}(```|~~~).*?^ {0,3}\1[ \t]*$", re.MULTILINE | re.DOTALL)
INLINE_CODE = re.compile(r"`[^`\n]*`")
LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\[\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
HEADING = re.compile(r"^ {0,3}#{1,6}[ \t]+(.+?)[ \t#]*$", re.MULTILINE)
SUBCOMMANDS = {"specula": {"serve": {}, "render": {}, "scenes": {}, "bench": {"tessellation": {}, "accuracy": {}, "serve": {}, "soak": {}}}}
PROGRAMS = ("specula", "specula-view", "specula-path", "specula-load")


def blank(match):
    """The match replaced by spaces, newlines kept, so offsets and line numbers stay."""
    return re.sub(r"[^\n]", " ", match[0])


def prose(text):
    """The page without fenced code blocks and inline code: where links and headings live."""
    return INLINE_CODE.sub(blank, FENCE.sub(blank, text))


def line_of(text, offset):
    return text.count("\n", 0, offset) + 1


def slug(heading):
    """GitHub's anchor for a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading).lower()
    return re.sub(r"[^\w\- ]", "", text).replace(" ", "-")


@functools.lru_cache(maxsize=None)
def anchors(page):
    """The anchors of a Markdown page's headings, numbered -1, -2, ... where a heading repeats."""
    seen, result = {}, set()
    for match in HEADING.finditer(FENCE.sub(blank, page.read_text())):
        base = slug(match[1])
        result.add(base if base not in seen else f"{base}-{seen[base]}")
        seen[base] = seen.get(base, 0) + 1
    return result


def link_problems(repository, page):
    text = page.read_text()
    problems = []
    for match in LINK.finditer(prose(text)):
        target = match[1]
        if re.match(r"[a-z][a-z0-9+.-]*:", target, re.IGNORECASE):
            continue  # http:, https:, mailto: are not files of this checkout
        path_part, _, anchor = target.partition("#")
        where = f"{page.relative_to(repository)}:{line_of(text, match.start())}"
        destination = (page.parent / path_part).resolve() if path_part else page
        if not destination.exists():
            problems.append(f"{where}: link '{target}' names a file that does not exist")
        elif anchor and destination.suffix == ".md" and anchor not in anchors(destination):
            problems.append(f"{where}: link '{target}' names no heading of {destination.name}")
    return problems


def commands(text):
    """(line, words) for each command in the page's fenced code blocks, prompts and continuations joined."""
    for block in FENCE.finditer(text):
        lines = block[0].split("\n")[1:-1]
        first = line_of(text, block.start()) + 1
        pending, start = "", first
        for number, line in enumerate(lines, first):
            if not pending:
                start = number
            if line.rstrip().endswith("\\"):
                pending += line.rstrip()[:-1] + " "
                continue
            joined, pending = pending + line, ""
            joined = re.sub(r"^\s*\$\s+", "", joined)
            try:
                words = shlex.split(joined, comments=True)
            except ValueError:
                continue  # not shell (JSON, program output)
            command = []
            for word in words + [";"]:
                if word in ("&&", "||", "|", ";"):
                    if command:
                        yield start, command
                    command = []
                else:
                    command.append(word)


def program_call(words):
    """(program, subcommands, flags, unknown subcommand or None) when the words run one of our programs, else None."""
    while words and re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*=.*", words[0]):
        words = words[1:]  # environment assignments before the program
    if not words or pathlib.PurePath(words[0]).name not in PROGRAMS:
        return None
    program, rest = pathlib.PurePath(words[0]).name, words[1:]
    subcommands, choices = [], SUBCOMMANDS.get(program, {})
    while rest and rest[0] in choices:
        subcommands.append(rest[0])
        choices, rest = choices[rest[0]], rest[1:]
    flags = [word.split("=", 1)[0] for word in rest if word.startswith("--")]
    takes_subcommand = bool(SUBCOMMANDS.get(program)) and not subcommands
    unknown = rest[0] if takes_subcommand and rest and not rest[0].startswith("-") else None
    return program, tuple(subcommands), flags, unknown


@functools.lru_cache(maxsize=None)
def help_text(binary, subcommands):
    run = subprocess.run([binary, *subcommands, "--help"], capture_output=True, text=True, timeout=120)
    return run.stdout + run.stderr


def command_problems(repository, page, binaries):
    text = page.read_text()
    problems = []
    for line, words in commands(text):
        call = program_call(words)
        if not call:
            continue
        program, subcommands, flags, unknown = call
        where = f"{page.relative_to(repository)}:{line}"
        shown = " ".join([program, *subcommands])
        if unknown:
            problems.append(f"{where}: `{program} {unknown}` is not a subcommand of {program}")
            continue
        listed = help_text(binaries[program], subcommands)
        for flag in flags:
            if not re.search(rf"(?<![\w-]){re.escape(flag)}(?![\w-])", listed):
                problems.append(f"{where}: `{shown}` has no flag {flag} (not in `{shown} --help`)")
    return problems


def stale_table_problems(repository):
    tool = repository / "docs" / "tools" / "bench_tables.py"
    spec = importlib.util.spec_from_file_location("bench_tables", tool)
    bench_tables = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(bench_tables)
    return [f"{section}: generated table is stale; run docs/tools/bench_tables.py"
            for section in bench_tables.stale_sections(repository)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repository", type=pathlib.Path, required=True)
    for program in PROGRAMS:
        parser.add_argument(f"--{program}", required=True, help=f"the built {program} executable")
    args = parser.parse_args()
    repository = args.repository.resolve()
    binaries = {program: getattr(args, program.replace("-", "_")) for program in PROGRAMS}
    pages = [repository / "README.md"] + sorted((repository / "docs").glob("*.md"))
    problems = []
    for page in pages:
        problems += link_problems(repository, page) + command_problems(repository, page, binaries)
    problems += stale_table_problems(repository)
    for problem in problems:
        print(problem)
    print(f"{len(pages)} pages checked: {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
