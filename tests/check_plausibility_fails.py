#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""The plausibility checks can fail (issue 31): scenes held to thresholds no solver meets.

tests/plausibility/tight_*.json each set one threshold below what every back end does (a
rebound of 0.01 m/s where Box2D leaves 0.031 m/s, no energy tolerance where the position pass
lifts a box out of the ground, rest for a rolling ball, hold for a box sliding down a
frictionless slope). Under each back end `meff validate` must exit with status 1, print FAIL
for each, name the check in summary.json (value above its limit) and give the JUnit case a
failure of type "plausibility" naming it.

usage: check_plausibility_fails.py MEFF SCENE_DIR OUTPUT_DIR
"""
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

EXPECTED = {"tight_rebound": "rebound", "tight_energy": "energy", "tight_rest": "rest",
            "tight_hold": "hold"}


def main():
    meff, scene_dir, output = sys.argv[1:4]
    scenes = sorted(os.path.join(scene_dir, name + ".json") for name in EXPECTED)
    problems = []
    os.makedirs(output, exist_ok=True)
    for backend in ("box2d", "colour", "soft_step"):
        report = os.path.join(output, backend)
        junit = os.path.join(output, backend + ".xml")
        command = [meff, "validate", *scenes, "--solver", backend, "--report", report,
                   "--junit", junit, "--no-plot", "--jobs", "1"]
        if backend == "box2d":
            command.append("--plausibility")
        run = subprocess.run(command, capture_output=True, text=True)
        print(run.stdout, end="")
        if run.returncode != 1:
            problems.append(f"{backend}: exit status {run.returncode}, expected 1")
        # Cases are named by their files (unique); the scenes' files are named as the scenes.
        cases = {os.path.splitext(os.path.basename(case.get("file")))[0]: case
                 for case in ElementTree.parse(junit).iter("testcase")}
        for name, check in EXPECTED.items():
            if f"FAIL plausibility {name} (solver {backend}," not in run.stdout:
                problems.append(f"{backend} {name}: no FAIL plausibility line")
            with open(os.path.join(report, name, "summary.json")) as f:
                summary = json.load(f)
            result = summary["plausibility"]["checks"][check]
            if result["passed"] or not result["value"] > result["limit"]:
                problems.append(f"{backend} {name}: {check} passed ({result})")
            failure = cases[name].find("failure") if name in cases else None
            if failure is None or failure.get("type") != "plausibility" or \
                    check not in failure.get("message", ""):
                problems.append(f"{backend} {name}: no JUnit failure of type plausibility "
                                f"naming {check}")
            if backend == "box2d" and summary.get("divergence_frame") is not None:
                problems.append(f"box2d {name}: diverged from Box2D 2.4.1")
    for problem in problems:
        print("PROBLEM " + problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
