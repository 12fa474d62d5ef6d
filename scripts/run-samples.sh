#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
# The main job: installs what is needed, builds the engine and runs the README's hello world (a
# first simulation result, minutes after the packages are in), then builds the meff tool (only
# it and the libraries it links: the test suite is scripts/test.sh's), runs every bundled sample
# scene, validates each against Box2D 2.4.1, and renders one sample to PNG frames. Everything
# else is written under out/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
MEFF_BUILD_TARGET=meff_hello scripts/build.sh
echo "== A first result: samples/embed/hello.cpp, a box falling onto the ground =="
build/samples/embed/meff_hello
echo "== The meff tool: every sample scene, validated against Box2D 2.4.1, one rendered =="
MEFF_BUILD_TARGET=meff scripts/build.sh
MEFF=build/tools/meff/meff
mkdir -p out/trajectories
for scene in samples/scenes/*.json; do
    name=$(basename "$scene" .json)
    "$MEFF" run "$scene" --trajectory "out/trajectories/$name.csv" \
        --contacts "out/trajectories/$name.contacts.csv" --joints "out/trajectories/$name.joints.csv"
done
"$MEFF" validate samples/scenes/*.json --report out/validation
"$MEFF" render samples/scenes/newtons_cradle.json --out out/frames/newtons_cradle --every 4 --joints \
    --overwrite
echo
echo "Trajectories:       out/trajectories/<scene>.csv (+ .contacts.csv, .joints.csv)"
echo "Validation reports: out/validation/<scene>/summary.json, divergence.csv, errors.png"
echo "Rendered frames:    out/frames/newtons_cradle/frame_*.png"
