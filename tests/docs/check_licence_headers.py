#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""Every source file of the project carries its licence (issue 33): an SPDX line
"SPDX-License-Identifier: MIT" within its first five lines. Source files: C++ (.cpp, .h, .h.in),
Python, shell and CMake files under the project's folders (build folders left out).
Usage: check_licence_headers.py ROOT"""
import pathlib
import sys

FOLDERS = ["engine", "scene", "validation", "render", "tools", "tests", "samples", "fuzz",
           "scripts", "cmake", ".ci"]
SUFFIXES = (".cpp", ".h", ".h.in", ".py", ".sh", ".cmake", ".cmake.in")


def is_source(path: pathlib.Path) -> bool:
    return path.name.endswith(SUFFIXES) or path.name == "CMakeLists.txt" or path.name == "run"


def main() -> int:
    root = pathlib.Path(sys.argv[1])
    missing = []
    checked = 0
    candidates = [root / "CMakeLists.txt"]
    for folder in FOLDERS:
        candidates += sorted((root / folder).rglob("*"))
    for path in candidates:
        if not path.is_file() or not is_source(path):
            continue
        checked += 1
        head = path.read_text(encoding="utf-8", errors="replace").splitlines()[:5]
        if not any("SPDX-License-Identifier: MIT" in line for line in head):
            missing.append(str(path.relative_to(root)))
    for name in missing:
        print(f"FAIL: {name} has no 'SPDX-License-Identifier: MIT' line in its first five lines")
    print(f"{checked - len(missing)} passed, {len(missing)} failed")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
