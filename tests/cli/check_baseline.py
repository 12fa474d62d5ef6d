#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""CTest cases for `meff validate --baseline DIR` (issue 32): a run of meff's own back ends
recorded once and compared with later runs (docs/validation.md, "Baselines").

    check_baseline.py MEFF SOURCE_DIR WORK_DIR CASE

Each CASE (a function below named case_CASE) runs the tool in WORK_DIR (emptied first), on
copies of bundled scenes under WORK_DIR/levels, with the baselines in WORK_DIR/base.
"""
import gzip
import json
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

MEFF, SOURCE, WORK, CASE = sys.argv[1:5]
SCENES = os.path.join(SOURCE, "samples", "scenes")
BACK_ENDS = ("box2d", "colour", "soft_step")


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def run(args, timeout=300):
    """Runs meff in WORK; returns (status, stdout, stderr) as text."""
    done = subprocess.run([MEFF] + args, capture_output=True, text=True, timeout=timeout,
                          cwd=WORK)
    print("$ meff " + " ".join(args))
    print("status %d\nstdout: %s\nstderr: %s" % (done.returncode, done.stdout[:2000],
                                                 done.stderr[:2000]))
    return done.returncode, done.stdout, done.stderr


def level(name, edit=None):
    """Copies samples/scenes/NAME.json to levels/NAME.json (changed by `edit`, a function of
    the scene's JSON, when given); returns its path relative to WORK."""
    os.makedirs(os.path.join(WORK, "levels"), exist_ok=True)
    path = os.path.join("levels", name + ".json")
    with open(os.path.join(SCENES, name + ".json")) as stream:
        scene = json.load(stream)
    if edit:
        edit(scene)
    with open(os.path.join(WORK, path), "w") as stream:
        json.dump(scene, stream, indent=2)
    return path


def baseline_file(path):
    return os.path.join(WORK, "base", path + ".baseline.gz")


def record(paths, back_end):
    status, stdout, _ = run(["validate", "--baseline", "base", "--record", "--solver", back_end]
                            + paths)
    if status != 0 or stdout.count("RECORDED ") != len(paths):
        fail("recording %s with %s: status %d" % (paths, back_end, status))


def lower_gravity(scene):
    scene.setdefault("world", {})["gravity"] = [0, -9.5]


def one_error_line(stderr, path, words):
    """stderr is one line naming the baseline file and saying `words`."""
    lines = stderr.strip().splitlines()
    if len(lines) != 1 or baseline_file(path) not in os.path.join(WORK, lines[0].split(":")[0]) \
            or words not in lines[0]:
        fail("expected one line naming %s and saying %r, got %r" % (baseline_file(path), words,
                                                                     stderr))


def case_record_compare():
    """Under each back end, a recorded run compared again with --bit-exact passes with every
    error exactly 0 (the same build repeats itself bit for bit); the file is gzip whose first
    lines say the format and the header (back end, scene hash, frames); and with the default
    tolerances it passes too."""
    paths = [level("stack10"), level("chain20"), level("pulley_elevator")]
    for back_end in BACK_ENDS:
        shutil.rmtree(os.path.join(WORK, "base"), ignore_errors=True)
        record(paths, back_end)
        with gzip.open(baseline_file(paths[0])) as stream:
            magic = stream.readline().decode()
            header = json.loads(stream.readline())
        if magic != "meff-baseline 1\n" or header["back_end"] != back_end or \
                not header["scene_hash"].startswith("fnv1a64:") or header["frames"] != 300:
            fail("baseline header: %r %r" % (magic, header))
        for extra in (["--bit-exact"], []):
            status, stdout, _ = run(["validate", "--baseline", "base", "--solver", back_end,
                                     "--report", "report"] + extra + paths)
            lines = [line for line in stdout.splitlines() if not line.startswith(" ")]
            if status != 0 or len([line for line in lines if line.startswith("PASS ")]) != 3:
                fail("%s %s: expected three PASS lines, status 0" % (back_end, extra))
            for name in ("stack10", "chain20", "pulley_elevator"):
                with open(os.path.join(WORK, "report", name, "summary.json")) as stream:
                    summary = json.load(stream)
                errors = [summary["max_" + quantity + "_error"] for quantity in
                          ("position", "angle", "velocity", "contact_impulse", "joint_impulse")]
                if summary["reference"] != "baseline" or any(errors):
                    fail("%s %s: errors %s, reference %s" % (back_end, name, errors,
                                                             summary["reference"]))


def case_perturbed():
    """A run that differs from its baseline fails with the first divergent frame: the scene's
    gravity lowered after recording (compared with --accept-scene-change) diverges at frame 1;
    fewer velocity iterations in the colour back end (the hidden --meff-velocity-iterations)
    diverge once contacts act. Exit status 1."""
    path = level("stack10")
    record([path], "colour")
    level("stack10", lower_gravity)
    status, stdout, _ = run(["validate", "--baseline", "base", "--solver", "colour",
                             "--accept-scene-change", path])
    if status != 1 or not stdout.startswith("FAIL ") or "diverged at frame 1 (" not in stdout:
        fail("lower gravity: expected FAIL diverged at frame 1, status 1")
    if "scene file differs from the one recorded" not in stdout:
        fail("the accepted scene change is not noted")
    level("stack10")
    status, stdout, _ = run(["validate", "--baseline", "base", "--solver", "colour",
                             "--meff-velocity-iterations", "2", path])
    if status != 1 or not stdout.startswith("FAIL ") or "diverged at frame " not in stdout:
        fail("2 velocity iterations: expected FAIL with a divergence frame, status 1")
    # Looser limits are taken: the lowered gravity moves the stack at most 1.2 mm, 0.017 m/s
    # and 0.059 N·s over its 300 frames (measured), within 1 cm, 0.1 m/s and 0.1 N·s.
    level("stack10", lower_gravity)
    status, stdout, _ = run(["validate", "--baseline", "base", "--solver", "colour",
                             "--accept-scene-change", "--tolerance", "position=0.01",
                             "--tolerance", "velocity=0.1", "--tolerance", "impulse=0.1", path])
    if status != 0 or not stdout.startswith("PASS "):
        fail("loose --tolerance: expected PASS")


def case_damaged():
    """A truncated, a corrupted and a foreign baseline file, one whose header promises frames it
    lacks and one of another format version each give one line on stderr naming the file and
    what is wrong, an ERROR case, exit status 2; the other level still runs."""
    paths = [level("stack10"), level("chain20")]
    record(paths, "soft_step")
    with open(baseline_file(paths[0]), "rb") as stream:
        good = stream.read()
    # The gzip trailer's CRC-32 changed: the data no longer matches its check.
    crc = len(good) - 8
    header = {"format_version": 1, "meff_version": "0", "back_end": "soft_step",
              "scene": "stack10", "scene_hash": "fnv1a64:0", "settings": {}, "frames": 300,
              "bodies": 11, "joints": 0}
    damages = {"truncated (the compressed data ends early)": good[: len(good) // 2],
               "corrupt (zlib: incorrect data check)":
                   good[:crc] + bytes([good[crc] ^ 0xFF]) + good[crc + 1:],
               "not a meff baseline (not gzip data)": b"{\"hello\": 1}\n",
               "truncated (its frames end early)":
                   gzip.compress(b"meff-baseline 1\n" + json.dumps(header).encode() + b"\n"),
               "format 2, this meff reads 1": gzip.compress(b"meff-baseline 2\n")}
    for words, data in damages.items():
        with open(baseline_file(paths[0]), "wb") as stream:
            stream.write(data)
        status, stdout, stderr = run(["validate", "--baseline", "base", "--solver", "soft_step"]
                                     + paths)
        one_error_line(stderr, paths[0], words)
        if status != 2 or not stdout.startswith("ERROR " + paths[0]) or \
                "\nPASS chain20" not in stdout:
            fail("%s: expected ERROR for the first level, PASS for the second, status 2" % words)


def case_mismatch():
    """A baseline is refused, one line naming the file and what differs, when recorded with
    another back end, from another version of the scene file (its hash), with other world
    settings or frames; a missing baseline is an ERROR case; the other level still runs."""
    paths = [level("stack10"), level("chain20")]
    record(paths, "colour")
    checks = [(["--solver", "soft_step"], "back end colour, this run has soft_step"),
              (["--solver", "colour", "--frames", "30"], "frames 300, this run has 30"),
              (["--solver", "colour", "--block-solver", "off"], "world.block_solver true")]
    for args, words in checks:
        status, stdout, stderr = run(["validate", "--baseline", "base"] + args + paths[:1])
        one_error_line(stderr, paths[0], words)
        if status != 2 or not stdout.startswith("ERROR "):
            fail("%s: expected an ERROR case, status 2" % args)
    level("stack10", lower_gravity)
    status, stdout, stderr = run(["validate", "--baseline", "base", "--solver", "colour"]
                                 + paths)
    one_error_line(stderr, paths[0], "another version of the scene file")
    if status != 2 or "\nPASS chain20" not in stdout:
        fail("scene changed: expected ERROR then PASS, status 2")
    status, stdout, stderr = run(["validate", "--baseline", "base", "--solver", "colour",
                                  level("weld_beam"), paths[1]])
    one_error_line(stderr, "levels/weld_beam.json", "no baseline recorded")
    if status != 2 or "\nPASS chain20" not in stdout:
        fail("missing baseline: expected ERROR then PASS, status 2")


def case_reports():
    """--junit and --report with a passing, a diverging and a missing baseline: one JUnit case
    each, named by its file (two levels of one name in two folders stay apart), the failure
    giving the frame; index.html a row each, PASS, FAIL with its first divergent frame, ERROR;
    bad options refused."""
    paths = [level("stack10"), level("chain20")]
    os.makedirs(os.path.join(WORK, "levels", "more"))
    shutil.copy(os.path.join(WORK, paths[0]), os.path.join(WORK, "levels", "more"))
    paths.append(os.path.join("levels", "more", "stack10.json"))
    record(paths[:2], "soft_step")
    level("chain20", lower_gravity)
    status, stdout, _ = run(["validate", "--baseline", "base", "--solver", "soft_step",
                             "--accept-scene-change", "--junit", "out/baseline.xml",
                             "--report", "report"] + paths)
    if status != 2:
        fail("expected exit status 2 (a baseline missing)")
    suite = ElementTree.parse(os.path.join(WORK, "out", "baseline.xml")).getroot()[0]
    cases = suite.findall("testcase")
    if [case.get("name") for case in cases] != paths:
        fail("JUnit cases not named by their paths")
    failure = cases[1].find("failure")
    if cases[0].find("failure") is not None or failure is None or \
            "diverged from baseline at frame 1" not in failure.get("message") or \
            cases[2].find("error") is None or cases[2].find("error").get("type") != "baseline":
        fail("JUnit outcomes: expected passed, failure at frame 1, error")
    with open(os.path.join(WORK, "report", "index.html")) as stream:
        page = stream.read()
    rows = page.split("<tbody>")[1].split("</tbody>")[0].split("</tr>")[:-1]
    if len(rows) != 3 or "PASS" not in rows[0] or "FAIL" not in rows[1] or \
            "<td>1</td>" not in rows[1] or "ERROR" not in rows[2]:
        fail("index.html rows: %s" % rows)
    if "against the baselines in base" not in page:
        fail("the page does not say what the levels were compared with")
    for args in (["--tolerance", "position=-1"], ["--tolerance", "size=1"], ["--record"]):
        extra = [] if "--record" in args else ["--baseline", "base"]
        status, _, stderr = run(["validate"] + extra + args + paths[:1])
        if status != 2 or not stderr:
            fail("%s: expected a refusal, exit status 2" % args)


if __name__ == "__main__":
    shutil.rmtree(WORK, ignore_errors=True)
    os.makedirs(WORK)
    globals()["case_" + CASE]()
    print("PASS: " + CASE)
