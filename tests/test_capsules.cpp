// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Capsules and rounded polygons (Box2D v3's shapes): mass against the closed forms, manifolds
// against hand-worked contacts, ray and shape casts against the analytic outline, resting and
// sliding bodies under every solver back end, and the scene fields with their errors.
#include "meff/b2djson.h"
#include "meff/box2d_v3_features.h"
#include "meff/debug_draw.h"
#include "meff/distance.h"
#include "meff/ray_cast.h"
#include "meff/scene.h"
#include "meff/validation.h"
#include "meff/world.h"

#include <catch2/catch.hpp>

#include "scene_errors.h"

#include <cmath>
#include <string>
#include <vector>

using namespace meff;
using meff::test::ErrorsOf;

namespace
{

/// Float sums of a dozen terms: a few ulps of the largest, relative.
constexpr double kMassTolerance = 1e-5;

double Pi()
{
    return 3.141592653589793;
}

WorldManifold Evaluate(const Manifold& m, const Transform& xfA, Real rA, const Transform& xfB,
                       Real rB)
{
    WorldManifold wm;
    wm.Initialize(m, xfA, rA, xfB, rB);
    return wm;
}

Transform At(Real x, Real y, Real angle = 0)
{
    return Transform(Vec2{x, y}, Rot(angle));
}

std::string SceneWithShape(const std::string& shape, const std::string& bodyType = "dynamic")
{
    return R"({ "meff_scene": 1, "bodies": [ { "name": "b", "type": ")" + bodyType +
           R"(", "shapes": [ )" + shape + R"( ] } ] })";
}

} // namespace

TEST_CASE("A capsule's mass is the closed form: m = rho(pi r^2 + 2rL), I of a rectangle and "
          "two half-discs",
          "[capsule]")
{
    const double r = 0.3, density = 2.5;
    const Capsule capsule{{0.5, 1.0}, {2.5, 1.0}, Real(r)}; // L = 2, centre (1.5, 1)
    const double length = 2;
    const MassData md = ComputeMass(capsule, Real(density));

    const double rectangle = density * 2 * r * length;
    const double discs = density * Pi() * r * r;
    CHECK(md.mass == Approx(rectangle + discs).epsilon(kMassTolerance));
    CHECK(md.center.x == Approx(1.5).epsilon(kMassTolerance));
    CHECK(md.center.y == Approx(1.0).epsilon(kMassTolerance));
    // About the centre: the 2r × L rectangle, m(L² + 4r²)/12, and the two half-discs, each
    // with its centroid 4r/(3π) beyond its end of the core: together m_c(r²/2 + L²/4 + L·4r/(3π))
    // (half-disc about its flat edge's middle m r²/2, moved by the parallel-axis theorem).
    const double a = 4 * r / (3 * Pi());
    const double central = rectangle * (length * length + 4 * r * r) / 12 +
                           discs * (r * r / 2 + length * length / 4 + length * a);
    const double aboutOrigin = central + (rectangle + discs) * (1.5 * 1.5 + 1.0 * 1.0);
    CHECK(md.rotationalInertia == Approx(aboutOrigin).epsilon(kMassTolerance));
}

TEST_CASE("A rounded box's mass is the rounded outline's, checked by integrating over a grid",
          "[capsule]")
{
    const double hw = 0.6, hh = 0.3, r = 0.2;
    Polygon box = MakeOffsetBox(Real(hw), Real(hh), {0.4f, -0.2f}, 0);
    box.radius = Real(r);
    const MassData md = ComputeRoundedMass(box, 1);
    // Area: the core, a band of width r along each edge, and four quarter discs.
    const double area = 4 * hw * hh + 4 * (hw + hh) * r + Pi() * r * r;
    CHECK(md.mass == Approx(area).epsilon(kMassTolerance));
    CHECK(md.center.x == Approx(0.4).epsilon(kMassTolerance));
    CHECK(md.center.y == Approx(-0.2).margin(1e-6));

    // The polar moment about the origin by the midpoint rule on a 2000 × 2000 grid over the
    // bounding box: the cells the outline cuts err by at most their area times the largest
    // |p|², about 4·perimeter·h·1.2 m² ≈ 1e-3 of the answer; 2e-3 is allowed.
    const int n = 2000;
    const double x0 = 0.4 - hw - r, y0 = -0.2 - hh - r;
    const double hx = 2 * (hw + r) / n, hy = 2 * (hh + r) / n;
    double inertia = 0;
    for (int i = 0; i < n; ++i)
    {
        for (int j = 0; j < n; ++j)
        {
            const double x = x0 + (i + 0.5) * hx, y = y0 + (j + 0.5) * hy;
            const double dx = std::max(std::abs(x - 0.4) - hw, 0.0);
            const double dy = std::max(std::abs(y + 0.2) - hh, 0.0);
            if (dx * dx + dy * dy <= r * r)
            {
                inertia += (x * x + y * y) * hx * hy;
            }
        }
    }
    CHECK(md.rotationalInertia == Approx(inertia).epsilon(2e-3));
}

TEST_CASE("Capsule manifolds against hand-worked contacts", "[capsule][manifold]")
{
    const Real r = 0.25;
    const Polygon box = MakeBox(2, Real(0.5)); // sharp (radius 0): top face y = 0.5
    const Transform xfBox = At(0, 0);

    SECTION("lying on a box: two points, depth the overlap, normal up")
    {
        const Real overlap = Real(0.02);
        const Polygon capsule = MakeCapsulePolygon({{-0.5f, 0}, {0.5f, 0}, r});
        const Transform xfCapsule = At(0.3f, Real(0.5) + r - overlap);
        Manifold m;
        CollideRoundedPolygons(m, box, xfBox, capsule, xfCapsule);
        REQUIRE(m.pointCount == 2);
        const WorldManifold wm = Evaluate(m, xfBox, 0, xfCapsule, r);
        CHECK(wm.normal.x == Approx(0).margin(1e-6));
        CHECK(wm.normal.y == Approx(1).margin(1e-6));
        for (int k = 0; k < 2; ++k)
        {
            CHECK(wm.separations[k] == Approx(-overlap).margin(1e-6));
        }
        // The points are under the caps' centres.
        CHECK(std::min(wm.points[0].x, wm.points[1].x) == Approx(-0.2).margin(1e-6));
        CHECK(std::max(wm.points[0].x, wm.points[1].x) == Approx(0.8).margin(1e-6));
    }
    SECTION("standing on its end: one point under the lower cap")
    {
        const Real overlap = Real(0.03);
        const Polygon capsule = MakeCapsulePolygon({{0, 0}, {0, 1}, r});
        const Transform xfCapsule = At(-1, Real(0.5) + r - overlap);
        Manifold m;
        CollideRoundedPolygons(m, box, xfBox, capsule, xfCapsule);
        REQUIRE(m.pointCount == 1);
        const WorldManifold wm = Evaluate(m, xfBox, 0, xfCapsule, r);
        CHECK(wm.normal.y == Approx(1).margin(1e-6));
        CHECK(wm.separations[0] == Approx(-overlap).margin(1e-6));
        CHECK(wm.points[0].x == Approx(-1).margin(1e-6));
    }
    SECTION("two capsules crossed: one point, depth rA + rB minus the gap of the cores")
    {
        const Polygon a = MakeCapsulePolygon({{-1, 0}, {1, 0}, r});
        const Polygon b = MakeCapsulePolygon({{0, 0}, {0, 1}, r});
        const Transform xfB = At(0.3f, 0.4f);
        Manifold m;
        CollideRoundedPolygons(m, a, At(0, 0), b, xfB);
        REQUIRE(m.pointCount == 1);
        const WorldManifold wm = Evaluate(m, At(0, 0), r, xfB, r);
        CHECK(wm.normal.y == Approx(1).margin(1e-6));
        CHECK(wm.separations[0] == Approx(0.4 - 0.5).margin(1e-6));
        CHECK(wm.points[0].x == Approx(0.3).margin(1e-6));
    }
    SECTION("against a circle: over the side and beyond a cap")
    {
        const Polygon capsule = MakeCapsulePolygon({{-1, 0}, {1, 0}, r});
        Manifold m;
        // Above the side: normal up, separation 0.6 − 0.25 − 0.4.
        CollidePolygonAndCircle(m, capsule, At(0, 0), Circle{{0, 0}, 0.4f}, At(0.5f, 0.6f));
        REQUIRE(m.pointCount == 1);
        WorldManifold wm = Evaluate(m, At(0, 0), r, At(0.5f, 0.6f), 0.4f);
        CHECK(wm.normal.y == Approx(1).margin(1e-6));
        CHECK(wm.separations[0] == Approx(0.6 - 0.25 - 0.4).margin(1e-6));
        // Beyond the cap at (1, 0), along (3, 4)/5 at distance 0.6.
        const Transform xfC = At(1 + 0.36f, 0.48f);
        CollidePolygonAndCircle(m, capsule, At(0, 0), Circle{{0, 0}, 0.4f}, xfC);
        REQUIRE(m.pointCount == 1);
        wm = Evaluate(m, At(0, 0), r, xfC, 0.4f);
        CHECK(wm.normal.x == Approx(0.6).margin(1e-5));
        CHECK(wm.normal.y == Approx(0.8).margin(1e-5));
        CHECK(wm.separations[0] == Approx(0.6 - 0.25 - 0.4).margin(1e-5));
    }
    SECTION("rounded corners meet along the line between the corners, not a face normal")
    {
        Polygon a = MakeBox(0.5f, 0.5f);
        a.radius = 0.1f;
        // B's lower-left corner core at (c − 0.5, c − 0.5): the cores' corners are √2(c − 1)
        // apart along the diagonal.
        const Real c = 1.13f;
        Manifold m;
        CollideRoundedPolygons(m, a, At(0, 0), a, At(c, c));
        REQUIRE(m.pointCount == 1);
        CHECK(m.type == Manifold::Type::Circles);
        const WorldManifold wm = Evaluate(m, At(0, 0), 0.1f, At(c, c), 0.1f);
        CHECK(wm.normal.x == Approx(std::sqrt(0.5)).margin(1e-5));
        CHECK(wm.normal.y == Approx(std::sqrt(0.5)).margin(1e-5));
        CHECK(wm.separations[0] == Approx(std::sqrt(2.0) * 0.13 - 0.2).margin(1e-5));
        // Apart by 0.012 m along the diagonal, though each face axis overlaps the skins: no
        // contact (the face-only test of Box2D 2.4.1 would report one 0.05 m deep).
        CollideRoundedPolygons(m, a, At(0, 0), a, At(1.15f, 1.15f));
        CHECK(m.pointCount == 0);
    }
    SECTION("on a two-sided segment, and on a one-sided one from either side")
    {
        const Polygon capsule = MakeCapsulePolygon({{-0.5f, 0}, {0.5f, 0}, r});
        const Real overlap = 0.01f;
        Manifold m;
        const Segment ground{{-3, 0}, {3, 0}, 0.01f};
        CollideRoundedPolygons(m, MakeCapsulePolygon({ground.point1, ground.point2, 0.01f}),
                               At(0, 0), capsule, At(0, 0.26f - overlap));
        REQUIRE(m.pointCount == 2);
        // Listed right to left the solid side is up.
        const ChainSegment oneSided{{4, 0}, {{3, 0}, {-3, 0}, 0.01f}, {-4, 0}};
        CollideChainSegmentAndRounded(m, oneSided, At(0, 0), capsule, At(0, 0.26f - overlap));
        REQUIRE(m.pointCount == 2);
        const WorldManifold wm = Evaluate(m, At(0, 0), 0.01f, At(0, 0.26f - overlap), r);
        CHECK(wm.normal.y == Approx(1).margin(1e-6));
        CHECK(wm.separations[0] == Approx(-overlap).margin(1e-6));
        CollideChainSegmentAndRounded(m, oneSided, At(0, 0), capsule, At(0, -0.2f));
        CHECK(m.pointCount == 0); // behind: passes through
    }
}

TEST_CASE("Ray casts hit a capsule's outline where the geometry says", "[capsule][query]")
{
    const Capsule capsule{{-1, 0}, {1, 0}, 0.5f};
    RayCastOutput out;
    SECTION("the flat side: from (0.3, 3) down, the hit is at y = 0.5")
    {
        REQUIRE(RayCast(capsule, At(0, 0), {{0.3f, 3}, {0.3f, -3}, 1}, out));
        CHECK(out.fraction == Approx(2.5 / 6).margin(1e-6));
        CHECK(out.normal.y == Approx(1).margin(1e-6));
    }
    SECTION("a cap: from (3, 0.3) left, the circle about (1, 0) at x = 1 + sqrt(0.25 - 0.09)")
    {
        REQUIRE(RayCast(capsule, At(0, 0), {{3, 0.3f}, {-3, 0.3f}, 1}, out));
        CHECK(out.fraction == Approx((3 - 1.4) / 6).margin(1e-6));
        CHECK(out.normal.x == Approx(0.8).margin(1e-5));
        CHECK(out.normal.y == Approx(0.6).margin(1e-5));
    }
    SECTION("turned a quarter turn and moved, through the world")
    {
        World world;
        const BodyId body = world.CreateBody({.position = {5, 2}, .angle = Real(Pi() / 2)});
        const ShapeId shape = world.CreateShape(body, {}, capsule);
        // The capsule now runs from (5, 1) to (5, 3); a ray from the right at y = 3.2 meets
        // the upper cap at x = 5 + sqrt(0.25 − 0.04).
        const RayResult hit = world.CastRayClosest({8, 3.2f}, {-6, 0});
        REQUIRE(hit.hit);
        CHECK(hit.shape == shape);
        CHECK(hit.point.x == Approx(5 + std::sqrt(0.21)).margin(1e-5));
        CHECK(hit.normal.x == Approx(std::sqrt(0.21) / 0.5).margin(1e-5));
        // Point queries: inside near a cap, outside beyond it.
        int found = 0;
        world.OverlapPoint({5.2f, 3.3f}, {}, [&](ShapeId) { return ++found, true; });
        CHECK(found == 1);
        world.OverlapPoint({5.4f, 3.4f}, {}, [&](ShapeId) { return ++found, true; });
        CHECK(found == 1);
        CHECK(world.GetShapeAABB(shape).lowerBound.y == Approx(0.5).margin(1e-6));
        CHECK(world.GetShapeAABB(shape).upperBound.x == Approx(5.5).margin(1e-6));
    }
    SECTION("a ray starting inside does not hit")
    {
        CHECK_FALSE(RayCast(capsule, At(0, 0), {{0.9f, 0.1f}, {5, 0.1f}, 1}, out));
        CHECK(TestPoint(capsule, At(0, 0), {1.4f, 0.2f}));
        CHECK_FALSE(TestPoint(capsule, At(0, 0), {1.4f, 0.4f}));
    }
}

TEST_CASE("A capsule cast down onto a box stops where its lower side meets the box",
          "[capsule][query]")
{
    World world;
    const BodyId ground = world.CreateBody({});
    world.CreateShape(ground, {}, MakeBox(5, 0.5f)); // top at 0.5, skin 0.01
    const Capsule capsule{{-0.5f, 0}, {0.5f, 0}, 0.25f};
    const RayResult hit = world.CastShapeClosest(capsule, At(0, 3), {0, -3});
    REQUIRE(hit.hit);
    // The capsule's centre travels from 3 to 0.5 + 0.25 (the surfaces meet), give or take
    // ShapeCast's stopping rule: within polygonSkin + linearSlop/2 of touching.
    const double travelled = 3 * double(hit.fraction);
    CHECK(3 - travelled == Approx(0.75).margin(0.0125));
    CHECK(hit.normal.y == Approx(1).margin(1e-5));
}

namespace
{

/// A world of one solver kind: a wide static box whose top is at y = 0.
World FlatGround(SolverKind kind)
{
    WorldDef def;
    def.solver.kind = kind;
    World world(def);
    const BodyId ground = world.CreateBody({.position = {0, -1}});
    world.CreateShape(ground, {}, MakeBox(20, 1));
    return world;
}

void StepSeconds(World& world, double seconds)
{
    for (int i = 0; i < int(std::lround(seconds * 60)); ++i)
    {
        world.Step(Real(1) / Real(60));
    }
}

} // namespace

TEST_CASE("Capsules and rounded boxes rest on the ground at their radius under every back end",
          "[capsule][solver]")
{
    const SolverKind kind = GENERATE(SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep);
    CAPTURE(SolverKindName(kind));
    World world = FlatGround(kind);
    const Real skin = world.GetTolerances().polygonSkin;
    const Real slop = world.GetTolerances().linearSlop;
    const BodyId capsule = world.CreateBody({.type = BodyType::Dynamic, .position = {-3, 1}});
    world.CreateShape(capsule, {}, Capsule{{-0.6f, 0}, {0.6f, 0}, 0.3f});
    Polygon rounded = MakeBox(0.4f, 0.25f);
    rounded.radius = 0.15f;
    const BodyId box = world.CreateBody({.type = BodyType::Dynamic, .position = {3, 1}});
    world.CreateShape(box, {}, rounded);
    StepSeconds(world, 3);
    // At rest the solvers leave the surfaces overlapping by up to the linear slop (Box2D's
    // allowed penetration; the soft step corrects to it too) beyond the ground's skin.
    CHECK(world.GetPosition(capsule).y == Approx(0.3 + skin).margin(slop + 1e-3));
    CHECK(world.GetPosition(box).y == Approx(0.25 + 0.15 + skin).margin(slop + 1e-3));
    CHECK(std::abs(world.GetAngle(capsule)) < 1e-3);
    CHECK(std::abs(world.GetAngle(box)) < 1e-3);
    CHECK(world.GetLinearVelocity(capsule).Length() < 1e-2);
    CHECK(world.GetLinearVelocity(box).Length() < 1e-2);
}

TEST_CASE("A capsule lying on a slope slides down it at g(sin t - mu cos t), as kinetic "
          "friction says",
          "[capsule][solver]")
{
    // A 30° slope with μ = 0.2 < tan 30°: the capsule lies on its side (two contact points,
    // no torque about its centre of mass from the normal forces, whose sum balances g·cos θ)
    // and slides without turning. The velocity after n steps of the semi-implicit Euler step
    // is exactly n·h·a, so velocity is compared, not position.
    const double theta = Pi() / 6, mu = 0.2, g = 10;
    World world;
    const BodyId slope = world.CreateBody({.angle = Real(-theta)});
    world.CreateShape(slope, {.friction = Real(mu)}, MakeBox(30, 1));
    // Down the slope is (cos θ, −sin θ)... the box's top face normal is (sin θ, cos θ).
    const Vec2 up{Real(std::sin(theta)), Real(std::cos(theta))};
    const Vec2 down{Real(std::cos(theta)), Real(-std::sin(theta))};
    const BodyId body = world.CreateBody(
        {.type = BodyType::Dynamic, .position = (1 + 0.3f + 0.004f) * up, .angle = Real(-theta)});
    world.CreateShape(body, {.friction = Real(mu)}, Capsule{{-0.6f, 0}, {0.6f, 0}, 0.3f});
    StepSeconds(world, 0.5); // settle onto the slope and slide
    const Real v0 = Dot(world.GetLinearVelocity(body), down);
    StepSeconds(world, 1);
    const Real v1 = Dot(world.GetLinearVelocity(body), down);
    const double a = g * (std::sin(theta) - mu * std::cos(theta));
    // Friction at its Coulomb limit each step makes the gain exact up to float round-off.
    CHECK(double(v1 - v0) == Approx(a * 1.0).epsilon(1e-3));
    CHECK(std::abs(world.GetAngularVelocity(body)) < 1e-3);
}

TEST_CASE("A capsule and a rounded box slide over the joints of a chain without catching",
          "[capsule][chain]")
{
    // Flat terrain of 1 m links listed right to left (solid side up), no friction: each body
    // keeps its 4 m/s across 8 joints. A contact on a joint's vertex with a sideways normal
    // (a "ghost collision") would take speed off.
    World world;
    const BodyId ground = world.CreateBody({});
    std::vector<Vec2> points;
    for (int x = 12; x >= -12; --x)
    {
        points.push_back({Real(x), 0});
    }
    world.CreateChain(ground, {.friction = 0}, Chain{.points = points});
    const BodyId capsule = world.CreateBody(
        {.type = BodyType::Dynamic, .position = {-8, 0.3f + 0.005f}, .linearVelocity = {4, 0}});
    world.CreateShape(capsule, {.friction = 0}, Capsule{{-0.5f, 0}, {0.5f, 0}, 0.3f});
    Polygon rounded = MakeBox(0.4f, 0.2f);
    rounded.radius = 0.05f;
    const BodyId box = world.CreateBody(
        {.type = BodyType::Dynamic, .position = {-4, 0.25f + 0.005f}, .linearVelocity = {4, 0}});
    world.CreateShape(box, {.friction = 0}, rounded);
    StepSeconds(world, 2);
    // Gravity only acts along the normal: the speed stays 4 m/s to float round-off.
    CHECK(world.GetLinearVelocity(capsule).x == Approx(4).margin(1e-3));
    CHECK(world.GetLinearVelocity(box).x == Approx(4).margin(1e-3));
    CHECK(world.GetPosition(capsule).y == Approx(0.3).margin(0.01));
}

TEST_CASE("A capsule drawn: its rounded outline and its axis", "[capsule][draw]")
{
    struct Recorder : DebugDraw
    {
        std::vector<Vec2> outline;
        std::vector<std::pair<Vec2, Vec2>> segments;
        void DrawPolygon(std::span<const Vec2>, const DrawColor&) override {}
        void DrawSolidPolygon(std::span<const Vec2> v, const DrawColor&) override
        {
            outline.assign(v.begin(), v.end());
        }
        void DrawCircle(Vec2, Real, const DrawColor&) override {}
        void DrawSolidCircle(Vec2, Real, Vec2, const DrawColor&) override {}
        void DrawSegment(Vec2 a, Vec2 b, const DrawColor&) override { segments.push_back({a, b}); }
        void DrawTransform(const Transform&) override {}
        void DrawPoint(Vec2, Real, const DrawColor&) override {}
    } recorder;
    World world;
    const BodyId body = world.CreateBody({.position = {1, 1}});
    world.CreateShape(body, {}, Capsule{{-1, 0}, {1, 0}, 0.5f});
    world.Draw(recorder);
    REQUIRE(recorder.outline.size() >= 16);
    for (const Vec2 p : recorder.outline)
    {
        // Every outline point is r from the core segment y = 1, x in [0, 2].
        const Real x = Clamp(p.x, 0, 2);
        CHECK(Distance(p, {x, 1}) == Approx(0.5).margin(1e-5));
    }
    REQUIRE(!recorder.segments.empty());
    CHECK(recorder.segments[0].first.x == Approx(0).margin(1e-6));
    CHECK(recorder.segments[0].second.x == Approx(2).margin(1e-6));
}

TEST_CASE("Capsule worlds snapshot and hash like any other", "[capsule][determinism]")
{
    World world = FlatGround(SolverKind::Box2D);
    const BodyId body =
        world.CreateBody({.type = BodyType::Dynamic, .position = {0, 2}, .angle = 0.4f});
    world.CreateShape(body, {}, Capsule{{-0.6f, 0}, {0.6f, 0}, 0.3f});
    StepSeconds(world, 0.3);
    const WorldSnapshot snapshot = world.SaveSnapshot();
    StepSeconds(world, 0.5);
    const std::uint64_t hash = world.GetStateHash();
    world.RestoreSnapshot(snapshot);
    StepSeconds(world, 0.5);
    CHECK(world.GetStateHash() == hash);
}

TEST_CASE("The engine refuses bad capsules and polygon radii, naming the field", "[capsule]")
{
    World world;
    const BodyId body = world.CreateBody({.type = BodyType::Dynamic});
    const auto refuses = [&](const Capsule& c, const std::string& field)
    {
        try
        {
            world.CreateShape(body, {}, c);
        }
        catch (const InvalidArgument& error)
        {
            CHECK_THAT(error.what(), Catch::Contains(field));
            return;
        }
        FAIL("accepted");
    };
    refuses({{0, 0}, {1, 0}, 0}, "Capsule::radius");
    refuses({{0, 0}, {1, 0}, -1}, "Capsule::radius");
    refuses({{0, 0}, {1, 0}, std::nanf("")}, "Capsule::radius");
    refuses({{0, 0}, {0.001f, 0}, 0.2f}, "Capsule::center2");
    refuses({{INFINITY, 0}, {1, 0}, 0.2f}, "Capsule::center1");
    Polygon box = MakeBox(1, 1);
    box.radius = -0.1f;
    CHECK_THROWS_WITH(world.CreateShape(body, {}, box), Catch::Contains("Polygon::radius"));
    box.radius = 0.005f; // within the skin: a sharp box, Box2D 2.4.1's
    const ShapeId sharp = world.CreateShape(body, {}, box);
    CHECK(world.GetPolygon(sharp).radius == world.GetTolerances().polygonSkin);
}

TEST_CASE("Scene files: capsules and rounded polygons, their errors, and what Box2D 2.4.1 "
          "tools refuse",
          "[capsule][scene]")
{
    const Scene scene =
        ParseScene(SceneWithShape(R"({ "type": "capsule", "center_a": [-1, 0], "center_b": [1, 0.5],
                            "radius": 0.25 },
                          { "type": "box", "half_width": 1, "half_height": 0.5, "radius": 0.1 },
                          { "type": "polygon", "vertices": [[0, 0], [1, 0], [0, 1]],
                            "radius": 0.05 })"),
                   "caps.json");
    const std::vector<SceneShape>& shapes = scene.bodies[0].shapes;
    REQUIRE(shapes.size() == 3);
    CHECK(shapes[0].type == SceneShapeType::Capsule);
    CHECK(shapes[0].centerB.y == 0.5);
    CHECK(shapes[0].radius == 0.25);
    CHECK(shapes[1].rounding == 0.1);
    CHECK(shapes[2].rounding == 0.05);
    BuiltScene built = BuildWorld(scene);
    const std::vector<ShapeId> ids = built.world.GetShapes(built.bodies[0]);
    // Newest first.
    CHECK(built.world.GetShapeType(ids[2]) == ShapeType::Capsule);
    CHECK(built.world.GetPolygon(ids[1]).radius == 0.1f);
    CHECK(built.world.GetMass(built.bodies[0]) ==
          Approx(Pi() * 0.0625 + 0.5 * std::sqrt(4.25) + 2 + 6 * 0.1 + Pi() * 0.01 + 0.5 +
                 (2 + std::sqrt(2.0)) * 0.05 + Pi() * 0.0025)
              .epsilon(1e-5));

    // meff validate and the b2dJson export refuse them, naming each field.
    try
    {
        validation::Validate(scene, {});
        FAIL("validated");
    }
    catch (const SceneError& error)
    {
        REQUIRE(error.messages().size() == 3);
        CHECK_THAT(error.messages()[0], Catch::StartsWith("caps.json: bodies[0].shapes[0].type: "
                                                          "\"capsule\""));
        CHECK_THAT(error.messages()[1], Catch::StartsWith("caps.json: bodies[0].shapes[1].radius"));
        CHECK_THAT(error.messages()[2], Catch::StartsWith("caps.json: bodies[0].shapes[2].radius"));
    }
    CHECK_THROWS_AS(ExportB2dJson(scene), SceneError);

    CHECK(ErrorsOf(SceneWithShape(R"({ "type": "capsule", "center_a": [0, 0],
                                       "center_b": [0, 0.001], "radius": 0.2 })")) ==
          std::vector<std::string>{"x.json: bodies[0].shapes[0].center_b: must be more than "
                                   "0.005 m from center_a (a capsule with one centre is a "
                                   "circle), got [0, 0.001]"});
    CHECK(ErrorsOf(SceneWithShape(R"({ "type": "capsule", "center_a": [0, 0],
                                       "center_b": [1, 0], "radius": 0 })")) ==
          std::vector<std::string>{"x.json: bodies[0].shapes[0].radius: must be > 0, got 0"});
    CHECK(ErrorsOf(SceneWithShape(R"({ "type": "box", "half_width": 1, "half_height": 1,
                                       "radius": 0.01 })")) ==
          std::vector<std::string>{"x.json: bodies[0].shapes[0].radius: must be above the "
                                   "polygon skin (0.01 m; every sharp polygon is rounded that "
                                   "much), or left out, got 0.01"});
}

TEST_CASE("Rounded polygon manifolds against every other shape, hand-worked", "[capsule][manifold]")
{
    // A 1 m square core rounded by 0.1 m: its top face (core) at y = 0.5, its surface at 0.6.
    Polygon rounded = MakeBox(0.5f, 0.5f);
    rounded.radius = 0.1f;
    const Real r = rounded.radius;
    Manifold m;
    SECTION("a circle over the face: normal up, depth the overlap")
    {
        const Real overlap = 0.02f;
        const Transform xfC = At(0.1f, 0.5f + r + 0.2f - overlap);
        CollidePolygonAndCircle(m, rounded, At(0, 0), Circle{{0, 0}, 0.2f}, xfC);
        REQUIRE(m.pointCount == 1);
        const WorldManifold wm = Evaluate(m, At(0, 0), r, xfC, 0.2f);
        CHECK(wm.normal.x == Approx(0).margin(1e-6));
        CHECK(wm.normal.y == Approx(1).margin(1e-6));
        CHECK(wm.separations[0] == Approx(-overlap).margin(1e-6));
    }
    SECTION("a circle beyond a rounded corner: along the line from the corner, (3, 4)/5")
    {
        // Corner core at (0.5, 0.5); the circle's centre 0.1 + 0.2 − 0.03 from it.
        const Real d = 0.27f;
        const Transform xfC = At(0.5f + 0.6f * d, 0.5f + 0.8f * d);
        CollidePolygonAndCircle(m, rounded, At(0, 0), Circle{{0, 0}, 0.2f}, xfC);
        REQUIRE(m.pointCount == 1);
        const WorldManifold wm = Evaluate(m, At(0, 0), r, xfC, 0.2f);
        CHECK(wm.normal.x == Approx(0.6).margin(1e-5));
        CHECK(wm.normal.y == Approx(0.8).margin(1e-5));
        CHECK(wm.separations[0] == Approx(-0.03).margin(1e-5));
    }
    SECTION("on a sharp box: two points under the core's corners, depth the overlap")
    {
        const Polygon box = MakeBox(2, 0.5f); // radius 0: top face at y = 0.5
        const Real overlap = 0.015f;
        const Transform xfR = At(0.25f, 0.5f + 0.5f + r - overlap);
        CollideRoundedPolygons(m, box, At(0, 0), rounded, xfR);
        REQUIRE(m.pointCount == 2);
        const WorldManifold wm = Evaluate(m, At(0, 0), 0, xfR, r);
        CHECK(wm.normal.y == Approx(1).margin(1e-6));
        CHECK(wm.separations[0] == Approx(-overlap).margin(1e-6));
        CHECK(wm.separations[1] == Approx(-overlap).margin(1e-6));
        CHECK(std::min(wm.points[0].x, wm.points[1].x) == Approx(-0.25).margin(1e-6));
        CHECK(std::max(wm.points[0].x, wm.points[1].x) == Approx(0.75).margin(1e-6));
    }
    SECTION("a capsule lying across its top: two points under the caps, depth the overlap")
    {
        const Real rc = 0.25f, overlap = 0.01f;
        const Polygon capsule = MakeCapsulePolygon({{-0.3f, 0}, {0.3f, 0}, rc});
        const Transform xfCap = At(0, 0.5f + r + rc - overlap);
        CollideRoundedPolygons(m, rounded, At(0, 0), capsule, xfCap);
        REQUIRE(m.pointCount == 2);
        const WorldManifold wm = Evaluate(m, At(0, 0), r, xfCap, rc);
        CHECK(wm.normal.y == Approx(1).margin(1e-6));
        CHECK(wm.separations[0] == Approx(-overlap).margin(1e-6));
        CHECK(wm.separations[1] == Approx(-overlap).margin(1e-6));
    }
    SECTION("on a two-sided segment, and on a one-sided one from the front but not behind")
    {
        // The world collides a two-sided segment as a two-vertex polygon with its skin as its
        // radius (contact.cpp), a chain's segment through CollideChainSegmentAndRounded.
        const Real skin = 0.01f, overlap = 0.01f;
        const Transform xfR = At(0, 0.5f + r + skin - overlap);
        CollideRoundedPolygons(m, MakeCapsulePolygon({{-3, 0}, {3, 0}, skin}), At(0, 0), rounded,
                               xfR);
        REQUIRE(m.pointCount == 2);
        WorldManifold wm = Evaluate(m, At(0, 0), skin, xfR, r);
        CHECK(wm.normal.y == Approx(1).margin(1e-6));
        CHECK(wm.separations[0] == Approx(-overlap).margin(1e-6));
        // Listed right to left the solid side is up.
        const ChainSegment oneSided{{4, 0}, {{3, 0}, {-3, 0}, skin}, {-4, 0}};
        CollideChainSegmentAndRounded(m, oneSided, At(0, 0), rounded, xfR);
        REQUIRE(m.pointCount == 2);
        wm = Evaluate(m, At(0, 0), skin, xfR, r);
        CHECK(wm.normal.y == Approx(1).margin(1e-6));
        CHECK(wm.separations[0] == Approx(-overlap).margin(1e-6));
        CHECK(wm.separations[1] == Approx(-overlap).margin(1e-6));
        // Its centre just below the segment, overlapping it from behind: no contact.
        CollideChainSegmentAndRounded(m, oneSided, At(0, 0), rounded, At(0, -0.3f));
        CHECK(m.pointCount == 0);
    }
}

namespace
{

/// A static ground of `kind` whose surface (a sharp polygon's, a segment's and a chain's being
/// their skin above their core) is at y = 0 under x = ±1.5, flat there (the circles: one of
/// radius 20 under each of x = ±1.5, whose tops are there).
void AddGround(World& world, const std::string& kind)
{
    const Real skin = world.GetTolerances().polygonSkin;
    if (kind == "box")
    {
        const BodyId body = world.CreateBody({.position = {0, -1 - skin}});
        world.CreateShape(body, {}, MakeBox(20, 1));
    }
    else if (kind == "circle")
    {
        for (const Real x : {-1.5f, 1.5f})
        {
            const BodyId body = world.CreateBody({.position = {x, -20}});
            world.CreateShape(body, {}, Circle{{0, 0}, 20});
        }
    }
    else if (kind == "capsule")
    {
        const BodyId body = world.CreateBody({.position = {0, -0.5f}});
        world.CreateShape(body, {}, Capsule{{-10, 0}, {10, 0}, 0.5f});
    }
    else if (kind == "rounded box")
    {
        Polygon box = MakeBox(10, 0.4f);
        box.radius = 0.1f;
        const BodyId body = world.CreateBody({.position = {0, -0.5f}});
        world.CreateShape(body, {}, box);
    }
    else if (kind == "segment")
    {
        const BodyId body = world.CreateBody({.position = {0, -skin}});
        world.CreateShape(body, {}, Segment{{-10, 0}, {10, 0}});
    }
    else // chain, listed right to left: the solid side up, and a joint under each body
    {
        const BodyId body = world.CreateBody({.position = {0, -skin}});
        std::vector<Vec2> points;
        for (int x = 10; x >= -10; --x)
        {
            points.push_back({Real(x) + 0.5f, 0});
        }
        world.CreateChain(body, {}, Chain{.points = points});
    }
}

} // namespace

TEST_CASE("Capsules and rounded boxes rest at their radius on every kind of shape, under every "
          "back end",
          "[capsule][solver]")
{
    // The world's dispatch for each pair (contact.cpp), solved: each ground's surface is at
    // y = 0 under the bodies, so a capsule's axis rests at its radius (0.3) and a rounded box's
    // centre at its half height plus its rounding (0.25 + 0.15).
    const SolverKind kind = GENERATE(SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep);
    const std::string ground =
        GENERATE("box", "circle", "capsule", "rounded box", "segment", "chain");
    CAPTURE(SolverKindName(kind), ground);
    WorldDef def;
    def.solver.kind = kind;
    World world(def);
    AddGround(world, ground);
    const Real slop = world.GetTolerances().linearSlop;
    const BodyId capsule = world.CreateBody({.type = BodyType::Dynamic, .position = {-1.5f, 0.5f}});
    world.CreateShape(capsule, {}, Capsule{{-0.5f, 0}, {0.5f, 0}, 0.3f});
    Polygon rounded = MakeBox(0.4f, 0.25f);
    rounded.radius = 0.15f;
    const BodyId box = world.CreateBody({.type = BodyType::Dynamic, .position = {1.5f, 0.6f}});
    world.CreateShape(box, {}, rounded);
    StepSeconds(world, 3);
    // At rest the surfaces overlap by up to the linear slop (Box2D's allowed penetration; the
    // soft step corrects to it too).
    CHECK(world.GetPosition(capsule).y == Approx(0.3).margin(slop + 1e-3));
    CHECK(world.GetPosition(box).y == Approx(0.25 + 0.15).margin(slop + 1e-3));
    // Level, but for the same allowance at either end of the contact: the capsule's points are
    // 1 m apart (under its caps' centres), the rounded box's 0.8 m (under its core's corners),
    // so either may tilt by up to slop/span (on a chain, whose segments each hold their own
    // points, 0.002 rad is measured).
    CHECK(std::abs(world.GetAngle(capsule)) < slop / 1.0f);
    CHECK(std::abs(world.GetAngle(box)) < slop / 0.8f);
    CHECK(world.GetLinearVelocity(capsule).Length() < 1e-2);
    CHECK(world.GetLinearVelocity(box).Length() < 1e-2);
}

namespace
{

Sweep Straight(Vec2 from, Vec2 to)
{
    Sweep sweep;
    sweep.c0 = from;
    sweep.c = to;
    return sweep;
}

} // namespace

TEST_CASE("Time of impact: a capsule and a rounded box swept at a thin wall stop where "
          "TimeOfImpact's target says",
          "[capsule][toi]")
{
    // TimeOfImpact stops when the cores are target = rA + rB − 3·slop apart, within slop/4
    // (its documented tolerance). The wall: a 0.2 m thick box, skin 0.01, faces at x = ±0.1.
    Polygon wall = MakeBox(0.1f, 2);
    wall.radius = 0.01f;
    TOIInput input;
    input.proxyA = MakeProxy(wall);
    input.sweepA = Straight({0, 0}, {0, 0});
    input.linearSlop = 0.005f;
    SECTION("a capsule lying along the sweep: its front cap's centre stops target from the face")
    {
        input.proxyB = MakeProxy(Capsule{{-0.5f, 0}, {0.5f, 0}, 0.25f});
        input.sweepB = Straight({-5, 0}, {5, 0});
        const TOIOutput out = TimeOfImpact(input);
        REQUIRE(out.state == TOIOutput::State::Touching);
        const double target = 0.01 + 0.25 - 3 * 0.005;
        const double x = -5 + 10 * double(out.t);
        CHECK(x + 0.5 == Approx(-0.1 - target).margin(0.25 * 0.005 + 1e-5));
    }
    SECTION("a capsule standing across the sweep and turning a quarter turn on the way")
    {
        // Upright at the start, lying flat at the end: near the wall it lies almost along the
        // sweep, so its front cap leads; the impact is no later than the upright capsule's.
        input.proxyB = MakeProxy(Capsule{{0, -0.5f}, {0, 0.5f}, 0.25f});
        input.sweepB = Straight({-5, 0}, {5, 0});
        const TOIOutput upright = TimeOfImpact(input);
        REQUIRE(upright.state == TOIOutput::State::Touching);
        CHECK(-5 + 10 * double(upright.t) == Approx(-0.1 - 0.245).margin(0.25 * 0.005 + 1e-5));
        input.sweepB.a = Real(Pi() / 2);
        const TOIOutput turning = TimeOfImpact(input);
        REQUIRE(turning.state == TOIOutput::State::Touching);
        CHECK(turning.t < upright.t);
        // At the reported time the cores are within the target ± slop/4.
        const Transform xfB = input.sweepB.GetTransform(turning.t);
        DistanceInput d;
        d.proxyA = input.proxyA;
        d.proxyB = input.proxyB;
        d.transformA = At(0, 0);
        d.transformB = xfB;
        SimplexCache cache;
        const DistanceOutput apart = ShapeDistance(d, cache);
        CHECK(double(apart.distance) == Approx(0.245).margin(0.25 * 0.005 + 1e-5));
    }
    SECTION("a rounded box: its core's face stops target from the wall's")
    {
        Polygon box = MakeBox(0.3f, 0.3f);
        box.radius = 0.1f;
        input.proxyB = MakeProxy(box);
        input.sweepB = Straight({-5, 0.5f}, {5, 0.5f});
        const TOIOutput out = TimeOfImpact(input);
        REQUIRE(out.state == TOIOutput::State::Touching);
        const double target = 0.01 + 0.1 - 3 * 0.005;
        const double x = -5 + 10 * double(out.t);
        CHECK(x + 0.3 == Approx(-0.1 - target).margin(0.25 * 0.005 + 1e-5));
    }
}

TEST_CASE("Continuous collision: a fast capsule or rounded box does not pass a thin wall, under "
          "every back end",
          "[capsule][toi][solver]")
{
    // 120 m/s at 60 Hz is 2 m a step (the most a body may move in one step, Box2D's
    // b2_maxTranslation) against a 0.1 m wall: without continuous collision the bodies pass
    // straight through (checked), with it they stop at the wall's face.
    const SolverKind kind = GENERATE(SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep);
    const bool capsuleBody = GENERATE(true, false);
    CAPTURE(SolverKindName(kind), capsuleBody);
    for (const bool continuous : {true, false})
    {
        WorldDef def;
        def.solver.kind = kind;
        def.gravity = {0, 0};
        def.continuous = continuous;
        World world(def);
        const BodyId wall = world.CreateBody({});
        world.CreateShape(wall, {}, MakeBox(0.05f, 3)); // faces at x = ±0.05 (surface ±0.06)
        // Started so that no step ends touching the wall: 2 m steps from x = −5.3 end at
        // −1.3 and 0.7, where neither body reaches the wall's surface (x = ±0.06).
        const BodyId body = world.CreateBody(
            {.type = BodyType::Dynamic, .position = {-5.3f, 0}, .linearVelocity = {120, 0}});
        Real front = 0; // the body's surface ahead of its centre
        if (capsuleBody)
        {
            world.CreateShape(body, {}, Capsule{{-0.3f, 0}, {0.3f, 0}, 0.2f});
            front = 0.5f;
        }
        else
        {
            Polygon box = MakeBox(0.2f, 0.2f);
            box.radius = 0.1f;
            world.CreateShape(body, {}, box);
            front = 0.3f;
        }
        Real furthest = -kMaxReal;
        for (int i = 0; i < 30; ++i)
        {
            world.Step(Real(1) / Real(60));
            furthest = Max(furthest, world.GetPosition(body).x + front);
        }
        CAPTURE(continuous, furthest);
        if (continuous)
        {
            // Its surface never beyond the wall's by more than the time of impact's target
            // (3 slops) and a slop of solver overlap: 0.02 m past −0.06.
            CHECK(furthest < Real(-0.06 + 0.02));
            CHECK(world.GetPosition(body).x < 0);
        }
        else
        {
            CHECK(world.GetPosition(body).x > 10);
        }
    }
}

TEST_CASE("Ray casts hit a rounded box's faces and corner arcs where the geometry says",
          "[capsule][query]")
{
    // A 1 m square core at (2, 0) rounded by 0.1: faces at x = 2 ± 0.6, corner arcs of radius
    // 0.1 about the core's corners (2 ± 0.5, ±0.5).
    World world;
    Polygon box = MakeBox(0.5f, 0.5f);
    box.radius = 0.1f;
    const BodyId body = world.CreateBody({.position = {2, 0}});
    const ShapeId shape = world.CreateShape(body, {}, box);
    SECTION("the face: a ray from the right at y = 0.3 meets x = 2.6, normal +x")
    {
        const RayResult hit = world.CastRayClosest({5, 0.3f}, {-5, 0});
        REQUIRE(hit.hit);
        CHECK(hit.shape == shape);
        CHECK(hit.point.x == Approx(2.6).margin(1e-5));
        CHECK(hit.normal.x == Approx(1).margin(1e-5));
    }
    SECTION("a corner arc: at y = 0.55 the ray meets the arc at x = 2.5 + sqrt(0.01 - 0.0025)")
    {
        const RayResult hit = world.CastRayClosest({5, 0.55f}, {-5, 0});
        REQUIRE(hit.hit);
        const double dx = std::sqrt(0.01 - 0.0025);
        CHECK(hit.point.x == Approx(2.5 + dx).margin(1e-5));
        CHECK(hit.normal.x == Approx(dx / 0.1).margin(1e-4));
        CHECK(hit.normal.y == Approx(0.5).margin(1e-4));
    }
    SECTION("beyond the arc (y = 0.61) the ray misses, though it crosses the core's box")
    {
        CHECK_FALSE(world.CastRayClosest({5, 0.61f}, {-5, 0}).hit);
        // A point in the sharp box's corner but outside the arc is outside the shape.
        int found = 0;
        world.OverlapPoint({2.59f, 0.59f}, {}, [&](ShapeId) { return ++found, true; });
        CHECK(found == 0);
        world.OverlapPoint({2.55f, 0.55f}, {}, [&](ShapeId) { return ++found, true; });
        CHECK(found == 1);
    }
}

TEST_CASE("Shape casts with and onto rounded shapes stop where the surfaces meet, less the skin",
          "[capsule][query]")
{
    // ShapeCast (b2ShapeCast's rule): it stops once the cores are within
    // rA + rB − polygonSkin plus at most linearSlop/2, each radius at least the skin.
    World world;
    const Real skin = world.GetTolerances().polygonSkin;
    const double halfSlop = 0.5 * double(world.GetTolerances().linearSlop);
    SECTION("a circle dropped onto a lying capsule")
    {
        const BodyId ground = world.CreateBody({});
        world.CreateShape(ground, {}, Capsule{{-2, 0}, {2, 0}, 0.25f});
        const RayResult hit = world.CastShapeClosest(Circle{{0, 0}, 0.2f}, At(0.7f, 3), {0, -3});
        REQUIRE(hit.hit);
        const double y = 3 - 3 * double(hit.fraction);
        CHECK(y >= 0.45 - double(skin) - 1e-5);
        CHECK(y <= 0.45 - double(skin) + halfSlop + 1e-5);
        CHECK(hit.normal.y == Approx(1).margin(1e-5));
    }
    SECTION("a rounded box dropped onto a sharp box")
    {
        const BodyId ground = world.CreateBody({});
        world.CreateShape(ground, {}, MakeBox(5, 0.5f)); // core top 0.5, radius the skin
        Polygon rounded = MakeBox(0.4f, 0.2f);
        rounded.radius = 0.1f;
        const RayResult hit = world.CastShapeClosest(rounded, At(0, 3), {0, -3});
        REQUIRE(hit.hit);
        // Cores within 0.01 + 0.1 − 0.01 = 0.1: the centre at 0.5 + 0.2 + 0.1.
        const double y = 3 - 3 * double(hit.fraction);
        CHECK(y >= 0.8 - 1e-5);
        CHECK(y <= 0.8 + halfSlop + 1e-5);
    }
    SECTION("a capsule cast sideways onto a standing capsule meets it cap to side")
    {
        const BodyId post = world.CreateBody({});
        world.CreateShape(post, {}, Capsule{{0, -1}, {0, 1}, 0.2f});
        const RayResult hit =
            world.CastShapeClosest(Capsule{{-0.5f, 0}, {0.5f, 0}, 0.3f}, At(-4, 0.2f), {4, 0});
        REQUIRE(hit.hit);
        // The front cap's centre at x + 0.5 stops 0.2 + 0.3 − skin (+ up to slop/2) from x = 0.
        const double front = -4 + 4 * double(hit.fraction) + 0.5;
        CHECK(front <= -(0.5 - double(skin)) + 1e-5);
        CHECK(front >= -(0.5 - double(skin)) - halfSlop - 1e-5);
        CHECK(hit.normal.x == Approx(-1).margin(1e-5));
    }
}
