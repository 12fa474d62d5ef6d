// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Revolute joints by colour (SolverKind::Colour, engine/src/solvers/colour/
// colour_joint_solver.cpp): a lone joint in a lane against the island-order solver, static
// equilibria whose joint reactions are known exactly (which also checks that the lanes'
// impulses reach the joints), a body with more joints than there are colours (the overflow),
// and a hanging net whose joints must not stretch more than in Box2D's order.
#include "analytic_support.h"

#include "meff/world.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace meff;
using namespace meff::analytic;

namespace
{

World MakeColourWorld(bool coloured, Vec2 gravity = {0, -10})
{
    WorldDef def;
    def.gravity = gravity;
    def.solver.kind = coloured ? SolverKind::Colour : SolverKind::Box2D;
    def.allowSleep = false; // convergence is read at rest, where an island would fall asleep
    return World{def};
}

/// A circle of radius 0.25 and the given density hanging at `position`.
BodyId AddBob(World& world, Vec2 position, Real density = 1)
{
    return AddBall(world, position, {0, 0}, Real(0.25), Material(density, 0));
}

} // namespace

TEST_CASE("Graph colouring: a pendulum in a lane swings as in island order", "[colouring][joints]")
{
    // One joint: its lane solves the same block row with the same K as the scalar code, so
    // the two worlds differ only by the position pass's SIMD sine and cosine (≤ 2 ulp).
    const auto build = [](bool coloured)
    {
        World world = MakeColourWorld(coloured);
        const BodyId pivot = AddAnchor(world, {0, 0});
        const BodyId bob = AddBob(world, {1, 0});
        world.CreateJoint(world.MakeRevoluteJointDef(pivot, bob, {0, 0}));
        return std::pair{std::move(world), bob};
    };
    auto [coloured, colouredBob] = build(true);
    auto [ordered, orderedBob] = build(false);
    for (int step = 0; step < 240; ++step)
    {
        coloured.Step(kDt);
        ordered.Step(kDt);
        INFO("step " << step);
        // Ulp-level differences (2.4e-7 relative on a 1 m arm) grow at most linearly in a
        // regular swing: 240 steps of them stay under 1e-4 m, yet a lane solving the wrong row
        // (or none) is off by centimetres within a few steps.
        REQUIRE(Distance(coloured.GetPosition(colouredBob), ordered.GetPosition(orderedBob)) <
                1e-4);
    }
}

TEST_CASE("Graph colouring: a hanging chain's joints carry the weight below them",
          "[colouring][joints][analytic]")
{
    // A straight vertical chain at rest: joint k (from the top) holds the n − k links below it,
    // F = (n − k)·m·g. The chain's joints alternate between two colours.
    constexpr int kLinks = 10;
    World world = MakeColourWorld(true);
    BodyId above = AddAnchor(world, {0, 0});
    std::vector<JointId> joints;
    std::vector<BodyId> links;
    for (int k = 0; k < kLinks; ++k)
    {
        const BodyId link = AddBob(world, {0, Real(-1 - k)});
        joints.push_back(world.CreateJoint(world.MakeRevoluteJointDef(above, link, {0, Real(-k)})));
        links.push_back(link);
        above = link;
    }
    for (int step = 0; step < 120; ++step)
    {
        world.Step(kDt);
    }
    const double mg = world.GetMass(links[0]) * 10;
    for (int k = 0; k < kLinks; ++k)
    {
        INFO("joint " << k);
        const JointReaction reaction = world.GetReaction(joints[k], 1 / kDt);
        // Warm-started over 120 steps the block rows converge to the static answer; 1e-4
        // relative is float round-off on sums of up to ten weights, plus the rest the
        // 8-iteration solve leaves on a chain that never moved.
        CHECK(reaction.force.y == Approx((kLinks - k) * mg).epsilon(1e-4));
        CHECK(std::abs(reaction.force.x) < 1e-4 * mg);
        // The position pass stops once every anchor gap is within linearSlop, so each link
        // may sit up to one slop further down than the link above it.
        const double slop = Tolerances{}.linearSlop;
        CHECK(Distance(world.GetPosition(links[k]), Vec2{0, Real(-1 - k)}) < (k + 1) * slop);
    }
}

TEST_CASE("Graph colouring: a body with more joints than colours overflows and still holds",
          "[colouring][joints][analytic]")
{
    // A dynamic bar pinned at both ends carries 70 pendulums, so 72 joints share the bar: the
    // colouring has 64 colours, the remaining joints go to the overflow, which is solved one
    // by one after the lanes. Every pendulum hangs at rest, so each joint carries m·g.
    constexpr int kPendulums = 70;
    World world = MakeColourWorld(true);
    const BodyId left = AddAnchor(world, {0, 0});
    const BodyId right = AddAnchor(world, {Real(kPendulums + 1), 0});
    const BodyId bar = AddBox(world, BodyType::Dynamic, {Real(kPendulums + 1) / 2, 0}, 0,
                              Real(kPendulums + 1) / 2, Real(0.1), Material(1, 0));
    world.CreateJoint(world.MakeRevoluteJointDef(left, bar, {0, 0}));
    world.CreateJoint(world.MakeRevoluteJointDef(right, bar, {Real(kPendulums + 1), 0}));
    std::vector<JointId> joints;
    std::vector<BodyId> bobs;
    for (int i = 0; i < kPendulums; ++i)
    {
        const Real x = Real(i + 1);
        const BodyId bob = AddBob(world, {x, -1});
        joints.push_back(world.CreateJoint(world.MakeRevoluteJointDef(bar, bob, {x, 0})));
        bobs.push_back(bob);
    }
    for (int step = 0; step < 120; ++step)
    {
        world.Step(kDt);
    }
    const double mg = world.GetMass(bobs[0]) * 10;
    for (int i = 0; i < kPendulums; ++i)
    {
        INFO("pendulum " << i);
        const JointReaction reaction = world.GetReaction(joints[i], 1 / kDt);
        // The bar sags by the pins' position error only; each pendulum's joint converges to its
        // bob's weight (1e-3 relative: the bar's residual motion, of order the position slop
        // over the step, moves the bobs a little).
        CHECK(reaction.force.y == Approx(mg).epsilon(1e-3));
        CHECK(std::abs(world.GetPosition(bobs[i]).x - Real(i + 1)) < 1e-3);
    }
}

TEST_CASE("Graph colouring: a hanging net stretches no more than in Box2D's order",
          "[colouring][joints]")
{
    // joint_grid in small: a 24×24 net of circles (not colliding) joined to the neighbour above
    // and to the left, hung from three static bodies of the top row. Eight iterations cannot
    // hold 1,100 joints rigid while the net falls and swings, so both orders stretch it; the
    // order changes how much. Island order carries corrections along the island's
    // depth-first path, colours carry them evenly over the net; the mean anchor gap by colour
    // must not exceed island order's.
    constexpr int kSide = 24;
    const auto run = [](bool coloured)
    {
        World world = MakeColourWorld(coloured);
        std::vector<BodyId> grid(kSide * kSide);
        std::vector<JointId> joints;
        ShapeDef material = Material(1, 0);
        material.filter.groupIndex = -1; // the net does not collide with itself
        for (int i = 0; i < kSide; ++i)
        {
            for (int k = 0; k < kSide; ++k)
            {
                const bool pinned = i == 0 && (k == 0 || k == kSide / 2 || k == kSide - 1);
                BodyDef def;
                def.type = pinned ? BodyType::Static : BodyType::Dynamic;
                def.position = {Real(k), Real(-i)};
                const BodyId body = world.CreateBody(def);
                world.CreateShape(body, material, Circle{{0, 0}, Real(0.4)});
                grid[i * kSide + k] = body;
                if (i > 0)
                {
                    joints.push_back(world.CreateJoint(
                        world.MakeRevoluteJointDef(grid[(i - 1) * kSide + k], body, def.position)));
                }
                if (k > 0)
                {
                    joints.push_back(world.CreateJoint(
                        world.MakeRevoluteJointDef(grid[i * kSide + k - 1], body, def.position)));
                }
            }
        }
        for (int step = 0; step < 240; ++step)
        {
            world.Step(kDt);
        }
        double sum = 0;
        for (const JointId joint : joints)
        {
            sum += Distance(world.GetAnchorA(joint), world.GetAnchorB(joint));
        }
        return sum / double(joints.size());
    };
    const double coloured = run(true);
    const double ordered = run(false);
    INFO("mean anchor gap: by colour " << coloured << " m, island order " << ordered << " m");
    CHECK(coloured <= ordered);
    CHECK(coloured > 0); // a net this size cannot be held exactly
}
