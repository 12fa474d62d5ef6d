// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Chains and one-sided segments through the API and the scene format: what CreateChain makes
// (segments, ghosts, order), what it refuses, what one-sidedness and the ghosts do to bodies
// and rays, snapshots, and the scene fields with their errors. Agreement with Box2D 2.4.1 bit
// for bit is test_chains_box2d.cpp's.
#include "meff/ray_cast.h"
#include "meff/scene.h"
#include "meff/world.h"

#include <catch2/catch.hpp>

#include "scene_errors.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace meff;
using meff::test::ErrorsOf;

namespace
{

using Messages = std::vector<std::string>;

/// A scene whose one body, of `bodyType`, has the single shape `shape` (JSON text).
std::string SceneWithShape(const std::string& shape, const std::string& bodyType = "static")
{
    return R"({ "meff_scene": 1, "bodies": [ { "name": "b", "type": ")" + bodyType +
           R"(", "shapes": [ )" + shape + R"( ] } ] })";
}

bool Same(Vec2 a, Vec2 b)
{
    return a.x == b.x && a.y == b.y;
}

} // namespace

TEST_CASE("CreateChain makes one segment per link, with its neighbours as ghosts", "[chain]")
{
    World world;
    const BodyId ground = world.CreateBody({});
    const ShapeId before = world.CreateShape(ground, {}, Circle{{0, -5}, 1});
    const std::vector<Vec2> points{{3, 0}, {2, 0}, {1, 1}, {0, 1}};

    SECTION("an open chain: ghosts continue its ends unless given")
    {
        const ChainId chain =
            world.CreateChain(ground, {.friction = 0.3f}, Chain{.points = points});
        const std::span<const ShapeId> segments = world.GetChainSegments(chain);
        REQUIRE(segments.size() == 3);
        for (std::size_t i = 0; i < segments.size(); ++i)
        {
            REQUIRE(world.GetShapeType(segments[i]) == ShapeType::ChainSegment);
            REQUIRE(world.GetChain(segments[i]) == chain);
            CHECK(world.GetShapeDef(segments[i]).friction == 0.3f);
            const ChainSegment& s = world.GetChainSegment(segments[i]);
            CHECK(Same(s.segment.point1, points[i]));
            CHECK(Same(s.segment.point2, points[i + 1]));
            CHECK(s.segment.radius == world.GetTolerances().polygonSkin);
        }
        CHECK(Same(world.GetChainSegment(segments[0]).ghost1, {4, 0}));
        CHECK(Same(world.GetChainSegment(segments[0]).ghost2, points[2]));
        CHECK(Same(world.GetChainSegment(segments[1]).ghost1, points[0]));
        CHECK(Same(world.GetChainSegment(segments[1]).ghost2, points[3]));
        CHECK(Same(world.GetChainSegment(segments[2]).ghost1, points[1]));
        CHECK(Same(world.GetChainSegment(segments[2]).ghost2, {-1, 1}));
        // The body lists the chain's segments together, in order, newest first among shapes.
        const std::vector<ShapeId> shapes = world.GetShapes(ground);
        REQUIRE(shapes.size() == 4);
        CHECK(shapes[0] == segments[0]);
        CHECK(shapes[1] == segments[1]);
        CHECK(shapes[2] == segments[2]);
        CHECK(shapes[3] == before);
        CHECK(world.GetChain(before).IsNull());
        // Chains have no mass: a dynamic body with one keeps the mass of its other shapes.
        const BodyId carrier = world.CreateBody({.type = BodyType::Dynamic});
        world.CreateShape(carrier, {.density = 2}, MakeBox(1, 1));
        const Real mass = world.GetMass(carrier);
        world.CreateChain(carrier, {.density = 5}, Chain{.points = points});
        CHECK(world.GetMass(carrier) == mass);
    }
    SECTION("explicit ghosts")
    {
        const ChainId chain = world.CreateChain(
            ground, {}, Chain{.points = points, .prev = Vec2{4, -1}, .next = Vec2{-1, 2}});
        const std::span<const ShapeId> segments = world.GetChainSegments(chain);
        CHECK(Same(world.GetChainSegment(segments[0]).ghost1, {4, -1}));
        CHECK(Same(world.GetChainSegment(segments[2]).ghost2, {-1, 2}));
    }
    SECTION("a loop: the last point joins the first, ghosts wrap round")
    {
        const ChainId chain = world.CreateChain(ground, {}, Chain{.points = points, .loop = true});
        const std::span<const ShapeId> segments = world.GetChainSegments(chain);
        REQUIRE(segments.size() == 4);
        const ChainSegment& closing = world.GetChainSegment(segments[3]);
        CHECK(Same(closing.segment.point1, points[3]));
        CHECK(Same(closing.segment.point2, points[0]));
        CHECK(Same(closing.ghost1, points[2]));
        CHECK(Same(closing.ghost2, points[1]));
        CHECK(Same(world.GetChainSegment(segments[0]).ghost1, points[3]));
    }
}

TEST_CASE("CreateChain refuses what cannot be a chain, and leaves the world as it was",
          "[chain][errors]")
{
    World world;
    const BodyId ground = world.CreateBody({});
    const std::vector<Vec2> two{{0, 0}, {1, 0}};
    const std::vector<Vec2> close{{0, 0}, {1, 0}, {1.004f, 0}};
    const std::vector<Vec2> closedOnItself{{0, 0}, {1, 0}, {1, 1}, {0.002f, 0}};
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    const std::vector<Vec2> notFinite{{0, 0}, {nan, 0}};

    CHECK_THROWS_WITH(world.CreateChain(ground, {}, Chain{.points = {two.data(), 1}}),
                      Catch::Contains("an open chain needs at least 2 points, got 1"));
    CHECK_THROWS_WITH(world.CreateChain(ground, {}, Chain{.points = two, .loop = true}),
                      Catch::Contains("a loop needs at least 3 points, got 2"));
    CHECK_THROWS_WITH(world.CreateChain(ground, {}, Chain{.points = close}),
                      Catch::Contains("points 1 and 2 must be further apart than the linear slop"));
    // A loop's closing link is checked too (Box2D 2.4.1 checks only the others).
    CHECK_THROWS_WITH(world.CreateChain(ground, {}, Chain{.points = closedOnItself, .loop = true}),
                      Catch::Contains("points 3 and 0 must be further apart"));
    CHECK_THROWS_WITH(world.CreateChain(ground, {}, Chain{.points = notFinite}),
                      Catch::Contains("points[1]: must be finite"));
    CHECK_THROWS_WITH(
        world.CreateChain(ground, {}, Chain{.points = two, .loop = false, .prev = Vec2{0, 0}}),
        Catch::Contains("prev and next: must be finite and further than the linear slop"));
    CHECK_THROWS_WITH(
        world.CreateChain(ground, {},
                          Chain{.points = closedOnItself, .loop = true, .next = Vec2{}}),
        Catch::Contains("a loop takes its ghost vertices from its own points"));
    CHECK_THROWS_WITH(world.CreateChain(ground, {.friction = -1}, Chain{.points = two}),
                      Catch::Contains("ShapeDef::friction"));
    CHECK_THROWS_WITH(world.CreateChain(BodyId{}, {}, Chain{.points = two}),
                      Catch::Contains("invalid body id"));
    CHECK(world.GetShapes(ground).empty());

    CHECK_THROWS_WITH(
        world.CreateShape(ground, {}, ChainSegment{{0, 0}, Segment{{0, 0}, {1, 0}}, {2, 0}}),
        Catch::Contains("ChainSegment (ghost1 to point1): points must be further apart"));
    CHECK_THROWS_WITH(
        world.CreateShape(ground, {}, ChainSegment{{-1, 0}, Segment{{0, 0}, {0, 0}}, {2, 0}}),
        Catch::Contains("ChainSegment::segment: points must be further apart"));
    CHECK(world.GetShapes(ground).empty());
}

TEST_CASE("A chain lives and dies whole", "[chain]")
{
    World world;
    const BodyId ground = world.CreateBody({});
    const std::vector<Vec2> points{{2, 0}, {0, 0}, {-2, 0}};
    const ChainId chain = world.CreateChain(ground, {}, Chain{.points = points});
    const std::vector<ShapeId> segments(world.GetChainSegments(chain).begin(),
                                        world.GetChainSegments(chain).end());
    CHECK_THROWS_WITH(world.DestroyShape(segments[0]),
                      Catch::Contains("destroy the whole chain with DestroyChain"));

    // A box resting on the chain falls once the chain is gone, and is woken to do so.
    const BodyId box = world.CreateBody({.type = BodyType::Dynamic, .position = {0, 0.51f}});
    world.CreateShape(box, {}, MakeBox(0.5f, 0.5f));
    for (int i = 0; i < 30; ++i)
    {
        world.Step(1.0f / 60);
    }
    REQUIRE(world.GetTouchingContactCount() > 0);
    const Real restingHeight = world.GetPosition(box).y;
    world.DestroyChain(chain);
    CHECK_FALSE(world.IsValid(chain));
    CHECK_FALSE(world.IsValid(segments[0]));
    CHECK(world.GetShapes(ground).empty());
    CHECK(world.GetContactCount() == 0);
    CHECK_THROWS_WITH(world.DestroyChain(chain), Catch::Contains("invalid chain id"));
    CHECK_THROWS_WITH(world.GetChainSegments(chain), Catch::Contains("invalid chain id"));
    world.Step(1.0f / 60);
    CHECK(world.GetPosition(box).y < restingHeight);

    // Its slot is reused under a new generation; destroying the body frees a chain too.
    const ChainId again = world.CreateChain(ground, {}, Chain{.points = points});
    CHECK(again.index == chain.index);
    CHECK(again.generation != chain.generation);
    world.DestroyBody(ground);
    CHECK_FALSE(world.IsValid(again));
}

TEST_CASE("A one-sided segment stops what comes from its front and lets the back through",
          "[chain]")
{
    // A platform from (2, 3) to (-2, 3): listed right to left, its top is solid. A ball thrown
    // up from below passes through it exactly as through empty space, then lands on its top.
    const auto run = [](bool withPlatform, std::vector<Vec2>& path)
    {
        World world;
        const BodyId ground = world.CreateBody({});
        if (withPlatform)
        {
            world.CreateShape(ground, {}, ChainSegment{{3, 3}, Segment{{2, 3}, {-2, 3}}, {-3, 3}});
        }
        const BodyId ball = world.CreateBody(
            {.type = BodyType::Dynamic, .position = {0, 1}, .linearVelocity = {0, 9}});
        world.CreateShape(ball, {}, Circle{{0, 0}, 0.25f});
        for (int i = 0; i < 180; ++i)
        {
            world.Step(1.0f / 60);
            path.push_back(world.GetPosition(ball));
        }
    };
    std::vector<Vec2> free, blocked;
    run(false, free);
    run(true, blocked);
    // Up to the platform's line from behind, bit for bit as in empty space: the back side
    // gives no contact at all, though the ball overlaps the segment for several steps.
    std::size_t i = 0;
    for (; free[i].y < 3; ++i)
    {
        REQUIRE(Same(blocked[i], free[i]));
    }
    CHECK(i > 10); // 2 m at 9 m/s, slowing: about 16 steps
    // Then up to nearly the free apex (1 + 9²/20 = 5.05 m, less the discrete step's g·dt·h)
    // and down onto the top, where it rests as on any ground: centre at 3 + radius + skin
    // (0.01 m) less the linear slop (0.005 m) the position correction leaves, within 1 mm.
    Real apex = 0;
    for (const Vec2 p : blocked)
    {
        apex = std::max(apex, p.y);
    }
    CHECK(apex > 4.9f);
    CHECK(blocked.back().y == Approx(3.255).margin(0.001));
    CHECK(free.back().y < 0);
}

TEST_CASE("A flat chain never catches a sliding shape; separate segments do", "[chain]")
{
    // Boxes and balls thrown along a floor of 80 collinear 0.5 m links, landing turned. On a
    // chain, the ghosts admit a contact normal only within Box2D's sinTol (sine 0.1) of the
    // floor's: nothing catches on the joints. On the same floor made of two-sided segments the
    // vertices between them give sideways normals (ghost collisions): measured up to 0.70.
    const auto worstLean = [](bool chain)
    {
        World world{WorldDef{.gravity = {0, -10}}};
        const BodyId ground = world.CreateBody({});
        std::vector<Vec2> points;
        for (int i = 0; i <= 80; ++i)
        {
            points.push_back({Real(20 - 0.5 * i), 0});
        }
        if (chain)
        {
            world.CreateChain(ground, {.friction = 0.1f}, Chain{.points = points});
        }
        else
        {
            for (std::size_t i = 0; i + 1 < points.size(); ++i)
            {
                world.CreateShape(ground, {.friction = 0.1f}, Segment{points[i], points[i + 1]});
            }
        }
        for (int k = 0; k < 10; ++k)
        {
            const BodyId body =
                world.CreateBody({.type = BodyType::Dynamic,
                                  .position = {Real(-18 + 0.7 * k), Real(0.5 + 0.3 * k)},
                                  .angle = Real(0.3 * k),
                                  .linearVelocity = {Real(6 + 0.5 * k), -2}});
            if (k % 2 == 1)
            {
                world.CreateShape(body, {.friction = 0.1f}, MakeBox(0.2f, 0.15f));
            }
            else
            {
                world.CreateShape(body, {.friction = 0.1f}, Circle{{0, 0}, 0.2f});
            }
        }
        Real worst = 0;
        int contacts = 0;
        for (int step = 0; step < 240; ++step)
        {
            world.Step(1.0f / 60);
            for (const ContactPointReport& c : world.GetContactReports())
            {
                if (c.bodyA == ground || c.bodyB == ground)
                {
                    worst = std::max(worst, std::abs(c.normal.x));
                    ++contacts;
                }
            }
        }
        REQUIRE(contacts > 4000); // about 4500: the shapes slid the whole time
        return worst;
    };
    CHECK(worstLean(true) <= 0.1f);
    CHECK(worstLean(false) > 0.3f);
}

TEST_CASE("Rays hit a chain from both sides, a lone one-sided segment from its front",
          "[chain][queries]")
{
    World world;
    const BodyId ground = world.CreateBody({});
    const std::vector<Vec2> points{{2, 0}, {-2, 0}}; // solid side up
    const ChainId chain = world.CreateChain(ground, {}, Chain{.points = points});
    const ShapeId ledge =
        world.CreateShape(ground, {}, ChainSegment{{3, 5}, Segment{{2, 5}, {-2, 5}}, {-3, 5}});

    // Down onto the chain's top and up onto its underside: both hit, as in Box2D 2.4.1
    // (b2ChainShape::RayCast casts at a two-sided edge), the normal facing the ray.
    const RayResult fromAbove = world.CastRayClosest({0, 1}, {0, -2});
    REQUIRE(fromAbove.hit);
    CHECK(world.GetChain(fromAbove.shape) == chain);
    CHECK(fromAbove.fraction == 0.5f);
    CHECK(Same(fromAbove.normal, {0, 1}));
    const RayResult fromBelow = world.CastRayClosest({0, -1}, {0, 2});
    REQUIRE(fromBelow.hit);
    CHECK(Same(fromBelow.normal, {0, -1}));

    // The ledge only from above (b2EdgeShape::RayCast with m_oneSided).
    const RayResult ontoLedge = world.CastRayClosest({0, 6}, {0, -2});
    REQUIRE(ontoLedge.hit);
    CHECK(ontoLedge.shape == ledge);
    CHECK(Same(ontoLedge.normal, {0, 1}));
    const RayResult underLedge = world.CastRayClosest({0, 4}, {0, 2});
    CHECK_FALSE(underLedge.hit);
    // Shape casts see segments as GJK does, without sides: a ball cast up hits the ledge.
    CHECK(world.CastShapeClosest(Circle{{0, 0}, 0.25f}, Transform({0, 3}, Rot(0)), {0, 3}).shape ==
          ledge);
    // Nothing contains a point.
    int found = 0;
    world.OverlapPoint({0, 0}, {}, [&](ShapeId) { return ++found > 0; });
    CHECK(found == 0);
}

TEST_CASE("Snapshots restore chains, and stepping on is bit-identical", "[chain][determinism]")
{
    BuiltScene built =
        BuildWorld(LoadScene(std::string(MEFF_SOURCE_DIR) + "/samples/scenes/terrain_car.json"));
    World& world = built.world;
    const auto hashes = [&world](int steps)
    {
        std::vector<std::uint64_t> result;
        for (int i = 0; i < steps; ++i)
        {
            world.Step(1.0f / 60);
            result.push_back(world.GetStateHash());
        }
        return result;
    };
    hashes(90);
    const ChainId terrain = built.chains[0][0];
    REQUIRE(world.IsValid(terrain));
    const WorldSnapshot snapshot = world.SaveSnapshot();
    const std::vector<std::uint64_t> original = hashes(120);

    // Destroying the terrain changes the run; the snapshot brings it, and the run, back.
    world.RestoreSnapshot(snapshot);
    world.DestroyChain(terrain);
    const std::vector<std::uint64_t> fallen = hashes(120);
    CHECK(fallen != original);
    world.RestoreSnapshot(snapshot);
    REQUIRE(world.IsValid(terrain));
    CHECK(world.GetChainSegments(terrain).size() == 50);
    CHECK(hashes(120) == original);
}

TEST_CASE("Scene chains and one-sided segments load with their ghosts resolved", "[chain][scene]")
{
    const Scene scene = ParseScene(R"({ "meff_scene": 1, "bodies": [ { "name": "g",
        "type": "static", "shapes": [
            { "type": "chain", "points": [[3, 0], [1, 0], [0, 1]] },
            { "type": "chain", "points": [[3, 0], [1, 0], [0, 1]], "prev": [4, 1], "next": [-1, 1] },
            { "type": "chain", "points": [[0, 0], [1, 0], [0, 1]], "loop": true },
            { "type": "segment", "points": [[1, 0], [0, 0]], "one_sided": true },
            { "type": "segment", "points": [[1, 0], [0, 0]], "one_sided": true,
              "prev": [2, 1], "next": [-1, -1] } ] } ] })",
                                   "x.json");
    const std::vector<SceneShape>& shapes = scene.bodies[0].shapes;
    CHECK(shapes[0].type == SceneShapeType::Chain);
    CHECK_FALSE(shapes[0].loop);
    CHECK(shapes[0].points.size() == 3);
    // Unset ghosts continue the end segments in straight lines.
    CHECK(shapes[0].prev->x == 5);
    CHECK(shapes[0].prev->y == 0);
    CHECK(shapes[0].next->x == -1);
    CHECK(shapes[0].next->y == 2);
    CHECK(shapes[1].prev->x == 4);
    CHECK(shapes[1].next->y == 1);
    CHECK(shapes[2].loop);
    CHECK_FALSE(shapes[2].prev.has_value());
    CHECK(shapes[3].oneSided);
    CHECK(shapes[3].prev->x == 2);
    CHECK(shapes[3].next->x == -1);
    CHECK(shapes[4].prev->y == 1);

    BuiltScene built = BuildWorld(scene);
    REQUIRE(built.chains[0].size() == 5);
    CHECK(built.world.GetChainSegments(built.chains[0][0]).size() == 2);
    CHECK(built.world.GetChainSegments(built.chains[0][2]).size() == 3);
    CHECK(built.shapes[0][0] == built.world.GetChainSegments(built.chains[0][0]).front());
    CHECK(built.chains[0][3].IsNull());
    CHECK(built.world.GetShapeType(built.shapes[0][3]) == ShapeType::ChainSegment);
    CHECK(built.world.GetChainSegment(built.shapes[0][4]).ghost2.y == -1);
    CHECK(built.world.GetShapes(built.bodies[0]).size() == 2 + 2 + 3 + 1 + 1);
}

TEST_CASE("Scene errors: chains and one-sided segments", "[chain][scene][errors]")
{
    CHECK(ErrorsOf(SceneWithShape(R"({ "type": "chain", "points": [[0, 0]] })")) ==
          Messages{"x.json: bodies[0].shapes[0].points: must list at least 2 points for an open "
                   "chain, got [[0, 0]]"});
    CHECK(ErrorsOf(
              SceneWithShape(R"({ "type": "chain", "points": [[0, 0], [1, 0]], "loop": true })")) ==
          Messages{"x.json: bodies[0].shapes[0].points: must list at least 3 points for a loop, "
                   "got [[0, 0], [1, 0]]"});
    CHECK(
        ErrorsOf(SceneWithShape(
            R"({ "type": "chain", "points": [[0, 0], [1, 0], [1, 1], [0.001, 0]], "loop": true })")) ==
        Messages{"x.json: bodies[0].shapes[0].points: consecutive points 3 and 0 must be more "
                 "than 0.005 m apart, got [[0, 0], [1, 0], [1, 1], [0.001, 0]]"});
    CHECK(
        ErrorsOf(SceneWithShape(
            R"({ "type": "chain", "points": [[0, 0], [1, 0], [1, 1]], "loop": true, "prev": [2, 2] })")) ==
        Messages{"x.json: bodies[0].shapes[0].prev: must be left out for a loop (its ghosts are "
                 "its own points), got [2, 2]"});
    CHECK(ErrorsOf(SceneWithShape(
              R"({ "type": "chain", "points": [[0, 0], [1, 0]], "next": [1, 0.001] })")) ==
          Messages{"x.json: bodies[0].shapes[0].next: must be more than 0.005 m from the end "
                   "point it precedes or follows, got [1, 0.001]"});
    // A chain may be on a dynamic body (as in Box2D), but gives it no mass.
    CHECK(
        ErrorsOf(SceneWithShape(R"({ "type": "chain", "points": [[0, 0], [1, 0]] })", "dynamic")) ==
        Messages{"x.json: bodies[0].shapes: a dynamic body needs mass: give one of its circles, "
                 "boxes or polygons a density > 0 (segments and chains have none), got "
                 "[{\"points\": [[0, 0], [1, 0]], \"type\": \"chain\"}]"});
    CHECK(ErrorsOf(SceneWithShape(
              R"({ "type": "segment", "points": [[0, 0], [1, 0]], "prev": [-1, 0] })")) ==
          Messages{"x.json: bodies[0].shapes[0].prev: is only for a one-sided segment "
                   "(\"one_sided\": true), got [-1, 0]"});
    CHECK(
        ErrorsOf(SceneWithShape(
            R"({ "type": "segment", "points": [[0, 0], [1, 0]], "one_sided": true, "next": "far" })")) ==
        Messages{"x.json: bodies[0].shapes[0].next: must be [x, y] with two finite numbers, "
                 "got \"far\""});
    // Bad points say so once; the ghosts are not measured from them.
    CHECK(ErrorsOf(SceneWithShape(
              R"({ "type": "chain", "points": [[0, 0], [0, 0]], "prev": [0, 0] })")) ==
          Messages{"x.json: bodies[0].shapes[0].points: consecutive points 0 and 1 must be more "
                   "than 0.005 m apart, got [[0, 0], [0, 0]]"});
}

TEST_CASE("Chains work with every solver back end", "[chain][solver]")
{
    // Chains only make manifolds, which every back end consumes. Each back end is held to what
    // the scenes' descriptions promise, not to Box2D's exact numbers (only Box2D's back end is
    // bit-identical). Back ends: add each new one here.
    for (const SolverKind kind : {SolverKind::Box2D, SolverKind::Colour})
    {
        INFO(SolverKindName(kind));
        const std::string dir = std::string(MEFF_SOURCE_DIR) + "/samples/scenes/";
        Scene car = LoadScene(dir + "terrain_car.json");
        car.world.solver.kind = kind;
        BuiltScene builtCar = BuildWorld(car);
        for (int i = 0; i < car.world.frames; ++i)
        {
            builtCar.world.Step(Real(car.world.dt));
        }
        // Over all five hills to the far flat (x > 34 m), on its wheels.
        const Vec2 chassis = builtCar.world.GetPosition(builtCar.bodyByName.at("chassis"));
        CHECK(chassis.x > 34);
        CHECK(chassis.y == Approx(0.96).margin(0.1));

        Scene shapes = LoadScene(dir + "chain_shapes.json");
        shapes.world.solver.kind = kind;
        BuiltScene builtShapes = BuildWorld(shapes);
        for (int i = 0; i < shapes.world.frames; ++i)
        {
            builtShapes.world.Step(Real(shapes.world.dt));
        }
        // Everything dropped into the loop stays inside it (radius 4 m round (0, 5)), and the
        // ball (radius 0.3 m) thrown through the platform rests on it: 3 + 0.3 + skin − slop.
        for (const char* name : {"box1", "box2", "ball1", "ball2", "hexagon", "bullet"})
        {
            const Vec2 p = builtShapes.world.GetPosition(builtShapes.bodyByName.at(name));
            CHECK(Distance(p, {0, 5}) < 4);
        }
        CHECK(builtShapes.world.GetPosition(builtShapes.bodyByName.at("jumper")).y ==
              Approx(3.305).margin(0.002));
    }
}
