// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Cross-check of the friction joint against Box2D 2.4.1's b2FrictionJoint (libbox2d): an
// island of joints only (no shapes, so no contacts) stepped in Box2D and, beside it, through
// meff's joint functions driven by a mirror of b2Island::Solve (box2d_joint_island.h). Both
// run in float with the same operation order, so they must agree bit for bit.
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

FrictionJointDef FrictionFromBox2D(const b2FrictionJoint& j)
{
    FrictionJointDef def;
    def.localAnchorA = ToMeff(j.GetLocalAnchorA());
    def.localAnchorB = ToMeff(j.GetLocalAnchorB());
    def.maxForce = j.GetMaxForce();
    def.maxTorque = j.GetMaxTorque();
    return def;
}

} // namespace

TEST_CASE("Friction joints agree with Box2D 2.4.1 step for step", "[joints][box2d][friction]")
{
    const bool warmStarting = GENERATE(true, false);
    CAPTURE(warmStarting);

    const b2Vec2 gravity(0.0f, -10.0f);
    b2World world(gravity);
    world.SetAllowSleeping(false);
    world.SetWarmStarting(warmStarting);
    b2BodyDef groundDef;
    groundDef.position.Set(0.5f, -0.25f); // the ground's frame is not the world's
    b2Body* ground = world.CreateBody(&groundDef);

    // ground -friction- f1 -friction- f2. f1 (2 kg) is held against gravity (20 N) by up to
    // 35 N while it also slides and spins; f2 (0.9 kg, 9 N) pulls on f1 through a joint of
    // only 6 N, so that joint's disc clamp binds for the whole run. Off-centre masses and
    // off-centre anchors exercise every term of K.
    b2MassData md1{2.0f, b2Vec2(0.1f, -0.05f), 0.7f};
    b2Body* f1 = MakeDynamic(world, b2Vec2(1.0f, 3.0f), 0.3f, md1, 0.1f, 0.05f);
    f1->SetLinearVelocity(b2Vec2(4.0f, 1.0f));
    f1->SetAngularVelocity(3.0f);
    b2MassData md2{0.9f, b2Vec2(-0.2f, 0.15f), 0.2f};
    b2Body* f2 = MakeDynamic(world, b2Vec2(2.2f, 2.6f), -0.4f, md2);
    f2->SetLinearVelocity(b2Vec2(-1.0f, 2.0f));
    f2->SetAngularVelocity(-5.0f);

    b2FrictionJointDef def1;
    def1.Initialize(ground, f1, b2Vec2(1.2f, 2.9f));
    def1.maxForce = 35.0f;
    def1.maxTorque = 1.5f;
    auto* friction1 = static_cast<b2FrictionJoint*>(world.CreateJoint(&def1));
    b2FrictionJointDef def2;
    def2.Initialize(f1, f2, b2Vec2(1.9f, 2.7f));
    def2.maxForce = 6.0f;
    def2.maxTorque = 0.4f;
    auto* friction2 = static_cast<b2FrictionJoint*>(world.CreateJoint(&def2));

    // Box2D's island: newest body first, joints depth-first (newest joint first), the static
    // ground last.
    Island island;
    const std::int32_t i2 = island.Add(f2, &md2);
    const std::int32_t i1 = island.Add(f1, &md1);
    const std::int32_t ig = island.Add(ground, nullptr);
    island.joints.push_back(MakeJoint(FrictionFromBox2D(*friction2), i1, i2));
    island.b2Joints.push_back(friction2);
    island.joints.push_back(MakeJoint(FrictionFromBox2D(*friction1), ig, i1));
    island.b2Joints.push_back(friction1);
    std::vector<Island*> islands{&island};

    const Tolerances tol = Box2DTolerances();
    float invDt0 = 0;
    Diff position, velocity, reaction, anchor;
    bool forceClamped = false, torqueClamped = false, forceFree = false, torqueFree = false;
    for (int i = 0; i < 240; ++i)
    {
        // Variable time step, so that dtRatio ≠ 1 rescales the warm-start impulses.
        const float dt = (i % 5 == 4) ? 1.0f / 30.0f : 1.0f / 60.0f;
        world.Step(dt, 8, 3);
        const StepContext step = Box2DStepContext(dt, invDt0, 8, 3, warmStarting, tol);
        SolveIslandsAndCompare(islands, step, ToMeff(gravity), position, velocity, reaction);

        for (std::size_t j = 0; j < island.joints.size(); ++j)
        {
            const auto toMeff = [](const b2Transform& xf)
            {
                Transform t;
                t.p = ToMeff(xf.p);
                t.q.s = xf.q.s;
                t.q.c = xf.q.c;
                return t;
            };
            b2Joint* b2j = island.b2Joints[j];
            anchor.Add(JointAnchorA(island.joints[j], toMeff(b2j->GetBodyA()->GetTransform())),
                       b2j->GetAnchorA());
            anchor.Add(JointAnchorB(island.joints[j], toMeff(b2j->GetBodyB()->GetTransform())),
                       b2j->GetAnchorB());
        }

        const FrictionJoint& held = std::get<FrictionJoint>(island.joints[1].data);
        forceFree = forceFree || held.linearImpulse.Length() < 0.9f * dt * held.maxForce;
        torqueFree = torqueFree || std::abs(held.angularImpulse) < 0.9f * dt * held.maxTorque;
        const FrictionJoint& pulled = std::get<FrictionJoint>(island.joints[0].data);
        forceClamped =
            forceClamped || pulled.linearImpulse.Length() >= 0.999f * dt * pulled.maxForce;
        torqueClamped = torqueClamped || std::abs(pulled.angularImpulse) == dt * pulled.maxTorque;
    }

    // The run exercised the clamps and the free regime (else the comparison proves less).
    CHECK(forceClamped);
    CHECK(torqueClamped);
    CHECK(forceFree);
    CHECK(torqueFree);
    // Same inputs, same float operations in the same order: identical results.
    CHECK(position.max == 0);
    CHECK(velocity.max == 0);
    CHECK(reaction.max == 0);
    CHECK(anchor.max == 0);
}

#endif // MEFF_DOUBLE
