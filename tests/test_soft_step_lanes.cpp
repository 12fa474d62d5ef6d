// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The soft step's SIMD lanes (solvers/soft_step/soft_contact_lanes.h, soft_revolute_lanes.h,
// soft_bodies.cpp's integration): a row solved in a lane does the scalar row's operations in the
// same order, so a contact or a hinge that shares no moving body with any other row gives the
// same bits whether it is solved in a lane (an island with at least kMinSoftLaneRows such rows)
// or alone (one row: scalar); likewise a body moved in a lane (kLanes consecutive bodies) or alone
// (fewer bodies than a lane: scalar).
// Bodies that do not collide with each other and hang from or rest on one static body make
// such rows: every one of them goes to colour 0, kLanes to a group.
#include "analytic_support.h"

#include "meff/world.h"

#include <catch2/catch.hpp>

#include <vector>

using namespace meff;
using namespace meff::analytic;

namespace
{

/// More rows than kMinSoftLaneRows (32), and not a multiple of four or eight: the last group
/// has empty lanes.
constexpr int kRows = 41;

World MakeLaneWorld()
{
    WorldDef def;
    def.solver.kind = SolverKind::SoftStep;
    def.allowSleep = false; // one island of every body: the lanes' threshold counts its rows
    // An island solved row by row (a row alone) relaxes until its sweeps agree, one in lanes
    // relaxes relaxIterations times (SoftStepSolver::SubStep); at kMaxSoftRelaxSweeps both
    // relax exactly as often, so what is compared is the rows' arithmetic alone.
    def.solver.softStep.relaxIterations = 8; // kMaxSoftRelaxSweeps
    return World{def};
}

/// The k-th body's start: every body differs, so that each row meets its own case (one or two
/// points, sliding or sticking, swinging fast or slow).
BodyDef StartOf(int k, Vec2 position)
{
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = position;
    def.angle = Real(0.02) * Real(k - 20);
    def.linearVelocity = {Real(0.1) * Real(k - 20), Real(-0.5)};
    def.angularVelocity = Real(0.05) * Real(k % 7);
    return def;
}

/// Only the ground (category 1) collides with the boxes (category 2).
ShapeDef BoxMaterial(int k)
{
    ShapeDef def = Material(1, Real(0.3) + Real(0.01) * Real(k), k % 5 == 0 ? Real(0.4) : Real(0));
    def.filter.categoryBits = 0x0002;
    def.filter.maskBits = 0x0001;
    return def;
}

/// Boxes `ks` dropped onto one ground.
std::vector<BodyId> AddBoxes(World& world, const std::vector<int>& ks)
{
    const BodyId ground = world.CreateBody(BodyDef{});
    world.CreateShape(ground, ShapeDef{}, Segment{{-50, 0}, {50, 0}});
    std::vector<BodyId> boxes;
    for (const int k : ks)
    {
        const BodyId box = world.CreateBody(StartOf(k, {0, Real(0.3)}));
        world.CreateShape(box, BoxMaterial(k), MakeBox(Real(0.5), Real(0.25)));
        boxes.push_back(box);
    }
    return boxes;
}

/// Rods `ks` hinged to one anchor; rods do not collide at all.
std::vector<BodyId> AddPendulums(World& world, const std::vector<int>& ks)
{
    const BodyId anchor = AddAnchor(world, {0, 5});
    std::vector<BodyId> rods;
    for (const int k : ks)
    {
        const BodyId rod = world.CreateBody(StartOf(k, {1, 5}));
        ShapeDef material = Material(1, 0);
        material.filter.maskBits = 0;
        world.CreateShape(rod, material, MakeBox(1, Real(0.05)));
        world.CreateJoint(world.MakeRevoluteJointDef(anchor, rod, {0, 5}));
        rods.push_back(rod);
    }
    return rods;
}

/// Free bodies `ks` (no collisions, no joints) with damping, some faster than the step's speed
/// limits (maxTranslation / dt = 120 m/s, maxRotation / dt ≈ 94 rad/s: the lane falls back to
/// one by one) and some turning more than kShortSeriesAngle per sub-step (the longer series).
std::vector<BodyId> AddFreeBodies(World& world, const std::vector<int>& ks)
{
    std::vector<BodyId> bodies;
    for (const int k : ks)
    {
        BodyDef def = StartOf(k, {Real(2) * Real(k), 0});
        def.linearVelocity = {Real(30) * Real(k - 20), Real(k % 4)};
        def.angularVelocity = Real(13) * Real(k % 9) - Real(20);
        def.linearDamping = Real(0.1) * Real(k % 3);
        def.angularDamping = Real(0.2) * Real(k % 4);
        const BodyId body = world.CreateBody(def);
        ShapeDef material = Material(1, 0);
        material.filter.maskBits = 0;
        world.CreateShape(body, material, MakeBox(Real(0.5), Real(0.25)));
        bodies.push_back(body);
    }
    return bodies;
}

/// Steps the world with all kRows rows and, for a few k, a world with row k alone; body k must
/// end in the same state bit for bit.
template <typename Add>
void CheckLanesMatchAlone(Add&& add)
{
    std::vector<int> all(kRows);
    for (int k = 0; k < kRows; ++k)
    {
        all[k] = k;
    }
    World lanes = MakeLaneWorld();
    const std::vector<BodyId> bodies = add(lanes, all);
    for (int i = 0; i < 120; ++i)
    {
        lanes.Step(kDt);
    }
    for (const int k : {0, 3, 17, 40})
    {
        CAPTURE(k);
        World alone = MakeLaneWorld();
        const BodyId body = add(alone, std::vector<int>{k}).front();
        for (int i = 0; i < 120; ++i)
        {
            alone.Step(kDt);
        }
        CHECK(lanes.GetPosition(bodies[k]).x == alone.GetPosition(body).x);
        CHECK(lanes.GetPosition(bodies[k]).y == alone.GetPosition(body).y);
        CHECK(lanes.GetAngle(bodies[k]) == alone.GetAngle(body));
        CHECK(lanes.GetLinearVelocity(bodies[k]).x == alone.GetLinearVelocity(body).x);
        CHECK(lanes.GetLinearVelocity(bodies[k]).y == alone.GetLinearVelocity(body).y);
        CHECK(lanes.GetAngularVelocity(bodies[k]) == alone.GetAngularVelocity(body));
    }
}

} // namespace

TEST_CASE("Soft step: a contact solved in a SIMD lane ends bit for bit as the same contact "
          "solved alone",
          "[soft_step][lanes]")
{
    CheckLanesMatchAlone(AddBoxes);
}

TEST_CASE("Soft step: a hinge solved in a SIMD lane ends bit for bit as the same hinge solved "
          "alone",
          "[soft_step][lanes]")
{
    CheckLanesMatchAlone(AddPendulums);
}

TEST_CASE("Soft step: a body moved in a SIMD lane ends bit for bit as the same body moved alone",
          "[soft_step][lanes]")
{
    CheckLanesMatchAlone(AddFreeBodies);
}
