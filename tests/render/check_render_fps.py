#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""--fps N gives an N fps movie whatever the sampling (issue 34): frames rendered every step or
every third step of a 60 Hz scene, assembled at --fps 30, play at 30 frames per second, one
movie frame per rendered frame; without --fps the movie plays in simulated time.
Usage: check_render_fps.py MEFF SCENE OUT_DIR. Exits 77 (skipped) without ffmpeg and ffprobe."""
import json
import os
import shutil
import subprocess
import sys

meff, scene, out = sys.argv[1:4]
if shutil.which("ffmpeg") is None or shutil.which("ffprobe") is None:
    print("skipped: ffmpeg and ffprobe are needed (Debian: apt-get install ffmpeg)")
    sys.exit(77)
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)


def probe(path):
    run = subprocess.run(["ffprobe", "-v", "error", "-select_streams", "v:0", "-count_frames",
                          "-show_entries", "stream=avg_frame_rate,nb_read_frames",
                          "-show_entries", "format=duration", "-of", "json", path],
                         capture_output=True, text=True, check=True)
    info = json.loads(run.stdout)
    stream = info["streams"][0]
    num, den = stream["avg_frame_rate"].split("/")
    return float(num) / float(den), int(stream["nb_read_frames"]), float(info["format"]["duration"])


def gif_starts(path):
    """Each frame's start (s), from the packets' time stamps."""
    run = subprocess.run(["ffprobe", "-v", "error", "-select_streams", "v:0", "-show_entries",
                          "packet=pts_time", "-of", "csv=p=0", path],
                         capture_output=True, text=True, check=True)
    return [float(line) for line in run.stdout.split()]


def movie(name, every, *extra):
    path = os.path.join(out, name)
    run = subprocess.run([meff, "render", scene, "--out", os.path.join(out, name + ".frames"),
                          "--frames", "60", "--every", str(every), "--size", "160x120", *extra],
                         capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"{name}: exit status {run.returncode}\n{run.stdout}{run.stderr}")
    return probe(path)


failures = []
for every in (1, 3):
    frames = 60 // every + 1
    for kind in ("mp4", "gif"):
        path = os.path.join(out, f"every{every}.{kind}")
        rate, count, duration = movie(f"every{every}.{kind}", every, f"--{kind}", path,
                                      "--fps", "30")
        print(f"--every {every} --{kind} --fps 30: {rate:.3f} fps, {count} frames, {duration:.3f} s")
        if count != frames:
            failures.append(f"--every {every} --{kind}: {count} frames, expected {frames}")
        if kind == "mp4":
            if abs(rate - 30) > 1e-6:
                failures.append(f"--every {every} --mp4 --fps 30: {rate:.3f} fps")
            continue
        # A GIF stores each frame's delay in whole hundredths of a second: at 30 fps ffmpeg
        # alternates 3 and 4 so that frame k starts at k/30 s rounded to the hundredth (the last
        # frame's delay is rounded too, so the average rate over a short movie is off by up to
        # a hundredth of its length). Each start within half a hundredth of k/30 s is 30 fps.
        starts = gif_starts(path)
        late = [(k, t) for k, t in enumerate(starts) if abs(t - k / 30) > 0.005 + 1e-9]
        if len(starts) != frames or late:
            failures.append(f"--every {every} --gif --fps 30: frame starts off 30 fps: {late[:3]}")
# Without --fps: simulated time, 1/(dt * every) = 20 fps at every 3rd step of 1/60 s.
rate, count, _ = movie("default.mp4", 3, "--mp4", os.path.join(out, "default.mp4"))
if abs(rate - 20) > 1e-6:
    failures.append(f"--every 3 --mp4 without --fps: {rate:.3f} fps, expected 20")
if failures:
    sys.exit("\n".join(failures))
print("fps: ok")
