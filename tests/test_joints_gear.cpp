// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Gear joint (Box2D 2.4.1's b2GearJoint): torque passed through a gear against its analytic
// answer under every solver back end, a rack and pinion, the sample scene gear_train.json,
// destroying a geared joint, and argument and scene-field errors.
#include "meff/scene.h"
#include "meff/world.h"

#include <catch2/catch.hpp>

#include "scene_errors.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace meff;

namespace
{

constexpr Real kDt = Real(1) / Real(60);
constexpr Real kPi = Real(3.14159265358979323846);

/// A disc of radius r and mass m centred at `position` (I = m·r²/2 about its centre).
BodyId AddDisc(World& world, Vec2 position, Real radius, Real mass)
{
    const BodyId body = world.CreateBody({.type = BodyType::Dynamic, .position = position});
    ShapeDef shape;
    shape.density = mass / (kPi * radius * radius);
    world.CreateShape(body, shape, Circle{{0, 0}, radius});
    return body;
}

/// A hinge from the ground to `body` at its centre.
JointId Hinge(World& world, BodyId ground, BodyId body)
{
    return world.CreateJoint(world.MakeRevoluteJointDef(ground, body, world.GetPosition(body)));
}

} // namespace

TEST_CASE("A gear passes torque: αA = T/(IA + IB/ratio²), θA + ratio·θB constant",
          "[joints][gear][analytic]")
{
    const SolverKind kind = GENERATE(SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep);
    CAPTURE(SolverKindName(kind));
    WorldDef worldDef;
    worldDef.gravity = {0, 0};
    worldDef.solver.kind = kind;
    World world(worldDef);
    const BodyId ground = world.CreateBody({});
    const BodyId a = AddDisc(world, {0, 0}, 1, 2);   // IA = 1 kg·m²
    const BodyId b = AddDisc(world, {3, 0}, 0.5, 4); // IB = 0.5 kg·m²
    const JointId hingeA = Hinge(world, ground, a);
    const JointId hingeB = Hinge(world, ground, b);
    GearJointDef def;
    def.joint1 = hingeA;
    def.joint2 = hingeB;
    def.ratio = Real(0.5);
    const JointId gear = world.CreateJoint(def);
    CHECK(world.GetJointType(gear) == JointType::Gear);
    CHECK(world.GetBodyA(gear) == a);
    CHECK(world.GetBodyB(gear) == b);

    // A torque on A alone drives both: the work T·θA goes into ½(IA + IB/ratio²)ωA².
    const Real torque = 3;
    const Real inertia = 1 + Real(0.5) / (Real(0.5) * Real(0.5)); // 3 kg·m²
    const Real alpha = torque / inertia;                          // 1 rad/s²
    for (int i = 1; i <= 60; ++i)
    {
        world.ApplyTorque(a, torque, true);
        world.Step(kDt);
    }
    const Real t = 1;
    // Each hinge holds its disc at its centre, so the gear's row is the only one on the
    // angular velocities and is solved exactly in one iteration (Box2D's order, colour);
    // the soft step solves the same row softly, within 0.1 % of it.
    const Real wA = world.GetAngularVelocity(a), wB = world.GetAngularVelocity(b);
    CHECK(wA == Approx(alpha * t).epsilon(1e-3));
    CHECK(wB == Approx(-wA / Real(0.5)).epsilon(1e-3));
    // θA = ½αt²: the soft step's velocity Verlet (half kicks) gets it exactly; symplectic
    // Euler (Box2D's order, colour) turns it into ½α·t·(t + h), the steps' own error.
    const Real angle = kind == SolverKind::SoftStep ? Real(0.5) * alpha * t * t
                                                    : Real(0.5) * alpha * t * (t + kDt);
    CHECK(world.GetAngle(a) == Approx(angle).epsilon(1e-3));
    // The constraint itself: θA + ratio·θB stays 0 within Box2D's angular slop (2°), far less
    // in practice.
    CHECK(std::abs(world.GetAngle(a) + Real(0.5) * world.GetAngle(b)) < Real(1e-3));
}

TEST_CASE("A rack and pinion: a prismatic side moves ratio⁻¹ metres per radian",
          "[joints][gear][analytic]")
{
    const SolverKind kind = GENERATE(SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep);
    CAPTURE(SolverKindName(kind));
    WorldDef worldDef;
    worldDef.gravity = {0, -10};
    worldDef.solver.kind = kind;
    World world(worldDef);
    const BodyId ground = world.CreateBody({});
    const BodyId pinion = AddDisc(world, {0, 3}, Real(0.5), 1);
    const BodyId rack = world.CreateBody({.type = BodyType::Dynamic, .position = {0, 2.4f}});
    ShapeDef shape;
    shape.density = Real(2.5);
    world.CreateShape(rack, shape, MakeBox(2, Real(0.1))); // 2 kg
    RevoluteJointDef axle = world.MakeRevoluteJointDef(ground, pinion, {0, 3});
    axle.enableMotor = true;
    axle.motorSpeed = -2;
    axle.maxMotorTorque = 100;
    const JointId axleId = world.CreateJoint(axle);
    const JointId rail =
        world.CreateJoint(world.MakePrismaticJointDef(ground, rack, {0, Real(2.4)}, {1, 0}));
    GearJointDef def;
    def.joint1 = axleId;
    def.joint2 = rail;
    def.ratio = -2; // θ − 2x constant: x = θ·0.5 m, the pinion's radius
    world.CreateJoint(def);
    for (int i = 0; i < 60; ++i)
    {
        world.Step(kDt);
    }
    // The motor reaches its speed within the first step (100 N·m against 1.1 kg·m² of
    // reflected inertia); after that the rack moves at ω·r = −1 m/s. Tolerances: the first
    // step's acceleration and the soft step's soft row, well under 1 %.
    CHECK(world.GetAngularVelocity(pinion) == Approx(-2).epsilon(1e-3));
    CHECK(world.GetLinearVelocity(rack).x == Approx(-1).epsilon(1e-3));
    CHECK(world.GetPosition(rack).x == Approx(Real(0.5) * world.GetAngle(pinion)).margin(1e-3));
    // The rail holds the rack's height (a rigid row, within Box2D's linear slop of 5 mm).
    CHECK(world.GetPosition(rack).y == Approx(2.4).margin(0.005));
}

TEST_CASE("Destroying a geared joint, or its body, destroys the gear first", "[joints][gear]")
{
    World world(WorldDef{});
    const BodyId ground = world.CreateBody({});
    const BodyId a = AddDisc(world, {0, 0}, 1, 1);
    const BodyId b = AddDisc(world, {3, 0}, 1, 1);
    const BodyId c = AddDisc(world, {6, 0}, 1, 1);
    const JointId hingeA = Hinge(world, ground, a);
    const JointId hingeB = Hinge(world, ground, b);
    const JointId hingeC = Hinge(world, ground, c);
    const JointId ab = world.CreateJoint(GearJointDef{hingeA, hingeB, 1, false});
    const JointId bc = world.CreateJoint(GearJointDef{hingeB, hingeC, 2, false});
    CHECK(world.GetJoints().size() == 5);

    world.DestroyJoint(hingeA);
    CHECK_FALSE(world.IsValid(ab));
    CHECK(world.IsValid(bc));
    CHECK(world.GetJoints().size() == 3);

    world.DestroyBody(c);
    CHECK_FALSE(world.IsValid(bc));
    CHECK_FALSE(world.IsValid(hingeC));
    CHECK(world.IsValid(hingeB));
    CHECK(world.GetJoints().size() == 1);
    world.Step(kDt); // nothing dangles
}

TEST_CASE("A gear refuses joints it cannot couple", "[joints][gear][errors]")
{
    World world(WorldDef{});
    const BodyId ground = world.CreateBody({});
    const BodyId a = AddDisc(world, {0, 0}, 1, 1);
    const BodyId b = AddDisc(world, {3, 0}, 1, 1);
    const JointId hinge = Hinge(world, ground, a);
    const JointId rod = world.CreateJoint(world.MakeDistanceJointDef(ground, b, {3, 2}, {3, 0}));
    const BodyId wall = world.CreateBody({.position = {5, 0}});
    const JointId pinned = world.CreateJoint(world.MakeRevoluteJointDef(b, wall, {5, 0}));
    const auto message = [&](GearJointDef def)
    {
        try
        {
            world.CreateJoint(def);
        }
        catch (const InvalidArgument& error)
        {
            return std::string(error.what());
        }
        return std::string("accepted");
    };
    CHECK(message({hinge, rod, 1, false}) ==
          "GearJointDef::joint2: must be a revolute or prismatic joint");
    CHECK(message({hinge, hinge, 1, false}) ==
          "GearJointDef::joint2: must be a different joint from joint1");
    CHECK(message({hinge, pinned, 1, false}) ==
          "GearJointDef::joint2: its body B must be dynamic (the gear turns it)");
    CHECK(message({hinge, JointId{}, 1, false}) != "accepted");
    const JointId hingeB = Hinge(world, ground, b);
    CHECK(message({hinge, hingeB, std::numeric_limits<Real>::infinity(), false}) ==
          "GearJointDef::ratio: must be finite, got inf");
    CHECK(world.GetJoints().size() == 4);
}

TEST_CASE("Scene files: gear joints load, build and report bad fields by path",
          "[scene][joints][gear]")
{
    using test::ErrorsOf;
    const std::string head = R"({ "meff_scene": 1, "bodies": [
                    { "name": "g", "type": "static" },
                    { "name": "a", "type": "dynamic", "position": [-1, 0],
                      "shapes": [ { "type": "circle", "radius": 0.5 } ] },
                    { "name": "b", "type": "dynamic", "position": [1, 0],
                      "shapes": [ { "type": "circle", "radius": 0.5 } ] } ],
        "joints": [ { "type": "revolute", "name": "ra", "body_a": "g", "body_b": "a",
                      "anchor": [-1, 0] },
                    { "type": "prismatic", "name": "pb", "body_a": "g", "body_b": "b",
                      "anchor": [1, 0], "axis": [0, 1] },
                    { "type": "weld", "name": "w", "body_a": "a", "body_b": "b",
                      "anchor": [0, 0] },
)";
    const Scene scene =
        ParseScene(head + R"( { "type": "gear", "name": "gear", "joint_a": "ra", "joint_b": "pb",
                     "ratio": -2.5 } ] })",
                   "x.json");
    REQUIRE(scene.joints.size() == 4);
    const SceneJoint& gear = scene.joints[3];
    CHECK(gear.type == JointType::Gear);
    CHECK(gear.jointIndexA == 0);
    CHECK(gear.jointIndexB == 1);
    CHECK(gear.bodyIndexA == 1);
    CHECK(gear.bodyIndexB == 2);
    CHECK(gear.ratio == -2.5);
    const BuiltScene built = BuildWorld(scene);
    CHECK(built.world.GetJointType(built.joints[3]) == JointType::Gear);
    CHECK(built.world.GetBodyA(built.joints[3]) == built.bodies[1]);

    CHECK(ErrorsOf(head + R"( { "type": "gear", "name": "gear", "joint_a": "w",
                                "joint_b": "later", "ratio": 1 },
                              { "type": "revolute", "name": "later", "body_a": "g",
                                "body_b": "b", "anchor": [1, 0] } ] })") ==
          std::vector<std::string>{
              "x.json: joints[3].joint_a: must name a revolute or prismatic joint, got \"w\"",
              "x.json: joints[3].joint_b: no joint earlier in the list has this name, got "
              "\"later\""});
    CHECK(ErrorsOf(head + R"( { "type": "gear", "name": "gear", "joint_a": "ra",
                                "joint_b": "ra", "body_a": "a" } ] })") ==
          std::vector<std::string>{
              "x.json: joints[3].joint_b: must differ from joint_a, got \"ra\"",
              "x.json: joints[3].body_a: unknown field (known fields here: type, name, joint_a, "
              "joint_b, ratio, collide_connected)"});
}

TEST_CASE("gear_train.json: the train runs at the gears' ratios and stops at the rack's limit",
          "[joints][gear][scene]")
{
    const SolverKind kind = GENERATE(SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep);
    CAPTURE(SolverKindName(kind));
    Scene scene = LoadScene(std::string(MEFF_SOURCE_DIR) + "/samples/scenes/gear_train.json");
    scene.world.solver.kind = kind;
    BuiltScene built = BuildWorld(scene);
    World& world = built.world;
    const BodyId drive = built.bodyByName.at("drive");
    const BodyId pinion = built.bodyByName.at("pinion");
    const BodyId rack = built.bodyByName.at("rack");
    for (int i = 0; i < 60; ++i)
    {
        world.Step(kDt);
    }
    // At 1 s: the drive at its motor's 1 rad/s, the pinion twice as fast back, the rack at
    // ω·r = −1 m/s (within 0.1 %: the first step's acceleration is long past).
    CHECK(world.GetAngularVelocity(drive) == Approx(1).epsilon(1e-3));
    CHECK(world.GetAngularVelocity(pinion) == Approx(-2).epsilon(1e-3));
    CHECK(world.GetLinearVelocity(rack).x == Approx(-1).epsilon(1e-3));
    for (int i = 0; i < 60; ++i)
    {
        world.Step(kDt);
    }
    // At 2 s the rack has hit its −1.5 m limit (at 1.5 s) and the train stands still:
    // the rack within the rail's linear slop of the limit, the pinion 3 rad round.
    CHECK(world.GetPosition(rack).x == Approx(-1.5).margin(0.005));
    CHECK(world.GetAngle(pinion) == Approx(-3).margin(0.01));
    CHECK(std::abs(world.GetLinearVelocity(rack).x) < 0.02);
}
