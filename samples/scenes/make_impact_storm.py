#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""Writes impact_storm.json: a scene of many time-of-impact events, validated against Box2D 2.4.1.

Run from this folder: python3 make_impact_storm.py
"""
import json

DESCRIPTION = (
    "Many continuous-collision events a step, in every way Box2D 2.4.1's SolveTOI meets them, "
    "so that validation checks meff's search for the earliest impact against Box2D's walk of the "
    "contact list, bit for bit. Continuous collision and sleeping are on. A pyramid of 36 boxes "
    "(1 m) settles on the ground; five bullets (circles of radius 0.12 m, no gravity) cross it at "
    "100 m/s from frame 117 on, and a kinematic paddle at 50 m/s ploughs through it at about "
    "frame 174. Ten darts (0.3 x 0.6 m) fall at 70 m/s onto a thin static shelf at y = 6 m and "
    "twelve hailstones (radius 0.1 m) at 80 m/s onto the ground, bouncing off. A kinematic piston "
    "at 0.6 m/s pushes a row of four boxes along the ground from frame 5. Six light boxes "
    "asleep on static ledges beside a wall are shot by bullets at 110 m/s (frames 180 to 281); "
    "one struck early in its step meets the wall in the same step, through a contact created "
    "during the continuous stage. Validation compares every body, contact impulse and awake "
    "flag with Box2D's every frame."
)

bodies = []


def body(name, kind, position, shapes, **extra):
    entry = {"name": name, "type": kind, "position": position, "shapes": shapes}
    entry.update(extra)
    bodies.append(entry)


def box(half_width, half_height, **material):
    return dict({"type": "box", "half_width": half_width, "half_height": half_height}, **material)


def circle(radius, **material):
    return dict({"type": "circle", "radius": radius}, **material)


body("ground", "static", [0, -0.5], [box(40, 0.5)])
body("shelf", "static", [0, 0], [{"type": "segment", "points": [[12, 6], [22, 6]]}])
ROWS = 8
for row in range(ROWS):
    for i in range(ROWS - row):
        body(f"pile{row}_{i}", "dynamic", [-3.5 + row * 0.5 + i, 0.5 + row],
             [box(0.5, 0.5, density=1, friction=0.6)])
for k, (x, y) in enumerate([(-200, 0.6), (-260, 1.6), (-320, 2.6), (-380, 3.6), (-440, 0.4)]):
    body(f"bullet{k}", "dynamic", [x, y], [circle(0.12, density=4, restitution=0.2)],
         bullet=True, gravity_scale=0, linear_velocity=[100, 0])
body("paddle", "kinematic", [-150, 2.5], [box(0.2, 1.2)], linear_velocity=[50, 0])
for k in range(10):
    body(f"dart{k}", "dynamic", [12.5 + k * 0.9, 40 + 7 * k],
         [box(0.15, 0.3, density=1, restitution=0.4)], linear_velocity=[0, -70], angle=0.3 * k)
for k in range(12):
    body(f"hail{k}", "dynamic", [-20 + k * 1.3, 30 + 11 * k],
         [circle(0.1, density=1, restitution=0.6)], linear_velocity=[3, -80])
# A kinematic piston pushes a row of boxes along the ground (a kinematic neighbour for the
# events of the boxes' contacts with the ground).
body("piston", "kinematic", [-32.05, 1], [box(0.3, 1)], linear_velocity=[0.6, 0])
for k in range(4):
    body(f"pushed{k}", "dynamic", [-31.2 + 1.02 * k, 0.5], [box(0.5, 0.5, density=1, friction=0.4)])
# The wall's face is at x = 30.5; ledge k's box starts 0.22 + 0.1 k m from it, each a bullet's
# path, the bullets' starts spread so that they strike at different fractions of a step.
body("wall", "static", [31, 10], [box(0.5, 12)])
for k, y in enumerate([10, 12, 14, 16, 18, 20]):
    x = 30.5 - 0.5 - (0.22 + 0.1 * k)
    body(f"ledge{k}", "static", [x, y - 0.1], [box(0.6, 0.1)])
    body(f"target{k}", "dynamic", [x, y + 0.5], [box(0.5, 0.5, density=0.2, friction=0.2)])
    body(f"sniper{k}", "dynamic", [-300 - 37.3 * k, y + 0.5],
         [circle(0.12, density=8, restitution=0.1)],
         bullet=True, gravity_scale=0, linear_velocity=[110, 0])

scene = {
    "meff_scene": 1,
    "name": "impact_storm",
    "description": DESCRIPTION,
    "world": {"gravity": [0, -10], "dt": 1 / 60, "frames": 300, "velocity_iterations": 8,
              "position_iterations": 3, "allow_sleep": True, "continuous": True},
    # The kinematic paddle crushes the pile into the wall: Box2D 2.4.1 (meff's Box2D back end)
    # presses a box 0.889 m into it; the plausibility limit is 1.5 times that
    # (docs/validation.md).
    "plausibility": {"penetration": 1.4},
    "bodies": bodies,
}
with open("impact_storm.json", "w") as out:
    json.dump(scene, out, indent=1)
    out.write("\n")
