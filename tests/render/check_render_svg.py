#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""An SVG frame, drawn by an SVG renderer (librsvg's rsvg-convert, as a browser would draw it),
shows the PNG frame's geometry: pyramid20 after a second, every dynamic-fill pixel inside a box
in one picture within one pixel of one in the other. Usage: check_render_svg.py MEFF SCENE
OUT_DIR. Exits 77 (skipped) without rsvg-convert."""
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from png_masks import DYNAMIC_FILL, read_png, stray_fill_pixels  # noqa: E402

meff, scene, out = sys.argv[1:4]
if shutil.which("rsvg-convert") is None:
    print("skipped: rsvg-convert is needed (Debian: apt-get install librsvg2-bin)")
    sys.exit(77)
shutil.rmtree(out, ignore_errors=True)
run = subprocess.run([meff, "render", scene, "--out", out, "--frames", "60", "--every", "60",
                      "--size", "480x360", "--svg"], capture_output=True, text=True)
if run.returncode != 0:
    sys.exit(f"meff render --svg: exit status {run.returncode}\n{run.stdout}{run.stderr}")
drawn = os.path.join(out, "svg.png")
subprocess.run(["rsvg-convert", "-w", "480", "-h", "360", "-o", drawn,
                os.path.join(out, "frame_00001.svg")], check=True)
png, svg = read_png(os.path.join(out, "frame_00001.png")), read_png(drawn)
# Both pictures are anti-aliased (meff render averages 3x3 samples, librsvg computes coverage),
# so an edge pixel may come out on either side of the fill-colour threshold: one pixel, no
# more; a shape a pixel or more off, missing or extra fails.
stray, inside_png, inside_svg = stray_fill_pixels(png, svg, DYNAMIC_FILL)
print(f"box fills: {inside_png} pixels inside in the PNG, {inside_svg} in the SVG drawn by "
      f"rsvg-convert; {len(stray)} more than a pixel from the other's")
if inside_png < 10000 or inside_svg < 10000:
    sys.exit("the boxes are missing from one of the pictures")
if stray:
    sys.exit(f"{len(stray)} fill pixels more than one pixel from the other picture's "
             f"(first {stray[:3]})")
print("svg: the SVG frame has the PNG frame's geometry")
