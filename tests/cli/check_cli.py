#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""CTest cases for the `meff` tool's outputs and its failures (issue 18):

    check_cli.py MEFF SOURCE_DIR WORK_DIR CASE

Each CASE (a function below named case_CASE) runs the tool as a user would and passes when it
does what the documentation (docs/cli.md, docs/validation.md) promises:

* regular output files appear whole or not at all, through a temporary file renamed into
  place; anything else is written through, in place: "-", /dev/stdout, a FIFO, a device; a
  symbolic link's target is written and the link kept;
* every failure is one line on stderr naming the path and the reason, exit status 1 (the run
  failed) or 2 (bad input, nothing run), never an abort;
* SIGINT and SIGTERM leave no temporary file behind.

WORK_DIR is emptied first and holds everything a case writes.
"""
import json
import os
import re
import signal
import stat
import subprocess
import sys
import threading
import time

MEFF, SOURCE, WORK, CASE = sys.argv[1:5]
ROD = os.path.join(SOURCE, "samples", "scenes", "anchored_rod.json")
STACK = os.path.join(SOURCE, "samples", "scenes", "stack10.json")
HEADER = "frame,time,body,x,y,angle,vx,vy,omega"


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def run(args, timeout=120, **kwargs):
    """Runs meff; returns (status, stdout, stderr) as text."""
    done = subprocess.run([MEFF] + args, capture_output=True, text=True, timeout=timeout,
                          **kwargs)
    print("$ meff " + " ".join(args))
    print("status %d\nstdout: %s\nstderr: %s" % (done.returncode, done.stdout[:400],
                                                 done.stderr[:400]))
    return done.returncode, done.stdout, done.stderr


def expect_one_line_error(status, stdout, stderr, expected_status, *needles):
    if status != expected_status:
        fail("exit status %d, expected %d" % (status, expected_status))
    if stderr.count("\n") != 1 or not stderr.endswith("\n"):
        fail("expected one line on stderr, got %r" % stderr)
    for needle in needles:
        if needle not in stderr:
            fail("stderr does not say %r: %r" % (needle, stderr))


def expect_trajectory(text, frames):
    """A trajectory CSV of anchored_rod (one dynamic body) over `frames` steps."""
    lines = text.splitlines()
    if not lines or lines[0] != HEADER:
        fail("the CSV does not start with its header: %r" % text[:200])
    if len(lines) != 1 + frames + 1:
        fail("%d lines, expected %d (header and frames 0 to %d)" % (len(lines), frames + 2,
                                                                    frames))


def leftovers():
    """Hidden temporary files left in WORK."""
    return [name for name in os.listdir(WORK) if name.startswith(".")]


def expect_no_leftovers():
    if leftovers():
        fail("temporary files left behind: %s" % leftovers())


# --- finding 1: outputs that are not regular files are written through ----------------------

def case_fifo():
    """A FIFO given as output is written through and stays a FIFO."""
    fifo = os.path.join(WORK, "fifo")
    os.mkfifo(fifo)
    received = []

    def reader():
        with open(fifo) as stream:
            received.append(stream.read())

    thread = threading.Thread(target=reader, daemon=True)
    thread.start()
    status, _, _ = run(["run", ROD, "--frames", "5", "--trajectory", fifo])
    thread.join(30)
    if status != 0:
        fail("exit status %d" % status)
    if not stat.S_ISFIFO(os.lstat(fifo).st_mode):
        fail("the FIFO was replaced by a regular file")
    expect_trajectory(received[0] if received else "", 5)
    expect_no_leftovers()


def make_device(name, major, minor):
    """A character device node in WORK (as root), else the system's own node."""
    if os.geteuid() == 0:
        path = os.path.join(WORK, name)
        os.mknod(path, 0o666 | stat.S_IFCHR, os.makedev(major, minor))
        return path
    return "/dev/" + name


def case_device():
    """A device given as output (a null device) is written through and stays a device."""
    null = make_device("null", 1, 3)
    status, _, _ = run(["run", ROD, "--frames", "5", "--trajectory", null])
    if status != 0:
        fail("exit status %d" % status)
    if not stat.S_ISCHR(os.lstat(null).st_mode):
        fail("%s was replaced by a regular file" % null)
    expect_no_leftovers()


def case_full_device():
    """A full device (every write fails with ENOSPC): one line naming it, exit status 1, and the
    device is still a device."""
    full = make_device("full", 1, 7)
    status, stdout, stderr = run(["run", ROD, "--frames", "2000", "--trajectory", full])
    expect_one_line_error(status, stdout, stderr, 1, full, "No space left on device")
    if not stat.S_ISCHR(os.lstat(full).st_mode):
        fail("%s was replaced by a regular file" % full)
    expect_no_leftovers()


def case_dev_stdout():
    """/dev/stdout: the CSV on standard output (a pipe here), the summary on standard error."""
    status, stdout, stderr = run(["run", ROD, "--frames", "5", "--trajectory", "/dev/stdout"])
    if status != 0:
        fail("exit status %d" % status)
    expect_trajectory(stdout, 5)
    if "anchored_rod: 2 bodies" not in stderr:
        fail("the summary should go to stderr when stdout carries the CSV")


def case_dash():
    """"-" is standard output."""
    status, stdout, _ = run(["run", ROD, "--frames", "5", "--trajectory", "-"])
    if status != 0:
        fail("exit status %d" % status)
    expect_trajectory(stdout, 5)
    status, _, stderr = run(["run", ROD, "--trajectory", "-", "--joints", "/dev/stdout"])
    expect_one_line_error(status, "", stderr, 2, "same file")


def case_closed_pipe():
    """`meff run ... --trajectory /dev/stdout | head -1`: once the reader is gone the run stops
    with one line on stderr naming the output and the broken pipe, exit status 1."""
    process = subprocess.Popen([MEFF, "run", ROD, "--frames", "100000000", "--trajectory",
                                "/dev/stdout"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               text=True)
    first = process.stdout.readline()
    process.stdout.close()
    try:
        status = process.wait(timeout=60)
    except subprocess.TimeoutExpired:
        process.kill()
        fail("the run went on after its output was closed")
    stderr = process.stderr.read()
    print("first line %r, status %d, stderr %r" % (first, status, stderr))
    if first.strip() != HEADER:
        fail("the first line is not the header")
    expect_one_line_error(status, "", stderr, 1, "/dev/stdout", "Broken pipe")


def case_symlink():
    """A symbolic link given as output: its target is replaced whole, the link kept."""
    target = os.path.join(WORK, "target.csv")
    link = os.path.join(WORK, "link.csv")
    with open(target, "w") as stream:
        stream.write("old\n")
    os.chmod(target, 0o640)
    os.symlink("target.csv", link)
    status, _, _ = run(["run", ROD, "--frames", "5", "--trajectory", link])
    if status != 0:
        fail("exit status %d" % status)
    if not os.path.islink(link) or os.readlink(link) != "target.csv":
        fail("the link was replaced")
    with open(target) as stream:
        expect_trajectory(stream.read(), 5)
    if stat.S_IMODE(os.stat(target).st_mode) != 0o640:
        fail("the target lost its permissions")
    # A link to a file that does not exist yet: the file is created, the link kept.
    dangling = os.path.join(WORK, "dangling.csv")
    os.symlink(os.path.join(WORK, "new.csv"), dangling)
    status, _, _ = run(["run", ROD, "--frames", "5", "--trajectory", dangling])
    if status != 0 or not os.path.islink(dangling):
        fail("a dangling link was not written through")
    with open(os.path.join(WORK, "new.csv")) as stream:
        expect_trajectory(stream.read(), 5)
    expect_no_leftovers()


# --- finding 2: failures of the output path are one line, never an abort --------------------

def case_symlink_loop():
    """Loops of symbolic links, as the output and in its directory: exit status 2, one line."""
    os.symlink("loop2", os.path.join(WORK, "loop1"))
    os.symlink("loop1", os.path.join(WORK, "loop2"))
    for output in (os.path.join(WORK, "loop1"), os.path.join(WORK, "loop1", "out.csv")):
        status, stdout, stderr = run(["run", ROD, "--frames", "5", "--trajectory", output])
        expect_one_line_error(status, stdout, stderr, 2, output, "symbolic links")


def case_unreadable_directory():
    """An output inside a directory the user may not enter: exit status 2, one line. Root
    ignores permissions, so as root the tool runs without the capabilities that let it."""
    locked = os.path.join(WORK, "locked")
    os.mkdir(locked)
    os.chmod(locked, 0)
    prefix = []
    if os.geteuid() == 0:
        prefix = ["setpriv", "--bounding-set", "-dac_override,-dac_read_search", "--"]
    output = os.path.join(locked, "sub", "out.csv")
    done = subprocess.run(prefix + [MEFF, "run", ROD, "--frames", "5", "--trajectory", output],
                          capture_output=True, text=True, timeout=60)
    os.chmod(locked, 0o700)
    print("status %d, stderr %r" % (done.returncode, done.stderr))
    expect_one_line_error(done.returncode, done.stdout, done.stderr, 2, output,
                          "Permission denied")


# --- finding 9: rough edges -----------------------------------------------------------------

def interrupted(signal_number):
    """A long run writing three outputs, stopped by a signal once its temporaries exist: the
    signal ends it (as the signal would) and nothing is left behind."""
    outputs = [os.path.join(WORK, name + ".csv") for name in ("t", "c", "j")]
    process = subprocess.Popen([MEFF, "run", ROD, "--frames", "100000000", "--trajectory",
                                outputs[0], "--contacts", outputs[1], "--joints", outputs[2]],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    deadline = time.time() + 60
    while len(leftovers()) < 3 and time.time() < deadline and process.poll() is None:
        time.sleep(0.05)
    if len(leftovers()) < 3:
        process.kill()
        fail("the run did not start writing its three outputs")
    time.sleep(0.3)  # well into the run
    process.send_signal(signal_number)
    status = process.wait(timeout=60)
    print("status %d, left: %s" % (status, os.listdir(WORK)))
    if status != -signal_number:
        fail("status %d: the run should end by the signal (%d)" % (status, -signal_number))
    expect_no_leftovers()
    if any(os.path.exists(path) for path in outputs):
        fail("an interrupted run wrote an output")


def case_sigterm():
    interrupted(signal.SIGTERM)


def case_sigint():
    interrupted(signal.SIGINT)


def case_dev_zero():
    """An endless file as the scene: refused, not read until memory runs out."""
    status, stdout, stderr = run(["run", "/dev/zero"], timeout=60)
    expect_one_line_error(status, stdout, stderr, 2, "/dev/zero", "not a scene file")


def case_validate_unwritable_report():
    """A report folder that cannot be written is bad input before anything runs: exit status
    2, one line, no scene validated (as `meff run` and `meff render` do)."""
    blocker = os.path.join(WORK, "file")
    with open(blocker, "w") as stream:
        stream.write("a file, so nothing can be created below it\n")
    report = os.path.join(blocker, "reports")
    status, stdout, stderr = run(["validate", STACK, "--report", report, "--no-plot"])
    expect_one_line_error(status, stdout, stderr, 2, report)
    if stdout:
        fail("something ran: %r" % stdout)


def case_box2d_assertions():
    """Numbers that tripped libbox2d's assertions (a circle of radius 1e20: ResetMassData's
    m_I > 0) abort nothing: validate, bench and render --overlay-box2d refuse the scene, exit
    status 2, naming the field."""
    scene = os.path.join(SOURCE, "tests", "bad_scenes", "box2d_assertion.json")
    for args in (["validate", scene, "--no-plot"], ["bench", scene, "--runs", "1", "--frames", "2"],
                 ["render", scene, "--out", os.path.join(WORK, "frames"), "--frames", "1",
                  "--overlay-box2d"]):
        status, stdout, stderr = run(args)
        if status != 2:
            fail("%s: exit status %d, expected 2" % (args[0], status))
        if "bodies[1].shapes[0].radius: too large: its area" not in stderr:
            fail("%s: the radius is not named: %r" % (args[0], stderr))


def case_validate_unmirrored():
    """A scene using a setting Box2D cannot mirror (the colour solver) says so on its line and
    in summary.json's notes, instead of a bare FAIL with "notes": []."""
    import json
    with open(STACK) as stream:
        scene = json.load(stream)
    scene["name"] = "stack10_colour"
    scene.setdefault("world", {})["solver"] = "colour"
    path = os.path.join(WORK, "stack10_colour.json")
    with open(path, "w") as stream:
        json.dump(scene, stream)
    report = os.path.join(WORK, "report")
    status, stdout, _ = run(["validate", path, "--report", report, "--no-plot"])
    line = stdout.splitlines()[0] if stdout else ""
    if 'not mirrored by Box2D: world.solver "colour" (see the notes)' not in line:
        fail("the line does not say what Box2D cannot mirror: %r" % line)
    if "note: world.solver is \"colour\"" not in stdout:
        fail("no note under the line")
    with open(os.path.join(report, "stack10_colour", "summary.json")) as stream:
        summary = json.load(stream)
    if summary["unmirrored"] != ['world.solver "colour"'] or len(summary["notes"]) != 2:
        fail("summary.json: unmirrored %r, notes %r" % (summary.get("unmirrored"),
                                                        summary["notes"]))
    if summary["settle"] is None or summary["passed"] != summary["settle"]["passed"]:
        fail("the settled state is not what was judged")
    if status != (0 if summary["passed"] else 1):
        fail("exit status %d for passed = %s" % (status, summary["passed"]))


def case_bench_threads():
    """--threads is checked up front: exit status 2, one line naming the option. A valid
    --threads N is used and said in the JSON report ("threads")."""
    for command in ("bench", "run"):
        for threads in ("0", "1.5", "1025"):
            status, stdout, stderr = run([command, STACK, "--threads", threads, "--runs", "1",
                                          "--frames", "2"] if command == "bench" else
                                         [command, STACK, "--threads", threads, "--frames", "2"])
            if status != 2 or "--threads" not in stderr or stdout:
                fail("%s --threads %s: status %d" % (command, threads, status))
    report = os.path.join(WORK, "bench.json")
    status, stdout, stderr = run(["bench", STACK, "--threads", "2", "--solver", "colour",
                                  "--against", "none", "--runs", "1", "--frames", "3",
                                  "--json", report])
    if status != 0 or stderr:
        fail("--threads 2: status %d, stderr %r" % (status, stderr))
    with open(report) as text:
        entry = json.load(text)[0]
    if entry.get("threads") != 2:
        fail("the JSON report does not say threads 2: %r" % entry)


def case_run_threads():
    """`meff run --threads N` writes the same bytes for any N: large_pyramid by colour (its
    colours are large enough to be spread over the threads), trajectory and contact impulses
    over 10 frames, on 1, 2 and 3 threads and without the option."""
    with open(os.path.join(SOURCE, "samples", "bench", "large_pyramid.json")) as text:
        scene = json.load(text)
    scene["world"]["solver"] = "colour"
    path = os.path.join(WORK, "large_pyramid_colour.json")
    with open(path, "w") as text:
        json.dump(scene, text)
    outputs = {}
    for threads in (None, "1", "2", "3"):
        name = threads or "default"
        trajectory = os.path.join(WORK, "trajectory_%s.csv" % name)
        contacts = os.path.join(WORK, "contacts_%s.csv" % name)
        args = ["run", path, "--frames", "10", "--trajectory", trajectory, "--contacts",
                contacts] + (["--threads", threads] if threads else [])
        status, stdout, stderr = run(args, timeout=300)
        if status != 0 or stderr:
            fail("--threads %s: status %d, stderr %r" % (threads, status, stderr))
        with open(trajectory, "rb") as a, open(contacts, "rb") as b:
            outputs[name] = (a.read(), b.read())
        if len(outputs[name][0].splitlines()) != 1 + 11 * 5050:
            fail("--threads %s: expected a row per box per frame" % threads)
    for name, output in outputs.items():
        if output != outputs["1"]:
            fail("--threads %s wrote other bytes than --threads 1" % name)


def case_run_save():
    """`meff run --save-at F --save OUT.json` writes the world after frame F as a scene whose
    frames are those left; run, it continues the original run bit for bit (anchored_rod: a
    pendulum, no contact, its joint's impulses carried in the file), every row from frame F on
    the same text; `meff validate` passes it, saying that Box2D 2.4.1 starts it without the saved
    warm start. A frame past the run, or a scene with characters, is bad input: one line,
    exit status 2, nothing written."""
    full = os.path.join(WORK, "full.csv")
    saved = os.path.join(WORK, "rod_100.json")
    status, stdout, stderr = run(["run", ROD, "--trajectory", full, "--save-at", "100",
                                  "--save", saved])
    if status != 0 or stderr:
        fail("status %d, stderr %r" % (status, stderr))
    with open(saved) as text:
        scene = json.load(text)
    if scene["world"]["frames"] != 140 or scene["name"] != "anchored_rod":
        fail("the saved scene's frames or name: %r, %r" % (scene["world"]["frames"],
                                                           scene["name"]))
    rest = os.path.join(WORK, "rest.csv")
    status, stdout, stderr = run(["run", saved, "--trajectory", rest])
    if status != 0 or stderr:
        fail("the saved scene did not run: status %d, stderr %r" % (status, stderr))

    def rows(path, first):
        """frame - first -> the row's state columns (body, x, y, angle, vx, vy, omega)."""
        out = {}
        with open(path) as text:
            for line in text.read().splitlines()[1:]:
                fields = line.split(",")
                if int(fields[0]) >= first:
                    out[int(fields[0]) - first] = fields[2:]
        return out
    original, replayed = rows(full, 100), rows(rest, 0)
    if len(replayed) != 141 or original != replayed:
        differing = [f for f in sorted(replayed) if original.get(f) != replayed[f]]
        fail("the replay differs from the original run from frame 100 + %s" % differing[:3])

    # Validated against Box2D 2.4.1, which cannot be given the saved warm start: both engines
    # start without it, the level passes, and its line says so.
    status, stdout, stderr = run(["validate", saved])
    if status != 0 or "PASS" not in stdout or "saved warm start" not in stdout:
        fail("the saved scene does not validate with its note: status %d, %r" % (status, stdout))

    status, stdout, stderr = run(["run", ROD, "--save-at", "241", "--save",
                                  os.path.join(WORK, "late.json")])
    expect_one_line_error(status, stdout, stderr, 2, "--save-at 241")
    character = os.path.join(SOURCE, "samples", "v3", "capsule_character.json")
    status, stdout, stderr = run(["run", character, "--save", os.path.join(WORK, "c.json")])
    expect_one_line_error(status, stdout, stderr, 2, "characters")
    for name in ("late.json", "c.json"):
        if os.path.exists(os.path.join(WORK, name)):
            fail("%s was written by a refused run" % name)
    expect_no_leftovers()


def case_bench_scenes():
    """Every scene of samples/bench/ loads and steps under each back end, timed by
    `meff bench --against none` (meff alone): one line per scene with its body count, its
    contacts and finite times, and a JSON report that says it ran against nothing."""
    folder = os.path.join(SOURCE, "samples", "bench")
    scenes = sorted(os.path.join(folder, name) for name in os.listdir(folder)
                    if name.endswith(".json"))
    if len(scenes) < 11:
        fail("expected the 11 bench scenes, found %d" % len(scenes))
    bodies = {}
    for path in scenes:
        with open(path) as scene:
            content = json.load(scene)
        bodies[content["name"]] = len(content["bodies"])
    for solver in ("box2d", "colour", "soft_step"):
        report = os.path.join(WORK, solver + ".json")
        status, stdout, stderr = run(["bench"] + scenes + ["--against", "none", "--frames", "3",
                                                           "--runs", "1", "--solver", solver,
                                                           "--json", report], timeout=600)
        if status != 0 or stderr:
            fail("--solver %s: status %d, stderr %r" % (solver, status, stderr))
        lines = stdout.splitlines()
        if (len(lines) != len(scenes) + 2 or "Box2D" in lines[0]
                or "(--against none)" not in lines[-1]):
            fail("--solver %s: expected a header without Box2D, a line per scene and the note "
                 "on meff alone, got %r" % (solver, stdout))
        for line in lines[1:-1]:
            # scene, bodies, contacts | median (min-max), and nothing after: no Box2D columns.
            match = re.fullmatch(r"(\S+) +(\d+) +(\d+) \| +([\d.]+) \( *([\d.]+)- *([\d.]+)\)",
                                 line)
            if not match:
                fail("--solver %s: not a line of meff's times alone: %r" % (solver, line))
            name, count, contacts = match[1], int(match[2]), int(match[3])
            median, low, high = (float(match[i]) for i in (4, 5, 6))
            # Every scene but joint_grid (whose circles never collide) has shapes close enough
            # for a contact. tumbler's boxes start 15 cm apart and fall freely for the first
            # steps: Box2D's 10 cm fat boxes pair them, the 5 cm ones of colour and the soft
            # step (ThroughputCollision) rightly do not.
            touching = (contacts > 0 or (name == "joint_grid" and contacts == 0)
                        or (name == "tumbler" and solver != "box2d" and contacts == 0))
            if count != bodies.get(name) or not touching or not 0 < low <= median <= high:
                fail("--solver %s: line %r (the scene has %s bodies)" % (solver, line,
                                                                          bodies.get(name)))
        with open(report) as text:
            entries = json.load(text)
        if sorted(entry["scene"] for entry in entries) != sorted(bodies):
            fail("--solver %s: the JSON report's scenes %r" % (solver, entries))
        for entry in entries:
            if (entry["against"] != "none" or entry["steps"] != 3 or entry["runs"] != 1
                    or "box2d_ms_per_step" in entry or entry["meff_ms_per_step"]["median"] <= 0):
                fail("--solver %s: JSON entry %r" % (solver, entry))


def case_bench_against_meff_profile():
    """`--against meff:<back end>` pairs meff with itself under another back end, and
    `--profile` splits meff's ms/step into the step's stages. meff against meff with the same
    back end (meff:box2d on a Box2D-order scene) must end at exactly the same positions
    (|dp| 0: the engine is deterministic); the
    stages are non-negative and add up to the step; the JSON names the peer and its keys are
    "peer_..."; an unknown peer is refused up front naming --against."""
    report = os.path.join(WORK, "bench.json")
    status, stdout, stderr = run(["bench", STACK, "--against", "meff:box2d", "--profile",
                                  "--runs", "2", "--frames", "30", "--json", report])
    if status != 0 or stderr:
        fail("status %d, stderr %r" % (status, stderr))
    lines = stdout.splitlines()
    if "meff:box2d ms/step" not in lines[0] or "differ only in their solver" not in lines[-1]:
        fail("header or note: %r" % stdout)
    if not lines[1].rstrip().endswith("0.00e+00"):
        fail("meff against itself must end at the same positions: %r" % lines[1])
    match = re.fullmatch(r"  meff stages ms/step: find contacts ([\d.]+), collide ([\d.]+), "
                         r"solve ([\d.]+), synchronize ([\d.]+), continuous ([\d.]+), "
                         r"other ([\d.]+) \(step ([\d.]+)\)", lines[2])
    if not match:
        fail("not a stage line: %r" % lines[2])
    stages = [float(match[i]) for i in range(1, 7)]
    step = float(match[7])
    # Printed to 4 decimals: six rounded stages and the rounded step, each off by at most
    # 0.00005 ms, agree within 7 × 0.00005 ms (the JSON's full figures are checked below).
    if step <= 0 or float(match[3]) <= 0 or abs(sum(stages) - step) > 7 * 0.00005 + 1e-12:
        fail("stages %r do not add up to the step %r" % (stages, step))
    with open(report) as text:
        entry = json.load(text)[0]
    profile = entry.get("meff_stage_ms_per_step", {})
    if (entry["against"] != "meff:box2d" or "box2d_ms_per_step" in entry
            or entry["peer_ms_per_step"]["median"] <= 0 or entry["max_position_difference_m"] != 0
            or sorted(profile) != sorted(["step", "find_contacts", "collide", "solve",
                                          "synchronize", "continuous", "other"])):
        fail("JSON entry %r" % entry)
    # "other" is the step less the named stages, so in full precision they add up to the step
    # (to double rounding: 1e-9 of it).
    parts = sum(value for key, value in profile.items() if key != "step")
    if abs(parts - profile["step"]) > 1e-9 * profile["step"]:
        fail("the JSON's stages add up to %r, its step is %r" % (parts, profile["step"]))
    status, stdout, stderr = run(["bench", STACK, "--against", "meff:fast", "--runs", "1",
                                  "--frames", "2"])
    if status != 2 or "--against" not in stderr or "meff:fast" not in stderr or stdout:
        fail("--against meff:fast: status %d" % status)


def main():
    if not os.path.isdir(WORK):
        os.makedirs(WORK)
    for name in os.listdir(WORK):
        path = os.path.join(WORK, name)
        if os.path.isdir(path) and not os.path.islink(path):
            os.chmod(path, 0o700)
            subprocess.run(["rm", "-rf", path], check=True)
        else:
            os.remove(path)
    case = globals().get("case_" + CASE)
    if case is None:
        fail("no case %r" % CASE)
    case()
    print("PASS")


main()
