#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""CTest (issue 20): check_progress.py MEFF SOURCE_DIR WORK_DIR

A long run shows its progress on a terminal and stays quiet when not on one. For `meff
validate` (scenes), `meff render` (frames) and `meff sweep` (settings):
  * with stderr on a terminal (a pseudo-terminal), stderr carries the progress line, redrawn
    in place: "LABEL [###...] DONE/TOTAL UNIT, M:SS elapsed", with ", ~M:SS left" while work
    remains; it reaches TOTAL/TOTAL and the line is ended with a newline;
  * with stderr not a terminal (a pipe, as in CI logs), stderr holds no progress at all;
  * stdout and the files written are the same either way (wall-clock times aside; for sweep,
    whose Pareto fronts are chosen by timings, the table's header and rows).
"""
import os
import pty
import re
import shutil
import subprocess
import sys

MEFF, SOURCE, WORK = sys.argv[1:4]
SCENES = [os.path.join(SOURCE, "samples", "scenes", name)
          for name in ("bouncing_ball.json", "pendulum_rod.json", "stack10.json")]


def run(arguments, terminal):
    """Runs meff; returns (stdout, stderr), stderr read from a pseudo-terminal if asked."""
    if not terminal:
        completed = subprocess.run([MEFF] + arguments, capture_output=True, text=True)
        if completed.returncode != 0:
            sys.exit(f"FAIL: meff {' '.join(arguments)} exited {completed.returncode}\n"
                     f"{completed.stderr}")
        return completed.stdout, completed.stderr
    master, slave = pty.openpty()
    process = subprocess.Popen([MEFF] + arguments, stdout=subprocess.PIPE, stderr=slave)
    os.close(slave)
    seen = b""
    while True:
        try:
            chunk = os.read(master, 4096)
        except OSError:  # EIO: the terminal's last writer has gone
            break
        if not chunk:
            break
        seen += chunk
    os.close(master)
    stdout = process.stdout.read().decode()
    if process.wait() != 0:
        sys.exit(f"FAIL: meff {' '.join(arguments)} exited {process.returncode}\n"
                 f"{seen.decode(errors='replace')}")
    # The terminal turns "\n" into "\r\n"; progress lines start with a bare "\r".
    return stdout, seen.decode().replace("\r\n", "\n")


def files(folder):
    return {name: open(os.path.join(folder, name), "rb").read()
            for name in sorted(os.listdir(folder))}


def untimed(text):
    """The text with its numbers and their padding masked: render and sweep print wall-clock
    times, and a time with no digits after the point ("25", as %g prints it) is one too."""
    return re.sub(r" *\d+(\.\d+)?([eE][-+]?\d+)?", " #", text)


def check(name, label, total, unit, arguments, out_folder=None, timed=False, head=None):
    quiet_out = on_tty_out = None  # the files written, when the command writes frames
    results = {}
    for terminal in (False, True):
        if out_folder is not None:
            shutil.rmtree(out_folder, ignore_errors=True)
        results[terminal] = run(arguments, terminal)
        if out_folder is not None:
            written = files(out_folder)
            if terminal:
                on_tty_out = written
            else:
                quiet_out = written
    (quiet_stdout, quiet_stderr), (tty_stdout, tty_stderr) = results[False], results[True]
    if "\r" in quiet_stderr or "elapsed" in quiet_stderr:
        sys.exit(f"FAIL: {name}: progress written to a pipe: {quiet_stderr!r}")
    if timed:
        quiet_stdout, tty_stdout = untimed(quiet_stdout), untimed(tty_stdout)
    if head is not None:
        quiet_stdout = quiet_stdout.splitlines()[:head]
        tty_stdout = tty_stdout.splitlines()[:head]
    if quiet_stdout != tty_stdout or quiet_out != on_tty_out:
        sys.exit(f"FAIL: {name}: the output differs with stderr on a terminal:\n"
                 f"{quiet_stdout}\n{tty_stdout}")
    pattern = re.compile(
        re.escape(label) + r" \[([#.]{30})\] (\d+)/(\d+) " + re.escape(unit) +
        r", (\d+:\d\d) elapsed(, ~\d+:\d\d left)?\x1b\[K")
    drawn = [m for m in pattern.finditer(tty_stderr)]
    if not drawn:
        sys.exit(f"FAIL: {name}: no progress line on the terminal: {tty_stderr!r}")
    for match in drawn:
        if tty_stderr[match.start() - 1] != "\r":
            sys.exit(f"FAIL: {name}: a progress line is not redrawn in place: {tty_stderr!r}")
        done, shown_total = int(match.group(2)), int(match.group(3))
        if shown_total != total or not 0 <= done <= total:
            sys.exit(f"FAIL: {name}: {done}/{shown_total} {unit}, expected a count of {total}")
        if match.group(1) != "#" * (done * 30 // total) + "." * (30 - done * 30 // total):
            sys.exit(f"FAIL: {name}: bar {match.group(1)} for {done}/{total}")
        if 0 < done < total and match.group(5) is None:
            sys.exit(f"FAIL: {name}: no estimate of the time left at {done}/{total}")
        if done == total and match.group(5) is not None:
            sys.exit(f"FAIL: {name}: time left shown when done")
    last = drawn[-1]
    if int(last.group(2)) != total or not tty_stderr[last.end():].startswith("\n"):
        sys.exit(f"FAIL: {name}: the line should end at {total}/{total} with a newline: "
                 f"{tty_stderr[last.start():]!r}")
    if not any(0 < int(m.group(2)) < total for m in drawn):
        sys.exit(f"FAIL: {name}: no line while work remained")
    print(f"{name}: {len(drawn)} progress lines on a terminal, none to a pipe")


shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)
check("validate", "validate", len(SCENES), "scenes",
      ["validate", "--jobs", "1", "--frames", "30", "--no-plot", "--report",
       os.path.join(WORK, "validate")] + SCENES)
frames = os.path.join(WORK, "frames")
check("render", "rendering stack10", 4, "frames",
      ["render", SCENES[2], "--frames", "6", "--every", "2", "--size", "80x60", "--out", frames,
       "--overwrite"], out_folder=frames, timed=True)
check("sweep", "sweep anchored_rod", 4, "settings",  # 12 settings in the quick grid
      ["sweep", os.path.join(SOURCE, "samples", "scenes", "anchored_rod.json"), "--quick",
       "--no-plot", "--shard", "1/3", "--out", os.path.join(WORK, "sweep")], timed=True, head=5)
