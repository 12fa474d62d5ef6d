#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""CTest cases for one command line and a run that reports every level (issue 32):

    check_levels.py MEFF SOURCE_DIR WORK_DIR CASE

Each CASE (a function below named case_CASE) runs the tool as a user or a CI job would. WORK_DIR
is emptied first and holds everything a case writes.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

MEFF, SOURCE, WORK, CASE = sys.argv[1:5]
SCENES = os.path.join(SOURCE, "samples", "scenes")
ROD = os.path.join(SCENES, "anchored_rod.json")
STACK = os.path.join(SCENES, "stack10.json")
CAPSULES = os.path.join(SOURCE, "samples", "v3", "capsules.json")
COMMANDS = ("run", "validate", "render", "sweep", "bench")


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def run(args, timeout=300):
    """Runs meff; returns (status, stdout, stderr) as text."""
    done = subprocess.run([MEFF] + args, capture_output=True, text=True, timeout=timeout)
    print("$ meff " + " ".join(args))
    print("status %d\nstdout: %s\nstderr: %s" % (done.returncode, done.stdout[:1500],
                                                 done.stderr[:1500]))
    return done.returncode, done.stdout, done.stderr


def project_version():
    with open(os.path.join(SOURCE, "CMakeLists.txt")) as stream:
        match = re.search(r"project\(meff VERSION ([0-9.]+)", stream.read())
    if not match:
        fail("no project(meff VERSION ...) in CMakeLists.txt")
    return match.group(1)


# --- one command line -------------------------------------------------------------------------

def case_version():
    """`meff --version` prints the project's version (CMakeLists.txt's), exit status 0."""
    status, stdout, _ = run(["--version"])
    if status != 0 or stdout.strip() != "meff " + project_version():
        fail("expected 'meff %s', got %r (status %d)" % (project_version(), stdout, status))


def case_help():
    """Every command's help shows --solver as its three names, never the parser's map
    ("{box2d->0,...} OR {0,1,2}"); run, validate, render and bench say --frames; bench's
    --steps is no longer listed."""
    for command in COMMANDS:
        status, stdout, _ = run([command, "--help"])
        if status != 0:
            fail("%s --help: exit status %d" % (command, status))
        if "--solver box2d|colour|soft_step" not in stdout:
            fail("%s --help does not offer --solver box2d|colour|soft_step" % command)
        if "->" in stdout or " OR " in stdout:
            fail("%s --help shows the parser's internals: %r" % (command, stdout))
        if command != "sweep" and "--frames" not in stdout:
            fail("%s --help has no --frames" % command)
    _, stdout, _ = run(["bench", "--help"])
    if "--steps" in stdout:
        fail("bench --help still lists --steps")


def trajectory(args):
    path = os.path.join(WORK, "trajectory.csv")
    status, _, stderr = run(["run", ROD, "--frames", "30", "--trajectory", path] + args)
    if status != 0:
        fail("run %s: exit status %d: %s" % (args, status, stderr))
    with open(path) as stream:
        return stream.read()


def case_solver_everywhere():
    """--solver is taken by run, validate, render, sweep and bench and changes the back end:
    run's trajectory by the soft step differs from Box2D's order (the rod's joint is solved
    another way), and the same as the scene's world.solver set to soft_step."""
    box2d = trajectory(["--solver", "box2d"])
    soft = trajectory(["--solver", "soft_step"])
    if box2d == soft:
        fail("run --solver soft_step wrote the same trajectory as --solver box2d")
    with open(ROD) as stream:
        scene = json.load(stream)
    scene.setdefault("world", {})["solver"] = "soft_step"
    path = os.path.join(WORK, "rod_soft.json")
    with open(path, "w") as stream:
        json.dump(scene, stream)
    out = os.path.join(WORK, "trajectory.csv")
    status, _, _ = run(["run", path, "--frames", "30", "--trajectory", out])
    with open(out) as stream:
        if status != 0 or stream.read() != soft:
            fail("--solver soft_step does not run what world.solver soft_step runs")
    # validate holds a back end Box2D cannot mirror to the plausibility checks (docs/validation.md)
    status, stdout, _ = run(["validate", ROD, "--frames", "30", "--solver", "colour",
                             "--no-plot"])
    if status not in (0, 1) or "plausibility" not in stdout or "colour" not in stdout:
        fail("validate --solver colour does not say it checked the colour back end: %r" % stdout)
    frames = os.path.join(WORK, "frames")
    status, _, _ = run(["render", ROD, "--out", frames, "--frames", "2", "--size", "64x48",
                        "--solver", "soft_step"])
    if status != 0 or len([n for n in os.listdir(frames) if n.endswith(".png")]) != 3:
        fail("render --solver soft_step did not write frames 0 to 2")
    status, stdout, _ = run(["bench", ROD, "--frames", "5", "--runs", "1", "--against", "none",
                             "--solver", "colour"])
    if status != 0:
        fail("bench --solver colour --frames 5: exit status %d" % status)
    sweep = os.path.join(WORK, "sweep")
    status, _, _ = run(["sweep", ROD, "--quick", "--seconds", "0.2", "--no-plot", "--out", sweep,
                        "--solver", "soft_step"])
    with open(os.path.join(sweep, "sweep.csv")) as stream:
        rows = list(csv_rows(stream.read()))
    solvers = {row["solver"] for row in rows}
    if status != 0 or solvers != {"soft_step"}:
        fail("sweep --solver soft_step ran settings of %s" % sorted(solvers))
    status, _, stderr = run(["run", ROD, "--solver", "bogus"])
    if status != 2 or "bogus" not in stderr:
        fail("--solver bogus: expected exit status 2 naming it, got %d: %r" % (status, stderr))


def csv_rows(text):
    lines = text.splitlines()
    header = lines[0].split(",")
    for line in lines[1:]:
        yield dict(zip(header, line.split(",")))


def case_bench_steps_deprecated():
    """bench's --steps still works as --frames does, with one warning line naming --frames."""
    status, _, stderr = run(["bench", ROD, "--steps", "5", "--runs", "1", "--against", "none"])
    if status != 0 or "--steps is deprecated, use --frames" not in stderr:
        fail("bench --steps: status %d, stderr %r" % (status, stderr))


# --- a run that reports every level -----------------------------------------------------------

def make_levels():
    """A folder as a CI job finds it: two good levels with the same internal name, a broken
    level (a typo in a field's value), a Box2D v3 level (capsules), and a good b2dJson level."""
    levels = os.path.join(WORK, "levels")
    os.makedirs(os.path.join(levels, "more"))
    shutil.copy(STACK, os.path.join(levels, "a_stack.json"))
    shutil.copy(STACK, os.path.join(levels, "more", "a_stack.json"))
    with open(STACK) as stream:
        broken = json.load(stream)
    broken["bodies"][1]["type"] = "dynamc"
    with open(os.path.join(levels, "broken.json"), "w") as stream:
        json.dump(broken, stream)
    shutil.copy(CAPSULES, os.path.join(levels, "capsules.json"))
    return [os.path.join(levels, "a_stack.json"), os.path.join(levels, "broken.json"),
            os.path.join(levels, "capsules.json"), os.path.join(levels, "more", "a_stack.json")]


def case_validate_every_level():
    """`meff validate` of a folder holding a broken level and a v3-only level: every level is
    reported (PASS, ERROR, SKIP on stdout; a JUnit case each, named by its file, unique; a
    summary.json each under --report), the good ones run, exit status 2 (a level could not be
    loaded); --junit's missing folders are created; the JUnit file and every summary carry
    meff's version."""
    paths = make_levels()
    junit = os.path.join(WORK, "out", "deeper", "validate.xml")
    report = os.path.join(WORK, "report")
    status, stdout, stderr = run(["validate"] + paths + ["--frames", "20", "--junit", junit,
                                                         "--report", report, "--no-plot"])
    if status != 2:
        fail("exit status %d, expected 2 (a level could not be loaded)" % status)
    lines = [line for line in stdout.splitlines() if not line.startswith(" ")]
    expected = ["PASS ", "ERROR " + paths[1], "SKIP " + paths[2], "PASS "]
    for line, start in zip(lines, expected):
        if not line.startswith(start):
            fail("expected a line starting %r, got %r" % (start, line))
    if "bodies[1].type" not in stderr or "capsule" not in stdout:
        fail("the broken level's field (stderr) or the capsule (stdout) is not named")
    root = ElementTree.parse(junit).getroot()
    suite = root.find("testsuite")
    cases = suite.findall("testcase")
    names = [case.get("name") for case in cases]
    if names != paths:
        fail("the test cases are not named by their files: %s" % names)
    if (suite.get("tests"), suite.get("errors"), suite.get("skipped"), suite.get("failures")) != \
            ("4", "1", "1", "0"):
        fail("counts tests/errors/skipped/failures: %s" % dict(suite.attrib))
    if cases[1].find("error") is None or "bodies[1].type" not in cases[1].find("error").text:
        fail("the broken level's case has no <error> naming the field")
    if cases[2].find("skipped") is None or "capsule" not in cases[2].find("skipped").get(
            "message"):
        fail("the capsule level's case is not <skipped> with the reason")
    version = project_version()
    prop = suite.find("properties/property[@name='meff.version']")
    if prop is None or prop.get("value") != version:
        fail("the JUnit file does not carry meff.version %s" % version)
    statuses = []
    for name in sorted(os.listdir(report)):
        summary_path = os.path.join(report, name, "summary.json")
        if not os.path.isfile(summary_path):
            continue
        with open(summary_path) as stream:
            summary = json.load(stream)
        if summary.get("meff_version") != version:
            fail("%s does not carry meff_version %s" % (summary_path, version))
        statuses.append(summary["status"])
    if sorted(statuses) != ["error", "passed", "passed", "skipped"]:
        fail("summaries: %s" % statuses)
    # The good levels alone pass: exit status 0; a v3 level alone is skipped, not failed.
    status, _, _ = run(["validate", paths[0], paths[2], "--frames", "20", "--no-plot"])
    if status != 0:
        fail("a passing level and a skipped one: exit status %d, expected 0" % status)


def case_validate_unmirrored_wording():
    """A scene whose own back end Box2D cannot mirror (world.solver soft_step) never prints
    "PASS ... diverged at frame 1": the line says what was compared (frame 0 and the settled
    state) and that frames were not judged."""
    with open(STACK) as stream:
        scene = json.load(stream)
    scene.setdefault("world", {})["solver"] = "soft_step"
    path = os.path.join(WORK, "stack_soft.json")
    with open(path, "w") as stream:
        json.dump(scene, stream)
    status, stdout, _ = run(["validate", path, "--no-plot"])
    line = stdout.splitlines()[0]
    if status != 0 or not line.startswith("PASS "):
        fail("stack10 by the soft step should settle where Box2D does: %r" % line)
    if "diverged" in line:
        fail("a PASS line says diverged: %r" % line)
    if "compared: frame 0 and the settled state" not in line or "not judged" not in line:
        fail("the line does not say what was compared: %r" % line)


if __name__ == "__main__":
    shutil.rmtree(WORK, ignore_errors=True)
    os.makedirs(WORK)
    globals()["case_" + CASE]()
    print("PASS: " + CASE)
