#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
# The step's serial remainder on two threads, in instructions (load-independent): runs
# `meff bench SCENE --solver SOLVER --against none --runs 1 --threads 2` under callgrind for 12
# and for 22 frames, collecting only inside World::Step, not inside ThreadPool::ParallelFor
# (the calling thread's waits), and again inside the tasks it hands out (every thread). Per step
# (22 frames minus 12, / 10): serial = the calling thread's instructions outside the tasks;
# parallel = the tasks' on every thread; the ceiling on two threads (Amdahl, perfect balance)
# is (serial + parallel) / (serial + parallel / 2).
# Usage: scripts/serial-share.sh MEFF SCENE.json SOLVER   (needs valgrind and python3)
set -euo pipefail
if [ $# -ne 3 ]; then
    echo "usage: $0 MEFF SCENE.json colour|soft_step" >&2
    exit 2
fi
MEFF=$1
SCENE=$2
SOLVER=$3
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
for frames in 12 22; do
    valgrind --tool=callgrind --separate-threads=yes --collect-atstart=no \
        --toggle-collect='meff::World::Step(*' --toggle-collect='*ThreadPool::ParallelFor*' \
        --toggle-collect='*FunctionRef<void (int, int, int)>::Call<*' \
        --callgrind-out-file="$WORK/run$frames.%p" \
        "$MEFF" bench "$SCENE" --solver "$SOLVER" --against none --runs 1 --frames "$frames" \
        --threads 2 >/dev/null 2>&1
done
python3 - "$WORK" "$SCENE" "$SOLVER" <<'PY'
import glob, re, sys

TASK = 'FunctionRef<void (int, int, int)>::Call<'

def split(path):
    """(collected instructions, of them inside tasks) of one thread's callgrind file."""
    names, total, tasks = {}, 0, 0
    fn = cfn = ''
    call = False
    for line in open(path):
        if line.startswith('totals:'):
            total = int(line.split()[1])
            continue
        m = re.match(r'(c?fn)=\((\d+)\)(?: (.*))?', line)
        if m:
            kind, key, name = m.groups()
            if name:
                names[key] = name.strip()
            if kind == 'fn':
                fn = names[key]
            else:
                cfn = names[key]
            continue
        if line.startswith('calls='):
            call = True
            continue
        if call:
            call = False
            parts = line.split()
            if len(parts) > 1 and TASK in cfn and TASK not in fn:
                tasks += int(parts[1])
    return total, tasks

def measure(frames):
    files = sorted(glob.glob(f'{sys.argv[1]}/run{frames}.*-*'),
                   key=lambda p: int(p.rsplit('-', 1)[1]))
    serial = parallel = 0
    for i, path in enumerate(files):
        total, tasks = split(path)
        if i == 0:
            serial = total - tasks
        parallel += tasks
    return serial, parallel

s12, p12 = measure(12)
s22, p22 = measure(22)
serial, parallel = (s22 - s12) / 10, (p22 - p12) / 10
print(f'{sys.argv[2]} {sys.argv[3]}: per step serial {serial / 1e6:.2f} M, parallel '
      f'{parallel / 1e6:.2f} M instructions; serial share {100 * serial / (serial + parallel):.1f} %; '
      f'two-thread ceiling {(serial + parallel) / (serial + parallel / 2):.2f}')
PY
