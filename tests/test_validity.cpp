// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The engine's acceptance rules (meff/validity.h) are one rule for the library and the scene
// loader (issue 18, findings 3 and 7): MakeBox and MakePolygon never return what CreateShape
// refuses; masses, inertias and areas that would be non-finite, zero or denormal are refused
// naming the field; the loader refuses exactly what the library refuses, and accepts what Box2D
// accepts (joints between bodies that cannot move, segments on dynamic bodies).
#include "test_random.h"
#include "meff/scene.h"
#include "meff/validation.h"
#include "meff/validity.h"
#include "meff/world.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace meff;

namespace
{

/// The refusal World::CreateShape throws for `shape` with `def` on a new body of `type`, or an
/// empty field when it is accepted.
template <typename Geometry>
Refusal RefusalOf(const Geometry& shape, ShapeDef def = {}, BodyType type = BodyType::Dynamic)
{
    World world;
    const BodyId body = world.CreateBody({.type = type});
    try
    {
        world.CreateShape(body, def, shape);
    }
    catch (const RefusedArgument& error)
    {
        CHECK(world.GetShapes(body).empty()); // refused: the world is unchanged
        CHECK(std::string(error.what()) == error.refusal().field + ": " + error.refusal().reason);
        return error.refusal();
    }
    return {};
}

/// The messages ParseScene throws for `text`, or an empty list when it loads.
std::vector<std::string> ErrorsOf(const std::string& text)
{
    try
    {
        ParseScene(text, "x.json");
    }
    catch (const SceneError& error)
    {
        return error.messages();
    }
    return {};
}

/// A scene with a static ground and one dynamic body with `shapes` (JSON text).
std::string DynamicBodyWith(const std::string& shapes)
{
    return R"({ "meff_scene": 1, "bodies": [ { "name": "ground", "type": "static" },
        { "name": "b", "type": "dynamic", "shapes": [ )" +
           shapes + R"( ] } ] })";
}

bool IsNormalPositive(Real value)
{
    return std::isfinite(value) && value >= std::numeric_limits<Real>::min();
}

} // namespace

TEST_CASE("validity: MakeBox refuses, naming the cause, the boxes CreateShape would refuse",
          "[validity]")
{
    // A box so large that its area overflows: MakeBox returned it, and CreateShape refused it
    // with a message about its normals (its edges' squared lengths overflow).
    CHECK_THROWS_WITH(MakeBox(1e19f, 1e19f), Catch::Contains("too large: edge 0 is 2e+19 m long"));
    // So thin that its edges have no direction: "edge 0 has zero length" from CreateShape.
    CHECK_THROWS_WITH(MakeBox(1e-20f, 1), Catch::Contains("edge 0 is 2e-20 m long: edges must be "
                                                          "longer than 1.1920929e-07 m"));
    CHECK_THROWS_AS(MakeOffsetBox(1e19f, 1e19f, {0, 0}, 0.3f), RefusedArgument);

    // Whatever MakeBox returns, CreateShape takes (on a static body: no mass involved). Sizes
    // log-uniform from 1e-10 to 1e20 m, where both ends are refused.
    test::Random random(18);
    int made = 0;
    int refused = 0;
    for (int i = 0; i < 2000; ++i)
    {
        const float halfWidth = std::pow(10.0f, random.Uniform(-10, 20));
        const float halfHeight = std::pow(10.0f, random.Uniform(-10, 20));
        Polygon box;
        try
        {
            box = MakeOffsetBox(halfWidth, halfHeight, {0, 0}, random.Uniform(-3, 3));
        }
        catch (const RefusedArgument&)
        {
            ++refused;
            continue;
        }
        ++made;
        INFO("half extents " << halfWidth << " x " << halfHeight);
        CHECK(RefusalOf(box, {}, BodyType::Static).field.empty());
    }
    // Both outcomes happen often enough for the property to mean something.
    CHECK(made > 500);
    CHECK(refused > 500);
}

TEST_CASE("validity: MakePolygon returns only what CreateShape accepts", "[validity]")
{
    test::Random random(7);
    int made = 0;
    for (int i = 0; i < 2000; ++i)
    {
        const float scale = std::pow(10.0f, random.Uniform(-4, 20));
        std::vector<Vec2> points;
        for (int k = 0; k < 3 + random.Index(6); ++k)
        {
            points.push_back({scale * random.Uniform(-1, 1), scale * random.Uniform(-1, 1)});
        }
        Polygon polygon;
        try
        {
            polygon = MakePolygon(points);
        }
        catch (const InvalidArgument&)
        {
            continue;
        }
        ++made;
        INFO("scale " << scale);
        CHECK(RefusalOf(polygon, {}, BodyType::Static).field.empty());
    }
    CHECK(made > 1000);
    // Points 1e19 m out make a hull whose area overflows: refused by MakePolygon itself.
    const std::vector<Vec2> huge = {{-1e19f, -1e19f}, {1e19f, -1e19f}, {0, 1e19f}};
    CHECK_THROWS_AS(MakePolygon(huge), RefusedArgument);
}

TEST_CASE("validity: masses, inertias and areas that are not normal floats are refused, naming "
          "the field",
          "[validity]")
{
    // Radius 1e20: the area πr² overflows (Box2D's ResetMassData asserted m_I > 0 on it).
    CHECK(RefusalOf(Circle{{0, 0}, 1e20f}).field == "Circle::radius");
    CHECK_THAT(RefusalOf(Circle{{0, 0}, 1e20f}).reason, Catch::Contains("too large: its area"));
    // Radius 1e18: the area fits, the inertia m·r²/2 does not.
    CHECK(RefusalOf(Circle{{0, 0}, 1e18f}).field == "Circle::radius");
    CHECK_THAT(RefusalOf(Circle{{0, 0}, 1e18f}).reason,
               Catch::Contains("rotational inertia about the body origin"));
    // Radius 1e-30: the area rounds to 0 (the body got mass 0 and floated).
    CHECK(RefusalOf(Circle{{0, 0}, 1e-30f}).field == "Circle::radius");
    CHECK_THAT(RefusalOf(Circle{{0, 0}, 1e-30f}).reason, Catch::Contains("too small"));
    // Densities whose mass overflows or is denormal: the density is at fault.
    CHECK(RefusalOf(Circle{{0, 0}, 1}, {.density = 2e38f}).field == "ShapeDef::density");
    CHECK(RefusalOf(Circle{{0, 0}, 1}, {.density = 1e-45f}).field == "ShapeDef::density");
    CHECK(RefusalOf(MakeBox(1, 1), {.density = 1e38f}).field == "ShapeDef::density");
    // Its mass fits; its inertia about the origin, m·(w² + h²)/3, does not.
    CHECK(RefusalOf(MakeBox(0.9f, 0.9f), {.density = 1e38f}).field == "Polygon::vertices");
    // A box with mass needs an area above b2_epsilon (Box2D's ComputeMass asserts it); the
    // same box without mass, or on a static body, is fine.
    CHECK(RefusalOf(MakeBox(1e-4f, 1e-4f)).field == "Polygon::vertices");
    CHECK(RefusalOf(MakeBox(1e-4f, 1e-4f), {.density = 0}).field.empty());
    CHECK(RefusalOf(MakeBox(1e-4f, 1e-4f), {}, BodyType::Static).field.empty());
    // Mass does not matter on static bodies, as in Box2D.
    CHECK(RefusalOf(Circle{{0, 0}, 1e18f}, {}, BodyType::Static).field.empty());
    // Fixed rotation: the inertia is never used, so only the mass counts.
    {
        World world;
        const BodyId body = world.CreateBody({.type = BodyType::Dynamic, .fixedRotation = true});
        CHECK_NOTHROW(world.CreateShape(body, ShapeDef{}, Circle{{0, 0}, 1e18f}));
    }
    // A tiny circle far from the body origin: each shape is fine, but the inertia about the
    // centre of mass, I_origin − m·|c|², rounds to nothing.
    CHECK(RefusalOf(Circle{{1e4f, 0}, 1e-3f}).field == "body");
    // Two shapes whose masses add up past the largest float (fixed rotation: only the masses
    // count).
    {
        World world;
        const BodyId body = world.CreateBody({.type = BodyType::Dynamic, .fixedRotation = true});
        world.CreateShape(body, ShapeDef{.density = 1e38f}, MakeBox(0.9f, 0.9f));
        CHECK_THROWS_WITH(world.CreateShape(body, ShapeDef{.density = 1e38f}, MakeBox(0.9f, 0.9f)),
                          Catch::Contains("body: too heavy"));
        CHECK(world.GetShapes(body).size() == 1);
        CHECK(IsNormalPositive(world.GetMass(body)));
    }
}

TEST_CASE("validity: what is accepted has a normal mass and inertia and steps finitely",
          "[validity]")
{
    // Circles of every size and density the rules let through: the body's mass and inertia are
    // normal floats, and a step keeps them finite (no NaN from 1/m or 1/I).
    test::Random random(3);
    int accepted = 0;
    for (int i = 0; i < 1000; ++i)
    {
        World world;
        const BodyId body = world.CreateBody({.type = BodyType::Dynamic, .angularVelocity = 1});
        const Circle circle{{random.Uniform(-5, 5), 0}, std::pow(10.0f, random.Uniform(-25, 21))};
        const ShapeDef def{.density = std::pow(10.0f, random.Uniform(-46, 39))};
        if (def.density == 0)
        {
            continue; // no mass at all: allowed, and not what this test is about
        }
        try
        {
            world.CreateShape(body, def, circle);
        }
        catch (const RefusedArgument&)
        {
            continue;
        }
        ++accepted;
        INFO("radius " << circle.radius << ", density " << def.density);
        CHECK(IsNormalPositive(world.GetMass(body)));
        CHECK(IsNormalPositive(world.GetRotationalInertia(body)));
        world.Step(Real(1) / 60);
        CHECK(world.GetPosition(body).IsValid());
        CHECK(std::isfinite(world.GetAngle(body)));
    }
    CHECK(accepted > 100);
}

TEST_CASE("validity: the loader refuses what the library refuses, at the scene's own field",
          "[validity][scene]")
{
    // The numbers of issue 18, each with the field that causes it.
    CHECK(ErrorsOf(DynamicBodyWith(R"({ "type": "circle", "radius": 1e20 })")) ==
          std::vector<std::string>{
              "x.json: bodies[1].shapes[0].radius: too large: its area 3.142e+40 m² overflows the "
              "engine's float (at most 3.4e+38), got 1e+20"});
    CHECK(ErrorsOf(DynamicBodyWith(R"({ "type": "circle", "radius": 1, "density": 2e38 })")) ==
          std::vector<std::string>{
              "x.json: bodies[1].shapes[0].density: too large: its mass overflows the engine's "
              "float (at most 3.4e+38) at density 2e+38 kg/m²"});
    const std::vector<std::string> denormal =
        ErrorsOf(DynamicBodyWith(R"({ "type": "circle", "radius": 1, "density": 1e-45 })"));
    REQUIRE(denormal.size() == 1);
    CHECK_THAT(denormal[0], Catch::StartsWith("x.json: bodies[1].shapes[0].density: too small"));
    const std::vector<std::string> tiny =
        ErrorsOf(DynamicBodyWith(R"({ "type": "circle", "radius": 1e-30 })"));
    REQUIRE(tiny.size() == 1);
    CHECK_THAT(tiny[0], Catch::StartsWith("x.json: bodies[1].shapes[0].radius: too small"));
    // Boxes: the half extent at fault.
    const std::vector<std::string> thin =
        ErrorsOf(DynamicBodyWith(R"({ "type": "box", "half_width": 1, "half_height": 1e-20 })"));
    REQUIRE(thin.size() == 1);
    CHECK_THAT(thin[0], Catch::StartsWith("x.json: bodies[1].shapes[0].half_height: edge "));
    const std::vector<std::string> huge =
        ErrorsOf(DynamicBodyWith(R"({ "type": "box", "half_width": 1e19, "half_height": 1e19 })"));
    REQUIRE(huge.size() == 1);
    CHECK_THAT(huge[0], Catch::StartsWith("x.json: bodies[1].shapes[0].half_width: too large"));
    // The body's shapes together: reported at the shape that breaks it.
    const std::vector<std::string> far = ErrorsOf(DynamicBodyWith(
        R"({ "type": "circle", "radius": 1, "density": 0 }, { "type": "circle", "radius": 1e-3, "center": [1e4, 0] })"));
    REQUIRE(far.size() == 1);
    CHECK_THAT(far[0], Catch::StartsWith("x.json: bodies[1].shapes[1]: the body with this shape: "
                                         "its rotational inertia about its centre of mass is "
                                         "lost to rounding"));
    // On a static body the same circle has no mass to compute: accepted, as in Box2D.
    CHECK(ErrorsOf(R"({ "meff_scene": 1, "bodies": [ { "name": "g", "type": "static",
        "shapes": [ { "type": "circle", "radius": 1e18 } ] } ] })")
              .empty());
}

TEST_CASE("validity: what Box2D accepts loads and validates — joints between bodies that cannot "
          "move, segments on dynamic bodies",
          "[validity][scene]")
{
    // A revolute joint between two static bodies and a weld between a static and a kinematic
    // body: Box2D accepts both (they do nothing), so scenes written for it must load, with a
    // warning each. A segment on a dynamic body: Box2D accepts it (no mass, collides with
    // polygons). The box falls, the segment-armed body lands on the ground, and everything
    // agrees with Box2D 2.4.1 to the last bit.
    const Scene scene = ParseScene(R"({ "meff_scene": 1, "world": { "frames": 120 },
        "bodies": [
          { "name": "ground", "type": "static",
            "shapes": [ { "type": "box", "half_width": 10, "half_height": 0.5 } ] },
          { "name": "post", "type": "static", "position": [3, 3] },
          { "name": "lift", "type": "kinematic", "position": [-3, 3], "linear_velocity": [0, 0.5] },
          { "name": "sled", "type": "dynamic", "position": [0, 2],
            "shapes": [ { "type": "box", "half_width": 0.5, "half_height": 0.25 },
                        { "type": "segment", "points": [[-1, -0.5], [1, -0.5]] } ] } ],
        "joints": [
          { "type": "revolute", "name": "idle_pin", "body_a": "ground", "body_b": "post",
            "anchor": [3, 3] },
          { "type": "weld", "name": "idle_weld", "body_a": "post", "body_b": "lift",
            "anchor": [0, 3] } ] })",
                                   "x.json");
    CHECK(scene.warnings ==
          std::vector<std::string>{"x.json: joints[0]: warning: neither body_a nor body_b is "
                                   "dynamic, so this joint does nothing (accepted, as Box2D "
                                   "accepts it)",
                                   "x.json: joints[1]: warning: neither body_a nor body_b is "
                                   "dynamic, so this joint does nothing (accepted, as Box2D "
                                   "accepts it)"});
    // By colour too, the idle joints (both bodies' inverse masses 0) step finitely.
    {
        Scene colour = scene;
        colour.world.solver.kind = SolverKind::Colour;
        BuiltScene coloured = BuildWorld(colour);
        for (int i = 0; i < 120; ++i)
        {
            coloured.world.Step(Real(colour.world.dt));
        }
        CHECK(coloured.world.GetPosition(coloured.bodyByName.at("sled")).IsValid());
    }
    BuiltScene built = BuildWorld(scene);
    // The segment adds no mass: the sled weighs its box, 1 kg/m² × 1 m × 0.5 m.
    CHECK(built.world.GetMass(built.bodyByName.at("sled")) == Approx(0.5f).epsilon(1e-6));
    const validation::ValidationResult result = validation::Validate(scene);
    CHECK(result.passed);
    CHECK(result.position.value == 0);
    CHECK(result.velocity.value == 0);
    CHECK(result.contactImpulse.value == 0);
    CHECK(result.jointImpulse.value == 0);
    // The segment carried the sled to rest on the ground (its skin and the ground's, less the
    // slop, below the segment's line at y − 0.5): the contact is real in both engines.
    const Vec2 sled = built.world.GetPosition(built.bodyByName.at("sled"));
    for (int i = 0; i < 120; ++i)
    {
        built.world.Step(Real(scene.world.dt));
    }
    CHECK(built.world.GetPosition(built.bodyByName.at("sled")).y < sled.y);
    CHECK(built.world.GetPosition(built.bodyByName.at("sled")).y ==
          Approx(0.5 + 0.5 + 0.015).margin(2e-3));
}
