// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Oracle 7: stacks at rest. A column of 10 boxes and a 20-row pyramid (210 boxes, half-extent
// 0.5, friction 0.6) on static ground stay standing.
//
// Geometry with the polygon skin: every box collides 0.01 m larger than drawn, and the
// position solver rests contacts at a separation of −linearSlop (it only corrects C =
// β(separation + slop) < 0). So boxes at rest sit a gap of 2·skin − slop = 0.015 m apart, as
// drawn. The stacks below are built with that gap, so they start at the solver's equilibrium.
#include "analytic_support.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace meff;
using namespace meff::analytic;

namespace
{

/// Static ground whose top face is y = 0.
BodyId AddGround(World& world, Real halfWidth)
{
    const BodyId ground = AddAnchor(world, {0, 0});
    world.CreateShape(ground, Material(1, Real(0.6)), MakeOffsetBox(halfWidth, 1, {0, -1}, 0));
    return ground;
}

} // namespace

TEST_CASE("A column of 10 boxes comes to rest and stays standing for 10 s", "[analytic][stacking]")
{
    World world = MakeWorld({0, -10});
    AddGround(world, 20);
    const Tolerances& tol = world.GetTolerances();
    const Real gap = 2 * tol.polygonSkin - tol.linearSlop; // 0.015 m
    const int count = 10;
    const Real half = Real(0.5);
    std::vector<BodyId> boxes;
    for (int i = 0; i < count; ++i)
    {
        const Real y = gap + half + Real(i) * (2 * half + gap);
        boxes.push_back(
            AddBox(world, BodyType::Dynamic, {0, y}, 0, half, half, Material(1, Real(0.6))));
    }
    const double topStart = world.GetPosition(boxes.back()).y;

    double maxDrift = 0;
    for (int step = 0; step < 600; ++step) // 10 s at 60 Hz
    {
        world.Step(kDt);
        for (const BodyId b : boxes)
        {
            maxDrift = std::max(maxDrift, std::abs(double(world.GetPosition(b).x)));
        }
    }

    // Sideways: a column under gravity alone has no reason to move sideways; anything is
    // solver asymmetry. 0.05 m is a tenth of a box's half-width: far from toppling, far above
    // noise.
    INFO("largest sideways drift: " << maxDrift << " m");
    CHECK(maxDrift < 0.05);
    // Height: each of the 10 contacts rests at separation −slop; under the load of the boxes
    // above, the velocity iterations leave a small sinking residual that the position solver
    // (β = 0.2 per iteration) balances by letting the contact sink a little below −slop. Bound:
    // at most one more slop per contact, 10·slop = 0.05 m for the top box.
    const double top = world.GetPosition(boxes.back()).y;
    INFO("top box y: " << top << " m, built at " << topStart << " m");
    CHECK(top == Approx(topStart).margin(count * tol.linearSlop));
    CHECK(top <= topStart + tol.linearSlop); // nothing pushes the stack up
    // At rest: every box's speed is below what gravity adds in one step (g·dt = 0.17 m/s) by
    // two orders of magnitude, and no box turns.
    for (const BodyId b : boxes)
    {
        const Vec2 v = world.GetLinearVelocity(b);
        CHECK(std::hypot(double(v.x), double(v.y)) < 1e-3);
        CHECK(std::abs(world.GetAngularVelocity(b)) < 1e-3);
        CHECK(std::abs(world.GetAngle(b)) < 1e-3);
    }
}

TEST_CASE("A 20-row pyramid of 210 boxes stands for 5 s", "[analytic][stacking][pyramid]")
{
    // Two layouts: boxes built at the resting gap (2·skin − slop), and boxes built exactly
    // touching as drawn (the benchmark layout, x = (i+1)/2 + (j − i) − 10, y = i + 1/2), which
    // with the skin start 0.02 m overlapped and are pushed apart, up and sideways.
    const bool touching = GENERATE(false, true);
    CAPTURE(touching);
    World world = MakeWorld({0, -10});
    AddGround(world, 40);
    const Tolerances& tol = world.GetTolerances();
    const Real gap = touching ? 0 : 2 * tol.polygonSkin - tol.linearSlop;
    const int rows = 20;
    const Real half = Real(0.5);
    const Real pitch = 2 * half + gap;
    // Row i (0 at the bottom) has rows − i boxes, each resting on the two below it.
    std::vector<BodyId> boxes;
    for (int i = 0; i < rows; ++i)
    {
        const Real y = gap + half + Real(i) * pitch;
        for (int j = i; j < rows; ++j)
        {
            const Real x = (Real(j) - Real(i) * Real(0.5) - Real(rows - 1) * Real(0.5)) * pitch;
            boxes.push_back(
                AddBox(world, BodyType::Dynamic, {x, y}, 0, half, half, Material(1, Real(0.6))));
        }
    }
    REQUIRE(boxes.size() == 210);
    const BodyId top = boxes.back();
    const Vec2 topStart = world.GetPosition(top);
    REQUIRE(topStart.x == Approx(0).margin(1e-5));

    for (int step = 0; step < 300; ++step) // 5 s
    {
        world.Step(kDt);
    }

    // Standing: the top box is where it was built, up to the settling of the 20 contacts in
    // the column below it — a collapse would drop it by metres. Each contact may end up to one
    // slop deeper than its resting separation (as for the column above: 20·slop = 0.1 m down);
    // in the touching layout each contact also starts 2·skin − slop = 0.015 m too deep and is
    // pushed apart, so the top may rise by up to 20 × 0.015 = 0.3 m.
    const Vec2 topEnd = world.GetPosition(top);
    INFO("top box from (" << topStart.x << ", " << topStart.y << ") to (" << topEnd.x << ", "
                          << topEnd.y << ")");
    const double rise = touching ? rows * double(2 * tol.polygonSkin - tol.linearSlop) : 0;
    CHECK(topEnd.y >= topStart.y - rows * tol.linearSlop);
    CHECK(topEnd.y <= topStart.y + rise + tol.linearSlop);
    // Sideways the top stays within a tenth of a half-width (the pyramid is symmetric; only
    // the solver's order breaks the symmetry).
    CHECK(std::abs(double(topEnd.x)) < 0.05);
    // No box is falling or toppling: every speed is below 0.05 m/s, under a third of what
    // gravity adds in one step (g·dt = 0.17 m/s), and every box is within 0.05 rad (3°) of
    // upright, where a toppling box passes 1 rad within a second.
    double maxSpeed = 0, maxTurn = 0;
    for (const BodyId b : boxes)
    {
        const Vec2 v = world.GetLinearVelocity(b);
        maxSpeed = std::max(maxSpeed, std::hypot(double(v.x), double(v.y)));
        maxTurn = std::max(maxTurn, std::abs(double(world.GetAngle(b))));
    }
    INFO("largest speed " << maxSpeed << " m/s, largest angle " << maxTurn << " rad");
    CHECK(maxSpeed < 0.05);
    CHECK(maxTurn < 0.05);
}
