// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Physics oracles of the World against closed forms of rigid-body mechanics, through the public
// API only. They are split by concept:
//   test_effective_mass.cpp  m_eff⁻¹ = m⁻¹ + I⁻¹(r × n)² at an offset point
//   test_collisions.cpp      P = (1+e)(u2 − u1)·m_red: circles, off-centre hits, bounce height
//   test_pendulum.cpp        pinned rod, spinning pinned body, distance-joint pendulum
//   test_ramp.cpp            sliding and sticking on a ramp with friction
//   test_stacking.cpp        a column of 10 and a 20-row pyramid at rest
// This file holds the API contracts those tests rely on: bad input is refused with
// InvalidArgument and leaves the world unchanged.
#include "analytic_support.h"
#include "error_checks.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace meff;
using namespace meff::analytic;

namespace
{
constexpr Real kNaN = std::numeric_limits<Real>::quiet_NaN();
constexpr Real kInf = std::numeric_limits<Real>::infinity();
} // namespace

TEST_CASE("A body id is stale after DestroyBody", "[world][api]")
{
    World world = MakeWorld({0, -10});
    const BodyId body =
        AddBox(world, BodyType::Dynamic, {1, 2}, 0, Real(0.5), Real(0.5), ShapeDef{});
    const ShapeId shape = world.GetShapes(body)[0];
    REQUIRE(world.IsValid(body));
    world.DestroyBody(body);

    CHECK_FALSE(world.IsValid(body));
    CHECK_FALSE(world.IsValid(shape)); // its shapes went with it
    MEFF_CHECK_ERROR(world.GetPosition(body));
    MEFF_CHECK_ERROR(world.GetLinearVelocity(body));
    MEFF_CHECK_ERROR(world.SetLinearVelocity(body, {1, 0}));
    MEFF_CHECK_ERROR(world.ApplyLinearImpulse(body, {1, 0}, {0, 0}));
    MEFF_CHECK_ERROR(world.CreateShape(body, ShapeDef{}, Circle{{0, 0}, 1}));
    MEFF_CHECK_ERROR(world.DestroyBody(body));
    MEFF_CHECK_ERROR(world.GetBody(shape));

    // A new body may reuse the slot, but never the id: the generation differs.
    BodyDef def;
    def.type = BodyType::Dynamic;
    const BodyId other = world.CreateBody(def);
    CHECK(other != body);
    CHECK(world.IsValid(other));
    CHECK_FALSE(world.IsValid(body));
    MEFF_CHECK_ERROR(world.GetPosition(body));
    CHECK(world.GetBodies().size() == 1);
}

TEST_CASE("A joint id is stale after its body is destroyed", "[world][api]")
{
    World world = MakeWorld({0, -10});
    const BodyId ground = AddAnchor(world, {0, 0});
    const BodyId rod = AddBox(world, BodyType::Dynamic, {1, 0}, 0, 1, Real(0.1), ShapeDef{});
    const JointId joint = world.CreateJoint(world.MakeRevoluteJointDef(ground, rod, {0, 0}));
    world.DestroyBody(rod);
    CHECK_FALSE(world.IsValid(joint));
    MEFF_CHECK_ERROR(world.GetReaction(joint, 60));
    MEFF_CHECK_ERROR(world.MakeRevoluteJointDef(ground, rod, {0, 0}));
    world.Step(kDt); // the world is still fine
}

TEST_CASE("CreateBody refuses non-finite numbers", "[world][api]")
{
    World world = MakeWorld({0, -10});
    const auto dynamic = [](Vec2 position, Real angle, Vec2 velocity)
    {
        BodyDef def;
        def.type = BodyType::Dynamic;
        def.position = position;
        def.angle = angle;
        def.linearVelocity = velocity;
        return def;
    };
    MEFF_CHECK_ERROR(world.CreateBody(dynamic({kNaN, 0}, 0, {0, 0})));
    MEFF_CHECK_ERROR(world.CreateBody(dynamic({0, kNaN}, 0, {0, 0})));
    MEFF_CHECK_ERROR(world.CreateBody(dynamic({kInf, 0}, 0, {0, 0})));
    MEFF_CHECK_ERROR(world.CreateBody(dynamic({0, 0}, kNaN, {0, 0})));
    MEFF_CHECK_ERROR(world.CreateBody(dynamic({0, 0}, 0, {0, kNaN})));
    // Nothing was created.
    CHECK(world.GetBodies().empty());
    MEFF_CHECK_NO_ERROR(world.CreateBody(dynamic({0, 0}, 0, {0, 0})));
}

TEST_CASE("MakeBox refuses non-positive and non-finite half-extents", "[world][api]")
{
    MEFF_CHECK_ERROR(MakeBox(-1, 1));
    MEFF_CHECK_ERROR(MakeBox(1, -1));
    MEFF_CHECK_ERROR(MakeBox(0, 1));
    MEFF_CHECK_ERROR(MakeBox(kNaN, 1));
    MEFF_CHECK_ERROR(MakeBox(1, kInf));
    MEFF_CHECK_NO_ERROR(MakeBox(Real(0.5), Real(0.25)));
}

TEST_CASE("Step refuses dt <= 0 and non-finite dt, leaving the world unchanged", "[world][api]")
{
    World world = MakeWorld({0, -10});
    const BodyId ball = AddBall(world, {0, 5}, {1, 0}, Real(0.5), ShapeDef{});
    MEFF_CHECK_ERROR(world.Step(0));
    MEFF_CHECK_ERROR(world.Step(Real(-1.0 / 60.0)));
    MEFF_CHECK_ERROR(world.Step(kNaN));
    MEFF_CHECK_ERROR(world.Step(kInf));
    CHECK(world.GetStepCount() == 0);
    CHECK(world.GetPosition(ball) == Vec2{0, 5});
    CHECK(world.GetLinearVelocity(ball) == Vec2{1, 0});
    world.Step(kDt);
    CHECK(world.GetStepCount() == 1);
}

TEST_CASE("Free fall without contacts follows semi-implicit Euler exactly", "[analytic][world]")
{
    // v_n = v0 − g·n·dt, y_n = y0 + dt·Σ v_k: the integrator the other oracles' tolerances
    // are derived from (Box2D 2.4.1: v += h·g first, then x += h·v).
    World world = MakeWorld({0, -10});
    const BodyId ball = AddBall(world, {0, 100}, {Real(1.5), 2}, Real(0.5), ShapeDef{});
    double vy = 2, y = 100, x = 0;
    const double h = kDt;
    for (int n = 1; n <= 60; ++n)
    {
        world.Step(kDt);
        vy -= 10 * h;
        y += h * vy;
        x += h * 1.5;
    }
    // 60 steps, each rounding y (≈ 100) and v: 2 roundings of |y| per step.
    CHECK(world.GetLinearVelocity(ball).x == Real(1.5));
    CHECK(world.GetLinearVelocity(ball).y == Approx(vy).margin(60 * 2 * kEps * 10));
    CHECK(world.GetPosition(ball).y == Approx(y).margin(60 * 2 * kEps * 100));
    CHECK(world.GetPosition(ball).x == Approx(x).margin(60 * 2 * kEps * 2));
}
