// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Cross-check of the joint solvers against Box2D 2.4.1 itself (Debian's libbox2d-dev): a
// small world of joints only (no shapes, so no contacts) is stepped in Box2D and, in
// parallel, through our joint functions driven by a mirror of b2Island::Solve. Both run in
// float with the same operation order, so they must agree bit for bit, step after step.
//
// Needs -lbox2d (and /usr/include/box2d).
#include "box2d_joint_island.h"

#include <catch2/catch.hpp>

using namespace meff;
using namespace meff::detail;
using namespace meff::test;

// Box2D computes in float: a double build has nothing to compare bit for bit.
#ifndef MEFF_DOUBLE

using namespace meff::test;

namespace
{

RevoluteJointDef FromBox2D(const b2RevoluteJoint& j)
{
    RevoluteJointDef def;
    def.localAnchorA = ToMeff(j.GetLocalAnchorA());
    def.localAnchorB = ToMeff(j.GetLocalAnchorB());
    def.referenceAngle = j.GetReferenceAngle();
    def.enableLimit = j.IsLimitEnabled();
    def.lowerAngle = j.GetLowerLimit();
    def.upperAngle = j.GetUpperLimit();
    def.enableMotor = j.IsMotorEnabled();
    def.motorSpeed = j.GetMotorSpeed();
    def.maxMotorTorque = j.GetMaxMotorTorque();
    return def;
}

} // namespace

TEST_CASE("Joints agree with Box2D 2.4.1 step for step", "[joints][box2d]")
{
    const bool warmStarting = GENERATE(true, false);
    CAPTURE(warmStarting);

    const b2Vec2 gravity(0.0f, -10.0f);
    b2World world(gravity);
    world.SetAllowSleeping(false);
    world.SetWarmStarting(warmStarting);
    b2BodyDef groundDef;
    b2Body* ground = world.CreateBody(&groundDef);

    // Chain: ground -revolute- b1 -rigid rod- b2. Masses with inexact reciprocals (3 kg)
    // and off-centre mass so that every term of the rows is exercised.
    b2MassData md1{3.0f, b2Vec2(0.1f, -0.05f), 0.9f};
    b2Body* b1 = MakeDynamic(world, b2Vec2(1.0f, 4.0f), 0.3f, md1, 0.1f, 0.2f);
    b1->SetAngularVelocity(0.5f);
    b2MassData md2{0.7f, b2Vec2(-0.02f, 0.03f), 0.11f};
    b2Body* b2 = MakeDynamic(world, b2Vec2(2.5f, 3.2f), -0.4f, md2);
    b2->SetLinearVelocity(b2Vec2(0.0f, 1.5f));

    b2RevoluteJointDef hingeDef;
    hingeDef.Initialize(ground, b1, b2Vec2(0.0f, 4.2f));
    auto* hinge = static_cast<b2RevoluteJoint*>(world.CreateJoint(&hingeDef));
    b2DistanceJointDef rodDef;
    rodDef.Initialize(b1, b2, b2Vec2(1.6f, 4.1f), b2Vec2(2.4f, 3.3f));
    auto* rod = static_cast<b2DistanceJoint*>(world.CreateJoint(&rodDef));

    // Pendulum with a weak motor and limits it will hit.
    b2MassData mdP{1.3f, b2Vec2(0.0f, 0.0f), 0.4f};
    b2Body* bP = MakeDynamic(world, b2Vec2(6.0f, 1.0f), 0.1f, mdP);
    bP->SetAngularVelocity(4.0f);              // up into the upper limit first, ...
    bP->SetLinearVelocity(b2Vec2(0.0f, 4.0f)); // ... turning about the pivot
    b2RevoluteJointDef pendDef;
    pendDef.Initialize(ground, bP, b2Vec2(5.0f, 1.0f));
    pendDef.enableLimit = true;
    pendDef.lowerAngle = -0.9f;
    pendDef.upperAngle = 0.25f;
    pendDef.enableMotor = true;
    pendDef.motorSpeed = 0.5f;
    pendDef.maxMotorTorque = 3.0f;
    auto* pend = static_cast<b2RevoluteJoint*>(world.CreateJoint(&pendDef));

    // Spring with limits it will hit.
    b2MassData mdS{3.0f, b2Vec2(0.05f, 0.0f), 0.3f};
    b2Body* bS = MakeDynamic(world, b2Vec2(11.5f, 0.0f), 0.0f, mdS);
    bS->SetLinearVelocity(b2Vec2(0.0f, -2.0f));
    b2DistanceJointDef springDef;
    springDef.bodyA = ground;
    springDef.bodyB = bS;
    springDef.localAnchorA.Set(10.0f, 0.0f);
    springDef.localAnchorB.Set(0.0f, 0.1f);
    springDef.length = 1.5f;
    springDef.minLength = 1.45f;
    springDef.maxLength = 1.6f;
    // Values for which other operation orders in b2LinearStiffness round differently.
    const float hertz = 1.7f, dampingRatio = 0.4f;
    b2LinearStiffness(springDef.stiffness, springDef.damping, hertz, dampingRatio, ground, bS);
    auto* spring = static_cast<b2DistanceJoint*>(world.CreateJoint(&springDef));

    const Tolerances tol = Box2DTolerances();

    // Box2D's islands. Seeds are taken newest body first and joints collected depth-first
    // through each body's joint list (newest joint first), so the chain island (seeded by
    // b2) solves the rod before the hinge. Static ground is a member of every island.
    Island chain, pendulum, springIsland;
    {
        const std::int32_t i2 = chain.Add(b2, &md2);
        const std::int32_t i1 = chain.Add(b1, &md1);
        const std::int32_t ig = chain.Add(ground, nullptr);
        DistanceJointDef def;
        def.localAnchorA = ToMeff(rod->GetLocalAnchorA());
        def.localAnchorB = ToMeff(rod->GetLocalAnchorB());
        def.length = rodDef.length;
        def.minLength = rodDef.minLength;
        def.maxLength = rodDef.maxLength;
        chain.joints.push_back(MakeJoint(def, i1, i2, b1->GetMass(), b2->GetMass(), tol));
        chain.b2Joints.push_back(rod);
        chain.joints.push_back(MakeJoint(FromBox2D(*hinge), ig, i1));
        chain.b2Joints.push_back(hinge);

        const DistanceJoint& d = std::get<DistanceJoint>(chain.joints[0].data);
        CHECK(d.length == rod->GetLength());
        CHECK(d.minLength == rod->GetMinLength());
        CHECK(d.maxLength == rod->GetMaxLength());
    }
    {
        const std::int32_t iP = pendulum.Add(bP, &mdP);
        const std::int32_t ig = pendulum.Add(ground, nullptr);
        pendulum.joints.push_back(MakeJoint(FromBox2D(*pend), ig, iP));
        pendulum.b2Joints.push_back(pend);
    }
    {
        const std::int32_t iS = springIsland.Add(bS, &mdS);
        const std::int32_t ig = springIsland.Add(ground, nullptr);
        DistanceJointDef def;
        def.localAnchorA = ToMeff(springDef.localAnchorA);
        def.localAnchorB = ToMeff(springDef.localAnchorB);
        def.length = springDef.length;
        def.minLength = springDef.minLength;
        def.maxLength = springDef.maxLength;
        def.hertz = hertz;
        def.dampingRatio = dampingRatio;
        springIsland.joints.push_back(
            MakeJoint(def, ig, iS, ground->GetMass(), bS->GetMass(), tol));
        springIsland.b2Joints.push_back(spring);

        // Our spring constants are b2LinearStiffness's, bit for bit.
        const DistanceJoint& d = std::get<DistanceJoint>(springIsland.joints[0].data);
        CHECK(d.stiffness == spring->GetStiffness());
        CHECK(d.damping == spring->GetDamping());
    }
    std::vector<Island*> islands{&chain, &pendulum, &springIsland};

    // Variable time step, so that dtRatio ≠ 1 rescales the warm-start impulses.
    float invDt0 = 0;
    Diff position, velocity, reaction;
    bool lowerHit = false, upperHit = false, springLimitHit = false;
    for (int i = 0; i < 300; ++i)
    {
        const float dt = (i % 5 == 4) ? 1.0f / 30.0f : 1.0f / 60.0f;
        world.Step(dt, 8, 3);

        const StepContext step = Box2DStepContext(dt, invDt0, 8, 3, warmStarting, tol);
        SolveIslandsAndCompare(islands, step, ToMeff(gravity), position, velocity, reaction);
        const RevoluteJoint& p = std::get<RevoluteJoint>(pendulum.joints[0].data);
        lowerHit = lowerHit || p.lowerImpulse > 0;
        upperHit = upperHit || p.upperImpulse > 0;
        const DistanceJoint& s = std::get<DistanceJoint>(springIsland.joints[0].data);
        springLimitHit = springLimitHit || s.lowerImpulse > 0 || s.upperImpulse > 0;
    }

    // The scenario exercised the limit rows (otherwise the comparison proves less).
    CHECK(lowerHit);
    CHECK(upperHit);
    CHECK(springLimitHit);
    // Same inputs, same float operations in the same order: identical results.
    CHECK(position.max == 0);
    CHECK(velocity.max == 0);
    CHECK(reaction.max == 0);
}

TEST_CASE("Default tolerances equal Box2D's constants", "[joints][box2d]")
{
    // Box2D evaluates its angular constants in float ((2.0f / 180.0f) · b2_pi); a default
    // computed in double and rounded once differs by an ulp (0.0349065848 vs 0.0349065885),
    // which would break the bit-for-bit agreement of the revolute limit rows.
    const Tolerances tol;
    const Tolerances b2 = Box2DTolerances();
    CHECK(tol.linearSlop == b2.linearSlop);
    CHECK(tol.maxLinearCorrection == b2.maxLinearCorrection);
    CHECK(tol.maxTranslation == b2.maxTranslation);
    CHECK(tol.maxRotation == b2.maxRotation);
    CHECK(tol.angularSlop == b2.angularSlop);
    CHECK(tol.maxAngularCorrection == b2.maxAngularCorrection);
}

#endif // MEFF_DOUBLE
