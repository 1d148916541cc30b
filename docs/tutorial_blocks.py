#!/usr/bin/env python3
"""The output blocks of docs/tutorial.md, from real runs.

Every fenced block of the tutorial preceded by a marker line

    <!-- tutorial: run -->
    ```console
    $ gearcoupling validate --data data/recordings/... --model paper
    (output)
    ```

is regenerated: the command after `$ ` is run (`gearcoupling` is the built program; no shell),
and what it prints replaces the lines below it. The commands run in order, in one scratch
directory where `data/` is the source tree's, so a file one writes (diagnosed.textproto) is there
for the next, and the output names relative paths only. Marker options, comma-separated:

    keep N lines then "TEXT"    keep the first N output lines and end with the line TEXT
    exit N                      the command must exit with N (an error shown on purpose);
                                without it, any exit but 0 stops the regeneration
    file NAME block 'TEXT'      not a command: the top-level `{ ... }` block of NAME (written
                                by an earlier command) that contains TEXT

`--check` compares what matters: the text exactly, and each number within a relative 1e-6 or one
unit of its last printed digit, whichever is larger (REL_TOLERANCE, same_text_and_numbers). A
program prints a number to the precision it carries, and the last digit of a long one differs
between CPUs and libm builds (a parameter printed with 17 significant digits ended in ...8395 on one
machine and ...8386 on another); a change of wording, or of a number beyond that, is still stale.

Usage:
    docs/tutorial_blocks.py --gearcoupling build/clients/cli/gearcoupling          # rewrite in place
    docs/tutorial_blocks.py --gearcoupling build/clients/cli/gearcoupling --check  # diff, exit 1

`cmake --build build --target update_tutorial` builds the program and rewrites the tutorial;
ctest's `docs.tutorial` runs the --check form.
"""

import argparse
import difflib
import os
import re
import shlex
import subprocess
import sys
import tempfile
from pathlib import Path

MARKER = re.compile(r"^<!-- tutorial: (.*) -->$")
KEEP = re.compile(r'^keep (\d+) lines then "(.*)"$')
FILE_BLOCK = re.compile(r"^file (\S+) block '(.*)'$")
OPTION = re.compile(r"""(?:[^,"']|"[^"]*"|'[^']*')+""")   # comma-separated, quotes kept whole
EXIT = re.compile(r"^exit (\d+)$")


NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
REL_TOLERANCE = 1e-6


def last_digit_unit(token):
    """One unit of the last printed digit of a number token: 0.0123 -> 1e-4, 12e3 -> 1e3."""
    mantissa, _, exponent = token.lower().lstrip("+-").partition("e")
    decimals = len(mantissa.partition(".")[2])
    return 10.0 ** (int(exponent or 0) - decimals)


def numbers_agree(a, b):
    if a == b:
        return True
    x, y = float(a), float(b)
    allowed = max(REL_TOLERANCE * max(abs(x), abs(y)), last_digit_unit(a), last_digit_unit(b))
    return abs(x - y) <= allowed * (1 + 1e-9)


def same_text_and_numbers(expected, actual):
    """True when two texts are the same but for numbers that agree (numbers_agree)."""
    expected_lines, actual_lines = expected.splitlines(), actual.splitlines()
    if len(expected_lines) != len(actual_lines):
        return False
    for e, a in zip(expected_lines, actual_lines):
        if NUMBER.sub("#", e) != NUMBER.sub("#", a):
            return False
        if not all(numbers_agree(x, y) for x, y in zip(NUMBER.findall(e), NUMBER.findall(a))):
            return False
    return True


class TutorialError(Exception):
    pass


def top_level_block(text, needle):
    """The top-level `name {` ... `}` block of a text proto that contains `needle`."""
    block = []
    for line in text.splitlines():
        if not block and line.endswith("{") and not line.startswith(" "):
            block = [line]
        elif block:
            block.append(line)
            if line == "}":
                if any(needle in l for l in block):
                    return block
                block = []
    raise TutorialError(f"no top-level block contains {needle!r}")


def run_command(command_line, program, workdir, source_dir, expected_exit):
    argv = shlex.split(command_line)
    if not argv or argv[0] != "gearcoupling":
        raise TutorialError(f"not a gearcoupling command: {command_line}")
    done = subprocess.run([program] + argv[1:], cwd=workdir, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True, timeout=600,
                          env=dict(os.environ, LC_ALL="C.UTF-8"))
    if done.returncode != expected_exit:
        raise TutorialError(f"exit {done.returncode}, expected {expected_exit}: {command_line}\n"
                            f"{done.stdout}")
    text = done.stdout.replace(str(workdir) + "/", "").replace(str(source_dir) + "/", "")
    return [line.rstrip() for line in text.splitlines()]


def regenerate(markdown, program, source_dir):
    lines = markdown.splitlines()
    out = []
    i = 0
    with tempfile.TemporaryDirectory(prefix="gc_tutorial_") as scratch:
        workdir = Path(scratch).resolve()
        (workdir / "data").symlink_to(source_dir / "data")
        while i < len(lines):
            marker = MARKER.match(lines[i])
            out.append(lines[i])
            i += 1
            if not marker:
                continue
            if i >= len(lines) or not lines[i].startswith("```"):
                raise TutorialError(f"line {i}: a tutorial marker must be followed by a fence")
            out.append(lines[i])
            i += 1
            body_start = i
            while i < len(lines) and lines[i] != "```":
                i += 1
            if i == len(lines):
                raise TutorialError(f"line {body_start}: the block is not closed")
            body = lines[body_start:i]
            options = [o.strip() for o in OPTION.findall(marker.group(1))]
            if options[0] == "run":
                if not body or not body[0].startswith("$ "):
                    raise TutorialError(f"line {body_start + 1}: a run block starts with '$ command'")
                expected_exit, keep = 0, None
                for option in options[1:]:
                    if KEEP.match(option):
                        keep = KEEP.match(option)
                    elif EXIT.match(option):
                        expected_exit = int(EXIT.match(option).group(1))
                    else:
                        raise TutorialError(f"line {body_start}: unknown option {option!r}")
                output = run_command(body[0][2:], program, workdir, source_dir, expected_exit)
                if keep:
                    output = output[:int(keep.group(1))] + [keep.group(2)]
                out.append(body[0])
                out.extend(output)
            elif FILE_BLOCK.match(options[0]):
                name, needle = FILE_BLOCK.match(options[0]).groups()
                out.extend(top_level_block((workdir / name).read_text(), needle))
            else:
                raise TutorialError(f"line {body_start}: unknown marker {marker.group(1)!r}")
            out.append(lines[i])
            i += 1
    return "\n".join(out) + "\n"


def main():
    here = Path(__file__).resolve().parent
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--gearcoupling", required=True, help="the built gearcoupling program")
    parser.add_argument("--tutorial", default=str(here / "tutorial.md"))
    parser.add_argument("--source-dir", default=str(here.parent))
    parser.add_argument("--check", action="store_true",
                        help="compare with the file instead of rewriting it; exit 1 on a difference")
    args = parser.parse_args()
    tutorial = Path(args.tutorial)
    current = tutorial.read_text()
    try:
        fresh = regenerate(current, str(Path(args.gearcoupling).resolve()),
                           Path(args.source_dir).resolve())
    except (TutorialError, subprocess.TimeoutExpired) as error:
        print(f"tutorial_blocks.py: {tutorial}: {error}", file=sys.stderr)
        return 2
    if args.check:
        if same_text_and_numbers(current, fresh):
            print(f"{tutorial}: every block is what the programs print")
            return 0
        sys.stdout.writelines(difflib.unified_diff(
            current.splitlines(keepends=True), fresh.splitlines(keepends=True),
            str(tutorial), "what the programs print"))
        print(f"\n{tutorial} is stale: run `cmake --build <build> --target update_tutorial`",
              file=sys.stderr)
        return 1
    if fresh != current:
        tutorial.write_text(fresh)
        print(f"{tutorial}: rewritten")
    else:
        print(f"{tutorial}: unchanged")
    return 0


if __name__ == "__main__":
    sys.exit(main())
