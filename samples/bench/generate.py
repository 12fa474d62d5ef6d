#!/usr/bin/env python3
"""Writes the benchmark scenes of samples/bench/ as Box2D v3's benchmark suite defines them
(shared/benchmarks.c: large_pyramid, joint_grid, tumbler), plus pyramids of 10, 20 and 50 rows
for the scaling measurement. Run it from anywhere; it rewrites the JSON files beside it."""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
WORLD = {"gravity": [0, -10], "dt": 1 / 60, "velocity_iterations": 8,
         "position_iterations": 3, "warm_starting": True, "block_solver": True,
         "allow_sleep": False, "continuous": False}


def write(name, description, frames, bodies, joints=()):
    scene = {"meff_scene": 1, "name": name, "description": description,
             "world": dict(WORLD, frames=frames), "bodies": list(bodies), "joints": list(joints)}
    with open(os.path.join(HERE, name + ".json"), "w") as out:
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


for rows, name in ((10, "pyramid10"), (20, "pyramid20"), (50, "pyramid50"),
                   (100, "large_pyramid")):
    count = rows * (rows + 1) // 2
    write(name, f"Benchmark: a pyramid of {rows} rows ({count} boxes of half-extent 0.5, "
          "density 1, friction 0.6) on a static ground box, sleeping off, as Box2D v3's "
          "large_pyramid. It should stand.", 500, pyramid(rows))

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
