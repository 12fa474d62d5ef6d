#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""CTest: the page of `meff validate --report` (issue 32), checked in a real browser.

    check_report.py MEFF SOURCE_DIR WORK_DIR [CHROMIUM]

A CI job validates a folder holding a level that diverges (the stack, run by meff with 4
velocity iterations against Box2D's 8), a broken level and a Box2D v3 level. Then:
  * DIR/index.html has one table row per level, in order, saying FAIL, ERROR and SKIP, the
    failure's first divergent frame and its largest errors;
  * the failure has its errors plotted (inline SVG) and the frames before and at the divergence
    (PNG files beside the page, 480x360, named relatively so the page works from disk);
  * with CHROMIUM: headless Chromium loads the page from disk (--dump-dom) and the DOM it built
    holds the table, every row and both images, each image loaded (naturalWidth > 0: a script
    in the page writes it into the DOM); and a screenshot is taken (WORK_DIR/screenshot.png) for
    a person to look at.
"""
import os
import shutil
import struct
import subprocess
import sys
from html.parser import HTMLParser

MEFF, SOURCE, WORK = sys.argv[1:4]
CHROMIUM = sys.argv[4] if len(sys.argv) > 4 else ""
STACK = os.path.join(SOURCE, "samples", "scenes", "stack10.json")
CAPSULES = os.path.join(SOURCE, "samples", "v3", "capsules.json")


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


class Page(HTMLParser):
    """The rows of table#levels (their cells' text), every <img>, <svg> and element id."""

    def __init__(self):
        super().__init__()
        self.rows, self.images, self.svgs, self.ids = [], [], 0, set()
        self._in_table = False
        self._cell = None

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if "id" in attrs:
            self.ids.add(attrs["id"])
        if tag == "table" and attrs.get("id") == "levels":
            self._in_table = True
        elif tag == "tr" and self._in_table:
            self.rows.append([])
        elif tag == "td" and self._in_table:
            self._cell = ""
        elif tag == "img":
            self.images.append(attrs)
        elif tag == "svg":
            self.svgs += 1

    def handle_endtag(self, tag):
        if tag == "table":
            self._in_table = False
        elif tag == "td" and self._cell is not None:
            self.rows[-1].append(self._cell.strip())
            self._cell = None

    def handle_data(self, data):
        if self._cell is not None:
            self._cell += data


def parse(text):
    page = Page()
    page.feed(text)
    page.rows = [row for row in page.rows if row]  # the header row has <th> only
    return page


def png_size(path):
    with open(path, "rb") as stream:
        head = stream.read(24)
    if head[:8] != b"\x89PNG\r\n\x1a\n":
        fail("%s is not a PNG" % path)
    return struct.unpack(">II", head[16:24])


shutil.rmtree(WORK, ignore_errors=True)
levels = os.path.join(WORK, "levels")
os.makedirs(levels)
shutil.copy(STACK, os.path.join(levels, "a_stack.json"))
with open(os.path.join(levels, "b_broken.json"), "w") as stream:
    stream.write('{"meff_scene": 1, "bodies": [{"name": "x", "type": "dynamc"}]}\n')
shutil.copy(CAPSULES, os.path.join(levels, "c_capsules.json"))
paths = [os.path.join(levels, name) for name in ("a_stack.json", "b_broken.json",
                                                 "c_capsules.json")]
report = os.path.join(WORK, "report")
done = subprocess.run([MEFF, "validate"] + paths + ["--frames", "60", "--report", report,
                                                    "--meff-velocity-iterations", "4"],
                      capture_output=True, text=True, timeout=600)
print(done.stdout + done.stderr)
if done.returncode != 2:
    fail("exit status %d, expected 2 (a level could not be loaded)" % done.returncode)
index = os.path.join(report, "index.html")
with open(index, encoding="utf-8") as stream:
    page = parse(stream.read())

if [row[0] for row in page.rows] != ["FAIL", "ERROR", "SKIP"]:
    fail("rows: %s" % page.rows)
if [row[1] for row in page.rows] != paths:
    fail("the rows do not name the levels' files in order: %s" % [row[1] for row in page.rows])
stack = page.rows[0]
if not stack[4].isdigit() or not all(float(value) >= 0 for value in stack[5:10]):
    fail("the failure's row has no divergent frame or errors: %s" % stack)
if float(stack[5]) <= 0:
    fail("the failure's largest position error is 0: %s" % stack)
if page.svgs < 1:
    fail("no plot (inline SVG) in the page")
if len(page.images) != 2:
    fail("expected the frames before and at the divergence, got %s" % page.images)
for image in page.images:
    src = image["src"]
    if os.path.isabs(src) or src.startswith(("http:", "https:", "file:")):
        fail("image %s is not named relative to the page" % src)
    if png_size(os.path.join(report, src)) != (480, 360):
        fail("%s is not 480x360" % src)
print("page: %d rows, %d plots, images %s" % (len(page.rows), page.svgs,
                                               [image["src"] for image in page.images]))

if CHROMIUM:
    url = "file://" + os.path.abspath(index)
    browser = [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu",
               "--user-data-dir=" + os.path.join(WORK, "profile")]
    dom = subprocess.run(browser + ["--virtual-time-budget=5000", "--dump-dom", url],
                         capture_output=True, text=True, timeout=120)
    if dom.returncode != 0 or "<table" not in dom.stdout:
        fail("chromium did not load the page: %d %s" % (dom.returncode, dom.stderr[-2000:]))
    loaded = parse(dom.stdout)
    if [row[0] for row in loaded.rows] != ["FAIL", "ERROR", "SKIP"] or len(loaded.images) != 2:
        fail("the browser's DOM lacks rows or images: %s %s" % (loaded.rows, loaded.images))
    # The page's script marks each image the browser decoded; a missing file stays unmarked.
    if sorted(image.get("data-loaded") for image in loaded.images) != ["480", "480"]:
        fail("the browser did not load both images: %s" % loaded.images)
    shot = os.path.join(WORK, "screenshot.png")
    subprocess.run(browser + ["--window-size=1100,1400", "--screenshot=" + shot, url],
                   capture_output=True, timeout=120)
    if not os.path.isfile(shot):
        fail("no screenshot taken")
    print("chromium: DOM has %d rows and 2 loaded images; screenshot %s" % (len(loaded.rows),
                                                                          shot))
print("PASS")
