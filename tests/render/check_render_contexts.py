#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""CTest: check_render_contexts.py MEFF SCENE WORK_DIR

`meff render --jobs 2` hands its OSMesa contexts from thread to thread: a frame is drawn on
whichever thread is free, with whichever context is free. A context may be current on one
thread at a time, so each frame must release its context before another thread takes it.
When it did not, OSMesa 22 (llvmpipe) crashed, aborted or hung in about 10 of 12 such runs on
a loaded two-core machine (and in about 1 of 30 three-frame renders: cli.progress's). Here:
  * three runs of 401 small frames (400 steps) on two threads each exit 0 within a minute (a hang is a
    failure, not a wait), and
  * write the same bytes as one thread does.
"""
import os
import shutil
import subprocess
import sys

MEFF, SCENE, WORK = sys.argv[1:4]
COMMON = ["render", SCENE, "--frames", "400", "--every", "1", "--size", "80x60", "--overwrite"]


def render(folder, jobs):
    arguments = [MEFF] + COMMON + ["--out", folder, "--jobs", str(jobs)]
    try:
        completed = subprocess.run(arguments, capture_output=True, text=True, timeout=60)
    except subprocess.TimeoutExpired:
        sys.exit(f"FAIL: {' '.join(arguments)} still running after 60 s (hung)")
    if completed.returncode != 0:
        sys.exit(f"FAIL: {' '.join(arguments)} exited {completed.returncode}\n"
                 f"{completed.stderr}")
    return {name: open(os.path.join(folder, name), "rb").read()
            for name in sorted(os.listdir(folder))}


shutil.rmtree(WORK, ignore_errors=True)
expected = render(os.path.join(WORK, "one"), 1)
if len(expected) != 401:  # frame 0 (the start) and one per step
    sys.exit(f"FAIL: one thread wrote {len(expected)} frames, expected 401")
for run in range(3):
    if render(os.path.join(WORK, "two"), 2) != expected:
        sys.exit(f"FAIL: run {run + 1} on two threads wrote other frames than one thread")
print("401 frames on two threads, three times: exit 0, the same bytes as one thread")
