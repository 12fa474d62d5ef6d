#!/usr/bin/env python3
"""meff view used as a person would, under Xvfb: a script loads a scene, steps it, takes a
screenshot, drags a body and throws it; the first screenshot must show the geometry of
`meff render`'s frame of the same state (same camera and size, no caption or legend) to within
a pixel. Usage: check_view_script.py MEFF SCENE OUT_DIR [KEEP.png]. Exits 77 (skipped) without
xvfb-run. KEEP.png: where to copy the whole window's screenshot after the throw (docs)."""
import os
import shutil
import struct
import subprocess
import sys
import zlib

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


def read_png(path):
    """8-bit RGB or RGBA, not interlaced (what meff writes): rows of (r, g, b)."""
    with open(path, "rb") as f:
        data = f.read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and colour in (2, 6) and interlace == 0, path
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        previous = line
    return rows


viewed = read_png(os.path.join(out, "view.png"))
rendered = read_png(os.path.join(out, "render", "frame_00001.png"))
assert len(viewed) == HEIGHT and len(viewed[0]) == WIDTH, "the screenshot has the wrong size"

# The palette's fills (DebugDraw colour half way to white): meff render's and the view's are the
# same colours, flat inside each shape.
DYNAMIC = (242, 198, 185)  # FillColor of DrawPalette::dynamicBody (0.90, 0.55, 0.45)


def mask(rows, colour):
    """The pixels inside a fill: of the fill colour, and so are their four neighbours. An
    anti-aliased edge pixel of meff render's (a mix of outline, fill and background) can happen
    to come out near the fill colour; one in the middle of fill-coloured neighbours cannot."""
    def fill(x, y):
        if not (0 <= y < len(rows) and 0 <= x < len(rows[0])):
            return False
        p = rows[y][x]
        return max(abs(p[i] - colour[i]) for i in range(3)) <= 6
    return {(x, y) for y in range(len(rows)) for x in range(len(rows[0]))
            if fill(x, y) and fill(x - 1, y) and fill(x + 1, y) and fill(x, y - 1) and fill(x, y + 1)}


def far(points, other):
    """The points of `points` farther than one pixel (8-neighbourhood) from every point of
    `other`."""
    return [p for p in points
            if not any((p[0] + dx, p[1] + dy) in other for dx in (-1, 0, 1) for dy in (-1, 0, 1))]


failures = []
# The ground is a segment (a line, anti-aliased in the render): the boxes' fills say it all.
a, b = mask(viewed, DYNAMIC), mask(rendered, DYNAMIC)
# Same geometry within a pixel: every inside-fill pixel of one image is at most one pixel from
# an inside-fill pixel of the other. The window draws without anti-aliasing (a pixel is the
# shape's when its centre is inside), meff render averages 3x3 samples, so where an edge falls
# within a pixel the two may decide that pixel differently, by one pixel at most; a shape
# drawn a pixel or more off, or missing, or extra, fails.
stray = far(a, b) + far(b, a)
print(f"box fills: {len(a)} pixels inside in the view, {len(b)} in the render; {len(stray)} "
      f"more than a pixel from the other's")
if len(a) < 10000 or len(b) < 10000:
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
