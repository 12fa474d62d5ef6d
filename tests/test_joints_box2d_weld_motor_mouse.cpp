// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Cross-check of the weld, motor and mouse joint solvers against Box2D 2.4.1 itself: small
// islands of joints only (no shapes, so no contacts) are stepped in Box2D and, in parallel,
// through our joint functions driven by a mirror of b2Island::Solve (box2d_joint_island.h).
// Both run in float with the same operation order, so they must agree bit for bit.
#include "box2d_joint_island.h"
#include "joints/joint.h"

#include <box2d/box2d.h>
#include <catch2/catch.hpp>

#include <vector>

using namespace meff;
using namespace meff::detail;
using namespace meff::test;

// Box2D computes in float: a double build has nothing to compare bit for bit.
#ifndef MEFF_DOUBLE

namespace
{

/// A weld definition with Box2D's anchors and reference angle.
WeldJointDef WeldFromBox2D(const b2WeldJoint& j, float hertz, float dampingRatio)
{
    WeldJointDef def;
    def.localAnchorA = ToMeff(j.GetLocalAnchorA());
    def.localAnchorB = ToMeff(j.GetLocalAnchorB());
    def.referenceAngle = j.GetReferenceAngle();
    def.hertz = hertz;
    def.dampingRatio = dampingRatio;
    return def;
}

MotorJointDef MotorFromBox2D(const b2MotorJoint& j, float correctionFactor)
{
    MotorJointDef def;
    def.linearOffset = ToMeff(j.GetLinearOffset());
    def.angularOffset = j.GetAngularOffset();
    def.maxForce = j.GetMaxForce();
    def.maxTorque = j.GetMaxTorque();
    def.correctionFactor = correctionFactor;
    return def;
}

} // namespace

TEST_CASE("Weld, motor and mouse joints agree with Box2D 2.4.1 step for step",
          "[joints][box2d][weld][motor][mouse]")
{
    const bool warmStarting = GENERATE(true, false);
    CAPTURE(warmStarting);

    const b2Vec2 gravity(0.0f, -10.0f);
    b2World world(gravity);
    world.SetAllowSleeping(false);
    world.SetWarmStarting(warmStarting);
    b2BodyDef groundDef;
    b2Body* ground = world.CreateBody(&groundDef);

    // Weld chain: ground =rigid= w1 =soft= w2. Off-centre masses, so that b2AngularStiffness
    // (inertia about the origin) and every term of K are exercised; inexact reciprocals.
    b2MassData md1{3.0f, b2Vec2(0.1f, -0.05f), 0.9f};
    b2Body* w1 = MakeDynamic(world, b2Vec2(1.0f, 4.0f), 0.3f, md1, 0.1f, 0.2f);
    w1->SetAngularVelocity(0.5f);
    b2MassData md2{0.7f, b2Vec2(-0.2f, 0.3f), 0.11f};
    b2Body* w2 = MakeDynamic(world, b2Vec2(2.5f, 3.2f), -0.4f, md2);
    w2->SetLinearVelocity(b2Vec2(0.0f, 1.5f));
    w2->SetAngularVelocity(-2.0f);
    b2WeldJointDef rigidDef;
    rigidDef.Initialize(ground, w1, b2Vec2(0.2f, 4.3f));
    auto* rigid = static_cast<b2WeldJoint*>(world.CreateJoint(&rigidDef));
    const float weldHertz = 2.3f, weldDamping = 0.35f;
    b2WeldJointDef softDef;
    softDef.Initialize(w1, w2, b2Vec2(1.8f, 3.6f));
    b2AngularStiffness(softDef.stiffness, softDef.damping, weldHertz, weldDamping, w1, w2);
    auto* soft = static_cast<b2WeldJoint*>(world.CreateJoint(&softDef));

    // A rigid weld between bodies that cannot turn (static ground, fixed-rotation slider):
    // K's angular entry is 0, so Box2D takes its 2×2 branches.
    b2BodyDef sliderDef;
    sliderDef.type = b2_dynamicBody;
    sliderDef.position.Set(6.0f, 2.0f);
    sliderDef.fixedRotation = true;
    sliderDef.linearVelocity.Set(1.0f, 2.0f);
    b2Body* slider = world.CreateBody(&sliderDef);
    b2MassData mdSlider{1.3f, b2Vec2(0.05f, 0.0f), 0.4f};
    slider->SetMassData(&mdSlider);
    b2WeldJointDef fixedDef;
    fixedDef.Initialize(ground, slider, b2Vec2(6.5f, 2.1f));
    auto* fixedWeld = static_cast<b2WeldJoint*>(world.CreateJoint(&fixedDef));

    // Motor chain: ground -motor- m1 -motor- m2 (a dynamic body A too). The forces are small
    // enough that the clamps bind at first, large enough to hold the bodies up later.
    b2MassData mdM1{2.0f, b2Vec2(0.0f, 0.1f), 0.5f};
    b2Body* m1 = MakeDynamic(world, b2Vec2(10.0f, 3.0f), 0.2f, mdM1);
    b2MassData mdM2{0.9f, b2Vec2(0.1f, 0.0f), 0.2f};
    b2Body* m2 = MakeDynamic(world, b2Vec2(11.0f, 3.5f), -0.3f, mdM2);
    m2->SetAngularVelocity(1.0f);
    b2MotorJointDef motorDef1;
    motorDef1.Initialize(ground, m1);
    motorDef1.linearOffset.Set(10.5f, 4.0f);
    motorDef1.angularOffset = 0.7f;
    motorDef1.maxForce = 80.0f;
    motorDef1.maxTorque = 2.0f;
    motorDef1.correctionFactor = 0.3f;
    auto* motor1 = static_cast<b2MotorJoint*>(world.CreateJoint(&motorDef1));
    b2MotorJointDef motorDef2;
    motorDef2.Initialize(m1, m2);
    motorDef2.linearOffset.Set(-0.5f, 1.2f);
    motorDef2.maxForce = 30.0f;
    motorDef2.maxTorque = 0.5f;
    motorDef2.correctionFactor = 0.45f;
    auto* motor2 = static_cast<b2MotorJoint*>(world.CreateJoint(&motorDef2));

    // Mouse: grab u off its centre, then pull it far away with a limited force.
    b2MassData mdU{1.7f, b2Vec2(0.05f, -0.1f), 0.6f};
    b2Body* u = MakeDynamic(world, b2Vec2(15.0f, 1.0f), 0.1f, mdU);
    b2MouseJointDef mouseDef;
    mouseDef.bodyA = ground;
    mouseDef.bodyB = u;
    mouseDef.target.Set(15.3f, 1.2f);
    mouseDef.maxForce = 60.0f;
    const float mouseHertz = 3.1f, mouseDamping = 0.45f;
    b2LinearStiffness(mouseDef.stiffness, mouseDef.damping, mouseHertz, mouseDamping, ground, u);
    auto* mouse = static_cast<b2MouseJoint*>(world.CreateJoint(&mouseDef));
    mouse->SetTarget(b2Vec2(18.0f, 3.0f));

    const Tolerances tol = Box2DTolerances();

    // Box2D's islands: seeds newest body first, joints depth-first through each body's joint
    // list (newest joint first); the static ground joins every island.
    Island welds, fixedIsland, motors, mouseIsland;
    {
        const std::int32_t i2 = welds.Add(w2, &md2);
        const std::int32_t i1 = welds.Add(w1, &md1);
        const std::int32_t ig = welds.Add(ground, nullptr);
        welds.joints.push_back(MakeJoint(WeldFromBox2D(*soft, weldHertz, weldDamping), i1, i2,
                                         w1->GetInertia(), w2->GetInertia()));
        welds.b2Joints.push_back(soft);
        welds.joints.push_back(
            MakeJoint(WeldFromBox2D(*rigid, 0, 0), ig, i1, ground->GetInertia(), w1->GetInertia()));
        welds.b2Joints.push_back(rigid);

        // Our spring constants are b2AngularStiffness's, bit for bit.
        const WeldJoint& w = std::get<WeldJoint>(welds.joints[0].data);
        CHECK(w.stiffness == soft->GetStiffness());
        CHECK(w.damping == soft->GetDamping());
        CHECK(std::get<WeldJoint>(welds.joints[1].data).stiffness == 0);
    }
    {
        const std::int32_t is = fixedIsland.Add(slider, &mdSlider);
        fixedIsland.bodies[is].invI = 0; // fixed rotation: Box2D keeps invI = 0
        const std::int32_t ig = fixedIsland.Add(ground, nullptr);
        fixedIsland.joints.push_back(MakeJoint(WeldFromBox2D(*fixedWeld, 0, 0), ig, is, 0, 0));
        fixedIsland.b2Joints.push_back(fixedWeld);
    }
    {
        const std::int32_t i2 = motors.Add(m2, &mdM2);
        const std::int32_t i1 = motors.Add(m1, &mdM1);
        const std::int32_t ig = motors.Add(ground, nullptr);
        motors.joints.push_back(MakeJoint(MotorFromBox2D(*motor2, 0.45f), i1, i2));
        motors.b2Joints.push_back(motor2);
        motors.joints.push_back(MakeJoint(MotorFromBox2D(*motor1, 0.3f), ig, i1));
        motors.b2Joints.push_back(motor1);
    }
    {
        const std::int32_t iu = mouseIsland.Add(u, &mdU);
        const std::int32_t ig = mouseIsland.Add(ground, nullptr);
        MouseJointDef def;
        def.target = ToMeff(mouseDef.target);
        def.maxForce = mouseDef.maxForce;
        def.hertz = mouseHertz;
        def.dampingRatio = mouseDamping;
        Transform xfU;
        xfU.p = ToMeff(u->GetTransform().p);
        xfU.q.s = u->GetTransform().q.s;
        xfU.q.c = u->GetTransform().q.c;
        mouseIsland.joints.push_back(
            MakeJoint(def, ig, iu, ground->GetMass(), u->GetMass(), xfU, true));
        mouseIsland.b2Joints.push_back(mouse);
        MouseJoint& m = std::get<MouseJoint>(mouseIsland.joints[0].data);
        CHECK(m.stiffness == mouse->GetStiffness());
        CHECK(m.damping == mouse->GetDamping());
        m.target = ToMeff(mouse->GetTarget()); // World::SetMouseTarget's effect
    }
    std::vector<Island*> islands{&welds, &fixedIsland, &motors, &mouseIsland};

    float invDt0 = 0;
    Diff position, velocity, reaction, anchor;
    bool motorForceClamped = false, motorTorqueClamped = false, mouseClamped = false;
    bool motorFree = false, mouseFree = false;
    for (int i = 0; i < 300; ++i)
    {
        // The pointer and the motor targets move during the run, as a game would move them.
        if (i == 120)
        {
            mouse->SetTarget(b2Vec2(16.0f, 0.5f));
            std::get<MouseJoint>(mouseIsland.joints[0].data).target = ToMeff(mouse->GetTarget());
            motor1->SetLinearOffset(b2Vec2(9.5f, 3.5f));
            motor1->SetAngularOffset(-0.4f);
            MotorJoint& m = std::get<MotorJoint>(motors.joints[1].data);
            m.linearOffset = ToMeff(motor1->GetLinearOffset());
            m.angularOffset = motor1->GetAngularOffset();
        }

        // Variable time step, so that dtRatio ≠ 1 rescales the warm-start impulses.
        const float dt = (i % 5 == 4) ? 1.0f / 30.0f : 1.0f / 60.0f;
        world.Step(dt, 8, 3);

        const StepContext step = Box2DStepContext(dt, invDt0, 8, 3, warmStarting, tol);
        SolveIslandsAndCompare(islands, step, ToMeff(gravity), position, velocity, reaction);

        // Anchors as Box2D reports them, from Box2D's own transforms.
        for (Island* island : islands)
        {
            for (std::size_t j = 0; j < island->joints.size(); ++j)
            {
                const Joint& joint = island->joints[j];
                b2Joint* b2j = island->b2Joints[j];
                const auto toMeff = [](const b2Transform& xf)
                {
                    Transform t;
                    t.p = ToMeff(xf.p);
                    t.q.s = xf.q.s;
                    t.q.c = xf.q.c;
                    return t;
                };
                anchor.Add(JointAnchorA(joint, toMeff(b2j->GetBodyA()->GetTransform())),
                           b2j->GetAnchorA());
                anchor.Add(JointAnchorB(joint, toMeff(b2j->GetBodyB()->GetTransform())),
                           b2j->GetAnchorB());
            }
        }

        const MotorJoint& m2j = std::get<MotorJoint>(motors.joints[0].data);
        const float maxLinear = dt * m2j.maxForce;
        motorForceClamped = motorForceClamped || m2j.linearImpulse.Length() >= 0.999f * maxLinear;
        motorTorqueClamped =
            motorTorqueClamped || std::abs(m2j.angularImpulse) == dt * m2j.maxTorque;
        motorFree = motorFree || m2j.linearImpulse.Length() < 0.9f * maxLinear;
        const MouseJoint& mj = std::get<MouseJoint>(mouseIsland.joints[0].data);
        const float maxMouse = dt * mj.maxForce;
        mouseClamped = mouseClamped || mj.impulse.Length() >= 0.999f * maxMouse;
        mouseFree = mouseFree || mj.impulse.Length() < 0.9f * maxMouse;
    }

    // The scenario exercised the clamps and the free regime (else the comparison proves less).
    CHECK(motorForceClamped);
    CHECK(motorTorqueClamped);
    CHECK(motorFree);
    CHECK(mouseClamped);
    CHECK(mouseFree);
    // Same inputs, same float operations in the same order: identical results.
    CHECK(position.max == 0);
    CHECK(velocity.max == 0);
    CHECK(reaction.max == 0);
    CHECK(anchor.max == 0);
}

#endif // MEFF_DOUBLE
