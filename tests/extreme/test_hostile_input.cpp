// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Hostile input to the library (issue 7): every bad value is refused the documented way, by
// meff::InvalidArgument, and leaves the world as it was; a step that produces a non-finite
// value throws meff::SimulationError naming the body and the step, and the world stays
// readable. (test_world_analytic.cpp and test_geometry.cpp hold the basic cases; these are the
// remaining ones, each checked to leave the world usable afterwards.)
#include "meff/world.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

using namespace meff;

namespace
{

constexpr Real kNaN = std::numeric_limits<Real>::quiet_NaN();
constexpr Real kInf = std::numeric_limits<Real>::infinity();
constexpr Real kDt = Real(1.0 / 60.0);

BodyId AddDynamicBox(World& world, Vec2 position, Real density = 1)
{
    BodyDef def;
    def.type = BodyType::Dynamic;
    def.position = position;
    const BodyId body = world.CreateBody(def);
    ShapeDef shape;
    shape.density = density;
    world.CreateShape(body, shape, MakeBox(Real(0.5), Real(0.5)));
    return body;
}

/// The world still steps and its bodies are finite: nothing bad got in.
void CheckWorldUsable(World& world)
{
    world.Step(kDt);
    for (const BodyId b : world.GetBodies())
    {
        CHECK(world.GetPosition(b).IsValid());
        CHECK(std::isfinite(world.GetAngle(b)));
        CHECK(world.GetLinearVelocity(b).IsValid());
    }
}

} // namespace

TEST_CASE("non-finite values are refused everywhere a number enters", "[hostile][api]")
{
    World world{WorldDef{}};
    const BodyId box = AddDynamicBox(world, {0, 2});
    const BodyId other = AddDynamicBox(world, {3, 2});
    const int shapesBefore = int(world.GetShapes(box).size());

    for (const Real bad : {kNaN, kInf, -kInf})
    {
        INFO("value " << bad);
        ShapeDef def;
        def.density = bad;
        CHECK_THROWS_AS(world.CreateShape(box, def, Circle{{0, 0}, 1}), InvalidArgument);
        def = ShapeDef{};
        def.friction = bad;
        CHECK_THROWS_AS(world.CreateShape(box, def, Circle{{0, 0}, 1}), InvalidArgument);
        def = ShapeDef{};
        def.restitution = bad;
        CHECK_THROWS_AS(world.CreateShape(box, def, Circle{{0, 0}, 1}), InvalidArgument);
        CHECK_THROWS_AS(world.CreateShape(box, ShapeDef{}, Circle{{bad, 0}, 1}), InvalidArgument);
        CHECK_THROWS_AS(world.CreateShape(box, ShapeDef{}, Circle{{0, 0}, bad}), InvalidArgument);
        CHECK_THROWS_AS(world.CreateShape(box, ShapeDef{}, Segment{{0, 0}, {bad, 1}}),
                        InvalidArgument);

        BodyDef body;
        body.type = BodyType::Dynamic;
        body.gravityScale = bad;
        CHECK_THROWS_AS(world.CreateBody(body), InvalidArgument);
        body = BodyDef{};
        body.angularVelocity = bad;
        CHECK_THROWS_AS(world.CreateBody(body), InvalidArgument);
        body = BodyDef{};
        body.linearDamping = bad;
        CHECK_THROWS_AS(world.CreateBody(body), InvalidArgument);

        CHECK_THROWS_AS(world.SetTransform(box, {bad, 0}, 0), InvalidArgument);
        CHECK_THROWS_AS(world.SetTransform(box, {0, 0}, bad), InvalidArgument);
        CHECK_THROWS_AS(world.SetLinearVelocity(box, {0, bad}), InvalidArgument);
        CHECK_THROWS_AS(world.SetAngularVelocity(box, bad), InvalidArgument);
        CHECK_THROWS_AS(world.ApplyForce(box, {bad, 0}, {0, 0}), InvalidArgument);
        CHECK_THROWS_AS(world.ApplyForce(box, {1, 0}, {0, bad}), InvalidArgument);
        CHECK_THROWS_AS(world.ApplyForceToCenter(box, {bad, 0}), InvalidArgument);
        CHECK_THROWS_AS(world.ApplyTorque(box, bad), InvalidArgument);
        CHECK_THROWS_AS(world.ApplyLinearImpulse(box, {0, bad}, {0, 0}), InvalidArgument);
        CHECK_THROWS_AS(world.ApplyAngularImpulse(box, bad), InvalidArgument);
        CHECK_THROWS_AS(world.SetGravity({0, bad}), InvalidArgument);
        CHECK_THROWS_AS(world.Step(bad), InvalidArgument);
        CHECK_THROWS_AS(world.MakeRevoluteJointDef(box, other, {bad, 0}), InvalidArgument);
        CHECK_THROWS_AS(world.MakeDistanceJointDef(box, other, {0, 0}, {0, bad}), InvalidArgument);

        RevoluteJointDef revolute = world.MakeRevoluteJointDef(box, other, {1.5f, 2});
        revolute.localAnchorA.x = bad;
        CHECK_THROWS_AS(world.CreateJoint(revolute), InvalidArgument);
        DistanceJointDef distance = world.MakeDistanceJointDef(box, other, {0, 2}, {3, 2});
        distance.length = bad;
        CHECK_THROWS_AS(world.CreateJoint(distance), InvalidArgument);

        WorldDef worldDef;
        worldDef.gravity.y = bad;
        CHECK_THROWS_AS(World{worldDef}, InvalidArgument);
    }
    // Nothing was created or changed by the refused calls.
    CHECK(world.GetBodies().size() == 2);
    CHECK(int(world.GetShapes(box).size()) == shapesBefore);
    CHECK(world.GetJoints().empty());
    CHECK(world.GetPosition(box) == Vec2{0, 2});
    CHECK(world.GetGravity() == Vec2{0, -10});
    CHECK(world.GetStepCount() == 0);
    CheckWorldUsable(world);
}

TEST_CASE("negative density is refused, zero density is allowed and stays finite", "[hostile][api]")
{
    World world{WorldDef{}};
    BodyDef def;
    def.type = BodyType::Dynamic;
    const BodyId body = world.CreateBody(def);
    ShapeDef shape;
    shape.density = -1;
    CHECK_THROWS_AS(world.CreateShape(body, shape, MakeBox(1, 1)), InvalidArgument);
    shape.density = -std::numeric_limits<Real>::denorm_min();
    CHECK_THROWS_AS(world.CreateShape(body, shape, MakeBox(1, 1)), InvalidArgument);
    CHECK(world.GetShapes(body).empty());
    // Zero density is allowed (documented: the shape adds no mass). Whatever mass the body is
    // then given, it must be finite and not negative, and stepping must stay finite.
    shape.density = 0;
    world.CreateShape(body, shape, MakeBox(1, 1));
    CHECK(world.GetMass(body) >= 0);
    CHECK(std::isfinite(world.GetMass(body)));
    // Negative damping, friction, restitution outside [0, 1]: refused too.
    ShapeDef bad;
    bad.friction = -0.1f;
    CHECK_THROWS_AS(world.CreateShape(body, bad, MakeBox(1, 1)), InvalidArgument);
    bad = ShapeDef{};
    bad.restitution = 1.5f;
    CHECK_THROWS_AS(world.CreateShape(body, bad, MakeBox(1, 1)), InvalidArgument);
    BodyDef damped;
    damped.angularDamping = -1;
    CHECK_THROWS_AS(world.CreateBody(damped), InvalidArgument);
    CheckWorldUsable(world);
}

TEST_CASE("zero-area polygons are refused, also when built by hand", "[hostile][api]")
{
    World world{WorldDef{}};
    BodyDef def;
    def.type = BodyType::Dynamic;
    const BodyId body = world.CreateBody(def);

    // Through the builder: collinear and coincident points.
    const Vec2 line[] = {{0, 0}, {1, 0}, {2, 0}};
    CHECK_THROWS_AS(MakePolygon(line), InvalidArgument);
    const Vec2 point[] = {{1, 1}, {1, 1}, {1, 1}, {1, 1}};
    CHECK_THROWS_AS(MakePolygon(point), InvalidArgument);

    // By hand, bypassing MakePolygon: the struct is public, so CreateShape must check it too.
    Polygon flat;
    flat.count = 3;
    flat.vertices[0] = {0, 0};
    flat.vertices[1] = {1, 0};
    flat.vertices[2] = {2, 0};
    CHECK_THROWS_AS(world.CreateShape(body, ShapeDef{}, flat), InvalidArgument);
    Polygon collapsed = MakeBox(1, 1);
    for (int i = 0; i < collapsed.count; ++i)
    {
        collapsed.vertices[i] = {0, 0};
    }
    CHECK_THROWS_AS(world.CreateShape(body, ShapeDef{}, collapsed), InvalidArgument);
    // Clockwise (inside-out) and non-convex polygons have the wrong normals: refused too.
    Polygon clockwise = MakeBox(1, 1);
    std::swap(clockwise.vertices[1], clockwise.vertices[3]);
    CHECK_THROWS_AS(world.CreateShape(body, ShapeDef{}, clockwise), InvalidArgument);
    CHECK(world.GetShapes(body).empty());

    // Tiny but real: a 1 mm box is accepted.
    CHECK_NOTHROW(world.CreateShape(body, ShapeDef{}, MakeBox(Real(0.0005), Real(0.0005))));
    CheckWorldUsable(world);
}

TEST_CASE("a destroyed body's id is refused by every call that takes it", "[hostile][api]")
{
    World world{WorldDef{}};
    const BodyId keep = AddDynamicBox(world, {0, 2});
    const BodyId gone = AddDynamicBox(world, {3, 2});
    const ShapeId goneShape = world.GetShapes(gone)[0];
    const JointId joint = world.CreateJoint(world.MakeRevoluteJointDef(keep, gone, {1.5f, 2}));
    world.DestroyBody(gone);

    CHECK_FALSE(world.IsValid(gone));
    CHECK_FALSE(world.IsValid(joint));
    CHECK_THROWS_AS(world.GetType(gone), InvalidArgument);
    CHECK_THROWS_AS(world.GetAngle(gone), InvalidArgument);
    CHECK_THROWS_AS(world.GetTransform(gone), InvalidArgument);
    CHECK_THROWS_AS(world.GetMass(gone), InvalidArgument);
    CHECK_THROWS_AS(world.GetShapes(gone), InvalidArgument);
    CHECK_THROWS_AS(world.SetTransform(gone, {0, 0}, 0), InvalidArgument);
    CHECK_THROWS_AS(world.ApplyTorque(gone, 1), InvalidArgument);
    CHECK_THROWS_AS(world.CreateShape(gone, ShapeDef{}, MakeBox(1, 1)), InvalidArgument);
    CHECK_THROWS_AS(world.DestroyShape(goneShape), InvalidArgument);
    CHECK_THROWS_AS(world.DestroyJoint(joint), InvalidArgument);
    CHECK_THROWS_AS(world.MakeDistanceJointDef(keep, gone, {0, 0}, {1, 1}), InvalidArgument);
    RevoluteJointDef stale;
    stale.bodyA = keep;
    stale.bodyB = gone;
    CHECK_THROWS_AS(world.CreateJoint(stale), InvalidArgument);
    // An id that never existed, and a default (null) id.
    CHECK_THROWS_AS(world.GetPosition(BodyId{12345, 1}), InvalidArgument);
    CHECK_THROWS_AS(world.GetPosition(BodyId{}), InvalidArgument);
    CHECK(world.GetBodies().size() == 1);
    CheckWorldUsable(world);
}

TEST_CASE("a joint between a body and itself is refused", "[hostile][api]")
{
    World world{WorldDef{}};
    const BodyId body = AddDynamicBox(world, {0, 2});
    RevoluteJointDef revolute;
    revolute.bodyA = body;
    revolute.bodyB = body;
    CHECK_THROWS_AS(world.CreateJoint(revolute), InvalidArgument);
    DistanceJointDef distance;
    distance.bodyA = body;
    distance.bodyB = body;
    CHECK_THROWS_AS(world.CreateJoint(distance), InvalidArgument);
    CHECK(world.GetJoints().empty());
    CheckWorldUsable(world);
}

TEST_CASE("a step that produces infinity stops with SimulationError naming body and step, the "
          "world stays readable",
          "[hostile][step]")
{
    World world{WorldDef{}};
    const BodyId ground = world.CreateBody(BodyDef{});
    world.CreateShape(ground, ShapeDef{}, Segment{{-10, 0}, {10, 0}});
    const BodyId calm = AddDynamicBox(world, {-3, Real(0.515)});
    // A very light body (1e-6 kg) pushed by the largest finite force: h·F/m overflows float.
    const BodyId victim = AddDynamicBox(world, {3, 5}, Real(1e-6));
    for (int i = 0; i < 10; ++i)
    {
        world.Step(kDt);
    }
    const Vec2 victimBefore = world.GetPosition(victim);
    const Vec2 calmBefore = world.GetPosition(calm);
    const std::uint64_t stepBefore = world.GetStepCount();

    world.ApplyForceToCenter(victim, {0, std::numeric_limits<Real>::max()});
    try
    {
        world.Step(kDt);
        FAIL("the step should have thrown SimulationError");
    }
    catch (const SimulationError& error)
    {
        const std::string what = error.what();
        INFO(what);
        CHECK(error.step == stepBefore);
        CHECK(error.bodyIndex == victim.index);
        // The message names both, so a log line alone is enough to find the culprit.
        CHECK(what.find("step " + std::to_string(stepBefore)) != std::string::npos);
        CHECK(what.find("body " + std::to_string(victim.index)) != std::string::npos);
    }
    // Readable: the bad body keeps its last good, finite state; ids and queries still work.
    CHECK(world.IsValid(victim));
    CHECK(world.GetPosition(victim) == victimBefore);
    CHECK(world.GetLinearVelocity(victim).IsValid());
    CHECK(world.GetPosition(calm).IsValid());
    CHECK(std::abs(world.GetPosition(calm).y - calmBefore.y) < 0.01f);
    CHECK(world.GetBodies().size() == 3);
    // Further steps are refused (meff::Error), not run on a broken state.
    CHECK_THROWS_AS(world.Step(kDt), Error);
    CHECK(world.GetPosition(victim) == victimBefore);
}
