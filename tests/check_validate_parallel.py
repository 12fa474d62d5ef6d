#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""CTest for `meff validate --jobs/--shard/--junit` (issue 20):
check_validate_parallel.py MEFF WORK_DIR SCENE...

Passes when, on the given scenes:
  * --jobs 2 prints exactly what --jobs 1 prints and writes the same report files byte for
    byte (summary.json, divergence.csv) and the same JUnit XML apart from its time attributes
    (wall clock, which differs between any two runs);
  * --shard 1/3, 2/3, 3/3 together validate every scene exactly once, each shard's JUnit file
    is well-formed, and the shards' <testsuite> blocks merged as docs/validation.md's
    "Regression runs" says hold every scene once;
  * a scene made to diverge (meff at 4 velocity iterations against Box2D's 8) is a JUnit
    <failure> naming the divergence frame, the quantity, where, and both engines' values, and
    the scene's summary.json lists the same details;
  * bad --shard and --jobs values, and a JUnit file that cannot be written, are refused with
    exit status 2 before anything runs.
"""
import filecmp
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

MEFF, WORK = sys.argv[1], sys.argv[2]
SCENES = sys.argv[3:]
FRAMES = "60"  # enough steps for contacts and joints to act; keeps the test short


def run(arguments, expect):
    completed = subprocess.run([MEFF] + arguments, capture_output=True, text=True)
    if completed.returncode != expect:
        sys.exit(f"FAIL: meff {' '.join(arguments)} exited {completed.returncode}, expected "
                 f"{expect}\nstdout:\n{completed.stdout}\nstderr:\n{completed.stderr}")
    return completed.stdout


def without_times(xml_text):
    return re.sub(r' time="[0-9.]+"', "", xml_text)


def same_tree(a, b):
    comparison = filecmp.dircmp(a, b)
    differing = comparison.diff_files + comparison.left_only + comparison.right_only
    if differing:
        sys.exit(f"FAIL: {a} and {b} differ: {differing}")
    for sub in comparison.common_dirs:
        same_tree(os.path.join(a, sub), os.path.join(b, sub))
    # dircmp compares shallowly (size and time): compare contents for real.
    for name in comparison.common_files:
        with open(os.path.join(a, name), "rb") as fa, open(os.path.join(b, name), "rb") as fb:
            if fa.read() != fb.read():
                sys.exit(f"FAIL: {a}/{name} differs between --jobs 1 and --jobs 2")


def cases(path):
    root = ElementTree.parse(path).getroot()
    if root.tag != "testsuites":
        sys.exit(f"FAIL: {path}: root element is {root.tag}, not testsuites")
    return [case.get("name") for case in root.iter("testcase")]


shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)
common = ["validate", "--frames", FRAMES, "--no-plot"] + SCENES
outputs = {}
for jobs in ("1", "2"):
    report = os.path.join(WORK, "report-" + jobs)
    junit = os.path.join(WORK, "junit-" + jobs + ".xml")
    stdout = run(common + ["--jobs", jobs, "--report", report, "--junit", junit], 0)
    outputs[jobs] = (stdout.replace(report, "REPORT"), report, junit)
if outputs["1"][0] != outputs["2"][0]:
    sys.exit("FAIL: --jobs 2 printed something else than --jobs 1:\n" + outputs["1"][0] +
             "\n---\n" + outputs["2"][0])
same_tree(outputs["1"][1], outputs["2"][1])
with open(outputs["1"][2]) as one, open(outputs["2"][2]) as two:
    if without_times(one.read()) != without_times(two.read()):
        sys.exit("FAIL: the JUnit files of --jobs 1 and --jobs 2 differ beyond time attributes")
names = cases(outputs["1"][2])
if len(names) != len(SCENES) or len(set(names)) != len(names):
    sys.exit(f"FAIL: {len(SCENES)} scenes gave JUnit cases {names}")

# Shards: every scene exactly once over the three, and the merge recipe works.
shard_cases = []
merged = ['<?xml version="1.0" encoding="UTF-8"?>', "<testsuites>"]
for index in (1, 2, 3):
    junit = os.path.join(WORK, f"shard-{index}.xml")
    run(common + ["--shard", f"{index}/3", "--junit", junit], 0)
    shard_cases += cases(junit)
    with open(junit) as text:
        inside = False
        for line in text.read().splitlines():
            inside = inside or line.startswith("<testsuite ")
            if inside:
                merged.append(line)
            inside = inside and line != "</testsuite>"
merged.append("</testsuites>")
if sorted(shard_cases) != sorted(names):
    sys.exit(f"FAIL: the shards validated {sorted(shard_cases)}, not each of {sorted(names)} "
             "once")
merged_path = os.path.join(WORK, "merged.xml")
with open(merged_path, "w") as out:
    out.write("\n".join(merged) + "\n")
if sorted(cases(merged_path)) != sorted(names):
    sys.exit("FAIL: the merged shards do not hold every scene once")

# A failure says where and what, with both engines' values.
junit = os.path.join(WORK, "failing.xml")
report = os.path.join(WORK, "failing")
run(["validate", SCENES[0], "--frames", FRAMES, "--no-plot", "--meff-velocity-iterations", "4",
     "--junit", junit, "--report", report], 1)
failures = list(ElementTree.parse(junit).getroot().iter("failure"))
if len(failures) != 1:
    sys.exit(f"FAIL: expected one <failure>, got {len(failures)}")
message, text = failures[0].get("message"), failures[0].text or ""
match = re.match(r"diverged from Box2D at frame (\d+): (\w+)", message)
if not match:
    sys.exit(f"FAIL: failure message without frame and quantity: {message!r}")
frame, quantity = match.groups()
detail = re.search(rf"frame {frame}: {quantity} \S+ > \S+ at (\S+): meff (.+), Box2D (.+)", text)
if not detail or detail.group(2) == detail.group(3):
    sys.exit(f"FAIL: failure text does not give where and both (differing) values: {text!r}")
import json  # noqa: E402 (only needed here)
folders = [name for name in os.listdir(report) if os.path.isdir(os.path.join(report, name))]
with open(os.path.join(report, folders[0], "summary.json")) as summary_file:
    summary = json.load(summary_file)
if not summary["divergence"] or summary["divergence"][0]["quantity"] != quantity:
    sys.exit(f"FAIL: summary.json's divergence does not match: {summary['divergence']}")

for bad in (["--shard", "0/3"], ["--shard", "4/3"], ["--shard", "1-3"], ["--jobs", "0"],
            # (a missing folder is created; one under a regular file cannot be)
            ["--junit", os.path.join(junit, "under", "a_file.xml")]):
    run(["validate", SCENES[0], "--no-plot"] + bad, 2)
print(f"validate --jobs/--shard/--junit: {len(SCENES)} scenes, jobs 1 = jobs 2, 3 shards cover "
      f"each once, failure at frame {frame} ({quantity} at {detail.group(1)})")
