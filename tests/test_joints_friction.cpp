// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Friction joint (Box2D 2.4.1's b2FrictionJoint): analytic checks under every solver back end
// (a box sliding on a top-down floor decelerates at maxForce/m, a spinning box stops at
// maxTorque/I), the reaction it reports, argument and scene-field errors, snapshots.
#include "joints/joint.h"
#include "meff/scene.h"
#include "meff/world.h"

#include <catch2/catch.hpp>

#include "scene_errors.h"

#include <cmath>
#include <limits>
#include <string>

using namespace meff;

namespace
{

constexpr Real kDt = Real(1) / Real(60);

World TopDownWorld(SolverKind kind, bool blockJoints)
{
    WorldDef def;
    def.gravity = {0, 0};
    def.solver.kind = kind;
    def.solver.blockJoints = blockJoints;
    def.allowSleep = false; // the velocity is read down to 0 without the body freezing early
    return World(def);
}

/// A 1 m square of density 2: m = 2 kg, I = m·(1² + 1²)/12 = 1/3 kg·m².
BodyId AddSquare(World& world, Vec2 position)
{
    const BodyId body = world.CreateBody({.type = BodyType::Dynamic, .position = position});
    ShapeDef shape;
    shape.density = 2;
    world.CreateShape(body, shape, MakeBox(Real(0.5), Real(0.5)));
    return body;
}

} // namespace

TEST_CASE("A box held to the floor by a friction joint slides to rest at maxForce/m",
          "[joints][friction][analytic]")
{
    const SolverKind kind = GENERATE(SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep);
    const bool blockJoints = GENERATE(true, false);
    CAPTURE(SolverKindName(kind), blockJoints);
    World world = TopDownWorld(kind, blockJoints);
    const BodyId ground = world.CreateBody({});
    const BodyId box = AddSquare(world, {0, 0});
    world.SetLinearVelocity(box, {6, 0});
    FrictionJointDef def = world.MakeFrictionJointDef(ground, box, {0, 0});
    def.maxForce = 4; // a = F/m = 2 m/s²: at rest after v0/a = 3 s = 180 steps, 9 m on
    const JointId joint = world.CreateJoint(def);
    CHECK(world.GetJointType(joint) == JointType::Friction);

    for (int i = 1; i <= 240; ++i)
    {
        world.Step(kDt);
        const Real v = world.GetLinearVelocity(box).x;
        if (i <= 179)
        {
            // Each step the bounded impulse h·F comes off m·v: v = v0 − a·t exactly but for
            // float rounding of the running sum (≤ 179 × 2⁻²⁴ × 6 m/s ≈ 7e-5 m/s).
            CHECK(v == Approx(6 - 2 * kDt * i).margin(1e-4));
            const JointReaction r = world.GetReaction(joint, 1 / kDt);
            CHECK(r.force.Length() == Approx(4).epsilon(1e-4)); // the bound, against the motion
            CHECK(r.force.x < 0);
        }
    }
    CHECK(world.GetLinearVelocity(box).x == Approx(0).margin(1e-4));
    CHECK(world.GetAngularVelocity(box) == 0);
    // Continuously v0²/(2a) = 9 m. Any first-order integration of the decelerating slide is
    // off by at most h·v0/2 = 0.05 m (semi-implicit Euler's sum: 8.95 m).
    CHECK(world.GetPosition(box).x == Approx(9).margin(0.051));
    CHECK(world.GetPosition(box).y == Approx(0).margin(1e-6));
    // At rest, the joint holds nothing.
    CHECK(world.GetReaction(joint, 1 / kDt).force.Length() == Approx(0).margin(1e-4));
}

TEST_CASE("A spinning box held by a friction joint stops at maxTorque/I without moving",
          "[joints][friction][analytic]")
{
    const SolverKind kind = GENERATE(SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep);
    CAPTURE(SolverKindName(kind));
    World world = TopDownWorld(kind, true);
    const BodyId ground = world.CreateBody({});
    const BodyId box = AddSquare(world, {1, 2});
    world.SetAngularVelocity(box, 10);
    FrictionJointDef def = world.MakeFrictionJointDef(ground, box, {1, 2});
    def.maxForce = 4;
    def.maxTorque = 1; // α = T/I = 3 rad/s²: 10 rad/s stops after 10/3 s = 200 steps
    const JointId joint = world.CreateJoint(def);
    for (int i = 1; i <= 60; ++i)
    {
        world.Step(kDt);
    }
    // After 1 s, 10 − 3 = 7 rad/s (float rounding of 60 decrements: far below 1e-4).
    CHECK(world.GetAngularVelocity(box) == Approx(7).margin(1e-4));
    CHECK(world.GetReaction(joint, 1 / kDt).torque == Approx(-1).epsilon(1e-4));
    for (int i = 61; i <= 260; ++i)
    {
        world.Step(kDt);
    }
    CHECK(world.GetAngularVelocity(box) == Approx(0).margin(1e-4));
    // The anchor is the centre of mass: the spin pushes it nowhere.
    CHECK(world.GetPosition(box).x == Approx(1).margin(1e-5));
    CHECK(world.GetPosition(box).y == Approx(2).margin(1e-5));
    // θ = ω0²/(2α) = 16.67 rad continuously; the step's first-order error ≤ h·ω0/2 = 0.084.
    CHECK(world.GetAngle(box) == Approx(100.0 / 6.0).margin(0.084));
}

TEST_CASE("A friction joint between two moving bodies slows their relative motion only",
          "[joints][friction][analytic]")
{
    const SolverKind kind = GENERATE(SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep);
    CAPTURE(SolverKindName(kind));
    World world = TopDownWorld(kind, true);
    const BodyId a = AddSquare(world, {0, 0});
    const BodyId b = AddSquare(world, {3, 0});
    world.SetLinearVelocity(a, {1, 0});
    world.SetLinearVelocity(b, {5, 0});
    FrictionJointDef def = world.MakeFrictionJointDef(a, b, {3, 0});
    def.maxForce = 4;
    world.CreateJoint(def);
    for (int i = 0; i < 120; ++i)
    {
        world.Step(kDt);
    }
    // Equal and opposite forces: momentum 2·1 + 2·5 = 12 kg·m/s is kept, and the relative
    // speed 4 m/s falls at 2F/m... = 4 m/s² to 0 after 1 s; then both move at 3 m/s.
    const Real va = world.GetLinearVelocity(a).x;
    const Real vb = world.GetLinearVelocity(b).x;
    CHECK(2 * va + 2 * vb == Approx(12).epsilon(1e-5));
    CHECK(vb - va == Approx(0).margin(1e-4));
    CHECK(va == Approx(3).margin(1e-4));
}

TEST_CASE("Friction joints reject bad arguments", "[joints][friction][make]")
{
    using detail::MakeJoint;
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    FrictionJointDef def;
    def.maxForce = -1;
    CHECK_THROWS_WITH(MakeJoint(def, 0, 1),
                      "FrictionJointDef::maxForce: must be finite and >= 0, got -1");
    def.maxForce = 1;
    def.maxTorque = nan;
    CHECK_THROWS_WITH(MakeJoint(def, 0, 1), Catch::Contains("FrictionJointDef::maxTorque") &&
                                                Catch::Contains("must be finite"));
    def.maxTorque = -Real(0.5);
    CHECK_THROWS_WITH(MakeJoint(def, 0, 1),
                      "FrictionJointDef::maxTorque: must be finite and >= 0, got -0.5");
    def.maxTorque = 0;
    def.localAnchorB = {nan, 0};
    CHECK_THROWS_AS(MakeJoint(def, 0, 1), InvalidArgument);

    World world = TopDownWorld(SolverKind::Box2D, true);
    const BodyId box = AddSquare(world, {0, 0});
    FrictionJointDef same;
    same.bodyA = box;
    same.bodyB = box;
    CHECK_THROWS_AS(world.CreateJoint(same), InvalidArgument);
    CHECK_THROWS_AS(world.MakeFrictionJointDef(box, box, {nan, 0}), InvalidArgument);
}

TEST_CASE("Snapshots replay a friction joint's slide bit for bit", "[joints][friction][snapshot]")
{
    const SolverKind kind = GENERATE(SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep);
    CAPTURE(SolverKindName(kind));
    World world = TopDownWorld(kind, true);
    const BodyId ground = world.CreateBody({});
    const BodyId box = AddSquare(world, {0, 0});
    world.SetLinearVelocity(box, {6, 1});
    world.SetAngularVelocity(box, 3);
    FrictionJointDef def = world.MakeFrictionJointDef(ground, box, {Real(0.3), Real(0.1)});
    def.maxForce = 4;
    def.maxTorque = Real(0.5);
    world.CreateJoint(def);
    for (int i = 0; i < 20; ++i)
    {
        world.Step(kDt);
    }
    const WorldSnapshot saved = world.SaveSnapshot();
    std::vector<std::uint64_t> first;
    for (int i = 0; i < 30; ++i)
    {
        world.Step(kDt);
        first.push_back(world.GetStateHash());
    }
    world.RestoreSnapshot(saved);
    for (int i = 0; i < 30; ++i)
    {
        world.Step(kDt);
        CHECK(world.GetStateHash() == first[std::size_t(i)]);
    }
}

TEST_CASE("Scene files: friction joints load, build and report bad fields by path",
          "[scene][joints][friction]")
{
    using test::ErrorsOf;
    const char* bodies = R"("bodies": [ { "name": "ground", "type": "static" },
                    { "name": "box", "type": "dynamic",
                      "shapes": [ { "type": "circle", "radius": 1 } ] } ],)";
    const Scene scene =
        ParseScene(std::string(R"({ "meff_scene": 1, "world": {"gravity": [0, 0]},)") + bodies + R"(
        "joints": [ { "type": "friction", "name": "f", "body_a": "ground", "body_b": "box",
                      "anchor": [0.5, 0.25], "max_force": 7, "max_torque": 2 },
                    { "type": "friction", "name": "g", "body_a": "ground", "body_b": "box",
                      "anchor": [0, 0] } ] })",
                   "x.json");
    REQUIRE(scene.joints.size() == 2);
    CHECK(scene.joints[0].type == JointType::Friction);
    CHECK(scene.joints[0].anchor.x == 0.5);
    CHECK(scene.joints[0].maxForce == 7);
    CHECK(scene.joints[0].maxTorque == 2);
    CHECK(scene.joints[1].maxForce == 0); // FrictionJointDef's defaults
    CHECK(scene.joints[1].maxTorque == 0);
    const BuiltScene built = BuildWorld(scene);
    CHECK(built.world.GetJointType(built.joints[0]) == JointType::Friction);
    CHECK(built.world.GetAnchorA(built.joints[0]) == Vec2(Real(0.5), Real(0.25)));
    CHECK(built.world.GetAnchorB(built.joints[0]) == Vec2(Real(0.5), Real(0.25)));

    CHECK(ErrorsOf(std::string(R"({ "meff_scene": 1,)") + bodies + R"(
        "joints": [ { "type": "friction", "name": "f", "body_a": "ground", "body_b": "box",
                      "max_force": -3, "max_torque": -1, "correction_factor": 0.3 } ] })") ==
          std::vector<std::string>{
              "x.json: joints[0].anchor: required field is missing",
              "x.json: joints[0].max_force: must be >= 0, got -3",
              "x.json: joints[0].max_torque: must be >= 0, got -1",
              "x.json: joints[0].correction_factor: unknown field (known fields here: type, name, "
              "body_a, body_b, collide_connected, local_anchor_a, local_anchor_b, anchor, "
              "max_force, max_torque)"});
}

TEST_CASE("friction_topdown.json: every back end slows the bodies to rest by the joints' bounds",
          "[scene][joints][friction][analytic]")
{
    const SolverKind kind = GENERATE(SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep);
    CAPTURE(SolverKindName(kind));
    Scene scene = LoadScene(std::string(MEFF_SOURCE_DIR) + "/samples/scenes/friction_topdown.json");
    scene.world.solver.kind = kind;
    BuiltScene built = BuildWorld(scene);
    World& world = built.world;
    const BodyId puck = built.bodyByName.at("puck");
    const BodyId spinner = built.bodyByName.at("spinner");
    const Real dt = Real(scene.world.dt);
    for (int i = 0; i < scene.world.frames; ++i)
    {
        world.Step(dt);
        for (std::size_t j = 0; j < built.joints.size(); ++j)
        {
            // No joint ever exceeds its bounds (relative 1e-5: the disc clamp's rounding).
            const JointReaction r = world.GetReaction(built.joints[j], 1 / dt);
            CHECK(r.force.Length() <= Real(scene.joints[j].maxForce) * Real(1 + 1e-5));
            CHECK(std::abs(r.torque) <= Real(scene.joints[j].maxTorque) * Real(1 + 1e-5));
        }
    }
    // The puck: 6 m/s at 2 m/s² stops after 9 m (first-order integration: within h·v0/2).
    CHECK(world.GetPosition(puck).x == Approx(-4 + 9).margin(0.051));
    // The spinner stops where it is after θ = 10²/(2·3) = 16.7 rad (within h·ω0/2 = 0.084).
    CHECK(world.GetAngle(spinner) == Approx(100.0 / 6.0).margin(0.084));
    CHECK(world.GetPosition(spinner).Length() == Approx(0).margin(1e-5));
    for (const BodyId body : built.bodies)
    {
        CHECK(world.GetLinearVelocity(body).Length() == Approx(0).margin(1e-4));
        CHECK(world.GetAngularVelocity(body) == Approx(0).margin(1e-4));
    }
}
