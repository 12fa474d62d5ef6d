#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
# Times meff beside Box2D v3 on samples/bench/ scenes, paired and alternating (docs/
# performance.md): per scene and round, v3 on 1 worker, meff by colour and by the soft step on 1
# thread, v3 on 2 workers, meff by colour and by the soft step on 2 threads. Prints ms/step per
# run, one line per scene and round, with the load average. Box2D v3 is not a dependency: build
# its `benchmark` program outside the project (erincatto/box2d, -DBOX2D_BENCHMARKS=ON) and pass
# its path.
#
# The bench scenes and v3's benchmark (-nc) turn continuous collision off; with --continuous
# both run with it on, as a game's world does by default (meff on copies of the scenes).
#
# Usage: scripts/bench-against-v3.sh [--continuous] MEFF V3_BENCHMARK ROUNDS SCENE...
#        (SCENE: large_pyramid ...)
set -euo pipefail
cd "$(dirname "$0")/.."
continuous=0
if [ "${1:-}" = --continuous ]; then
    continuous=1
    shift
fi
meff=$(realpath "$1")
v3=$(realpath "$2")
rounds=$3
shift 3
bench=$PWD/samples/bench
work=$(mktemp -d) # v3's benchmark writes files into the working directory
trap 'rm -rf "$work"' EXIT
cd "$work"
v3_continuous=-nc
if [ "$continuous" = 1 ]; then
    v3_continuous=
    for scene in "$@"; do
        python3 -c "import json, sys; d = json.load(open(sys.argv[1])); d['world']['continuous'] = True; json.dump(d, open(sys.argv[2], 'w'))" \
            "$bench/$scene.json" "$work/$scene.json"
    done
    bench=$work
fi
for round in $(seq 1 "$rounds"); do
    for scene in "$@"; do
        steps=$(python3 -c "import json, sys; print(json.load(open(sys.argv[1]))['world']['frames'])" \
            "$bench/$scene.json")
        line="round $round $scene load $(cut -d' ' -f1 /proc/loadavg)"
        for run in v3:1 colour:1 soft_step:1 v3:2 colour:2 soft_step:2; do
            kind=${run%%:*}
            threads=${run##*:}
            if [ "$kind" = v3 ]; then
                total=$("$v3" -b="$scene" -w="$threads" -t=2 -r=1 $v3_continuous 2>/dev/null |
                    awk '/^run 0/ {print $4}')
                ms=$(python3 -c "import sys; print('%.3f' % (float(sys.argv[1]) / int(sys.argv[2])))" \
                    "${total:-nan}" "$steps")
            else
                ms=$("$meff" bench "$bench/$scene.json" --solver "$kind" --against none --runs 1 \
                    --threads "$threads" 2>/dev/null | grep "^ *$scene " | sed 's/.*| *//' |
                    awk '{print $1}')
            fi
            line="$line | $kind t$threads ${ms:-NA}"
        done
        echo "$line"
    done
done
