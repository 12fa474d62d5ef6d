#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""CTest (issue 20): check_sweep_parallel.py MEFF SCENE WORK_DIR

`meff sweep --quick` with --jobs 2 gives the rows --jobs 1 gives, in the same order, equal in
every column but the timings (wall and CPU time of each run, which differ between any two
runs); --shard 1/2 and 2/2 together give those rows too, each exactly once; --threads 3 (each
meff world on a pool of three) gives them too. The rod is too small for its colour run to hand
work to the threads (tests/test_threads.cpp checks large scenes): this checks that the option is
taken and changes no result.
"""
import csv
import os
import shutil
import subprocess
import sys

MEFF, SCENE, WORK = sys.argv[1:4]
TIMINGS = {"ms_per_sim_s", "ms_per_sim_s_min", "ms_per_sim_s_max", "ms_per_step",
           "cpu_ms_per_sim_s", "runs"}


def sweep(name, extra):
    out = os.path.join(WORK, name)
    completed = subprocess.run([MEFF, "sweep", SCENE, "--quick", "--no-plot", "--out", out] + extra,
                               capture_output=True, text=True)
    if completed.returncode != 0:
        sys.exit(f"FAIL: sweep {extra} exited {completed.returncode}\n{completed.stderr}")
    with open(os.path.join(out, "sweep.csv")) as table:
        return [tuple((k, v) for k, v in row.items() if k not in TIMINGS)
                for row in csv.DictReader(table)]


shutil.rmtree(WORK, ignore_errors=True)
one = sweep("one", ["--jobs", "1"])
two = sweep("two", ["--jobs", "2"])
# The quick grid: 9 of Box2D's settings run by both engines, one by colour and two soft-step
# settings run by meff alone (Box2D has only its own order).
if len(one) != 9 * 2 + 3:
    sys.exit(f"FAIL: the quick grid has 21 rows (9 settings x 2 engines, 3 meff-only), got "
             f"{len(one)}")
if one != two:
    sys.exit("FAIL: --jobs 2 gave other rows (or another order) than --jobs 1")
threads = sweep("threads", ["--threads", "3"])
if threads != one:
    sys.exit("FAIL: --threads 3 gave other rows (or another order) than --threads 1")
shards = sweep("shard1", ["--shard", "1/2"]) + sweep("shard2", ["--shard", "2/2"])
if sorted(shards) != sorted(one) or len(set(shards)) != len(shards):
    sys.exit("FAIL: the two shards do not give every row exactly once")
print(f"sweep: --jobs 2 = --threads 3 = --jobs 1 ({len(one)} rows, timings aside); 2 shards "
      f"cover them once")
