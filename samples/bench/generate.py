#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""Writes the benchmark scenes of samples/bench/ as Box2D v3's benchmark suite defines them
(shared/benchmarks.c: large_pyramid, joint_grid, tumbler, many_pyramids, compounds, smash,
spinner, washer; frames as v3's benchmark program steps them), plus pyramids of 10, 20 and 50
rows for the scaling measurement. Where v3 uses a shape Box2D 2.4.1 lacks (capsules, rounded
boxes), the scene's description says what stands in, so that `meff bench`'s default peer can run
it. Run it from anywhere; it rewrites the JSON files
beside it. `generate.py --pyramid ROWS OUT.json` writes only a pyramid of ROWS rows, to OUT.json
(the cost-per-body measurement's larger pyramids, too large to bundle)."""
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
WORLD = {"gravity": [0, -10], "dt": 1 / 60, "velocity_iterations": 8,
         "position_iterations": 3, "warm_starting": True, "block_solver": True,
         "allow_sleep": False, "continuous": False}


def write(name, description, frames, bodies, joints=(), path=None, **world):
    scene = {"meff_scene": 1, "name": name, "description": description,
             "world": dict(WORLD, frames=frames, **world), "bodies": list(bodies), "joints": list(joints)}
    with open(path or os.path.join(HERE, name + ".json"), "w") as out:
        json.dump(scene, out, separators=(",", ":"))
        out.write("\n")


def box(hw, hh, center=(0, 0), density=1.0, friction=0.6):
    return {"type": "box", "half_width": hw, "half_height": hh, "center": list(center),
            "density": density, "friction": friction}


def pyramid(rows):
    bodies = [{"name": "ground", "type": "static",
               "shapes": [box(100, 1, (0, -1), density=0, friction=0.6)]}]
    for i in range(rows):
        for j in range(i, rows):
            x = (i + 1) * 0.5 + (j - i) - rows * 0.5
            y = (2 * i + 1) * 0.5
            bodies.append({"name": f"b{i}_{j}", "type": "dynamic", "position": [x, y],
                           "shapes": [box(0.5, 0.5)]})
    return bodies


def write_pyramid(rows, name, path=None):
    count = rows * (rows + 1) // 2
    write(name, f"Benchmark: a pyramid of {rows} rows ({count} boxes of half-extent 0.5, "
          "density 1, friction 0.6) on a static ground box, sleeping off, as Box2D v3's "
          "large_pyramid. It should stand.", 500, pyramid(rows), path=path)


if len(sys.argv) == 4 and sys.argv[1] == "--pyramid":
    # generate.py --pyramid ROWS OUT.json: one pyramid of any size (docs/performance.md's cost
    # per body from 55 to 20,100 boxes; the large ones are not bundled), and nothing else.
    write_pyramid(int(sys.argv[2]), f"pyramid{sys.argv[2]}", sys.argv[3])
    sys.exit(0)

for rows, name in ((10, "pyramid10"), (20, "pyramid20"), (50, "pyramid50"),
                   (100, "large_pyramid")):
    write_pyramid(rows, name)

# joint_grid: 100x100 circles joined to the neighbour above and to the left.
N = 100
bodies, joints = [], []
for k in range(N):
    for i in range(N):
        static = i == 0 and N // 2 - 3 <= k <= N // 2 + 3
        bodies.append({"name": f"c{k}_{i}", "type": "static" if static else "dynamic",
                       "position": [k, -i],
                       "shapes": [{"type": "circle", "radius": 0.4, "density": 1,
                                   "friction": 0.6,
                                   "filter": {"category": 2, "mask": 0xFFFF & ~2}}]})
        if i > 0:
            joints.append({"type": "revolute", "name": f"up{k}_{i}", "body_a": f"c{k}_{i - 1}",
                           "body_b": f"c{k}_{i}", "anchor": [k, -i + 0.5]})
        # Box2D v3 also joins neighbouring static bodies of the top row; such a joint never
        # enters an island and does nothing, and meff's loader refuses it, so it is left out.
        left_static = i == 0 and N // 2 - 3 <= k - 1 and k <= N // 2 + 3
        if k > 0 and not (static and left_static):
            joints.append({"type": "revolute", "name": f"left{k}_{i}",
                           "body_a": f"c{k - 1}_{i}", "body_b": f"c{k}_{i}",
                           "anchor": [k - 0.5, -i]})
write("joint_grid", "Benchmark: a 100x100 grid of circles (radius 0.4, not colliding with each "
      "other) joined by revolute joints to the neighbour above and to the left, hanging from "
      "the 7 static bodies k = 47..53 of the top row, as Box2D v3's joint_grid. The sheet "
      "should sag like cloth.", 500, bodies, joints)

# tumbler: a motor-driven box container full of small boxes.
walls = [box(0.5, 10, (10, 0), density=50), box(0.5, 10, (-10, 0), density=50),
         box(10, 0.5, (0, 10), density=50), box(10, 0.5, (0, -10), density=50)]
bodies = [{"name": "ground", "type": "static"},
          {"name": "tumbler", "type": "dynamic", "position": [0, 10], "shapes": walls}]
joints = [{"type": "revolute", "name": "motor", "body_a": "ground", "body_b": "tumbler",
           "anchor": [0, 10], "enable_motor": True, "motor_speed": math.pi / 180 * 25,
           "max_motor_torque": 1e8}]
for i in range(45):
    for j in range(45):
        bodies.append({"name": f"box{i}_{j}", "type": "dynamic",
                       "position": [-9 + 0.4 * i, 1 + 0.4 * j], "shapes": [box(0.125, 0.125)]})
write("tumbler", "Benchmark: a hollow square container (walls of density 50) turned at 25 deg/s "
      "by a revolute motor (max torque 1e8 N m) around (0, 10), holding 45x45 small boxes, as "
      "Box2D v3's tumbler. The boxes should tumble inside and never leave it.", 750, bodies,
      joints)


# The scenes below were added later; their bodies leave out fields at their defaults (density 1,
# friction 0.6, centre [0, 0]) to keep the files small, and round computed coordinates to 1e-6 m
# so the files read plainly (both engines load the same numbers, so nothing is lost).
def at(x):
    return round(x, 6)


def square(half, **material):
    return dict({"type": "box", "half_width": half, "half_height": half}, **material)


def polygon(points, **material):
    return dict({"type": "polygon", "vertices": [[at(x), at(y)] for x, y in points]}, **material)


def dynamic(name, position, shapes, **fields):
    return dict({"name": name, "type": "dynamic", "position": [at(position[0]), at(position[1])],
                 "shapes": shapes}, **fields)


# many_pyramids: 20 rows of 20 pyramids of 10 rows (22,000 boxes), each row of pyramids on its
# own ground segment, 11 m above the last.
ROWS = COLUMNS = 20
BASE = 10
EXTENT = 0.5
shelf = 2 * EXTENT * (BASE + 1)
width = 2 * EXTENT * COLUMNS * (BASE + 1)
ground = [{"type": "segment", "points": [[-width / 2, r * shelf], [width / 2, r * shelf]]}
          for r in range(ROWS)]
bodies = [{"name": "ground", "type": "static", "shapes": ground}]
for r in range(ROWS):
    for c in range(COLUMNS):
        center_x = -width / 2 + c * (2 * EXTENT * BASE + 2 * EXTENT) + 2 * EXTENT
        for i in range(BASE):
            for j in range(i, BASE):
                x = (i + 1) * EXTENT + 2 * (j - i) * EXTENT + center_x - 0.5
                y = (2 * i + 1) * EXTENT + r * shelf
                bodies.append(dynamic(f"p{r}_{c}_{i}_{j}", (x, y), [square(EXTENT)]))
write("many_pyramids", "Benchmark: 20 rows of 20 pyramids of 10 rows each (22,000 boxes of "
      "half-extent 0.5, density 1, friction 0.6), each row of pyramids on its own static ground "
      "segment 220 m long, 11 m above the one below, as Box2D v3's many_pyramids. Every "
      "pyramid should stand.", 200, bodies)

# compounds: 3,000 bodies of two triangles each, dropped into a box of 80 m by 100 m.
ground = [box(0.55, 0.5, (x, 0)) for x in range(-40, 41)]
ground += [box(0.5, 0.55, (-40, y)) for y in range(1, 101)]
ground += [box(0.5, 0.55, (40, y)) for y in range(1, 101)]
ground.append({"type": "segment", "points": [[-800, -80], [800, -80]]})
bodies = [{"name": "ground", "type": "static", "shapes": ground}]
left = polygon([(-1, 0), (0.5, 1), (0, 2)], friction=0.5)
right = polygon([(1, 0), (-0.5, 1), (0, 2)], friction=0.5)
side = 0.25
for i in range(20):
    for j in range(150):
        bodies.append(dynamic(f"c{i}_{j}", (i * 2 - 19 + side, j * 2.25 + 0.575 + 5),
                              [left, right]))
        side = -side
write("compounds", "Benchmark: 3,000 compound bodies (20 columns of 150), each two triangles "
      "(density 1, friction 0.5) leaning on each other like an A, dropped into an open box 80 m "
      "wide with walls 100 m high (boxes of the static ground; a segment 80 m below catches "
      "any that escape), as Box2D v3's compounds. They should fall and pile up in the box.", 500,
      bodies)

# smash: a heavy box at 40 m/s into a sleeping block of 9,600 small boxes, without gravity.
bodies = [dynamic("smasher", (-20, 0), [square(4, density=8)], linear_velocity=[40, 0])]
for i in range(120):
    for j in range(80):
        bodies.append(dynamic(f"s{i}_{j}", (i * 0.4 + 30, (j - 40) * 0.4), [square(0.2)],
                              awake=False))
write("smash", "Benchmark: without gravity, a box of half-extent 4 (density 8) flies at 40 m/s "
      "into a block of 120 x 80 boxes of half-extent 0.2 (density 1, friction 0.6) that start "
      "asleep, as Box2D v3's smash. The block should burst apart.", 300, bodies, gravity=[0, 0])

# spinner: 6,076 small bodies in a round drum stirred by a motorized bar.
drum = [[at(40 * math.cos(-2 * math.pi * k / 360)), at(40 * math.sin(-2 * math.pi * k / 360) + 32)]
        for k in range(360)]
bodies = [{"name": "ground", "type": "static",
           "shapes": [{"type": "chain", "points": drum, "loop": True, "friction": 0.1}]},
          dynamic("spinner", (0, 12), [box(0.6, 20.2, friction=0)])]
joints = [{"type": "revolute", "name": "motor", "body_a": "ground", "body_b": "spinner",
           "anchor": [0, 12], "enable_motor": True, "motor_speed": 5,
           "max_motor_torque": 1e10}]
r = 0.25
capsule = polygon([(0.25, -r), (0.25 + r * math.cos(math.pi / 6), -r / 2),
                   (0.25 + r * math.cos(math.pi / 6), r / 2), (0.25, r), (-0.25, r),
                   (-0.25 - r * math.cos(math.pi / 6), r / 2),
                   (-0.25 - r * math.cos(math.pi / 6), -r / 2), (-0.25, -r)],
                  density=0.25, friction=0.1, restitution=0.1)
shapes = [capsule, {"type": "circle", "radius": 0.35, "density": 0.25, "friction": 0.1,
                    "restitution": 0.1},
          square(0.35, density=0.25, friction=0.1, restitution=0.1)]
x, y = -23.0, 2.0
for i in range(2 * 3038):
    bodies.append(dynamic(f"g{i}", (x, y), [shapes[i % 3]]))
    x += 0.5
    if x >= 23:
        x, y = -23.0, y + 0.5
write("spinner", "Benchmark: 6,076 bodies (in turn a capsule, a circle of radius 0.35 and a box "
      "of half-extent 0.35; density 0.25, friction 0.1, restitution 0.1) in a drum of radius 40 "
      "(a 360-point chain loop, friction 0.1) stirred by a bar of half-extents 0.6 x 20.2 "
      "(frictionless) turned at 5 rad/s by a revolute motor of up to 1e10 N m, as Box2D v3's "
      "spinner. Stand-ins, so that Box2D 2.4.1 (meff bench's default peer) can run it too: "
      "each capsule (segment "
      "0.5 m, radius 0.25) is an 8-sided polygon inscribed in it, with flat sides and two "
      "corners on each cap, and v3's bar, a box of half-extents 0.4 x 20 rounded by 0.2 m, is "
      "the box around it; v3's motor torque is unlimited. The bodies should churn around the "
      "drum.", 500, bodies, joints)

# washer: a turning drum with four paddles, full of 8,100 small boxes.
ring = []
step = math.pi / 18
for i in range(36):
    a1, a2 = i * step, (i + 1) * step
    ring.append(polygon([(rad * math.cos(a), rad * math.sin(a)) for rad in (16, 18)
                         for a in (a1 + 0.1 * step, a2 - 0.1 * step)]))
    if i % 9 == 0:
        ring.append(polygon([(rad * math.cos(a), rad * math.sin(a)) for rad in (14, 16)
                             for a in (a1, a2)]))
bodies = [{"name": "washer", "type": "kinematic", "position": [0, 10],
           "angular_velocity": at(math.pi / 180 * 25), "linear_velocity": [0.001, -0.002],
           "shapes": ring}]
for i in range(90):
    for j in range(90):
        bodies.append(dynamic(f"w{i}_{j}", (-9.9 + 0.21 * j, 0.1 + 0.21 * i), [square(0.1)]))
write("washer", "Benchmark: a kinematic drum (inner radius 16 m, 36 wall blocks with small gaps "
      "and four paddles reaching in to 14 m) turning at 25 deg/s around (0, 10) with v3's slight "
      "drift of (0.001, -0.002) m/s, holding 90 x 90 boxes of half-extent 0.1 (density 1, "
      "friction 0.6), as Box2D v3's washer (whose boxes also raise hit events, which this scene "
      "does not ask for). The boxes should tumble like laundry.", 500, bodies)
