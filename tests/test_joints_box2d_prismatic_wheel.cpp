// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Cross-check of the prismatic and wheel joints against Box2D 2.4.1 itself: islands of joints
// only are stepped in Box2D and, in parallel, through meff's joint functions (see
// box2d_joint_island.h). Same inputs and the same float operations in the same order must give
// identical results, step after step, through limits, motors and springs.
#include "box2d_joint_island.h"

#include <catch2/catch.hpp>

using namespace meff;
using namespace meff::detail;

// Box2D computes in float: a double build has nothing to compare bit for bit.
#ifndef MEFF_DOUBLE

using namespace meff::test;

namespace
{

/// meff's definition of a Box2D prismatic joint. The axis is the b2 definition's (not the
/// joint's normalized one), so that both engines normalize the same vector once.
PrismaticJointDef FromBox2D(const b2PrismaticJointDef& b2Def)
{
    PrismaticJointDef def;
    def.localAnchorA = ToMeff(b2Def.localAnchorA);
    def.localAnchorB = ToMeff(b2Def.localAnchorB);
    def.localAxisA = ToMeff(b2Def.localAxisA);
    def.referenceAngle = b2Def.referenceAngle;
    def.enableLimit = b2Def.enableLimit;
    def.lowerTranslation = b2Def.lowerTranslation;
    def.upperTranslation = b2Def.upperTranslation;
    def.enableMotor = b2Def.enableMotor;
    def.motorSpeed = b2Def.motorSpeed;
    def.maxMotorForce = b2Def.maxMotorForce;
    return def;
}

/// Box2D's wheel joint keeps its axis as given, meff normalizes it: Box2D gets the axis
/// normalized once (as the scene mirror does), meff the raw one, which it normalizes the same
/// way. The spring constants come from b2LinearStiffness with the same hertz and ratio.
struct WheelPair
{
    b2WheelJointDef b2Def;
    WheelJointDef def;
};

WheelPair MakeWheelPair(b2Body* a, b2Body* b, b2Vec2 anchor, b2Vec2 worldAxis, float hertz,
                        float dampingRatio)
{
    WheelPair pair;
    pair.b2Def.Initialize(a, b, anchor, worldAxis);
    pair.def.localAnchorA = ToMeff(pair.b2Def.localAnchorA);
    pair.def.localAnchorB = ToMeff(pair.b2Def.localAnchorB);
    pair.def.localAxisA = ToMeff(pair.b2Def.localAxisA);
    pair.b2Def.localAxisA.Normalize();
    pair.def.hertz = hertz;
    pair.def.dampingRatio = dampingRatio;
    pair.b2Def.stiffness = 0;
    pair.b2Def.damping = 0;
    if (hertz > 0)
    {
        b2LinearStiffness(pair.b2Def.stiffness, pair.b2Def.damping, hertz, dampingRatio, a, b);
    }
    return pair;
}

void CopyLimitsAndMotor(const b2WheelJointDef& from, WheelJointDef& to)
{
    to.enableLimit = from.enableLimit;
    to.lowerTranslation = from.lowerTranslation;
    to.upperTranslation = from.upperTranslation;
    to.enableMotor = from.enableMotor;
    to.motorSpeed = from.motorSpeed;
    to.maxMotorTorque = from.maxMotorTorque;
}

} // namespace

TEST_CASE("Prismatic and wheel joints agree with Box2D 2.4.1 step for step",
          "[joints][box2d][prismatic][wheel]")
{
    const bool warmStarting = GENERATE(true, false);
    CAPTURE(warmStarting);

    const b2Vec2 gravity(0.0f, -10.0f);
    b2World world(gravity);
    world.SetAllowSleeping(false);
    world.SetWarmStarting(warmStarting);
    b2BodyDef groundDef;
    b2Body* ground = world.CreateBody(&groundDef);
    const Tolerances tol = Box2DTolerances();

    // Island 1, an elevator carrying a wheel: ground -prismatic- car -wheel- tyre. The car
    // slides on an oblique, unnormalized axis, starts turned (a reference angle) and spinning,
    // and falls into the lower limit before the motor drives it up into the upper one. Masses
    // with inexact reciprocals and off-centre mass exercise every term of the rows.
    b2MassData mdCar{3.0f, b2Vec2(0.1f, -0.05f), 0.9f};
    b2Body* car = MakeDynamic(world, b2Vec2(1.0f, 2.0f), 0.3f, mdCar, 0.1f, 0.2f);
    car->SetAngularVelocity(0.5f);
    car->SetLinearVelocity(b2Vec2(-1.0f, -6.0f));
    b2MassData mdTyre{0.7f, b2Vec2(-0.02f, 0.03f), 0.11f};
    b2Body* tyre = MakeDynamic(world, b2Vec2(1.5f, 1.4f), -0.4f, mdTyre);
    tyre->SetAngularVelocity(-2.0f);

    b2PrismaticJointDef liftDef;
    liftDef.Initialize(ground, car, b2Vec2(1.0f, 2.1f), b2Vec2(0.3f, 1.1f));
    liftDef.enableLimit = true;
    liftDef.lowerTranslation = -0.35f;
    liftDef.upperTranslation = 0.8f;
    liftDef.enableMotor = true;
    liftDef.motorSpeed = 1.3f;
    liftDef.maxMotorForce = 70.0f; // > the load (3.7 kg · 10 m/s² along the axis)
    auto* lift = static_cast<b2PrismaticJoint*>(world.CreateJoint(&liftDef));

    // Suspension along the car's tilted "down", spring with damping, limits it will hit, and
    // a motor that saturates.
    WheelPair suspension =
        MakeWheelPair(car, tyre, b2Vec2(1.5f, 1.4f), b2Vec2(0.2f, -0.9f), 2.3f, 0.35f);
    suspension.b2Def.enableLimit = true;
    suspension.b2Def.lowerTranslation = -0.05f;
    suspension.b2Def.upperTranslation = 0.12f;
    suspension.b2Def.enableMotor = true;
    suspension.b2Def.motorSpeed = -6.0f;
    suspension.b2Def.maxMotorTorque = 0.4f;
    CopyLimitsAndMotor(suspension.b2Def, suspension.def);
    auto* wheel = static_cast<b2WheelJoint*>(world.CreateJoint(&suspension.b2Def));

    // Island 2: a wheel on a static axle support, no spring, falling into its lower limit,
    // with a strong motor (the motor mass alone: no lever arm).
    b2MassData mdHub{1.3f, b2Vec2(0.0f, 0.0f), 0.4f};
    b2Body* hub = MakeDynamic(world, b2Vec2(6.0f, 1.0f), 0.1f, mdHub);
    hub->SetLinearVelocity(b2Vec2(0.5f, 2.0f));
    WheelPair hanging = MakeWheelPair(ground, hub, b2Vec2(6.0f, 1.0f), b2Vec2(0.0f, 1.0f), 0, 0);
    hanging.b2Def.enableLimit = true;
    hanging.b2Def.lowerTranslation = -0.4f;
    hanging.b2Def.upperTranslation = 0.3f;
    hanging.b2Def.enableMotor = true;
    hanging.b2Def.motorSpeed = 3.0f;
    hanging.b2Def.maxMotorTorque = 50.0f;
    CopyLimitsAndMotor(hanging.b2Def, hanging.def);
    auto* hangingWheel = static_cast<b2WheelJoint*>(world.CreateJoint(&hanging.b2Def));

    // Island 3: two free bodies on a prismatic joint whose limits are closer than the slop
    // (Box2D 2.4.1's equality-row branch of the position pass), without a motor.
    b2MassData mdP{2.0f, b2Vec2(0.05f, 0.0f), 0.3f};
    b2Body* p1 = MakeDynamic(world, b2Vec2(11.0f, 0.0f), 0.2f, mdP);
    p1->SetAngularVelocity(1.5f);
    b2MassData mdQ{0.9f, b2Vec2(0.0f, 0.02f), 0.2f};
    b2Body* p2 = MakeDynamic(world, b2Vec2(12.0f, 0.5f), 0.0f, mdQ);
    p2->SetLinearVelocity(b2Vec2(-1.0f, -0.3f)); // closing along the axis
    b2PrismaticJointDef lockDef;
    lockDef.Initialize(p1, p2, b2Vec2(11.5f, 0.25f), b2Vec2(1.0f, 0.5f));
    lockDef.enableLimit = true;
    lockDef.lowerTranslation = 0.3f;
    lockDef.upperTranslation = 0.305f;
    auto* lock = static_cast<b2PrismaticJoint*>(world.CreateJoint(&lockDef));

    // Island 4: a free, spinning chassis whose wheel is thrown against the suspension's
    // limits, so that the position pass corrects a violated limit while body A turns (Box2D
    // 2.4.1 then mixes the step's axis with the fresh one).
    b2MassData mdFree{4.0f, b2Vec2(0.0f, 0.1f), 1.5f};
    b2Body* spinner = MakeDynamic(world, b2Vec2(20.0f, 5.0f), 0.0f, mdFree);
    spinner->SetAngularVelocity(3.0f);
    b2MassData mdSmall{0.6f, b2Vec2(0.0f, 0.0f), 0.05f};
    b2Body* thrown = MakeDynamic(world, b2Vec2(20.5f, 4.5f), 0.0f, mdSmall);
    thrown->SetLinearVelocity(b2Vec2(1.0f, -5.0f));
    WheelPair flung =
        MakeWheelPair(spinner, thrown, b2Vec2(20.5f, 4.5f), b2Vec2(0.3f, 1.0f), 1.5f, 0.1f);
    flung.b2Def.enableLimit = true;
    flung.b2Def.lowerTranslation = -0.1f;
    flung.b2Def.upperTranslation = 0.1f;
    CopyLimitsAndMotor(flung.b2Def, flung.def);
    auto* flungWheel = static_cast<b2WheelJoint*>(world.CreateJoint(&flung.b2Def));

    // Box2D's islands: seeds newest body first, joints collected depth-first through each
    // body's joint list (newest first). Island 1 is seeded by the tyre, so the wheel joint
    // comes before the prismatic one.
    Island elevator, axle, pair;
    {
        const std::int32_t iTyre = elevator.Add(tyre, &mdTyre);
        const std::int32_t iCar = elevator.Add(car, &mdCar);
        const std::int32_t iGround = elevator.Add(ground, nullptr);
        elevator.joints.push_back(
            MakeJoint(suspension.def, iCar, iTyre, car->GetMass(), tyre->GetMass()));
        elevator.b2Joints.push_back(wheel);
        elevator.joints.push_back(MakeJoint(FromBox2D(liftDef), iGround, iCar));
        elevator.b2Joints.push_back(lift);

        // Our spring constants and axes are Box2D's, bit for bit.
        const WheelJoint& w = std::get<WheelJoint>(elevator.joints[0].data);
        CHECK(w.stiffness == wheel->GetStiffness());
        CHECK(w.damping == wheel->GetDamping());
        CHECK(w.stiffness > 0);
        CHECK(w.localXAxisA.x == wheel->GetLocalAxisA().x);
        CHECK(w.localXAxisA.y == wheel->GetLocalAxisA().y);
        const PrismaticJoint& p = std::get<PrismaticJoint>(elevator.joints[1].data);
        CHECK(p.localXAxisA.x == lift->GetLocalAxisA().x);
        CHECK(p.localXAxisA.y == lift->GetLocalAxisA().y);
    }
    {
        const std::int32_t iHub = axle.Add(hub, &mdHub);
        const std::int32_t iGround = axle.Add(ground, nullptr);
        axle.joints.push_back(MakeJoint(hanging.def, iGround, iHub, 0, hub->GetMass()));
        axle.b2Joints.push_back(hangingWheel);
    }
    {
        const std::int32_t i2 = pair.Add(p2, &mdQ);
        const std::int32_t i1 = pair.Add(p1, &mdP);
        pair.joints.push_back(MakeJoint(FromBox2D(lockDef), i1, i2));
        pair.b2Joints.push_back(lock);
    }
    Island free;
    {
        const std::int32_t iThrown = free.Add(thrown, &mdSmall);
        const std::int32_t iSpinner = free.Add(spinner, &mdFree);
        free.joints.push_back(
            MakeJoint(flung.def, iSpinner, iThrown, spinner->GetMass(), thrown->GetMass()));
        free.b2Joints.push_back(flungWheel);
    }
    std::vector<Island*> islands{&elevator, &axle, &pair, &free};

    // Variable time step, so that dtRatio ≠ 1 rescales the warm-start impulses (and Box2D
    // 2.4.1's wheel joint leaves its limit impulses unscaled).
    float invDt0 = 0;
    Diff position, velocity, reaction;
    bool liftLower = false, liftUpper = false, liftMotorSaturated = false;
    bool wheelLower = false, wheelUpper = false, wheelMotorSaturated = false;
    bool hubLower = false, lockActive = false, flungLimits = false;
    for (int i = 0; i < 300; ++i)
    {
        const float dt = (i % 5 == 4) ? 1.0f / 30.0f : 1.0f / 60.0f;
        world.Step(dt, 8, 3);

        const StepContext step = Box2DStepContext(dt, invDt0, 8, 3, warmStarting, tol);
        SolveIslandsAndCompare(islands, step, ToMeff(gravity), position, velocity, reaction);
        const auto& l = std::get<PrismaticJoint>(elevator.joints[1].data);
        liftLower = liftLower || l.lowerImpulse > 0;
        liftUpper = liftUpper || l.upperImpulse > 0;
        liftMotorSaturated = liftMotorSaturated || std::abs(l.motorImpulse) == dt * 70.0f;
        const auto& w = std::get<WheelJoint>(elevator.joints[0].data);
        wheelLower = wheelLower || w.lowerImpulse > 0;
        wheelUpper = wheelUpper || w.upperImpulse > 0;
        wheelMotorSaturated = wheelMotorSaturated || std::abs(w.motorImpulse) == dt * 0.4f;
        hubLower = hubLower || std::get<WheelJoint>(axle.joints[0].data).lowerImpulse > 0;
        const auto& k = std::get<PrismaticJoint>(pair.joints[0].data);
        lockActive = lockActive || k.lowerImpulse > 0 || k.upperImpulse > 0;
        const auto& f = std::get<WheelJoint>(free.joints[0].data);
        flungLimits = flungLimits || f.lowerImpulse > 0 || f.upperImpulse > 0;
    }

    // The scenario exercised the limit and motor rows (otherwise the comparison proves less).
    CHECK(liftLower);
    CHECK(liftUpper);
    CHECK(liftMotorSaturated);
    CHECK(wheelLower);
    CHECK(wheelUpper);
    CHECK(wheelMotorSaturated);
    CHECK(hubLower);
    CHECK(lockActive);
    CHECK(flungLimits);
    // Same inputs, same float operations in the same order: identical results.
    CHECK(position.max == 0);
    CHECK(velocity.max == 0);
    CHECK(reaction.max == 0);
}

#endif // MEFF_DOUBLE
