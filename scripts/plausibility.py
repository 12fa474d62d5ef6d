#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""Measures the plausibility figures of issue 31 from `meff run --trajectory` (docs/soft-step.md,
"Plausible in every scene").

    scripts/plausibility.py build/tools/meff/meff samples/extreme/rod_into_wall.json \
        [--solver soft_step] [--set soft_step.relax_iterations=8] [--continuous on|off]

runs the scene once with the solver (and settings) given, and prints what the scene is about:
  rod_into_wall           the pair's rebound speed (m/s) after it met the wall, and the kinetic
                          energy it keeps (J)
  violated_rod            the largest kinetic energy (J) and the kinetic energy at 1 s
  heavy_dropped_on_light  whether the heavy box stays on top, and how far the light one is pressed
                          beyond rest (m)
  stack12_small           the largest drift of a box between 1 s and 10 s (m)
  pulley_joint, theo_jansen, bullet_test (samples/testbed/): how far box 1 is pulled back up
                          after its lowest point, the fastest body, the plank's rise above its
                          start
and, for every scene, the largest kinetic energy and whether any number was not finite. Masses and
inertias are computed from the scene's boxes and circles (the only shapes these scenes use).
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile


def body_mass(body):
    """Mass (kg) and rotational inertia about the origin (kg m^2) of a body's boxes and circles."""
    mass = inertia = 0.0
    for s in body.get("shapes", []):
        density = s.get("density", 1.0)
        cx, cy = s.get("center", [0.0, 0.0])
        if s["type"] == "box":
            w, h = 2 * s["half_width"], 2 * s["half_height"]
            m = density * w * h
            i = m * (w * w + h * h) / 12
        elif s["type"] == "circle":
            r = s["radius"]
            m = density * math.pi * r * r
            i = 0.5 * m * r * r
        else:
            continue
        mass += m
        inertia += i + m * (cx * cx + cy * cy)
    return mass, inertia


def run(meff, scene, solver, settings, continuous):
    if solver:
        scene["world"]["solver"] = solver
    for key, value in settings:
        path = key.split(".")
        target = scene["world"]
        for p in path[:-1]:
            target = target.setdefault(p, {})
        target[path[-1]] = json.loads(value)
    if continuous is not None:
        scene["world"]["continuous"] = continuous
    with tempfile.TemporaryDirectory() as tmp:
        scene_path = os.path.join(tmp, "scene.json")
        with open(scene_path, "w") as f:
            json.dump(scene, f)
        out = os.path.join(tmp, "t.csv")
        subprocess.run([meff, "run", scene_path, "--trajectory", out], check=True,
                       stdout=subprocess.DEVNULL)
        frames = {}
        with open(out) as f:
            for row in csv.DictReader(f):
                frames.setdefault(int(row["frame"]), {})[row["body"]] = {
                    k: float(row[k]) for k in ("time", "x", "y", "angle", "vx", "vy", "omega")}
    return [frames[k] for k in sorted(frames)]


def kinetic(state, masses):
    return sum(0.5 * masses.get(b, (0, 0))[0] * (s["vx"] ** 2 + s["vy"] ** 2) + 0.5 * masses.get(b, (0, 0))[1] * s["omega"] ** 2
               for b, s in state.items())


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("meff")
    parser.add_argument("scene")
    parser.add_argument("--solver", default="soft_step")
    parser.add_argument("--set", action="append", default=[],
                        help="world setting KEY=JSON, e.g. soft_step.relax_iterations=8")
    parser.add_argument("--continuous", choices=["on", "off"])
    args = parser.parse_args()
    with open(args.scene) as f:
        scene = json.load(f)
    settings = [s.split("=", 1) for s in args.set]
    continuous = None if args.continuous is None else args.continuous == "on"
    frames = run(args.meff, scene, args.solver, settings, continuous)
    masses = {}
    for body in scene["bodies"]:
        if body.get("type", "static") == "dynamic":
            # The trajectory is in body origins; these scenes' shapes are centred on them.
            masses[body["name"]] = body_mass(body)
    dt = scene["world"].get("dt", 1 / 60)
    finite = all(math.isfinite(v) for state in frames for s in state.values() for v in s.values())
    energies = [kinetic(state, masses) for state in frames]
    name = scene["name"]
    print(f"{name} [{args.solver} {' '.join(args.set)}"
          f"{' continuous ' + args.continuous if args.continuous else ''}]")
    print(f"  finite: {finite}; largest kinetic energy {max(energies):.6g} J")
    if name == "rod_into_wall":
        m = {b: masses[b][0] for b in ("front", "rear")}
        total = sum(m.values())
        vcm = [sum(m[b] * s[b]["vx"] for b in m) / total for s in frames]
        hit = next(i for i, v in enumerate(vcm) if v < 7.9)  # the first frame it met the wall
        rebound = max(0.0, -min(vcm[hit:]))
        print(f"  rebound speed {rebound:.6g} m/s (largest speed away from the wall after the hit);"
              f" at the end {-vcm[-1]:.6g} m/s; kinetic energy at the end {energies[-1]:.6g}"
              f" of {energies[0]:.6g} J")
    elif name == "violated_rod":
        second = round(1 / dt)
        print(f"  kinetic energy at 1 s {energies[second]:.6g} J, at the end {energies[-1]:.6g} J")
    elif name == "heavy_dropped_on_light":
        rest_gap = 1.015  # heavy centre above light centre at rest (1 m boxes, 0.015 m gap)
        rest_light = 0.515
        on_top = all(s["heavy"]["y"] - s["light"]["y"] > 0.9 for s in frames)
        pressed = max(max(rest_gap - (s["heavy"]["y"] - s["light"]["y"]),
                          rest_light - s["light"]["y"]) for s in frames)
        final = frames[-1]
        print(f"  heavy on top all run: {on_top}; light pressed beyond rest at most {pressed:.6g} m;"
              f" at the end heavy x {final['heavy']['x']:.4g} y {final['heavy']['y']:.4g},"
              f" light y {final['light']['y']:.4g}")
    elif name == "stack12_small":
        first = frames[round(1 / dt)]
        last = frames[min(len(frames) - 1, round(10 / dt))]
        drift = max(math.hypot(last[b]["x"] - first[b]["x"], last[b]["y"] - first[b]["y"])
                    for b in first)
        print(f"  largest drift between 1 s and 10 s {drift:.6g} m")
    elif name == "pulley_joint":
        ys = [s["box1"]["y"] for s in frames]
        low = min(range(len(ys)), key=lambda i: ys[i])
        print(f"  box 1 pulled back up by {max(ys[low:]) - ys[low]:.6g} m after its lowest point")
    elif name == "theo_jansen":
        fastest = max(math.hypot(b["vx"], b["vy"]) for s in frames for b in s.values())
        print(f"  fastest body {fastest:.6g} m/s")
    elif name == "bullet_test":
        rise = max(s["plank"]["y"] for s in frames) - frames[0]["plank"]["y"]
        print(f"  the plank's highest point above its start {rise:.6g} m")
    return 0 if finite else 1


if __name__ == "__main__":
    sys.exit(main())
