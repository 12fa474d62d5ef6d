#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""meff view used as a person would, under Xvfb: a script loads a scene, steps it, takes a
screenshot, drags a body and throws it; the first screenshot must show the geometry of
`meff render`'s frame of the same state (same camera and size, no caption or legend) to within
a pixel. Usage: check_view_script.py MEFF SCENE OUT_DIR [KEEP.png]. Exits 77 (skipped) without
xvfb-run. KEEP.png: where to copy the whole window's screenshot after the throw (docs)."""
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "render"))
from png_masks import DYNAMIC_FILL, read_png, stray_fill_pixels  # noqa: E402

meff, scene, out = sys.argv[1:4]
keep = sys.argv[4] if len(sys.argv) > 4 else None
if shutil.which("xvfb-run") is None:
    print("skipped: xvfb-run is needed (Debian: apt-get install xvfb xauth)")
    sys.exit(77)
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)

WIDTH, HEIGHT = 480, 360
CAMERA = (0.0, 10.5, 23.0)  # x, y, height (m): pyramid20's twenty rows, 22 m wide
STEPS = 60
script = os.path.join(out, "script.txt")
with open(script, "w", encoding="utf-8") as f:
    f.write(f"""# pyramid20 after a second, then a brick pulled out of the top and thrown; the whole window
# with the view moved right of the panel
size {WIDTH} {HEIGHT}
camera {CAMERA[0]} {CAMERA[1]} {CAMERA[2]}
step {STEPS}
screenshot {out}/view.png
drag 0 19.8 6 21 40
expect grabbed
release
step 20
expect released
camera -7 10.5 23
screenshot_window {out}/window.png
""")
env = dict(os.environ, LIBGL_ALWAYS_SOFTWARE="1")
view = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1280x800x24", meff, "view", scene,
                       "--script", script, "--size", "1000x700"],
                      capture_output=True, text=True, env=env, timeout=300)
print(view.stdout + view.stderr)
if view.returncode != 0:
    sys.exit(f"meff view --script: exit status {view.returncode}")
render = subprocess.run([meff, "render", scene, "--out", os.path.join(out, "render"),
                         "--frames", str(STEPS), "--every", str(STEPS), "--size",
                         f"{WIDTH}x{HEIGHT}", "--camera", ",".join(map(str, CAMERA)),
                         "--no-caption", "--no-legend"], capture_output=True, text=True)
if render.returncode != 0:
    sys.exit(f"meff render: exit status {render.returncode}\n{render.stdout}{render.stderr}")


viewed = read_png(os.path.join(out, "view.png"))
rendered = read_png(os.path.join(out, "render", "frame_00001.png"))
assert len(viewed) == HEIGHT and len(viewed[0]) == WIDTH, "the screenshot has the wrong size"

failures = []
# The ground is a segment (a line, anti-aliased in the render): the boxes' fills say it all.
stray, inside_view, inside_render = stray_fill_pixels(viewed, rendered, DYNAMIC_FILL)
# Same geometry within a pixel: every inside-fill pixel of one image is at most one pixel from
# an inside-fill pixel of the other. The window draws without anti-aliasing (a pixel is the
# shape's when its centre is inside), meff render averages 3x3 samples, so where an edge falls
# within a pixel the two may decide that pixel differently, by one pixel at most; a shape
# drawn a pixel or more off, or missing, or extra, fails.
print(f"box fills: {inside_view} pixels inside in the view, {inside_render} in the render; "
      f"{len(stray)} more than a pixel from the other's")
if inside_view < 10000 or inside_render < 10000:
    failures.append("the boxes are missing from one of the images")
if stray:
    failures.append(f"{len(stray)} fill pixels more than one pixel from the other image's "
                    f"(first {stray[:3]})")
if not os.path.exists(os.path.join(out, "window.png")):
    failures.append("no window screenshot")
if failures:
    sys.exit("\n".join(failures))
if keep:
    shutil.copyfile(os.path.join(out, "window.png"), keep)
print("view script: screenshot matches meff render's frame")
