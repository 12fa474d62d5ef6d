#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""Writes the extreme scenes of samples/extreme/ (issue 7: stability at the extremes).

The JSON files are committed; this script is how they were made, so a change of geometry is
made here and the files regenerated (`python3 samples/extreme/make_scenes.py`). Nothing at
build or test time runs it.

Geometry conventions (Box2D 2.4.1's, which meff follows): boxes, polygons and segments carry a
collision skin of 0.01 m and the position solver rests contacts at a separation of -0.005 m
(the linear slop), so two skinned shapes at rest are 2*0.01 - 0.005 = 0.015 m apart as drawn
and a circle rests 0.01 - 0.005 = 0.005 m above a segment. Every stack below is built at that
resting distance, so it starts at the solver's equilibrium and what the tests see is the
solver holding it, not the bodies dropping into place.
"""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
DT = 1.0 / 60.0
GAP = 0.015  # resting distance between two skinned shapes (see above)
STAND = 1800  # 30 s at 60 Hz: "they stand for 30 s of simulated time"


def world(frames, dt=DT, gravity=(0, -10), continuous=False):
    w = {"gravity": list(gravity), "dt": dt, "frames": frames, "velocity_iterations": 8,
         "position_iterations": 3}
    if continuous:
        w["continuous"] = True
    return w


def ground(half_width=20.0, x=0.0, friction=0.6, name="ground"):
    body = {"name": name, "type": "static",
            "shapes": [{"type": "segment", "points": [[-half_width, 0], [half_width, 0]],
                        "friction": friction}]}
    if x != 0:
        body["position"] = [x, 0]
    return body


def box(name, x, y, hw, hh, density=1.0, friction=0.6, angle=0.0, body_type="dynamic"):
    shape = {"type": "box", "half_width": hw, "half_height": hh}
    if density != 1.0:
        shape["density"] = density
    if friction != 0.6:
        shape["friction"] = friction
    body = {"name": name, "type": body_type, "position": [r(x), r(y)], "shapes": [shape]}
    if angle != 0.0:
        body["angle"] = r(angle)
    return body


def r(v):
    """Rounds to 12 significant digits so the files stay readable; the value written is the
    value both engines read."""
    return float(f"{v:.12g}")


def column(prefix, count, half, x0=0.0, offsets=None, density=1.0):
    bodies = []
    for i in range(count):
        y = GAP + half + i * (2 * half + GAP)
        dx = offsets[i] if offsets else 0.0
        bodies.append(box(f"{prefix}{i}", x0 + dx, y, half, half, density))
    return bodies


def pyramid(rows, half=0.5, x0=0.0, y0=0.0, density=1.0, prefix="box", pitch=None):
    """Rows of boxes, `rows` at the bottom, one at the top; `pitch` is the centre distance
    (default: resting distance, 2*half + GAP)."""
    pitch = pitch if pitch is not None else 2 * half + GAP
    bodies = []
    for row in range(rows):
        n = rows - row
        y = y0 + GAP + half + row * pitch
        for k in range(n):
            x = x0 + (k - (n - 1) / 2) * pitch
            bodies.append(box(f"{prefix}{row}_{k}", x, y, half, half, density))
    return bodies


def scene(name, description, w, bodies, joints=None, camera=None, plausibility=None):
    s = {"meff_scene": 1, "name": name, "description": description, "world": w}
    # The plausibility checks' thresholds (docs/validation.md), set only where Box2D 2.4.1
    # itself (meff's Box2D back end) goes beyond a default: 1.5 times its figure, rounded up
    # to two significant digits, the figure quoted where the scene is made.
    if plausibility:
        s["plausibility"] = plausibility
    s["bodies"] = bodies
    if joints:
        s["joints"] = joints
    if camera:
        s["render"] = {"camera": {"center": list(camera[0]), "height": camera[1]}}
    return s


def write(s):
    path = os.path.join(HERE, s["name"] + ".json")
    with open(path, "w") as f:
        json.dump(s, f, indent=1)
        f.write("\n")


# --- High mass ratio -------------------------------------------------------------------------

for ratio in (100, 1000):
    write(scene(
        f"mass_ratio_{ratio}",
        f"High mass ratio {ratio}:1. A 1 m cube of 1 kg on the ground carries a 1 m cube of "
        f"{ratio} kg (same size, density {ratio}). Sequential impulses with 8 iterations "
        f"converge slowly at such ratios, so the heavy box sinks into the light one by more than "
        f"the 0.005 m slop before position correction pushes it back. What must hold: nothing "
        f"passes through anything (the heavy box stays above the light box, the light box above "
        f"the ground, penetration bounded) and the pair stands for 30 s.",
        world(STAND),
        [ground(5), box("light", 0, GAP + 0.5, 0.5, 0.5),
         box("heavy", 0, GAP + 0.5 + 1 + GAP, 0.5, 0.5, density=ratio)],
        camera=((0, 1), 4),
        # Box2D: at 1000:1 the light box is pressed 0.345 m into the ground.
        plausibility={"penetration": 0.52} if ratio == 1000 else None))

rows = 6
heavy_y = GAP + 0.5 + rows * (1 + GAP)
write(scene(
    "heavy_on_pyramid",
    "A pyramid of 6 rows of light 1 m cubes (1 kg each, 21 boxes) with a 1 m cube of 100 kg "
    "on its top box: 100 times a light box, 4.8 times the whole pyramid. What must hold: no box "
    "passes through another or the ground, the pyramid does not collapse, and it stands for "
    "30 s. With Box2D's default 8 velocity iterations it does not (in meff as in Box2D 2.4.1): "
    "see docs/stability.md's table for the iterations it needs.",
    world(STAND),
    [ground(10)] + pyramid(rows) + [box("heavy", 0, heavy_y, 0.5, 0.5, density=100)],
    camera=((0, 3.5), 9)))

# A chain of 20 light links (0.125 m x 0.5 m, density 1: 0.0625 kg) hanging straight down from
# a pin, with a weight of 6.25 kg (100 links' mass) hooked to its end, released at rest: the
# joints start exact and the solver must take up the weight's pull through 20 light links.
links = 20
link_half = 0.25
top = 25.0
bodies = [{"name": "anchor", "type": "static", "position": [0, top]}]
joints = []
for i in range(links):
    bodies.append(box(f"link{i}", 0, top - (2 * i + 1) * link_half, 0.0625, link_half))
    joints.append({"type": "revolute", "name": f"hinge{i}",
                   "body_a": "anchor" if i == 0 else f"link{i - 1}", "body_b": f"link{i}",
                   "anchor": [0, top - 2 * i * link_half]})
weight_half = 0.25
bodies.append(box("weight", 0, top - 2 * links * link_half - weight_half, weight_half,
                  weight_half, density=100))
joints.append({"type": "revolute", "name": "hook", "body_a": f"link{links - 1}",
               "body_b": "weight", "anchor": [0, top - 2 * links * link_half]})
write(scene(
    "chain_heavy_weight",
    "A chain of 20 light links (0.125 m x 0.5 m, 0.0625 kg each) joined by revolute joints, "
    "hanging from a pin, with a 0.5 m cube of 6.25 kg (100 times a link) hooked to its end, "
    "released at rest. Chains of light links holding a heavy body are the classic weakness "
    "of sequential impulses: each velocity iteration carries the weight's pull one link "
    "further, so with 8 iterations the chain first stretches by metres and then recovers "
    "slowly. What must hold: the total gap of the 21 joints stays below the bounds stated in "
    "the test (one for 8 iterations, one for more).",
    world(STAND),
    bodies, joints, camera=((0, 14), 24),
    # Box2D: a hinge of the chain is still open by 0.0976 m in the last second.
    plausibility={"joint_gap": 0.15}))

# --- Stacks that must stand 30 s -------------------------------------------------------------

# Slight offsets: deterministic, within +-0.04 m (8 % of the half-width), alternating in sign so
# the column zig-zags but its centre of mass stays over its base.
offsets = [0.04 * math.sin(2.4 * i + 0.3) for i in range(15)]
write(scene(
    "stack15_offset",
    "A vertical stack of 15 one-metre boxes, each shifted sideways by up to 4 cm (a zig-zag). "
    "Each box starts at its resting distance from the one below. What must hold: it stands for "
    "30 s: no box falls or slides off, no box turns by more than a degree.",
    world(STAND), [ground(5)] + column("box", 15, 0.5, offsets=offsets),
    camera=((0, 8), 18)))

# Card house: cards are 1 m x 0.02 m boxes (drawn; with the 0.01 m skin they collide as
# 0.04 m thick). Two levels: two leaning pairs (Λ) at the bottom, a flat card across their
# tops, one leaning pair on it. Friction 0.7 everywhere.
CARD_L = 0.5  # half-length
CARD_T = 0.01  # half-thickness as drawn
SKIN = 0.01
TILT = math.radians(20)
CARD_FRICTION = 0.7


def leaning_pair(prefix, cx, base_y):
    """Two cards leaning on each other, the apex above cx, their lowest points at base_y
    (the resting height on the surface below)."""
    s, c = math.sin(TILT), math.cos(TILT)
    # Left card: axis u = (s, c); its inner face normal n = (c, -s). The inner top corner of
    # the core rectangle is centre + L u + T n; with the skin, the card's rightmost point there
    # is that corner + SKIN along x. Put it 0.0075 m left of cx (the two skins then rest
    # 0.015 m apart, the resting distance).
    corner_dx = CARD_L * s + CARD_T * c + SKIN
    x_left = cx - 0.0075 - corner_dx
    # Lowest point: the inner bottom corner of the core, centre - L u + T n, minus the skin.
    lowest_dy = -CARD_L * c - CARD_T * s - SKIN
    y = base_y - lowest_dy
    return [
        {"name": f"{prefix}_l", "type": "dynamic", "position": [r(x_left), r(y)],
         "angle": r(-TILT),
         "shapes": [{"type": "box", "half_width": CARD_T, "half_height": CARD_L,
                     "friction": CARD_FRICTION}]},
        {"name": f"{prefix}_r", "type": "dynamic", "position": [r(2 * cx - x_left), r(y)],
         "angle": r(TILT),
         "shapes": [{"type": "box", "half_width": CARD_T, "half_height": CARD_L,
                     "friction": CARD_FRICTION}]},
    ], y + CARD_L * c + CARD_T * s + SKIN  # apex: the highest point of the pair


level0 = 0.005  # a skinned corner rests 0.005 m above the ground segment (see top)
spread = 1.0
pair_a, apex = leaning_pair("card0a", -spread / 2, level0)
pair_b, _ = leaning_pair("card0b", spread / 2, level0)
flat_y = apex + 0.005 + SKIN + CARD_T  # resting on the apexes, centre of the flat card
flat = {"name": "card1_flat", "type": "dynamic", "position": [0, r(flat_y)],
        "shapes": [{"type": "box", "half_width": CARD_L, "half_height": CARD_T,
                    "friction": CARD_FRICTION}]}
pair_c, _ = leaning_pair("card2", 0.0, flat_y + CARD_T + SKIN - 0.005)
write(scene(
    "card_house",
    "A two-level house of cards: cards are 1 m x 0.02 m (0.04 m thick with the collision "
    "skin), friction 0.7, leaning 20 degrees from vertical in pairs. Two pairs stand on the "
    "ground, a flat card lies across their tops and a third pair stands on it. Cards are held "
    "up by friction at their feet and by each other at their tops. What must hold: it stands "
    "for 30 s (no card falls, the top apex drops less than the bound in the test).",
    world(STAND, gravity=(0, -10)),
    [ground(5, friction=CARD_FRICTION)] + pair_a + pair_b + [flat] + pair_c,
    camera=((0, 1.1), 3)))

# Arch of voussoirs: a semicircular arch, inner radius 3 m, outer 4 m, cut into 9 blocks whose
# joints point at the centre. No mortar: the blocks stand by friction (0.6) and normal force.
# Each radial face is moved 0.0075 m into its block so that neighbours start at the 0.015 m
# resting distance, and the two springers' bottom faces 0.015 m above the ground.
R_IN, R_OUT, BLOCKS = 3.0, 4.0, 9
bodies = [ground(10)]
for k in range(BLOCKS):
    a0 = math.pi * k / BLOCKS
    a1 = math.pi * (k + 1) / BLOCKS
    d0 = GAP if k == 0 else GAP / 2  # offset of face a0 along its normal (into the block)
    d1 = GAP if k == BLOCKS - 1 else GAP / 2

    def point(radius, angle, offset):
        return (radius * math.cos(angle) - offset * math.sin(angle),
                radius * math.sin(angle) + offset * math.cos(angle))

    pts = [point(R_IN, a0, d0), point(R_OUT, a0, d0), point(R_OUT, a1, -d1),
           point(R_IN, a1, -d1)]
    cx = sum(p[0] for p in pts) / 4
    cy = sum(p[1] for p in pts) / 4
    bodies.append({"name": f"voussoir{k}", "type": "dynamic", "position": [r(cx), r(cy)],
                   "shapes": [{"type": "polygon",
                               "vertices": [[r(p[0] - cx), r(p[1] - cy)] for p in pts]}]})
write(scene(
    "arch",
    "A semicircular arch of 9 voussoirs (inner radius 3 m, outer 4 m, joints radial) on flat "
    "ground, standing by friction (0.6) and compression alone: no joints, no mortar. Its "
    "thickness ratio 1/3.5 is well above Heyman's minimum for a semicircle (about 0.11), so a "
    "rigid-block arch stands. What must hold: it stands for 30 s; the keystone sags less than "
    "the bound in the test and no block slides out.",
    world(STAND), bodies, camera=((0, 2.5), 7)))

# --- Overlap recovery ------------------------------------------------------------------------

write(scene(
    "overlap_recovery",
    "A pyramid of 4 rows (10 one-metre boxes) created 25 % overlapped: centres 0.75 m apart "
    "horizontally and vertically, the bottom row 0.25 m into the ground. The position solver "
    "pushes them apart (at most 0.2 m per iteration, Baumgarte 0.2), which moves bodies "
    "without giving them velocity, so they separate without exploding. What must hold: the "
    "largest speed of any box stays below the bound in the test, and after 5 s they are "
    "separated, at rest and nothing flew away.",
    world(300), [ground(10)] + pyramid(4, pitch=0.75, y0=-0.25 - GAP),
    camera=((0, 2), 6),
    # Pushed out of their overlap, the boxes are lifted: Box2D's position pass raises the
    # energy by 53 J, 0.53 m of lift per box on average; the bottom row starts 0.272 m deep.
    plausibility={"energy_lift": 0.8, "penetration": 0.41}))

# --- Friction ramp ---------------------------------------------------------------------------

# Five ramps at the same slope, tan(theta) = 0.4 (21.8 degrees), each with one box; box and
# ramp share a friction coefficient mu so that the mixed value sqrt(mu*mu) = mu. mu = 0, 0.25,
# 0.375 slide (mu < tan theta); 0.45, 0.75 stay.
TAN = 0.4
theta = math.atan(TAN)
bodies = []
for i, mu in enumerate((0.0, 0.25, 0.375, 0.45, 0.75)):
    x0 = 12.0 * i
    # The ramp: a static segment from (x0 - 5, 5*tan) down to (x0 + 5, -5*tan).
    bodies.append({"name": f"ramp{i}", "type": "static", "position": [x0, 0],
                   "shapes": [{"type": "segment",
                               "points": [[-5, r(5 * TAN)], [5, r(-5 * TAN)]],
                               "friction": mu}]})
    # The box: 0.5 m half-size, turned to the slope, resting on it at the upper third.
    s, c = math.sin(theta), math.cos(theta)
    along = -2.0  # m from the ramp's centre, uphill
    px, py = along * c, -along * s
    nx, ny = s, c  # the ramp's upward normal
    dist = 0.5 + GAP
    bodies.append({"name": f"box_mu{str(mu).replace('.', '_')}", "type": "dynamic",
                   "position": [r(x0 + px + dist * nx), r(py + dist * ny)],
                   "angle": r(-theta),
                   "shapes": [{"type": "box", "half_width": 0.5, "half_height": 0.5,
                               "friction": mu}]})
write(scene(
    "friction_ramp",
    "Five ramps inclined at tan(theta) = 0.4 (21.8 degrees), each with a 1 m box resting on "
    "it; box and ramp have the same friction coefficient mu (so the mixed coefficient "
    "sqrt(mu*mu) is mu): 0, 0.25, 0.375, 0.45 and 0.75. Coulomb: a box slides when "
    "mu < tan(theta), with acceleration g (sin(theta) - mu cos(theta)), and stays when "
    "mu > tan(theta). What must hold: the first three slide at that acceleration, the last two "
    "do not move.",
    world(120), bodies, camera=((24, 0), 12)))

# --- Far from the origin ---------------------------------------------------------------------

for exponent in (3, 4, 5):
    x0 = 10.0 ** exponent
    write(scene(
        f"far_stack_1e{exponent}",
        f"The 10-box column of samples/scenes/stack10.json moved to x = 1e{exponent} m (the "
        f"ground with it), and beside it a box sliding at 2 m/s that friction (0.6) stops after "
        f"v^2/(2 mu g) = 0.33 m. In float, positions near x = 1e{exponent} are spaced "
        f"{2.0 ** (math.floor(math.log2(x0)) - 23):.3g} m apart, against the solver's 0.005 m "
        f"slop, and a step moves a body only if v*dt exceeds half that spacing. The test "
        f"compares it with the same scene at the origin and states where precision ends.",
        world(STAND), [ground(5, x=x0)] + column("box", 10, 0.5, x0=x0) +
        [{"name": "slider", "type": "dynamic", "position": [x0 + 2.5, GAP + 0.5],
          "linear_velocity": [2, 0],
          "shapes": [{"type": "box", "half_width": 0.5, "half_height": 0.5}]}],
        camera=((x0, 5), 12)))

# --- Speed -----------------------------------------------------------------------------------

for speed in (100, 1000):
    write(scene(
        f"bullet_{speed}",
        f"A ball of radius 0.05 m fired at {speed} m/s, no gravity, at a static wall 0.1 m "
        f"thick (0.12 m with the skin), with continuous collision (time of impact) requested. "
        f"At 60 Hz the ball moves {speed / 60:.1f} m per step (Box2D and meff clamp a step's "
        f"motion to 2 m, so at most 120 m/s survives the first step). With continuous "
        f"collision on (this file), the ball stops at the wall in both meff and Box2D 2.4.1; "
        f"with it off, it jumps over the wall in one step (tunnelling).",
        world(60, gravity=(0, 0), continuous=True),
        [{"name": "wall", "type": "static", "position": [0, 0],
          "shapes": [{"type": "box", "half_width": 0.05, "half_height": 2}]},
         {"name": "ball", "type": "dynamic", "position": [-5.3, 0],
          "linear_velocity": [speed, 0],
          "shapes": [{"type": "circle", "radius": 0.05}]}],
        camera=((0, 0), 6)))

# --- Long runs -------------------------------------------------------------------------------

write(scene(
    "long_pendulum",
    "A pendulum for 100000 steps (27.8 min at 60 Hz): a 0.2 m cube of 1 kg (density 25) "
    "pinned by a revolute joint to a fixed point 2 m away, released from horizontal. No "
    "damping, no contacts: its energy m g y + kinetic should stay constant. What must hold: "
    "the energy drift over the run is measured and stays below the bound in the test.",
    world(100000),
    [{"name": "pivot", "type": "static", "position": [0, 10]},
     box("bob", 2, 10, 0.1, 0.1, density=25)],
    [{"type": "revolute", "name": "pin", "body_a": "pivot", "body_b": "bob",
      "anchor": [0, 10]}],
    camera=((0, 9), 5)))

write(scene(
    "long_bounce",
    "A ball with restitution 1 dropped from 5 m onto the ground, for 100000 steps. A perfectly "
    "elastic bounce keeps its energy; restitution must never add energy. What must hold: the "
    "ball's energy never exceeds its initial value by more than the bound in the test.",
    world(100000),
    [ground(5),
     {"name": "ball", "type": "dynamic", "position": [0, 5.5],
      "shapes": [{"type": "circle", "radius": 0.5, "restitution": 1}]}],
    camera=((0, 3), 7)))

# --- Tiny and large bodies -------------------------------------------------------------------

TINY = 0.005
write(scene(
    "tiny_bodies",
    "Bodies of 1 cm: a column of 3 boxes of 1 cm and a ball of 1 cm diameter on the ground. "
    "The collision skin (0.01 m) and slop (0.005 m) are Box2D's constants for bodies of 0.1 m "
    "to 10 m; here the skin is larger than the bodies, so they rest visibly apart (0.015 m "
    "gaps, 1.5 times their size), and they collide as rounded blobs: the column of three "
    "falls over (in Box2D 2.4.1 too). What must hold: nothing falls through the ground or "
    "another body, and everything ends at rest.",
    world(STAND),
    [ground(1)] + [box(f"tiny{i}", 0, GAP + TINY + i * (2 * TINY + GAP), TINY, TINY)
                   for i in range(3)] +
    [{"name": "ball", "type": "dynamic", "position": [0.2, 0.005 + TINY],
      "shapes": [{"type": "circle", "radius": TINY}]}],
    camera=((0.1, 0.05), 0.2)))

BIG = 50.0
write(scene(
    "large_bodies",
    "Bodies of 100 m: a column of 3 boxes 100 m wide (10000 kg each at density 1) on the "
    "ground, and a 100 m ball beside them. Lengths are 10 times Box2D's recommended range; "
    "the tolerances (0.005 m slop, 2 m largest step motion) do not scale. What must hold: "
    "they stand for 30 s, nothing sinks through the ground.",
    world(STAND),
    [ground(500)] + [box(f"big{i}", 0, GAP + BIG + i * (2 * BIG + GAP), BIG, BIG)
                     for i in range(3)] +
    [{"name": "ball", "type": "dynamic", "position": [200, 0.005 + BIG],
      "shapes": [{"type": "circle", "radius": BIG}]}],
    camera=((50, 150), 320)))

write(scene(
    "dt_sweep_stack",
    "The 10-box column of stack10.json, run by the test at time steps from 1/30 s to 1/1000 s "
    "(the file's dt is 1/60 s). What must hold at every dt: it stands for 30 s.",
    world(STAND), [ground(5)] + column("box", 10, 0.5), camera=((0, 5), 12)))

# --- Plausibility of the soft step (issue 31) ------------------------------------------------

write(scene(
    "rod_into_wall",
    "Two 40 kg boxes (1 m, density 40) joined by a rigid 5 m distance joint slide at 8 m/s "
    "without gravity into a static wall; every restitution is 0 (issue 31). Without restitution "
    "nothing may bounce back: the pair must stop at the wall. Box2D 2.4.1 leaves it 0.031 m/s; "
    "the soft step once returned 2.54 m/s (258 of the 2560 J).",
    {"gravity": [0, 0], "dt": DT, "frames": 240, "velocity_iterations": 8,
     "position_iterations": 3},
    [{"name": "wall", "type": "static",
      "shapes": [{"type": "box", "half_width": 0.5, "half_height": 3, "center": [10, 0],
                  "density": 0}]},
     {"name": "front", "type": "dynamic", "position": [5, 0], "linear_velocity": [8, 0],
      "shapes": [{"type": "box", "half_width": 0.5, "half_height": 0.5, "density": 40}]},
     {"name": "rear", "type": "dynamic", "position": [0, 0], "linear_velocity": [8, 0],
      "shapes": [{"type": "box", "half_width": 0.5, "half_height": 0.5, "density": 40}]}],
    joints=[{"type": "distance", "name": "rod", "body_a": "front", "body_b": "rear",
             "anchor_a": [5, 0], "anchor_b": [0, 0]}],
    camera=((5, 0), 8)))

write(scene(
    "violated_rod",
    "A rigid distance joint that starts 1.59 m too long, without gravity: a wheel (radius 1.6, "
    "density 1) on an axle, and a box (1 m, density 1) 3.1 m from the wheel's anchor on a rod "
    "of length 1.5 (issue 31's scene, its numbers made exact in float so that the scene "
    "survives a b2dJson round trip). Nothing moves at the start, so closing the gap may give "
    "the bodies no lasting energy: Box2D 2.4.1 closes it by moving them (0 J); the soft step "
    "once turned the gap into 876 J of motion that lasted the whole run.",
    {"gravity": [0, 0], "dt": DT, "frames": 600, "velocity_iterations": 8,
     "position_iterations": 3},
    [{"name": "ground", "type": "static"},
     {"name": "wheel", "type": "dynamic", "position": [0, 5],
      "shapes": [{"type": "circle", "radius": 1.6, "density": 1}]},
     {"name": "b", "type": "dynamic", "position": [3, 5],
      "shapes": [{"type": "box", "half_width": 0.5, "half_height": 0.5, "density": 1}]}],
    joints=[{"type": "revolute", "name": "axle", "body_a": "ground", "body_b": "wheel",
             "anchor": [0, 5]},
            {"type": "distance", "name": "rod", "body_a": "wheel", "body_b": "b",
             "local_anchor_a": [0, -0.75], "local_anchor_b": [0, 0], "length": 1.5}],
    camera=((1, 5), 8)))

write(scene(
    "heavy_dropped_on_light",
    "Mass ratio under impact: a 1 m cube of 1000 kg (density 1000) dropped from 1 m onto a 1 m "
    "cube of 1 kg resting on the ground (issue 31). It lands at about 4.5 m/s. What must hold: "
    "the heavy box stays on top and presses the light one no more than 2 cm beyond rest, "
    "nothing bounces (restitution 0).",
    world(600),
    [ground(5),
     box("light", 0, GAP + 0.5, 0.5, 0.5),
     box("heavy", 0, GAP + 1.0 + GAP + 0.5 + 1.0, 0.5, 0.5, density=1000)],
    camera=((0, 1.5), 5),
    # Box2D (2.4.1's weak spot at high mass ratios): the heavy box slides off, presses the light
    # one 0.483 m into the ground and leaves the ground at 3.14 m/s.
    plausibility={"penetration": 0.73, "rebound_speed": 4.8}))

write(scene(
    "stack12_small",
    "A column of 12 boxes of 0.4 m (density 1, friction 0.6) built at the resting distance on "
    "the ground (issue 31). What must hold: it stands, and no box drifts more than 5 mm between "
    "1 s and 10 s.",
    world(STAND), [ground(5)] + column("box", 12, 0.2), camera=((0, 2.7), 6)))
