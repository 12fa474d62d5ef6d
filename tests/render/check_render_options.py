#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""meff render's frame options from the command line (issue 34): --follow with --svg,
--no-caption and --no-legend writes a PNG and an SVG per frame; --transparent writes RGBA PNGs.
Usage: check_render_options.py MEFF SCENE OUT_DIR (SCENE has a body named chassis)."""
import os
import shutil
import subprocess
import sys

meff, scene, out = sys.argv[1:4]
shutil.rmtree(out, ignore_errors=True)


def render(name, *extra):
    directory = os.path.join(out, name)
    run = subprocess.run([meff, "render", scene, "--out", directory, "--frames", "120",
                          "--every", "40", "--size", "160x120", *extra],
                         capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"{name}: exit status {run.returncode}\n{run.stdout}{run.stderr}")
    return directory, sorted(os.listdir(directory))


directory, files = render("follow", "--follow", "chassis", "--svg", "--no-caption", "--no-legend")
expected = [f"frame_{k:05d}.{ext}" for k in range(4) for ext in ("png", "svg")]
if files != sorted(expected):
    sys.exit(f"--svg wrote {files}, expected {sorted(expected)}")
with open(os.path.join(directory, "frame_00003.svg"), encoding="utf-8") as svg:
    text = svg.read()
if not text.startswith("<?xml") or "<svg" not in text or "<text" in text:
    sys.exit("the SVG frame is not an SVG without text (--no-caption, --no-legend)")

directory, files = render("transparent", "--transparent")
with open(os.path.join(directory, "frame_00000.png"), "rb") as png:
    header = png.read(26)
# IHDR: bit depth at byte 24, colour type at 25 (6: RGBA).
if header[25] != 6:
    sys.exit(f"--transparent wrote colour type {header[25]}, expected 6 (RGBA)")
print("render options: follow, svg, no caption/legend, transparent: ok")
