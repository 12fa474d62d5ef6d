#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""docs/cli.md's option lists are the `meff` tool's own --help.

Each `<!-- meff-help: COMMAND -->` marker in docs/cli.md is followed by a ```text block holding
the output of `meff COMMAND --help` (`meff --help` for the marker `meff`).

    cli_help.py MEFF DOCS/CLI.MD --check   fails, with a diff, when a block differs from the
                                           tool's help (the test docs.cli_help)
    cli_help.py MEFF DOCS/CLI.MD --write   rewrites the blocks from the tool's help
"""
import difflib
import re
import subprocess
import sys

MARKER = re.compile(r"^<!-- meff-help: (\S+) -->$")


def help_text(meff, command):
    arguments = [meff, "--help"] if command == "meff" else [meff, command, "--help"]
    result = subprocess.run(arguments, capture_output=True, text=True, check=True)
    # The usage line names the program as it was called; the page names it `meff`.
    return result.stdout.replace(meff, "meff").rstrip("\n") + "\n"


def regenerate(meff, text):
    lines = text.split("\n")
    out, i = [], 0
    while i < len(lines):
        out.append(lines[i])
        marker = MARKER.match(lines[i])
        i += 1
        if not marker:
            continue
        if i >= len(lines) or lines[i] != "```text":
            raise SystemExit(f"line {i}: a ```text block must follow {lines[i - 1]}")
        end = lines.index("```", i + 1)
        out.append("```text")
        out.extend(help_text(meff, marker.group(1)).rstrip("\n").split("\n"))
        out.append("```")
        i = end + 1
    return "\n".join(out)


def main():
    if len(sys.argv) != 4 or sys.argv[3] not in ("--check", "--write"):
        raise SystemExit(__doc__)
    meff, path, mode = sys.argv[1:]
    with open(path, encoding="utf-8") as file:
        current = file.read()
    wanted = regenerate(meff, current)
    if mode == "--write":
        with open(path, "w", encoding="utf-8") as file:
            file.write(wanted)
        return 0
    if wanted != current:
        sys.stdout.writelines(difflib.unified_diff(current.splitlines(True),
                                                   wanted.splitlines(True), path, "meff --help"))
        print(f"{path} differs from the tool's --help: run tests/docs/cli_help.py MEFF {path} "
              "--write")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
