#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""Writes samples/solver2d/: the scenes of Erin Catto's Solver2D (github.com/erincatto/solver2d,
samples/collection/*.cpp) in meff's scene format. The numbers are Solver2D's; each scene's
description names its source file and sample and says what could not be translated.

The JSON files are committed; this script is how they were made (`python3
samples/solver2d/make_scenes.py`). Nothing at build or test time runs it. It reuses the
shape and body helpers of samples/testbed/make_scenes.py.

Translation rules, so that a scene is what Solver2D builds:
- Solver2D's shape defaults are friction 0.6, restitution 0, density 1 (the scene format's
  too); its ground bodies are static; gravity is (0, -10).
- Solver2D's sample application steps at 60 Hz with 4 primary and 2 secondary iterations, and
  its default solver (PGS_NGS_Block) is Box2D 2.4.1's: velocity iterations 4, position
  iterations 2, warm starting on. Solver2D has neither sleeping nor continuous collision: both
  off in every scene.
- Solver2D's polygons have no skin; Box2D 2.4.1's (and so meff's) carry a 0.01 m one, so bodies
  rest 0.01 m further apart than in Solver2D. Positions are Solver2D's.
- A capsule (a segment swept by a radius) is not a Box2D 2.4.1 shape. It is built as the union
  that it is: a box between the two cap centres, its half height the radius less the 0.01 m
  skin, and a circle of the radius at each end. The circles' density is halved so that the
  body's mass is about the capsule's (each circle's half that lies inside the box would
  otherwise count twice).
- Where Solver2D builds a size by build type (NDEBUG), the debug size is used, so that every
  back end can run the battery in the test suite; the description says so.

Plausibility thresholds ("plausibility", docs/validation.md): the defaults, except where Box2D
2.4.1 itself (meff's Box2D back end) goes beyond one; there the scene's limit is 1.5 times
Box2D's figure, rounded up to two significant digits, and the figure is quoted beside it.
"""
import importlib.util
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
_spec = importlib.util.spec_from_file_location(
    "testbed_scenes", os.path.join(HERE, "..", "testbed", "make_scenes.py"))
tb = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(tb)

SOURCE = "Solver2D (erincatto/solver2d), samples/collection/"
SKIN = 0.01  # Box2D 2.4.1's polygon radius (b2_polygonRadius)


def box(hw, hh, center=(0, 0), angle=0.0, density=1.0, friction=0.6, **kw):
    return tb.box(hw, hh, center, angle, density=density, friction=friction, **kw)


def circle(r, center=(0, 0), density=1.0, friction=0.6, **kw):
    return tb.circle(r, center, density=density, friction=friction, **kw)


def segment(p1, p2, density=1.0, friction=0.6, **kw):
    return tb.segment(p1, p2, density=density, friction=friction, **kw)


def polygon(vertices, density=1.0, friction=0.6, **kw):
    return tb.polygon(vertices, density=density, friction=friction, **kw)


def capsule(p1, p2, r, density=1.0, friction=0.6, **kw):
    """A capsule as a box and two circles (module docstring)."""
    c = ((p1[0] + p2[0]) / 2, (p1[1] + p2[1]) / 2)
    half = math.hypot(p2[0] - p1[0], p2[1] - p1[1]) / 2
    angle = math.atan2(p2[1] - p1[1], p2[0] - p1[0])
    return [box(half, r - SKIN, c, angle, density=density, friction=friction, **kw),
            circle(r, p1, density=density / 2, friction=friction, **kw),
            circle(r, p2, density=density / 2, friction=friction, **kw)]


static = tb.static
dynamic = tb.dynamic
revolute = tb.revolute

# Thresholds where Box2D 2.4.1 (meff's Box2D back end, at these scenes' 4 velocity and 2
# position iterations) goes beyond a default: 1.5 times Box2D's figure, rounded up to two
# significant digits (Box2D's figure in the comment). energy_lift is set so that the energy
# limit is 1.5 times Box2D's gain: bodies created overlapping (or touching, so that Box2D's
# 0.01 m skin overlaps) are pushed apart and up, and joints created open lift the bodies they
# close on. Scenes Box2D does not bring to rest at these iterations have no rest check.
BOX2D_LIMITS = {
    "arch": {"penetration": 0.14, "rebound_speed": 2.5},  # 0.0904 m; 1.63 m/s (it falls)
    "ball_and_chain": {"joint_gap": 35.0},  # 22.9 m: the chain pulled apart by the ball
    "bridge": {"joint_gap": 25.0},  # 16.3 m
    "confined": {"penetration": 0.33},  # 0.213 m: a ball squeezed into a wall
    "far_chain": {"joint_gap": 28.0},  # 18.1 m
    "far_recovery": {"energy_lift": 0.30, "penetration": 0.23},  # 19.4 J; 0.148 m
    "friction_ramp": {"penetration": 0.15},  # 0.0957 m
    "high_mass_ratio_1": {"penetration": 1.6, "rebound_speed": 3.1},  # 1.06 m; 2.00 m/s
    "high_mass_ratio_2": {"penetration": 0.69, "rebound_speed": 7.9},  # 0.457 m; 5.26 m/s
    "high_mass_ratio_3": {"penetration": 0.69, "rebound_speed": 7.9},  # 0.457 m; 5.26 m/s
    "overlap_recovery": {"energy_lift": 0.42, "penetration": 0.23},  # 28.0 J; 0.150 m
    "pyramid": {"energy_lift": 0.14},  # 196 J: the skins' overlap pushes the rows up
    "far_ragdoll_pile": {"penetration": 0.12, "rebound_speed": 2.0},  # 0.075 m; 1.32 m/s
    "ragdoll": {"penetration": 0.095, "rebound_speed": 2.3},  # 0.0629 m; 1.49 m/s
    "stretched_chain": {"energy_lift": 26.0, "joint_gap": 0.37},  # 860 J; 0.246 m
    "vertical_stack": {"penetration": 0.21},  # 0.137 m (the column falls)
}
NO_REST = {"arch", "far_ragdoll_pile", "high_mass_ratio_2", "high_mass_ratio_3", "vertical_stack"}

# Structures that must hold their shape ("hold", docs/validation.md): from `after` (0 for those
# built standing, 2 s for those dropped into place, by when every body has landed) no body may
# move further than half the size of the structure's building block, a 1 m box or a 0.4 m card.
# A body that has moved that far has left its place (a box half off the one under it, a card's
# foot off the flat card it stood on); settling moves them far less (a 20-row pyramid sinks by
# 0.27 m at most under these iterations as its skins and slops compress; the card house's
# starting overlaps push its cards apart by 0.088 m at most without gravity), and a fall moves
# them by more than their size (1.3 m and more). The house of cards and the column fall at
# these iterations in Box2D 2.4.1 itself (tests/check_plausibility.py lists the figures).
HOLD = {
    "card_house": {"after": 0.0, "distance": 0.2},
    "far_pyramid": {"after": 2.0, "distance": 0.5},
    "overlap_recovery": {"after": 2.0, "distance": 0.5},
    "pyramid": {"after": 0.0, "distance": 0.5},
    "vertical_stack": {"after": 2.0, "distance": 0.5},
}

SCENES = {}


def scene(name, sample, source, description, frames, bodies, joints=(), plausibility=None,
          render_height=None, render_center=None):
    w = {"gravity": [0, -10], "dt": 1.0 / 60.0, "frames": frames, "velocity_iterations": 4,
         "position_iterations": 2, "warm_starting": True, "allow_sleep": False,
         "continuous": False}
    s = {"meff_scene": 1, "name": "solver2d_" + name,
         "description": SOURCE + source + ', sample "' + sample + '": ' + description,
         "world": w, "bodies": bodies}
    if joints:
        s["joints"] = list(joints)
    plausibility = dict(plausibility or {}, **BOX2D_LIMITS.get(name, {}))
    if name in NO_REST:
        plausibility.pop("rest", None)
    if name in HOLD:
        plausibility["hold"] = HOLD[name]
    if plausibility:
        s["plausibility"] = plausibility
    if render_height:
        s["render"] = {"camera": {"center": list(render_center or (0, 0)),
                                  "height": render_height}}
    SCENES[name] = s


REST = {"rest": {"after": 8.0, "speed": 0.05}}


def ground_box(hw=100.0, hh=1.0, y=-1.0, friction=0.6):
    return static("ground", [box(hw, hh, friction=friction)], position=(0, y))


# --- sample_contact.cpp -------------------------------------------------------------------
def single_box():
    bodies = [static("ground", [segment((-66, 0), (66, 0), friction=0.5)]),
              dynamic("box", (0, 4), [box(1, 1, friction=0.5)])]
    scene("single_box", "Single Box", "sample_contact.cpp",
          "a 2 m box (friction 0.5) dropped from 3 m above its resting height onto a 132 m "
          "ground segment.", 300, bodies, plausibility=REST)


def high_mass_ratio_1():
    bodies = [static("ground", [segment((-66, 0), (66, 0), friction=0.5)])]
    for j in range(3):
        count = 10
        offset = -20.0 + 2.0 * (count + 1.0) * j
        y = 1.0
        row = 0
        while count > 0:
            for i in range(count):
                coeff = i - 0.5 * count
                yy = y + 2.0 if count == 1 else y
                density = (j + 1.0) * 100.0 if count == 1 else 1.0
                bodies.append(dynamic(f"p{j}_r{row}_{i}", (2.0 * coeff + offset, yy),
                                      [box(1, 1, density=density, friction=0.5)]))
            count -= 1
            row += 1
            y += 2.0
    scene("high_mass_ratio_1", "High Mass Ratio 1", "sample_contact.cpp",
          "three pyramids of 2 m boxes (friction 0.5), 10 rows each, the single top box of "
          "each 100, 200 and 300 times as dense as the others and dropped from 2 m above its "
          "place.", 600, bodies, render_height=40, render_center=(2, 10))


def high_mass_ratio(thick):
    small = 0.5
    if thick:
        ground = static("ground", [box(40, 2)], position=(0, -2))
    else:
        ground = static("ground", [segment((-20, 0), (20, 0))])
    bodies = [ground,
              dynamic("small_left", (-9, 0.5), [box(small, small)]),
              dynamic("small_right", (9, 0.5), [box(small, small)]),
              dynamic("big", (0, 26), [box(10, 10)])]
    name, sample = (("high_mass_ratio_3", "High Mass Ratio 3") if thick
                    else ("high_mass_ratio_2", "High Mass Ratio 2"))
    ground_text = "an 80 x 4 m ground box" if thick else "a 40 m ground segment"
    scene(name, sample, "sample_contact.cpp",
          f"a 20 m box (400 kg) dropped from 6 m onto two 1 m boxes (1 kg) standing 18 m "
          f"apart on {ground_text}: a 400:1 mass ratio under impact.", 600, bodies,
          plausibility=REST)


def friction_ramp():
    shapes = [segment((-40, 0), (40, 0), friction=0.2),
              box(13, 0.25, (-4, 22), -0.25, friction=0.2),
              box(0.25, 1, (10.5, 19), friction=0.2),
              box(13, 0.25, (4, 14), 0.25, friction=0.2),
              box(0.25, 1, (-10.5, 11), friction=0.2),
              box(13, 0.25, (-4, 6), -0.25, friction=0.2)]
    bodies = [static("ground", shapes)]
    for i, mu in enumerate((0.75, 0.5, 0.35, 0.1, 0.0)):
        bodies.append(dynamic(f"box{i}", (-15 + 4 * i, 28), [box(0.5, 0.5, density=25,
                                                                  friction=mu)]))
    scene("friction_ramp", "Friction Ramp", "sample_contact.cpp",
          "three ramps (friction 0.2) tilted 0.25 rad in turn, with stops at their low ends; "
          "five 1 m boxes (density 25, friction 0.75, 0.5, 0.35, 0.1 and 0) dropped on the top "
          "one: the mixed friction sqrt(0.2 mu) of the first two (0.39, 0.32) holds them on the "
          "0.25 rad slope (tan 0.255), the others slide down.", 600, bodies)


def overlap_recovery():
    count, overlap, extent = 4, 0.25, 0.5
    bodies = [static("ground", [segment((-40, 0), (40, 0))])]
    fraction = 1.0 - overlap
    y = extent
    for i in range(count):
        x = fraction * extent * (i - count)
        for j in range(i, count):
            bodies.append(dynamic(f"box{i}_{j}", (x, y), [box(extent, extent)]))
            x += 2.0 * fraction * extent
        y += 2.0 * fraction * extent
    scene("overlap_recovery", "Overlap Recovery", "sample_contact.cpp",
          "a pyramid of ten 1 m boxes created overlapping by 25 % (centres 0.75 m apart), the "
          "bottom row 0.25 m into the ground: the solver must push them apart without "
          "throwing them.", 600, bodies, plausibility=REST)


def vertical_stack():
    bodies = [ground_box()]
    for i in range(15):
        shift = -0.01 if i % 2 == 0 else 0.01
        bodies.append(dynamic(f"box{i}", (shift, 0.55 + 1.1 * i),
                              [box(0.5, 0.5, friction=0.3)]))
    scene("vertical_stack", "Vertical Stack", "sample_contact.cpp",
          "15 boxes of 1 m (friction 0.3) 0.1 m apart in a column, shifted 0.01 m left and "
          "right in turn, dropped onto a 200 x 2 m ground box (the sample's box variant; its "
          "circle variant is switched off in the source). At these iterations Box2D 2.4.1 lets the "
          "column fall.", 600, bodies, plausibility=REST)


def pyramid():
    base, h = 20, 0.5
    bodies = [ground_box()]
    for i in range(base):
        y = (2.0 * i + 1.0) * h
        for j in range(i, base):
            x = (i + 1.0) * h + 2.0 * (j - i) * h - h * base
            bodies.append(dynamic(f"box{i}_{j}", (x, y), [box(h, h)]))
    scene("pyramid", "Pyramid", "sample_contact.cpp",
          "a pyramid of 1 m boxes touching each other, 20 on its base (the sample's debug "
          "size; 100 when built with NDEBUG), 210 boxes, on a 200 x 2 m ground box.", 600,
          bodies, plausibility=REST)


ARCH_INNER = [(16.0, 0.0), (14.93803712795643, 5.133601056842984),
              (13.79871746027416, 10.24928069555078), (12.56252963284711, 15.34107019122473),
              (11.20040987372525, 20.39856541571217), (9.66521217819836, 25.40369899225096),
              (7.87179930638133, 30.3179337000085), (5.635199558196225, 35.03820717801641),
              (2.405937953536585, 39.09554102558315)]
ARCH_OUTER = [(24.0, 0.0), (22.33619528222415, 6.02299846205841),
              (20.54936888969905, 12.00964361211476), (18.60854610798073, 17.9470321677465),
              (16.46769273811807, 23.81367936585418), (14.05325025774858, 29.57079353071012),
              (11.23551045834022, 35.13775818285372), (7.752568160730571, 40.30450679009583),
              (3.016931552701656, 44.28891593799322)]


def arch():
    p1 = [(0.25 * x, 0.25 * y) for x, y in ARCH_INNER]
    p2 = [(0.25 * x, 0.25 * y) for x, y in ARCH_OUTER]
    bodies = [static("ground", [segment((-100, 0), (100, 0))])]
    for i in range(8):
        bodies.append(dynamic(f"right{i}", (0, 0), [polygon([p1[i], p2[i], p2[i + 1],
                                                              p1[i + 1]])]))
    for i in range(8):
        m = lambda p: (-p[0], p[1])
        bodies.append(dynamic(f"left{i}", (0, 0), [polygon([m(p2[i]), m(p1[i]), m(p1[i + 1]),
                                                             m(p2[i + 1])])]))
    bodies.append(dynamic("keystone", (0, 0), [polygon([p1[8], p2[8], (-p2[8][0], p2[8][1]),
                                                         (-p1[8][0], p1[8][1])])]))
    for i in range(4):
        bodies.append(dynamic(f"load{i}", (0, 0.5 + p2[8][1] + 1.0 * i), [box(2, 0.5)]))
    scene("arch", "Arch", "sample_contact.cpp",
          "a pointed arch of 17 blocks (friction 0.6, no mortar) 4 m to 6 m from the centre "
          "at its feet and 11 m high, its blocks touching along their joints, with four 4 x 1 m "
          "boxes stacked on the keystone. Solver2D's test of whether a solver holds it: at these "
          "iterations Box2D 2.4.1 lets it fall.", 600, bodies, plausibility=REST,
          render_height=16, render_center=(0, 7))


def double_domino():
    count = 15
    bodies = [ground_box()]
    m = 0.25 * 1.0  # a 0.25 x 1 m domino of density 1
    inertia = m * (0.25 ** 2 + 1.0 ** 2) / 12
    x = -0.5 * count
    for i in range(count):
        extra = {}
        if i == 0:
            # The sample's linear impulse (0.2, 0) N s at (x, 1), 0.5 m above the centre.
            extra = {"linear_velocity": [0.2 / m, 0.0],
                     "angular_velocity": -0.5 * 0.2 / inertia}
        bodies.append(dynamic(f"domino{i}", (x, 0.5), [box(0.125, 0.5)], **extra))
        x += 1.0
    scene("double_domino", "Double Domino", "sample_contact.cpp",
          "15 dominoes of 0.25 x 1 m, 1 m apart; the first is given the impulse (0.2, 0) N s "
          "0.5 m above its centre (here its effect: 0.8 m/s and -4.52 rad/s), and the row "
          "falls.", 600, bodies)


def confined():
    grid = 25
    walls = []
    for a, b in (((-10.5, 0), (10.5, 0)), ((-10.5, 0), (-10.5, 20.5)),
                 ((10.5, 0), (10.5, 20.5)), ((-10.5, 20.5), (10.5, 20.5))):
        walls += capsule(a, b, 0.5)
    bodies = [static("ground", walls)]
    for column in range(grid):
        for row in range(grid):
            x = -8.75 + column * 18.0 / grid
            y = 1.5 + row * 18.0 / grid
            bodies.append(dynamic(f"ball{column}_{row}", (x, y), [circle(0.5)],
                                  gravity_scale=0.0))
    scene("confined", "Confined", "sample_contact.cpp",
          "625 balls of radius 0.5 m without gravity created overlapping in a 25 x 25 grid "
          "(0.72 m apart) inside a closed box of four capsule walls of radius 0.5 m (each here "
          "a box and two circles): they must spread out and fill the box without escaping.",
          300, bodies, render_height=24, render_center=(0, 10))


def card_house():
    height, thickness = 0.2, 0.001
    a0, a1, a2 = math.radians(25), math.radians(-25), 0.5 * math.pi
    bodies = [static("ground", [box(40, 2, friction=0.7)], position=(0, -2))]
    n, z0, y = 5, 0.0, height - 0.02
    level = 0
    while n:
        z = z0
        for i in range(n):
            if i != n - 1:
                bodies.append(dynamic(f"flat{level}_{i}", (z + 0.25, y + height - 0.015),
                                      [box(thickness, height, friction=0.7)], angle=a2))
            bodies.append(dynamic(f"left{level}_{i}", (z, y),
                                  [box(thickness, height, friction=0.7)], angle=a1))
            z += 0.175
            bodies.append(dynamic(f"right{level}_{i}", (z, y),
                                  [box(thickness, height, friction=0.7)], angle=a0))
            z += 0.175
        y += height * 2.0 - 0.03
        z0 += 0.175
        n -= 1
        level += 1
    scene("card_house", "Card House", "sample_contact.cpp",
          "a house of 0.4 m cards (0.002 m thick; friction 0.7) leaning 25 degrees from vertical "
          "in pairs, five levels from 5 pairs down to 1, flat cards across the pairs (from PEEL)."
          " Solver2D builds its cards 2 to 9 mm apart and 1.7 mm into the ground (the flat cards "
          "of a level overlap end to end); with Box2D 2.4.1's 0.01 m skin on every card and the "
          "ground, each card here starts overlapping its neighbours by 11 to 22 mm. It falls "
          "within 2.5 s in every back end, at these iterations as at Box2D's default 8 and 3 (and"
          " the soft step at up to 32 sub-steps); Solver2D's own solvers all let it fall at its 4"
          " and 2 iterations too (its soft step holds it from 8 sub-steps).", 600,
          bodies, plausibility=REST, render_height=2.5, render_center=(0.7, 1.0))


def circle_stack():
    bodies = [static("ground", [segment((-40, 0), (40, 0))])]
    for i in range(10):
        bodies.append(dynamic(f"ball{i}", (0, 4.0 + 3.0 * i), [circle(1.0)]))
    scene("circle_stack", "Circle Stack", "sample_contact.cpp",
          "ten balls of radius 1 m, 3 m apart in a column, dropped onto the ground: they land "
          "on each other and roll off.", 600, bodies)


# --- sample_far.cpp -----------------------------------------------------------------------
def far_pyramid():
    ox, oy = 100000.0, -80000.0
    base, h = 10, 0.5
    shift = 1.25 * h
    bodies = [static("ground", [box(100, 1)], position=(ox, oy - 1))]
    for i in range(base):
        y = (2.0 * i + 1.0) * shift + 0.5
        for j in range(i, base):
            x = (i + 1.0) * shift + 2.0 * (j - i) * shift - h * base
            bodies.append(dynamic(f"box{i}_{j}", (x + ox, y + oy), [box(h, h)]))
    scene("far_pyramid", "Pyramid (Far)", "sample_far.cpp",
          "a pyramid of 55 one-metre boxes (10 on its base, created 0.25 m apart) dropped onto "
          "a ground box, all of it at (100000, -80000) m from the origin, where a float's step "
          "is 7.8 mm.", 600, bodies, render_height=14, render_center=(ox, oy + 5))


def far_stack():
    ox, oy = 40000.0, -25000.0
    bodies = [static("ground", [box(10, 1)], position=(ox, oy - 1)),
              dynamic("ball", (ox + 1.875, oy + 0.125), [circle(0.1)]),
              dynamic("block", (ox - 1.875, oy + 0.15), [box(0.1, 0.125)]),
              dynamic("plank", (ox, oy + 0.325), [box(2, 0.05)]),
              dynamic("small", (ox - 0.5, oy + 0.9), [box(0.25, 0.25)]),
              dynamic("large", (ox - 0.55, oy + 1.7), [box(0.5, 0.5)])]
    scene("far_stack", "Stack (Far)", "sample_far.cpp",
          "a 4 m plank laid on a 0.1 m ball and a small block, two boxes stacked on it off "
          "centre, at (40000, -25000) m from the origin (a float's step there: 3.9 mm).", 600,
          bodies, render_height=5, render_center=(ox, oy + 1.5))


def far_recovery():
    ox, oy = 80000.0, -70000.0
    count, overlap, extent = 4, 0.25, 0.5
    bodies = [static("ground", [segment((-40, 0), (40, 0))], position=(ox, oy))]
    fraction = 1.0 - overlap
    y = extent
    for i in range(count):
        x = fraction * extent * (i - count)
        for j in range(i, count):
            bodies.append(dynamic(f"box{i}_{j}", (x + ox, y + oy), [box(extent, extent)]))
            x += 2.0 * fraction * extent
        y += 2.0 * fraction * extent
    scene("far_recovery", "Recovery (Far)", "sample_far.cpp",
          "the overlap recovery pyramid (ten 1 m boxes created 25 % overlapped) at "
          "(80000, -70000) m from the origin (a float's step there: 7.8 mm).", 600, bodies,
          render_height=6, render_center=(ox - 1, oy + 2))


def chain_of_capsules(name, sample, source, description, count, hx, r, density, origin,
                      frames, ball=None, render=None):
    ox, oy = origin
    bodies = [static("ground", position=(ox, oy))]
    joints = []
    prev = "ground"
    for i in range(count):
        link = f"link{i}"
        bodies.append(dynamic(link, ((1 + 2 * i) * hx + ox, count * hx + oy),
                              capsule((-hx, 0), (hx, 0), r, density=density),
                              linear_damping=0.1, angular_damping=0.1))
        joints.append(revolute(f"hinge{i}", prev, link, (2 * i * hx + ox, count * hx + oy)))
        prev = link
    if ball:
        radius = ball
        bodies.append(dynamic("ball", ((1 + 2 * count) * hx + radius - hx + ox,
                                       count * hx + oy), [circle(radius, density=density)],
                              linear_damping=0.1, angular_damping=0.1))
        joints.append(revolute(f"hinge{count}", prev, "ball",
                               (2 * count * hx + ox, count * hx + oy)))
    scene(name, sample, source, description, frames, bodies, joints,
          render_height=render[0] if render else None,
          render_center=render[1] if render else None)


def far_chain():
    chain_of_capsules(
        "far_chain", "Far Chain", "sample_far.cpp",
        "a chain of 40 capsule links (0.2 m between cap centres, radius 0.025 m, density 20, "
        "each here a box and two circles; linear and angular damping 0.1) pinned at one end "
        "and released horizontal, at (40000, -35000) m from the origin (a float's step there: "
        "3.9 mm).", 40, 0.1, 0.025, 20.0, (40000.0, -35000.0), 600,
        render=(10, (40000.0, -35000.0)))


# --- sample_joints.cpp --------------------------------------------------------------------
def bridge():
    count, xbase = 160, -80.0
    bodies = [static("ground")]
    joints = []
    prev = "ground"
    for i in range(count):
        plank = f"plank{i}"
        bodies.append(dynamic(plank, (xbase + 0.5 + i, 20), [box(0.5, 0.125, density=20)],
                              linear_damping=0.1, angular_damping=0.1))
        joints.append(revolute(f"hinge{i}", prev, plank, (xbase + i, 20)))
        prev = plank
    joints.append(revolute(f"hinge{count}", prev, "ground", (xbase + count, 20)))
    scene("bridge", "Bridge", "sample_joints.cpp",
          "a bridge of 160 planks of 1 x 0.25 m (density 20, linear and angular damping 0.1) "
          "hinged end to end and to the ground at both ends, 160 m long, sagging under its "
          "own weight from straight.", 600, bodies, joints, render_height=60,
          render_center=(0, 0))


def ball_and_chain():
    chain_of_capsules(
        "ball_and_chain", "Ball & Chain", "sample_joints.cpp",
        "a chain of 40 capsule links (1 m between cap centres, radius 0.125 m, density 20, "
        "each here a box and two circles; damping 0.1) pinned at one end, holding a ball of "
        "radius 8 m (density 20: about 250 times a link), all released horizontal.", 40, 0.5,
        0.125, 20.0, (0.0, 0.0), 600, ball=8.0, render=(100, (20, -10)))


def joint_grid():
    numi, numk = 1, 20
    shift = 1.0
    bodies = []
    joints = []
    names = []
    fixed_names = set()
    for k in range(numk):
        for i in range(numi):
            name = f"node{k}_{i}"
            fixed = numk // 2 - 3 <= k <= numk // 2 + 3 and i == 0
            shapes = [circle(0.4, filter={"category": 2, "mask": 65533})]
            if fixed:
                fixed_names.add(name)
                bodies.append(static(name, shapes, position=(k * shift, -i * shift)))
            else:
                bodies.append(dynamic(name, (k * shift, -i * shift), shapes,
                                      gravity_scale=2.0))
            if i > 0:
                joints.append({"type": "revolute", "name": f"down{k}_{i}", "body_a": names[-1],
                               "body_b": name, "local_anchor_a": [0, -0.5 * shift],
                               "local_anchor_b": [0, 0.5 * shift]})
            if k > 0 and not (fixed and names[-numi] in fixed_names):
                joints.append({"type": "revolute", "name": f"across{k}_{i}",
                               "body_a": names[-numi], "body_b": name,
                               "local_anchor_a": [0.5 * shift, 0],
                               "local_anchor_b": [-0.5 * shift, 0]})
            names.append(name)
    scene("joint_grid", "Joint Grid", "sample_joints.cpp",
          "the sample's debug size (1 x 20; 100 x 100 with NDEBUG): a row of 20 balls of radius "
          "0.4 m hinged 1 m apart, the middle seven fixed, the others hanging on each side under "
          "twice gravity; the balls do not collide with each other (category 2, mask ~2). The "
          "sample also hinges the fixed balls to each other, which does nothing; those six "
          "joints are left out.", 600, bodies, joints)


def stretched_chain():
    count, length = 40, 1.0
    base = length * count
    bodies = [static("ground")]
    joints = []
    y = base - 2.0 * length
    prev, anchor_a = "ground", [0, base - 0.5 * length]
    for i in range(count):
        name = f"ball{i}"
        bodies.append(dynamic(name, (0, y), [circle(0.2, filter={"category": 1, "mask": 0})]))
        joints.append({"type": "revolute", "name": f"hinge{i}", "body_a": prev,
                       "body_b": name, "local_anchor_a": anchor_a,
                       "local_anchor_b": [0, 0.5 * length]})
        prev, anchor_a = name, [0, -0.5 * length]
        y -= 2.0 * length
    scene("stretched_chain", "Stretched Chain", "sample_joints.cpp",
          "40 balls of radius 0.2 m (colliding with nothing) hung from a fixed point by "
          "revolute joints whose anchors are 1 m apart along the chain, but created 2 m apart: "
          "every joint starts 1 m open, and the chain must close to 40 m without flying "
          "apart.", 600, bodies, joints, render_height=90, render_center=(0, 0))


# The ragdoll of human.cpp: (bone, parent, position, capsules as (p1, p2, radius, foot),
# pivot, lower, upper, max motor torque as a fraction of 0.025 N m per unit scale).
HUMAN = [
    ("hip", None, 0.95, [((0, -0.02), (0, 0.025), 0.095, False)], None, 0, 0, 0),
    ("torso", "hip", 1.2, [((0, -0.135), (0, 0.135), 0.09, False)], 1.025, -0.25, 0.0, 0.5),
    ("head", "torso", 1.5, [((0, -0.0325), (0, 0.0325), 0.08, False),
                            ((0, -0.12), (0, -0.08), 0.05, False)], 1.4, -0.3, 0.1, 0.25),
    ("upper_left_leg", "hip", 0.775, [((0, -0.125), (0, 0.125), 0.055, False)], 0.9, -0.05,
     0.4, 1.0),
    ("lower_left_leg", "upper_left_leg", 0.475, [((0, -0.14), (0, 0.125), 0.045, False),
                                                 ((-0.02, -0.175), (0.13, -0.175), 0.03,
                                                  True)], 0.625, -0.5, -0.02, 0.5),
    ("upper_right_leg", "hip", 0.775, [((0, -0.125), (0, 0.125), 0.055, False)], 0.9, -0.05,
     0.4, 1.0),
    ("lower_right_leg", "upper_right_leg", 0.475, [((0, -0.14), (0, 0.125), 0.045, False),
                                                   ((-0.02, -0.175), (0.13, -0.175), 0.03,
                                                    True)], 0.625, -0.5, -0.02, 0.5),
    ("upper_left_arm", "torso", 1.225, [((0, -0.125), (0, 0.125), 0.035, False)], 1.35, -0.05,
     0.8, 0.25),
    ("lower_left_arm", "upper_left_arm", 0.975, [((0, -0.125), (0, 0.125), 0.03, False)], 1.1,
     0.01, 0.5, 0.1),
    ("upper_right_arm", "torso", 1.225, [((0, -0.125), (0, 0.125), 0.035, False)], 1.35, -0.05,
     0.8, 0.25),
    ("lower_right_arm", "upper_right_arm", 0.975, [((0, -0.125), (0, 0.125), 0.03, False)], 1.1,
     0.01, 0.5, 0.1),
]


def human(prefix, position, group):
    """Solver2D's Human::Spawn at scale 1: 11 bones, friction 0.4 (feet 0.1), no collision
    within the body (group -group), limited, motor-braked revolute joints."""
    px, py = position
    bodies, joints = [], []
    for bone, parent, y, capsules, pivot, lower, upper, torque in HUMAN:
        shapes = []
        for p1, p2, r, foot in capsules:
            shapes += capsule(p1, p2, r, friction=0.1 if foot else 0.4,
                              filter={"group": -group})
        bodies.append(dynamic(prefix + bone, (px, py + y), shapes))
        if parent:
            joints.append(revolute(prefix + bone, prefix + parent, prefix + bone,
                                   (px, py + pivot), enable_limit=True,
                                   lower_angle=lower * math.pi, upper_angle=upper * math.pi,
                                   enable_motor=True, motor_speed=0.0,
                                   max_motor_torque=torque * 0.025))
    return bodies, joints


def ragdoll():
    bodies, joints = human("", (0, 4), 1)
    scene("ragdoll", "Ragdoll", "sample_joints.cpp and human.cpp",
          "a ragdoll of 11 capsule bones (each capsule here a box and two circles; friction "
          "0.4, feet 0.1) joined by revolute joints with angle limits and weak braking motors, "
          "its parts not colliding with each other, dropped from 4 m onto a 40 x 2 m ground "
          "box.", 600, [ground_box(hw=20)] + bodies, joints, plausibility=REST,
          render_height=6.5, render_center=(0, 3))


def far_ragdoll_pile():
    ox, oy = 6000.0, -1500.0
    ground = static("ground", [box(10, 0.5, (-5, 2), -0.15 * math.pi),
                               box(10, 0.5, (5, 2), 0.15 * math.pi)], position=(ox, oy - 1))
    bodies, joints = [ground], []
    for group, (x, y) in enumerate(((0, 0.5), (-0.2, 1), (0.2, 1), (-0.4, 1.5), (0.4, 1.5),
                                    (0, 2)), start=1):
        b, j = human(f"human{group}_", (ox + x, oy + y), group)
        bodies += b
        joints += j
    scene("far_ragdoll_pile", "Ragdoll Pile (Far)", "sample_far.cpp and human.cpp",
          "six ragdolls (as in the Ragdoll scene, each not colliding with itself) created "
          "overlapping one another in a V-shaped trough of two 20 m boards tilted 27 degrees, "
          "at (6000, -1500) m from the origin: they must separate and settle.", 600, bodies,
          joints, plausibility=REST, render_height=5, render_center=(ox, oy + 1))


for build in (single_box, high_mass_ratio_1, lambda: high_mass_ratio(False),
              lambda: high_mass_ratio(True), friction_ramp, overlap_recovery, vertical_stack,
              pyramid, arch, double_domino, confined, card_house, circle_stack, far_pyramid,
              far_stack, far_recovery, far_chain, bridge, ball_and_chain, joint_grid,
              stretched_chain, ragdoll, far_ragdoll_pile):
    build()

if __name__ == "__main__":
    tb.write_scenes(SCENES, HERE)
