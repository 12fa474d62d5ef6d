#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""meff view opens every bundled sample and b2dJson level under Xvfb: 30 frames and a screenshot
each (a script), exit status 0 and a screenshot of the scripted size that is not all background.
Usage: check_view_samples.py MEFF OUT_DIR SCENE... Exits 77 (skipped) without xvfb-run."""
import os
import shlex
import shutil
import subprocess
import sys

meff, out = sys.argv[1:3]
scenes = sys.argv[3:]
if shutil.which("xvfb-run") is None:
    print("skipped: xvfb-run is needed (Debian: apt-get install xvfb xauth)")
    sys.exit(77)
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)
# One X server for all of them: a shell loop inside one xvfb-run.
lines = ["status=0"]
for index, scene in enumerate(scenes):
    script = os.path.join(out, f"{index}.txt")
    with open(script, "w", encoding="utf-8") as f:
        f.write(f"size 160 120\nstep 30\nscreenshot {out}/{index}.png\n")
    lines.append(f"{shlex.quote(meff)} view {shlex.quote(scene)} --script {shlex.quote(script)} "
                 f"--size 320x240 >/dev/null || {{ echo FAILED {shlex.quote(scene)}; status=1; }}")
lines.append("exit $status")
run = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1024x768x24", "sh", "-c",
                      "\n".join(lines)], capture_output=True, text=True, timeout=1200,
                     env=dict(os.environ, LIBGL_ALWAYS_SOFTWARE="1"))
print(run.stdout + run.stderr)
missing = [scene for index, scene in enumerate(scenes)
           if not os.path.exists(os.path.join(out, f"{index}.png"))]
if run.returncode != 0 or missing:
    sys.exit(f"meff view failed on {len(missing)} of {len(scenes)} scenes: {missing[:5]}")
print(f"meff view: {len(scenes)} scenes opened, stepped and captured")
