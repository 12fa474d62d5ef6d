#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""Compiles and runs the code blocks of the README and docs/, so the documentation cannot go stale.

The convention (what a writer of the docs must know):

- Every ```cpp block is built against meff::engine with the flags the engine asks of its users
  and -Wall -Wextra -Wpedantic -Werror:
  - a block with `int main(` is a *program*: compiled, linked and run; it must exit with 0;
  - any other block is a *fragment*: it is pasted into the body of a function that has
    `using namespace meff;`, a `game` object (tests/docs/docs_fragment.h: `running()` is true
    for 120 frames, `frameSeconds()` gives 1/60 s, and `draw`, `touch`, `entered`, `stress`,
    `playImpactSound` take anything) and a world with named bodies and values
    (`MEFF_DOCS_NAMES` in that header: `world`, `ground`, `door`, `box`, `eye`, ...). Each
    fragment is compiled and run in its own function, with its own world; unused variables and
    parameters are allowed there (a fragment shows a call, not a whole program).
- An HTML comment on the line before the fence changes that (it does not show on the page):
  - `<!-- docs-test: fragment -->` / `<!-- docs-test: program -->`: say it explicitly;
  - `<!-- docs-test: fragment-no-world -->`: a fragment that makes its own world and bodies,
    so only `using namespace meff;` and `game` are given;
  - `<!-- docs-test: file PATH -->`: the block must be PATH's content (relative to the
    repository root) byte for byte, and is built and run as a program: the README's hello
    world is samples/embed/hello.cpp;
  - `<!-- docs-test: skip REASON -->`: not built (the reason is required).
- Every ```sh block is checked by `bash -n` (syntax only: most need a built tree, a machine
  with the packages, or files the reader has); `skip REASON` applies too.
- Other languages (cmake, yaml, json, plain text) are not checked.

Usage: check_docs_code.py --root DIR --work DIR --cxx COMPILER [--launcher L] --includes A|B
       --definitions A|B --options A|B --library LIB [--extra-flags F] FILE.md...
"""
import argparse
import pathlib
import re
import shutil
import subprocess
import sys

MARKER = re.compile(r"^<!--\s*docs-test:\s*(\S+)\s*(.*?)\s*-->\s*$")
FENCE = re.compile(r"^```(\S*)\s*$")


class Block:
    def __init__(self, path, line, language, text, kind, argument):
        self.path, self.line, self.language, self.text = path, line, language, text
        self.kind, self.argument = kind, argument

    def where(self):
        return f"{self.path}:{self.line}"


def read_blocks(root, relative):
    """The fenced blocks of a Markdown file, each with its marker (or None) and first line."""
    lines = (root / relative).read_text(encoding="utf-8").split("\n")
    blocks, i = [], 0
    while i < len(lines):
        fence = FENCE.match(lines[i])
        if not fence:
            i += 1
            continue
        language, start = fence.group(1), i + 1
        end = start
        while end < len(lines) and lines[end].rstrip() != "```":
            end += 1
        if end == len(lines):
            raise SystemExit(f"{relative}:{i + 1}: a ``` block is never closed")
        previous = i - 1
        while previous >= 0 and not lines[previous].strip():
            previous -= 1
        marker = MARKER.match(lines[previous]) if previous >= 0 else None
        kind, argument = (marker.group(1), marker.group(2)) if marker else (None, "")
        text = "\n".join(lines[start:end]) + "\n"
        blocks.append(Block(relative, start + 1, language, text, kind, argument))
        i = end + 1
    return blocks


def classify(block):
    kinds = {"program", "fragment", "fragment-no-world", "file", "skip"}
    if block.kind is not None and block.kind not in kinds:
        raise SystemExit(f"{block.where()}: unknown docs-test marker '{block.kind}'")
    if block.kind == "skip" and not block.argument:
        raise SystemExit(f"{block.where()}: 'docs-test: skip' needs a reason")
    if block.kind is None:
        return "program" if "int main(" in block.text else "fragment"
    return block.kind


def run(command, what, **kwargs):
    result = subprocess.run(command, capture_output=True, text=True, **kwargs)
    if result.returncode != 0:
        print(f"FAIL: {what}\n$ {' '.join(map(str, command))}\n{result.stdout}{result.stderr}")
        return False
    return True


def split(value):
    return [item for item in value.split("|") if item]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--root", required=True, type=pathlib.Path)
    parser.add_argument("--work", required=True, type=pathlib.Path)
    parser.add_argument("--cxx", required=True)
    parser.add_argument("--launcher", default="")
    parser.add_argument("--includes", default="")
    parser.add_argument("--definitions", default="")
    parser.add_argument("--options", default="")
    parser.add_argument("--library", required=True)
    parser.add_argument("--extra-flags", default="")
    parser.add_argument("files", nargs="+")
    args = parser.parse_args()

    if args.work.exists():
        shutil.rmtree(args.work)
    args.work.mkdir(parents=True)
    here = pathlib.Path(__file__).resolve().parent
    compile_flags = ["-std=c++20", "-Wall", "-Wextra", "-Wpedantic", "-Werror", f"-I{here}"]
    compile_flags += [f"-I{include}" for include in split(args.includes)]
    compile_flags += [f"-D{definition}" for definition in split(args.definitions)]
    compile_flags += split(args.options) + args.extra_flags.split()
    link_flags = [args.library, "-pthread"] + args.extra_flags.split()
    compiler = ([args.launcher] if args.launcher else []) + [args.cxx]

    failures, counts = 0, {"program": 0, "fragment": 0, "sh": 0, "skipped": 0}
    for relative in args.files:
        fragments = []
        for block in read_blocks(args.root, relative):
            if block.language not in ("cpp", "sh"):
                continue
            kind = classify(block)
            if kind == "skip":
                counts["skipped"] += 1
                continue
            if block.language == "sh":
                counts["sh"] += 1
                if not run(["bash", "-n"], f"{block.where()}: sh block", input=block.text):
                    failures += 1
                continue
            if kind == "file":
                quoted = args.root / block.argument
                if quoted.read_text(encoding="utf-8") != block.text:
                    print(f"FAIL: {block.where()}: the block is not {block.argument} verbatim")
                    failures += 1
                    continue
                kind = "program"
            if kind == "program":
                counts["program"] += 1
                name = f"{re.sub(r'[^A-Za-z0-9]', '_', relative)}_{block.line}"
                source = args.work / f"{name}.cpp"
                source.write_text(f'#line {block.line} "{relative}"\n{block.text}')
                binary = args.work / name
                if not run(compiler + compile_flags + [str(source), "-o", str(binary)] + link_flags,
                           f"{block.where()}: program does not build"):
                    failures += 1
                elif not run([str(binary)], f"{block.where()}: program does not exit with 0"):
                    failures += 1
                continue
            counts["fragment"] += 1
            fragments.append((block, kind))
        if not fragments:
            continue
        # A file's fragments share one translation unit, each in its own function.
        name = re.sub(r"[^A-Za-z0-9]", "_", relative)
        parts = ['#include "docs_fragment.h"\n']
        for index, (block, kind) in enumerate(fragments):
            names = "MEFF_DOCS_GAME" if kind == "fragment-no-world" else "MEFF_DOCS_NAMES"
            parts.append(f"static void Fragment{index}()\n{{\n    using namespace meff;\n"
                         f"    {names}\n#line {block.line} \"{relative}\"\n{block.text}}}\n")
        calls = "".join(f'    ok &= docs::Run("{block.where()}", Fragment{index});\n'
                        for index, (block, _) in enumerate(fragments))
        parts.append(f"int main()\n{{\n    bool ok = true;\n{calls}    return ok ? 0 : 1;\n}}\n")
        source = args.work / f"{name}_fragments.cpp"
        source.write_text("".join(parts))
        binary = args.work / f"{name}_fragments"
        relaxed = ["-Wno-unused-variable", "-Wno-unused-but-set-variable", "-Wno-unused-parameter"]
        if not run(compiler + compile_flags + relaxed + [str(source), "-o", str(binary)]
                   + link_flags, f"{relative}: fragments do not build"):
            failures += 1
        elif not run([str(binary)], f"{relative}: a fragment failed when run"):
            failures += 1

    print(f"{counts['program']} programs, {counts['fragment']} fragments, {counts['sh']} sh "
          f"blocks checked, {counts['skipped']} skipped; {failures} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
