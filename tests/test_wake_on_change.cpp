// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Review fixes around sleeping and events: joint setters wake only on a change (as Box2D
// 2.4.1's SetMotorSpeed, SetTarget, SetLinearOffset), end events of shapes destroyed between
// steps reach a game that reads events once per step, and a snapshot does not hold on to the
// pre-solve callback.
#include <catch2/catch.hpp>

#include "meff/world.h"

#include <memory>

using namespace meff;

namespace
{

constexpr Real kStep = Real(1) / 60;

/// A dynamic box on a static ground body, asleep, and a joint between them made by `make`.
struct SleepingPair
{
    World world{WorldDef{.allowSleep = true}};
    BodyId ground = world.CreateBody(BodyDef{});
    BodyId box = world.CreateBody(BodyDef{.type = BodyType::Dynamic, .position = {0, 2}});

    SleepingPair() { world.CreateShape(box, ShapeDef{}, MakeBox(Real(0.5), Real(0.5))); }
    void Sleep()
    {
        world.SetAwake(box, false);
        REQUIRE_FALSE(world.IsAwake(box));
    }
};

} // namespace

TEST_CASE("Joint setters wake their bodies only when the value changes", "[sleeping][joints]")
{
    SleepingPair pair;
    SECTION("motor speed")
    {
        RevoluteJointDef def = pair.world.MakeRevoluteJointDef(pair.ground, pair.box, {0, 2});
        def.enableMotor = true;
        def.motorSpeed = 1;
        const JointId joint = pair.world.CreateJoint(def);
        pair.Sleep();
        pair.world.SetJointMotorSpeed(joint, 1); // unchanged: a game may set it every frame
        CHECK_FALSE(pair.world.IsAwake(pair.box));
        pair.world.SetJointMotorSpeed(joint, 2);
        CHECK(pair.world.IsAwake(pair.box));
    }
    SECTION("mouse target")
    {
        const JointId joint = pair.world.CreateJoint(MouseJointDef{
            .bodyA = pair.ground, .bodyB = pair.box, .target = {0, 2}, .maxForce = 100});
        pair.Sleep();
        pair.world.SetMouseTarget(joint, {0, 2});
        CHECK_FALSE(pair.world.IsAwake(pair.box));
        pair.world.SetMouseTarget(joint, {1, 2});
        CHECK(pair.world.IsAwake(pair.box));
    }
    SECTION("motor joint offsets")
    {
        const MotorJointDef def = pair.world.MakeMotorJointDef(pair.ground, pair.box);
        const JointId joint = pair.world.CreateJoint(def);
        pair.Sleep();
        pair.world.SetMotorJointOffsets(joint, def.linearOffset, def.angularOffset);
        CHECK_FALSE(pair.world.IsAwake(pair.box));
        pair.world.SetMotorJointOffsets(joint, def.linearOffset, def.angularOffset + 1);
        CHECK(pair.world.IsAwake(pair.box));
    }
}

TEST_CASE("End events of a shape destroyed between steps are read after the next step", "[events]")
{
    World world(WorldDef{});
    const BodyId ground = world.CreateBody(BodyDef{});
    const ShapeId floor = world.CreateShape(ground, ShapeDef{}, Segment{{-5, 0}, {5, 0}});
    const ShapeId gate =
        world.CreateShape(ground, ShapeDef{.isSensor = true}, MakeOffsetBox(2, 2, {0, 1}, 0));
    const BodyId box =
        world.CreateBody(BodyDef{.type = BodyType::Dynamic, .position = {0, Real(0.5)}});
    const ShapeId crate = world.CreateShape(box, ShapeDef{}, MakeBox(Real(0.5), Real(0.5)));
    for (int i = 0; i < 10; ++i)
    {
        world.Step(kStep); // the crate rests on the floor, inside the sensor
    }
    REQUIRE(world.GetContactEndEvents().empty());

    world.DestroyBody(box);
    // Recorded at once ...
    REQUIRE(world.GetContactEndEvents().size() == 1);
    REQUIRE(world.GetSensorEndEvents().size() == 1);
    // ... and still there, first, after the next step: a game reading events once per step
    // sees that the crate left the floor and the gate.
    world.Step(kStep);
    REQUIRE(world.GetContactEndEvents().size() == 1);
    const ContactEvent& ended = world.GetContactEndEvents()[0];
    CHECK(((ended.shapeA == floor && ended.shapeB == crate) ||
           (ended.shapeA == crate && ended.shapeB == floor)));
    REQUIRE(world.GetSensorEndEvents().size() == 1);
    CHECK(world.GetSensorEndEvents()[0].sensorShape == gate);
    CHECK(world.GetSensorEndEvents()[0].visitorShape == crate);
    // One step later they are gone: carried once, not forever.
    world.Step(kStep);
    CHECK(world.GetContactEndEvents().empty());
    CHECK(world.GetSensorEndEvents().empty());
}

TEST_CASE("A snapshot does not keep the pre-solve callback's captures alive", "[events]")
{
    World world(WorldDef{});
    auto token = std::make_shared<int>(0);
    world.SetPreSolveCallback([token](const PreSolveContact&) { return true; });
    REQUIRE(token.use_count() == 2); // ours and the world's copy
    const WorldSnapshot snapshot = world.SaveSnapshot();
    CHECK(token.use_count() == 2);
    world.SetPreSolveCallback(nullptr);
    CHECK(token.use_count() == 1);
}
