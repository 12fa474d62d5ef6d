#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
# Regenerates the renderer's and the viewer's images in docs/images/ from today's code:
#   render-strip.png   newtons_cradle, frames 0, 30, 60, 90 and 120, side by side (README)
#   render-follow.png  terrain_car with --follow chassis, every second, side by side
#                      (docs/rendering.md)
#   viewer.png         `meff view` under Xvfb after a scripted drag and throw (README,
#                      docs/viewer.md); only when meff was built with the viewer and xvfb-run
#                      is installed
# The sweep plots (sweep-*.png, sweep3-*.png) come from `meff sweep` (see the README).
# Usage: scripts/make-doc-images.sh [BUILD_DIR]   (default: build)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
meff="$build/tools/meff/meff"
strip="$build/tools/strip/meff_strip"
for tool in "$meff" "$strip"; do
    if [ ! -x "$tool" ]; then
        echo "make-doc-images: $tool is missing: build the meff and meff_strip targets first" >&2
        exit 2
    fi
done
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
images="$root/docs/images"

"$meff" render "$root/samples/scenes/newtons_cradle.json" --out "$work/strip" \
    --frames 120 --every 30 --size 400x300 --joints
"$strip" "$images/render-strip.png" "$work"/strip/frame_*.png

"$meff" render "$root/samples/scenes/terrain_car.json" --out "$work/follow" \
    --follow chassis --frames 480 --every 120 --size 320x240 --joints
"$strip" "$images/render-follow.png" "$work"/follow/frame_*.png

if command -v xvfb-run >/dev/null && [ -f "$build/tools/view/libmeff_viewer_app.a" ]; then
    python3 "$root/tests/view/check_view_script.py" "$meff" \
        "$root/samples/scenes/pyramid20.json" "$work/view" "$images/viewer.png"
else
    echo "make-doc-images: viewer.png not regenerated (needs meff built with the viewer and" \
        "xvfb-run)" >&2
fi
echo "make-doc-images: wrote $images"
