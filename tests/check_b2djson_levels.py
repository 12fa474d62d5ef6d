#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""CTest (issue 20, the CI job for Box2D users' levels):
check_b2djson_levels.py MEFF LEVEL_DIR WORK_DIR SAMPLE_SCENE

What a team's CI does with a folder of R.U.B.E. levels, on the hand-written b2dJson levels of
LEVEL_DIR (every body, fixture and joint kind, every convention of the format):
  * `meff import` converts each level (exit status 0; what meff leaves out is said on stderr,
    one "warning:" line each) and the meff scene it writes runs;
  * `meff validate --jobs 2 --junit` takes the folder of levels directly (recognized by their
    content) and every level passes against Box2D 2.4.1; the JUnit XML is well-formed, has one
    test case per level, names each level's file, and counts no failure or error;
  * `meff export` of a sample scene gives a level that `meff run` takes directly and that
    imports back; `meff render`, `bench` and `sweep` take a level directly too (by content, and
    with `--format b2djson`); `--format b2djson` forced on a meff scene is refused (exit
    status 2).
"""
import glob
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

MEFF, LEVELS, WORK, SAMPLE = sys.argv[1:5]


def run(arguments, expect=0):
    completed = subprocess.run([MEFF] + arguments, capture_output=True, text=True)
    if completed.returncode != expect:
        sys.exit(f"FAIL: meff {' '.join(arguments)} exited {completed.returncode}, expected "
                 f"{expect}\nstdout:\n{completed.stdout}\nstderr:\n{completed.stderr}")
    return completed


shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)
levels = sorted(glob.glob(os.path.join(LEVELS, "*.json")))
if len(levels) < 3:
    sys.exit(f"FAIL: expected the hand-written levels in {LEVELS}, found {levels}")

for level in levels:
    scene = os.path.join(WORK, "imported-" + os.path.basename(level))
    imported = run(["import", level, "-o", scene])
    for line in imported.stderr.splitlines():
        if not line.startswith(level + ": warning: "):
            sys.exit(f"FAIL: import of {level} printed a line that is not a warning: {line!r}")
    run(["run", scene, "--frames", "30"])

junit = os.path.join(WORK, "levels.xml")
validated = run(["validate", "--jobs", "2", "--junit", junit, "--no-plot"] + levels)
root = ElementTree.parse(junit).getroot()
suites = root.findall("testsuite")
if root.tag != "testsuites" or len(suites) != 1:
    sys.exit("FAIL: the JUnit file is not one <testsuite> inside <testsuites>")
cases = suites[0].findall("testcase")
if len(cases) != len(levels) or suites[0].get("tests") != str(len(levels)):
    sys.exit(f"FAIL: {len(levels)} levels, but {len(cases)} test cases "
             f"(tests=\"{suites[0].get('tests')}\")")
if suites[0].get("failures") != "0" or suites[0].get("errors") != "0":
    sys.exit("FAIL: a level failed validation:\n" + validated.stdout)
if sorted(case.get("file") for case in cases) != levels:
    sys.exit(f"FAIL: the test cases do not name the level files: "
             f"{[case.get('file') for case in cases]}")
for case in cases:
    if case.find("failure") is not None or case.find("error") is not None:
        sys.exit(f"FAIL: {case.get('name')} has a failure or error element")
    if not (case.findtext("system-out") or "").startswith("PASS "):
        sys.exit(f"FAIL: {case.get('name')}'s output does not start with PASS")

level = os.path.join(WORK, "exported.json")
run(["export", SAMPLE, "-o", level])
run(["run", level, "--frames", "30"])
run(["import", level, "-o", os.path.join(WORK, "back.json")])
# The other commands take a level directly too, by its content and with --format b2djson.
first = levels[0]
frames = os.path.join(WORK, "frames")
run(["render", first, "--frames", "2", "--size", "80x60", "--out", frames])
if sorted(os.listdir(frames)) != [f"frame_{k:05d}.png" for k in range(3)]:
    sys.exit(f"FAIL: render of {first} wrote {sorted(os.listdir(frames))}")
benched = run(["bench", "--format", "b2djson", first, "--frames", "10", "--runs", "1"])
if os.path.splitext(os.path.basename(first))[0] not in benched.stdout:
    sys.exit(f"FAIL: bench of {first} does not name it:\n{benched.stdout}")
swept = os.path.join(WORK, "sweep")
run(["sweep", level, "--format", "b2djson", "--quick", "--no-plot", "--shard", "1/9", "--out",
     swept])
if not os.path.isfile(os.path.join(swept, "sweep.csv")):
    sys.exit(f"FAIL: sweep of {level} wrote no sweep.csv")
refused = run(["run", SAMPLE, "--format", "b2djson"], expect=2)
if SAMPLE not in refused.stderr:
    sys.exit(f"FAIL: forcing b2djson on a meff scene should name the file: {refused.stderr!r}")
print(f"b2dJson levels: {len(levels)} imported and validated with --jobs 2 --junit "
      f"({len(cases)} passing test cases); {os.path.basename(SAMPLE)} exported, run, swept and "
      "imported back; a level rendered and benched")
