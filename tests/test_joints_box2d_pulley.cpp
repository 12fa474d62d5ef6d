// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Cross-check of the pulley joint against Box2D 2.4.1's b2PulleyJoint (libbox2d): an island
// of joints only (no shapes, so no contacts) stepped in Box2D and, beside it, through meff's
// joint functions driven by a mirror of b2Island::Solve (box2d_joint_island.h). Both run in
// float with the same operation order, so they must agree bit for bit.
#include "box2d_joint_island.h"
#include "joints/joint.h"

#include <box2d/box2d.h>
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace meff;
using namespace meff::detail;
using namespace meff::test;

// Box2D computes in float: a double build has nothing to compare bit for bit.
#ifndef MEFF_DOUBLE

namespace
{

/// The definition Box2D's joint was made from (its local anchors are not public).
PulleyJointDef PulleyFromBox2D(const b2PulleyJointDef& d)
{
    PulleyJointDef def;
    def.groundAnchorA = ToMeff(d.groundAnchorA);
    def.groundAnchorB = ToMeff(d.groundAnchorB);
    def.localAnchorA = ToMeff(d.localAnchorA);
    def.localAnchorB = ToMeff(d.localAnchorB);
    def.lengthA = d.lengthA;
    def.lengthB = d.lengthB;
    def.ratio = d.ratio;
    return def;
}

} // namespace

TEST_CASE("Pulley joints agree with Box2D 2.4.1 step for step", "[joints][box2d][pulley]")
{
    const bool warmStarting = GENERATE(true, false);
    CAPTURE(warmStarting);

    const b2Vec2 gravity(0.0f, -10.0f);
    b2World world(gravity);
    world.SetAllowSleeping(false);
    world.SetWarmStarting(warmStarting);

    // A block and tackle (ratio 1.7) with off-centre masses and anchors, so that the loads
    // swing and turn and every term of the row's k is exercised; the lighter side starts
    // moving, a sideways push makes both swing.
    b2MassData mdA{2.0f, b2Vec2(0.1f, -0.05f), 0.7f};
    b2Body* a = MakeDynamic(world, b2Vec2(-2.0f, 3.0f), 0.3f, mdA, 0.1f, 0.05f);
    a->SetLinearVelocity(b2Vec2(1.5f, 0.5f));
    b2MassData mdB{3.1f, b2Vec2(-0.2f, 0.15f), 0.9f};
    b2Body* b = MakeDynamic(world, b2Vec2(3.0f, 4.0f), -0.2f, mdB);
    b->SetAngularVelocity(-1.0f);
    b2PulleyJointDef def;
    def.Initialize(a, b, b2Vec2(-2.0f, 9.0f), b2Vec2(3.3f, 10.0f), b2Vec2(-1.9f, 3.4f),
                   b2Vec2(3.2f, 4.3f), 1.7f);
    auto* pulley = static_cast<b2PulleyJoint*>(world.CreateJoint(&def));

    Island island;
    const std::int32_t ib = island.Add(b, &mdB);
    const std::int32_t ia = island.Add(a, &mdA);
    island.joints.push_back(MakeJoint(PulleyFromBox2D(def), ia, ib));
    island.b2Joints.push_back(pulley);
    std::vector<Island*> islands{&island};

    const Tolerances tol = Box2DTolerances();
    float invDt0 = 0;
    Diff position, velocity, reaction, anchor;
    for (int i = 0; i < 240; ++i)
    {
        // Variable time step, so that dtRatio ≠ 1 rescales the warm-start impulse.
        const float dt = (i % 5 == 4) ? 1.0f / 30.0f : 1.0f / 60.0f;
        world.Step(dt, 8, 3);
        const StepContext step = Box2DStepContext(dt, invDt0, 8, 3, warmStarting, tol);
        SolveIslandsAndCompare(islands, step, ToMeff(gravity), position, velocity, reaction);
    }
    // The rope kept its length (Box2D's position pass stops within a linear slop) and moved.
    const float lengthNow = pulley->GetCurrentLengthA() + 1.7f * pulley->GetCurrentLengthB();
    CHECK(lengthNow == Approx(def.lengthA + 1.7f * def.lengthB).margin(b2_linearSlop));
    CHECK(std::abs(pulley->GetCurrentLengthA() - def.lengthA) > 0.5f);
    // Same inputs, same float operations in the same order: identical results.
    CHECK(position.max == 0);
    CHECK(velocity.max == 0);
    CHECK(reaction.max == 0);
}

#endif // MEFF_DOUBLE
