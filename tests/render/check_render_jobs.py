#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""CTest (issue 20): check_render_jobs.py MEFF SCENE WORK_DIR

`meff render` on several threads, on several machines, and into a folder that holds frames:
  * --jobs 2 writes the same files, byte for byte, as --jobs 1;
  * --shard 1/2 and 2/2 into one folder write together exactly the files one job writes;
  * a folder that already holds frames is refused (exit status 2, one line, nothing changed)
    without --overwrite; with it, the old frames are removed first, so a shorter render leaves
    none of the longer one's behind; other files in the folder are left alone;
  * --gif with --shard is refused (a movie needs every frame);
  * --threads 3 (the world stepped on a pool of three) writes the same files as --threads 1:
    large_pyramid by colour, whose contact colours and bodies are many enough to be spread
    over the threads.
"""
import json
import os
import shutil
import subprocess
import sys

MEFF, SCENE, WORK = sys.argv[1:4]
PYRAMID = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "samples",
                       "bench", "large_pyramid.json")
COMMON = ["render", SCENE, "--frames", "8", "--every", "2", "--size", "160x120", "--contacts",
          "--impulses", "--joints", "--overlay-box2d"]


def run(arguments, expect=0):
    completed = subprocess.run([MEFF] + arguments, capture_output=True, text=True)
    if completed.returncode != expect:
        sys.exit(f"FAIL: meff {' '.join(arguments)} exited {completed.returncode}, expected "
                 f"{expect}\n{completed.stdout}{completed.stderr}")
    return completed


def files(folder):
    return {name: open(os.path.join(folder, name), "rb").read()
            for name in sorted(os.listdir(folder))}


shutil.rmtree(WORK, ignore_errors=True)
one, two, shards = (os.path.join(WORK, name) for name in ("one", "two", "shards"))
run(COMMON + ["--out", one, "--jobs", "1"])
run(COMMON + ["--out", two, "--jobs", "2"])
expected = [f"frame_{k:05d}.png" for k in range(5)]
if list(files(one)) != expected:
    sys.exit(f"FAIL: --jobs 1 wrote {list(files(one))}, expected {expected}")
if files(one) != files(two):
    sys.exit("FAIL: --jobs 2 wrote other bytes than --jobs 1")
for index in (1, 2):
    run(COMMON + ["--out", shards, "--shard", f"{index}/2"])
if files(shards) != files(one):
    sys.exit(f"FAIL: shards 1/2 and 2/2 wrote {list(files(shards))}, not what one job writes")

before = files(one)
refused = run(COMMON + ["--out", one], expect=2)
if len(refused.stderr.splitlines()) != 1 or "--overwrite" not in refused.stderr:
    sys.exit(f"FAIL: the refusal should be one line naming --overwrite: {refused.stderr!r}")
if files(one) != before:
    sys.exit("FAIL: a refused render changed the folder")
with open(os.path.join(one, "notes.txt"), "w") as notes:
    notes.write("not a frame\n")
run(["render", SCENE, "--frames", "2", "--every", "2", "--size", "160x120", "--out", one,
     "--overwrite"])
if list(files(one)) != ["frame_00000.png", "frame_00001.png", "notes.txt"]:
    sys.exit(f"FAIL: --overwrite left {list(files(one))}; expected the 2 new frames and notes.txt")
run(COMMON + ["--out", os.path.join(WORK, "movie"), "--shard", "1/2", "--gif",
              os.path.join(WORK, "x.gif")], expect=2)

with open(PYRAMID) as text:
    pyramid = json.load(text)
pyramid["world"]["solver"] = "colour"
colour_scene = os.path.join(WORK, "large_pyramid_colour.json")
with open(colour_scene, "w") as text:
    json.dump(pyramid, text)
by_threads = {}
for threads in ("1", "3"):
    folder = os.path.join(WORK, "threads" + threads)
    run(["render", colour_scene, "--frames", "4", "--every", "2", "--size", "160x120",
         "--contacts", "--impulses", "--out", folder, "--threads", threads])
    by_threads[threads] = files(folder)
if len(by_threads["1"]) != 3 or by_threads["3"] != by_threads["1"]:
    sys.exit(f"FAIL: --threads 3 wrote other files than --threads 1: {list(by_threads['3'])}")
print("render: --jobs 2 = --jobs 1, 2 shards = 1 job, --overwrite refuses and replaces, "
      "--threads 3 = --threads 1")
