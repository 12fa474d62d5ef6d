// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Cross-check of the gear joint against Box2D 2.4.1's b2GearJoint (libbox2d): an island of
// joints only (no shapes, so no contacts) stepped in Box2D and, beside it, through meff's joint
// functions driven by a mirror of b2Island::Solve (box2d_joint_island.h). Both run in float
// with the same operation order, so they must agree bit for bit.
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

RevoluteJointDef RevoluteFromBox2D(const b2RevoluteJoint& j)
{
    RevoluteJointDef def;
    def.localAnchorA = ToMeff(j.GetLocalAnchorA());
    def.localAnchorB = ToMeff(j.GetLocalAnchorB());
    def.referenceAngle = j.GetReferenceAngle();
    def.enableMotor = j.IsMotorEnabled();
    def.motorSpeed = j.GetMotorSpeed();
    def.maxMotorTorque = j.GetMaxMotorTorque();
    return def;
}

PrismaticJointDef PrismaticFromBox2D(const b2PrismaticJoint& j)
{
    PrismaticJointDef def;
    def.localAnchorA = ToMeff(j.GetLocalAnchorA());
    def.localAnchorB = ToMeff(j.GetLocalAnchorB());
    def.localAxisA = ToMeff(j.GetLocalAxisA());
    def.referenceAngle = j.GetReferenceAngle();
    return def;
}

/// What a gear reads of a body when it is made: its transform and its angle.
GearPose PoseOf(const b2Body* body)
{
    const b2Transform& xf = body->GetTransform();
    GearPose pose;
    pose.xf.p = ToMeff(xf.p);
    pose.xf.q.s = xf.q.s;
    pose.xf.q.c = xf.q.c;
    pose.angle = body->GetAngle();
    return pose;
}

} // namespace

TEST_CASE("Gear joints agree with Box2D 2.4.1 step for step", "[joints][box2d][gear]")
{
    const bool warmStarting = GENERATE(true, false);
    CAPTURE(warmStarting);

    const b2Vec2 gravity(0.0f, -10.0f);
    b2World world(gravity);
    world.SetAllowSleeping(false);
    world.SetWarmStarting(warmStarting);

    // Two wheels on the ground, geared to each other (ratio 2: the first turns twice as far
    // back), and the second driving a tilted rack (rack and pinion, ratio 1/0.8 m). The
    // masses sit off the hinges, so gravity turns the wheels and every term of k is used; a
    // motor on the first wheel fights the weights.
    b2BodyDef groundDef;
    b2Body* ground = world.CreateBody(&groundDef);
    b2MassData md1{1.5f, b2Vec2(0.3f, -0.1f), 1.1f};
    b2Body* w1 = MakeDynamic(world, b2Vec2(-2.0f, 4.0f), 0.2f, md1, 0.0f, 0.05f);
    w1->SetAngularVelocity(2.0f);
    b2MassData md2{2.5f, b2Vec2(-0.2f, 0.25f), 1.7f};
    b2Body* w2 = MakeDynamic(world, b2Vec2(1.0f, 4.0f), -0.4f, md2);
    b2MassData mdR{0.8f, b2Vec2(0.1f, 0.05f), 0.3f};
    b2Body* rack = MakeDynamic(world, b2Vec2(1.5f, 2.5f), 0.1f, mdR);

    b2RevoluteJointDef r1Def;
    r1Def.Initialize(ground, w1, b2Vec2(-2.0f, 4.0f));
    r1Def.enableMotor = true;
    r1Def.motorSpeed = 1.0f;
    r1Def.maxMotorTorque = 6.0f;
    auto* r1 = static_cast<b2RevoluteJoint*>(world.CreateJoint(&r1Def));
    b2RevoluteJointDef r2Def;
    r2Def.Initialize(ground, w2, b2Vec2(1.05f, 3.95f));
    auto* r2 = static_cast<b2RevoluteJoint*>(world.CreateJoint(&r2Def));
    b2PrismaticJointDef pDef;
    pDef.Initialize(ground, rack, b2Vec2(1.4f, 2.6f), b2Vec2(1.0f, 0.2f));
    auto* slide = static_cast<b2PrismaticJoint*>(world.CreateJoint(&pDef));
    b2GearJointDef g1Def;
    g1Def.bodyA = w1;
    g1Def.bodyB = w2;
    g1Def.joint1 = r1;
    g1Def.joint2 = r2;
    g1Def.ratio = 2.0f;
    auto* g1 = static_cast<b2GearJoint*>(world.CreateJoint(&g1Def));
    b2GearJointDef g2Def;
    g2Def.bodyA = w2;
    g2Def.bodyB = rack;
    g2Def.joint1 = r2;
    g2Def.joint2 = slide;
    g2Def.ratio = 1.0f / 0.8f;
    auto* g2 = static_cast<b2GearJoint*>(world.CreateJoint(&g2Def));

    // Box2D's island: the newest body (the rack) seeds it; each body's joints newest first,
    // depth first: rack, ground, w2, w1 and g2, slide, g1, r2, r1.
    Island island;
    const std::int32_t iR = island.Add(rack, &mdR);
    const std::int32_t iG = island.Add(ground, nullptr);
    const std::int32_t i2 = island.Add(w2, &md2);
    const std::int32_t i1 = island.Add(w1, &md1);
    const Joint jr1 = MakeJoint(RevoluteFromBox2D(*r1), iG, i1);
    const Joint jr2 = MakeJoint(RevoluteFromBox2D(*r2), iG, i2);
    const Joint jp = MakeJoint(PrismaticFromBox2D(*slide), iG, iR);
    GearJointDef gear1;
    gear1.ratio = g1Def.ratio;
    GearJointDef gear2;
    gear2.ratio = g2Def.ratio;
    const Joint jg1 =
        MakeJoint(gear1, jr1, jr2, PoseOf(w1), PoseOf(w2), PoseOf(ground), PoseOf(ground));
    const Joint jg2 =
        MakeJoint(gear2, jr2, jp, PoseOf(w2), PoseOf(rack), PoseOf(ground), PoseOf(ground));
    island.joints = {jg2, jp, jg1, jr2, jr1};
    island.b2Joints = {g2, slide, g1, r2, r1};
    std::vector<Island*> islands{&island};

    const Tolerances tol = Box2DTolerances();
    float invDt0 = 0;
    Diff position, velocity, reaction;
    const float angle1 = w1->GetAngle(), angle2 = w2->GetAngle();
    const float slide0 = slide->GetJointTranslation();
    for (int i = 0; i < 240; ++i)
    {
        // Variable time step, so that dtRatio ≠ 1 rescales the other joints' warm start.
        const float dt = (i % 5 == 4) ? 1.0f / 30.0f : 1.0f / 60.0f;
        world.Step(dt, 8, 3);
        const StepContext step = Box2DStepContext(dt, invDt0, 8, 3, warmStarting, tol);
        SolveIslandsAndCompare(islands, step, ToMeff(gravity), position, velocity, reaction);
    }
    // The gears held (Box2D's position pass corrects them every step: within an angular slop
    // of b2_angularSlop·ratio-scaled error each) and the train moved.
    const float turned1 = w1->GetAngle() - angle1, turned2 = w2->GetAngle() - angle2;
    const float slid = slide->GetJointTranslation() - slide0;
    CHECK(std::abs(turned2) > 0.5f);
    CHECK(turned1 + 2.0f * turned2 == Approx(0).margin(0.01));
    CHECK(turned2 + slid / 0.8f == Approx(0).margin(0.01));
    // Same inputs, same float operations in the same order: identical results.
    CHECK(position.max == 0);
    CHECK(velocity.max == 0);
    CHECK(reaction.max == 0);
}

#endif // MEFF_DOUBLE
