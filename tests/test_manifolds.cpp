// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Contact manifolds (engine/src/collision/manifold_*.cpp, world_manifold.cpp).
//
// Every case is checked through WorldManifold: point count, normal (unit, from A to B),
// separations, and the feature ids Box2D 2.4.1 would give. Expected values are worked out by
// hand from the geometry in each comment.
//
// Tolerance: coordinates are at most a few metres and each reported value comes from ~10-30
// float operations (relative rounding 6e-8 each), so errors are ~1e-6 m; kTol = 1e-5 m is ten
// times that and still a thousand times smaller than the 0.01 m skin, so a wrong feature, side
// or missing skin term cannot pass.
#include "collision/manifold_internal.h"
#include "meff/collision.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace meff;

namespace
{

constexpr double kTol = 1e-5;
constexpr Real kSkin = Real(0.01); // what the world sets Polygon::radius and Segment::radius to

Transform Xf(Real x, Real y, Real angle = 0)
{
    Transform xf;
    xf.Set(Vec2(x, y), angle);
    return xf;
}

Polygon Box(Real hx, Real hy)
{
    Polygon p = MakeBox(hx, hy);
    p.radius = kSkin;
    return p;
}

ContactFeature Feature(int indexA, int indexB, int typeA, int typeB)
{
    ContactFeature f;
    f.indexA = std::uint8_t(indexA);
    f.indexB = std::uint8_t(indexB);
    f.typeA = std::uint8_t(typeA);
    f.typeB = std::uint8_t(typeB);
    return f;
}

constexpr int V = ContactFeature::Vertex;
constexpr int F = ContactFeature::Face;

std::vector<std::uint32_t> SortedKeys(const Manifold& m)
{
    std::vector<std::uint32_t> keys;
    for (int i = 0; i < m.pointCount; ++i)
    {
        keys.push_back(m.points[i].id.Key());
    }
    std::sort(keys.begin(), keys.end());
    return keys;
}

WorldManifold World(const Manifold& m, const Transform& xfA, Real rA, const Transform& xfB, Real rB)
{
    WorldManifold wm;
    wm.separations[0] = wm.separations[1] = 0;
    wm.Initialize(m, xfA, rA, xfB, rB);
    return wm;
}

void CheckNormal(const WorldManifold& wm, double nx, double ny)
{
    CHECK(wm.normal.x == Approx(nx).margin(kTol));
    CHECK(wm.normal.y == Approx(ny).margin(kTol));
}

void CheckPoint(Vec2 p, double x, double y)
{
    CHECK(p.x == Approx(x).margin(kTol));
    CHECK(p.y == Approx(y).margin(kTol));
}

} // namespace

// ---------------------------------------------------------------------------------------------
// Circles

TEST_CASE("CollideCircles", "[manifold][circle]")
{
    const Circle a{Vec2(0, 0), Real(0.5)};
    const Circle b{Vec2(0, 0), Real(0.25)};
    Manifold m;

    SECTION("separated")
    {
        m.pointCount = 2; // must be cleared
        CollideCircles(m, a, Xf(0, 0), b, Xf(Real(0.76), 0));
        CHECK(m.pointCount == 0);
    }
    SECTION("exactly touching counts as contact")
    {
        // distance^2 = 0.5625 = (0.5 + 0.25)^2 exactly in float; Box2D rejects only d^2 > r^2.
        CollideCircles(m, a, Xf(0, 0), b, Xf(Real(0.75), 0));
        REQUIRE(m.pointCount == 1);
        const WorldManifold wm = World(m, Xf(0, 0), a.radius, Xf(Real(0.75), 0), b.radius);
        CheckNormal(wm, 1, 0);
        CHECK(wm.separations[0] == Approx(0).margin(kTol));
        CheckPoint(wm.points[0], 0.5, 0);
    }
    SECTION("overlapping, with offset centres in turned bodies")
    {
        const Circle offA{Vec2(1, 0), Real(0.5)};
        const Circle offB{Vec2(0, Real(0.5)), Real(0.25)};
        const Transform xfA = Xf(-1, 0, 0);                      // centre at (0, 0)
        const Transform xfB = Xf(Real(0.9), Real(0.3), kPi / 2); // centre at (0.4, 0.3)
        CollideCircles(m, offA, xfA, offB, xfB);
        REQUIRE(m.pointCount == 1);
        CHECK(m.type == Manifold::Type::Circles);
        CHECK(m.localPoint == offA.center);
        CHECK(m.points[0].localPoint == offB.center);
        CHECK(m.points[0].id.Key() == 0);
        const WorldManifold wm = World(m, xfA, offA.radius, xfB, offB.radius);
        CheckNormal(wm, 0.8, 0.6); // (0.4, 0.3) / 0.5
        CHECK(wm.separations[0] == Approx(0.5 - 0.75).margin(kTol));
        // Midway between the surface points (0.4, 0.3) and (0.2, 0.15).
        CheckPoint(wm.points[0], 0.3, 0.225);
    }
    SECTION("coincident centres")
    {
        CollideCircles(m, a, Xf(1, 1), b, Xf(1, 1));
        REQUIRE(m.pointCount == 1);
        const WorldManifold wm = World(m, Xf(1, 1), a.radius, Xf(1, 1), b.radius);
        // No direction is defined: Box2D falls back to +x.
        CheckNormal(wm, 1, 0);
        CHECK(wm.separations[0] == Approx(-0.75).margin(kTol));
    }
    SECTION("feature key stays 0 under small motion")
    {
        CollideCircles(m, a, Xf(0, 0), b, Xf(Real(0.6), Real(0.1)));
        const auto before = SortedKeys(m);
        CollideCircles(m, a, Xf(0, 0), b, Xf(Real(0.601), Real(0.099), Real(0.01)));
        CHECK(SortedKeys(m) == before);
        CHECK(before == std::vector<std::uint32_t>{0});
    }
}

TEST_CASE("CollidePolygonAndCircle", "[manifold][circle][polygon]")
{
    const Polygon box = Box(Real(0.5), Real(0.5));
    const Circle ball{Vec2(0, 0), Real(0.25)};
    const Real r = kSkin + ball.radius; // 0.26
    Manifold m;

    SECTION("separated above a face")
    {
        CollidePolygonAndCircle(m, box, Xf(0, 0), ball, Xf(0, Real(0.5) + r + Real(0.001)));
        CHECK(m.pointCount == 0);
    }
    SECTION("separated beyond a corner though inside both face slabs' extensions")
    {
        // Centre (0.75, 0.75): 0.25 from both faces (< 0.26) but 0.354 from the corner.
        CollidePolygonAndCircle(m, box, Xf(0, 0), ball, Xf(Real(0.75), Real(0.75)));
        CHECK(m.pointCount == 0);
    }
    SECTION("face contact")
    {
        CollidePolygonAndCircle(m, box, Xf(0, 0), ball, Xf(Real(0.2), Real(0.7)));
        REQUIRE(m.pointCount == 1);
        CHECK(m.type == Manifold::Type::FaceA);
        CHECK(m.localNormal == Vec2(0, 1));
        CHECK(m.points[0].id.Key() == 0);
        const WorldManifold wm = World(m, Xf(0, 0), box.radius, Xf(Real(0.2), Real(0.7)), 0.25f);
        CheckNormal(wm, 0, 1);
        CHECK(wm.separations[0] == Approx(0.2 - 0.26).margin(kTol));
    }
    SECTION("corner contact")
    {
        const Transform xfB = Xf(Real(0.6), Real(0.6));
        CollidePolygonAndCircle(m, box, Xf(0, 0), ball, xfB);
        REQUIRE(m.pointCount == 1);
        // Box2D reports a vertex contact as FaceA with the corner as plane point.
        CHECK(m.type == Manifold::Type::FaceA);
        CHECK(m.localPoint == Vec2(Real(0.5), Real(0.5)));
        const WorldManifold wm = World(m, Xf(0, 0), box.radius, xfB, ball.radius);
        CheckNormal(wm, std::sqrt(0.5), std::sqrt(0.5));
        CHECK(wm.separations[0] == Approx(0.1 * std::sqrt(2.0) - 0.26).margin(kTol));
    }
    SECTION("deep: centre inside the polygon")
    {
        CollidePolygonAndCircle(m, box, Xf(0, 0), ball, Xf(Real(0.1), Real(0.3)));
        REQUIRE(m.pointCount == 1);
        const WorldManifold wm = World(m, Xf(0, 0), box.radius, Xf(Real(0.1), Real(0.3)), 0.25f);
        CheckNormal(wm, 0, 1); // the top face is the shallowest (0.2 deep)
        CHECK(wm.separations[0] == Approx(-0.2 - 0.26).margin(kTol));
    }
    SECTION("centre exactly at the centroid picks face 0")
    {
        // All four faces are 0.5 deep; the strict '>' keeps the first, face 0 (normal -y).
        CollidePolygonAndCircle(m, box, Xf(0, 0), ball, Xf(0, 0));
        REQUIRE(m.pointCount == 1);
        CHECK(m.localNormal == Vec2(0, -1));
        const WorldManifold wm = World(m, Xf(0, 0), box.radius, Xf(0, 0), ball.radius);
        CHECK(wm.separations[0] == Approx(-0.5 - 0.26).margin(kTol));
    }
    SECTION("turned polygon")
    {
        const Real angle = kPi / 6;
        const Transform xfA = Xf(1, 2, angle);
        // 0.6 along the box's turned +y face normal from its centre: 0.1 beyond the face.
        const Vec2 up(-std::sin(angle), std::cos(angle));
        const Transform xfB = Xf(1 + Real(0.6) * up.x, 2 + Real(0.6) * up.y);
        CollidePolygonAndCircle(m, box, xfA, ball, xfB);
        REQUIRE(m.pointCount == 1);
        const WorldManifold wm = World(m, xfA, box.radius, xfB, ball.radius);
        CheckNormal(wm, up.x, up.y);
        CHECK(wm.separations[0] == Approx(0.1 - 0.26).margin(kTol));
        CHECK(Dot(wm.normal, xfB.p - xfA.p) > 0);
    }
    SECTION("key stays 0 as the circle slides over a face")
    {
        CollidePolygonAndCircle(m, box, Xf(0, 0), ball, Xf(Real(0.2), Real(0.7)));
        const auto before = SortedKeys(m);
        CollidePolygonAndCircle(m, box, Xf(0, 0), ball, Xf(Real(0.21), Real(0.699)));
        CHECK(SortedKeys(m) == before);
    }
}

// ---------------------------------------------------------------------------------------------
// Polygons

TEST_CASE("CollidePolygons: box resting on a box", "[manifold][polygon]")
{
    const Polygon a = Box(Real(0.5), Real(0.5));
    const Polygon b = Box(Real(0.5), Real(0.5));
    Manifold m;

    SECTION("separated by more than the two skins")
    {
        CollidePolygons(m, a, Xf(0, 0), b, Xf(0, Real(1.03)));
        CHECK(m.pointCount == 0);
    }
    SECTION("touching within the skins")
    {
        const Transform xfB = Xf(0, Real(1.01)); // 0.01 gap, skins 0.02
        CollidePolygons(m, a, Xf(0, 0), b, xfB);
        REQUIRE(m.pointCount == 2);
        // Equal separations on both sides: A keeps the reference face (its top face, 2).
        CHECK(m.type == Manifold::Type::FaceA);
        CHECK(m.localNormal == Vec2(0, 1));
        // B's bottom face (0) is incident: its vertices 0 and 1.
        CHECK(m.points[0].id.Key() == Feature(2, 0, F, V).Key());
        CHECK(m.points[1].id.Key() == Feature(2, 1, F, V).Key());
        const WorldManifold wm = World(m, Xf(0, 0), a.radius, xfB, b.radius);
        CheckNormal(wm, 0, 1);
        for (int i = 0; i < 2; ++i)
        {
            CHECK(wm.separations[i] == Approx(0.01 - 0.02).margin(kTol));
            CHECK(wm.points[i].y == Approx(0.505).margin(kTol)); // midway between surfaces
        }
        CHECK(wm.points[0].x == Approx(-0.5).margin(kTol));
        CHECK(wm.points[1].x == Approx(0.5).margin(kTol));
    }
    SECTION("deep and offset: the incident face is clipped")
    {
        const Transform xfB = Xf(Real(0.3), Real(0.6)); // 0.4 deep, shifted right
        CollidePolygons(m, a, Xf(0, 0), b, xfB);
        REQUIRE(m.pointCount == 2);
        CHECK(m.type == Manifold::Type::FaceA);
        const WorldManifold wm = World(m, Xf(0, 0), a.radius, xfB, b.radius);
        CheckNormal(wm, 0, 1);
        CHECK(wm.separations[0] == Approx(-0.4 - 0.02).margin(kTol));
        CHECK(wm.separations[1] == Approx(-0.4 - 0.02).margin(kTol));
        // B's bottom face runs x = -0.2 .. 0.8; A's side plane with its skins is x = 0.52.
        CHECK(wm.points[0].x == Approx(-0.2).margin(kTol));
        CHECK(wm.points[1].x == Approx(0.52).margin(kTol));
        CHECK(m.points[0].id.Key() == Feature(2, 0, F, V).Key());
        // The clipped point: A's vertex 2 against B's face 0.
        CHECK(m.points[1].id.Key() == Feature(2, 0, V, F).Key());
    }
    SECTION("complete overlap")
    {
        CollidePolygons(m, a, Xf(1, 1), b, Xf(1, 1));
        REQUIRE(m.pointCount == 2);
        const WorldManifold wm = World(m, Xf(1, 1), a.radius, Xf(1, 1), b.radius);
        CHECK(wm.normal.Length() == Approx(1).margin(kTol));
        CHECK(wm.separations[0] == Approx(-1.02).margin(kTol));
        CHECK(wm.separations[1] == Approx(-1.02).margin(kTol));
    }
    SECTION("keys are stable under a small motion")
    {
        CollidePolygons(m, a, Xf(0, 0), b, Xf(Real(0.3), Real(0.99)));
        const auto before = SortedKeys(m);
        REQUIRE(before.size() == 2);
        CollidePolygons(m, a, Xf(0, 0), b, Xf(Real(0.302), Real(0.9895), Real(0.002)));
        CHECK(SortedKeys(m) == before);
    }
}

TEST_CASE("CollidePolygons: turned bodies", "[manifold][polygon]")
{
    const Polygon a = Box(1, Real(0.5));
    const Polygon b = Box(Real(0.5), Real(0.5));
    const Real angle = kPi / 6;
    const Vec2 up(-std::sin(angle), std::cos(angle));
    const Transform xfA = Xf(2, -1, angle);
    // B turned the same way, 1.005 along A's up axis: 0.005 gap between the faces.
    const Transform xfB = Xf(2 + Real(1.005) * up.x, -1 + Real(1.005) * up.y, angle);
    Manifold m;
    CollidePolygons(m, a, xfA, b, xfB);
    REQUIRE(m.pointCount == 2);
    const WorldManifold wm = World(m, xfA, a.radius, xfB, b.radius);
    CheckNormal(wm, up.x, up.y);
    CHECK(wm.separations[0] == Approx(0.005 - 0.02).margin(kTol));
    CHECK(wm.separations[1] == Approx(0.005 - 0.02).margin(kTol));
    CHECK(Dot(wm.normal, xfB.p - xfA.p) > 0);
}

TEST_CASE("CollidePolygons: B's face becomes the reference only when clearly better",
          "[manifold][polygon]")
{
    // Two unit boxes: B at rest, A above it turned by theta with its lowest corner 0.005 above
    // B. Along B's top face the separation is 0.005; along A's bottom face it is smaller by
    // h(1 - cos theta) (h = height of A's centre), so B's face is the better axis. Box2D keeps
    // A's face unless B's is better by more than k_tol = 0.0005.
    const Polygon a = Box(Real(0.5), Real(0.5));
    const Polygon b = Box(Real(0.5), Real(0.5));
    const Polygon wide = Box(3, Real(0.5));
    const auto collide = [&](Real theta, Manifold& m, Transform& xfA)
    {
        const Real h = Real(0.5) * (std::cos(theta) + std::sin(theta)) + Real(0.5) + Real(0.005);
        xfA = Xf(0, h, theta);
        CollidePolygons(m, a, xfA, b, Xf(0, 0));
    };
    Manifold m;
    Transform xfA;

    SECTION("difference 0.0003 < k_tol: A's face stays the reference")
    {
        collide(Real(0.0245), m, xfA);
        REQUIRE(m.pointCount >= 1);
        CHECK(m.type == Manifold::Type::FaceA);
        const WorldManifold wm = World(m, xfA, a.radius, Xf(0, 0), b.radius);
        // A's bottom face normal, turned by theta: from A (above) down towards B.
        CheckNormal(wm, std::sin(0.0245), -std::cos(0.0245));
        // B's top-left corner (vertex 3) under A's bottom face (0); the other end of B's top
        // face lies beyond the skins below A's tilted face and is dropped.
        CHECK(m.pointCount == 1);
        CHECK(m.points[0].id.Key() == Feature(0, 3, F, V).Key());
    }
    SECTION("difference 0.001 > k_tol: B's face is the reference, ids swapped back")
    {
        collide(Real(0.045), m, xfA);
        REQUIRE(m.pointCount >= 1);
        CHECK(m.type == Manifold::Type::FaceB);
        CHECK(m.localNormal == Vec2(0, 1));
        const WorldManifold wm = World(m, xfA, a.radius, Xf(0, 0), b.radius);
        CheckNormal(wm, 0, -1); // still from A to B
        // The lowest corner of A (vertex 0, turned left of the bottom) is 0.005 above B.
        CHECK(wm.separations[0] == Approx(0.005 - 0.02).margin(kTol));
        // Features name A first although B's face was the reference.
        CHECK(m.points[0].id.Key() == Feature(0, 2, V, F).Key());
    }
    SECTION("a diamond corner on a face")
    {
        // A turned 45 degrees with its bottom corner 0.05 into B: only B's face separates well.
        const Transform xfDiamond =
            Xf(Real(0.1), Real(0.5) + std::sqrt(Real(0.5)) - Real(0.05), kPi / 4);
        CollidePolygons(m, a, xfDiamond, wide, Xf(0, 0));
        REQUIRE(m.pointCount == 1);
        CHECK(m.type == Manifold::Type::FaceB);
        CHECK(m.points[0].id.Key() == Feature(0, 2, V, F).Key());
        const WorldManifold wm = World(m, xfDiamond, a.radius, Xf(0, 0), wide.radius);
        CheckNormal(wm, 0, -1);
        CHECK(wm.separations[0] == Approx(-0.05 - 0.02).margin(kTol));
        CHECK(wm.points[0].x == Approx(0.1).margin(kTol));
    }
}

TEST_CASE("CollidePolygons: triangle corner into a box", "[manifold][polygon]")
{
    const std::vector<Vec2> points = {Vec2(-1, 0), Vec2(1, 0), Vec2(0, Real(-0.5))};
    Polygon wedge = MakePolygon(points); // apex down at (0, -0.5)
    wedge.radius = kSkin;
    const Polygon box = Box(2, Real(0.5));
    const Transform xfA = Xf(0, Real(0.95)); // apex 0.05 into the box's top face (y = 0.5)
    Manifold m;
    CollidePolygons(m, wedge, xfA, box, Xf(0, 0));
    REQUIRE(m.pointCount == 1);
    const WorldManifold wm = World(m, xfA, wedge.radius, Xf(0, 0), box.radius);
    CheckNormal(wm, 0, -1);
    CHECK(wm.separations[0] == Approx(-0.05 - 0.02).margin(kTol));
    CHECK(wm.points[0].x == Approx(0).margin(kTol));
}

// ---------------------------------------------------------------------------------------------
// Segments

TEST_CASE("CollideSegmentAndCircle", "[manifold][segment][circle]")
{
    const Segment ground{Vec2(-2, 0), Vec2(2, 0), kSkin};
    const Circle ball{Vec2(0, 0), Real(0.5)};
    const Real r = kSkin + ball.radius; // 0.51
    Manifold m;

    SECTION("separated")
    {
        CollideSegmentAndCircle(m, ground, Xf(0, 0), ball, Xf(0, r + Real(0.01)));
        CHECK(m.pointCount == 0);
        CollideSegmentAndCircle(m, ground, Xf(0, 0), ball, Xf(Real(2.6), 0));
        CHECK(m.pointCount == 0);
    }
    SECTION("face contact from above and from below (two-sided)")
    {
        CollideSegmentAndCircle(m, ground, Xf(0, 0), ball, Xf(Real(0.3), Real(0.4)));
        REQUIRE(m.pointCount == 1);
        CHECK(m.type == Manifold::Type::FaceA);
        CHECK(m.points[0].id.Key() == Feature(0, 0, F, V).Key());
        WorldManifold wm = World(m, Xf(0, 0), kSkin, Xf(Real(0.3), Real(0.4)), ball.radius);
        CheckNormal(wm, 0, 1);
        CHECK(wm.separations[0] == Approx(0.4 - 0.51).margin(kTol));
        CheckPoint(wm.points[0], 0.3, (0.01 + (0.4 - 0.5)) / 2);

        CollideSegmentAndCircle(m, ground, Xf(0, 0), ball, Xf(Real(0.3), Real(-0.4)));
        REQUIRE(m.pointCount == 1);
        wm = World(m, Xf(0, 0), kSkin, Xf(Real(0.3), Real(-0.4)), ball.radius);
        CheckNormal(wm, 0, -1);
        CHECK(wm.separations[0] == Approx(0.4 - 0.51).margin(kTol));
    }
    SECTION("beyond either end: a circles manifold at the end point")
    {
        CollideSegmentAndCircle(m, ground, Xf(0, 0), ball, Xf(Real(2.3), Real(0.2)));
        REQUIRE(m.pointCount == 1);
        CHECK(m.type == Manifold::Type::Circles);
        CHECK(m.localPoint == Vec2(2, 0));
        CHECK(m.points[0].id.Key() == Feature(1, 0, V, V).Key());
        WorldManifold wm = World(m, Xf(0, 0), kSkin, Xf(Real(2.3), Real(0.2)), ball.radius);
        const double d = std::sqrt(0.09 + 0.04);
        CheckNormal(wm, 0.3 / d, 0.2 / d);
        CHECK(wm.separations[0] == Approx(d - 0.51).margin(kTol));

        CollideSegmentAndCircle(m, ground, Xf(0, 0), ball, Xf(Real(-2.3), 0));
        REQUIRE(m.pointCount == 1);
        CHECK(m.localPoint == Vec2(-2, 0));
        CHECK(m.points[0].id.Key() == Feature(0, 0, V, V).Key());
        wm = World(m, Xf(0, 0), kSkin, Xf(Real(-2.3), 0), ball.radius);
        CheckNormal(wm, -1, 0);
    }
    SECTION("exactly touching an end counts")
    {
        const Segment bare{Vec2(-2, 0), Vec2(2, 0), 0};
        CollideSegmentAndCircle(m, bare, Xf(0, 0), ball, Xf(Real(2.5), 0)); // d^2 = r^2 = 0.25
        CHECK(m.pointCount == 1);
    }
    SECTION("turned segment")
    {
        const Real angle = kPi / 3;
        const Transform xfA = Xf(1, 1, angle);
        const Vec2 up(-std::sin(angle), std::cos(angle));
        const Vec2 along(std::cos(angle), std::sin(angle));
        const Vec2 c = xfA.p + Real(0.5) * along + Real(0.45) * up;
        CollideSegmentAndCircle(m, ground, xfA, ball, Xf(c.x, c.y));
        REQUIRE(m.pointCount == 1);
        const WorldManifold wm = World(m, xfA, kSkin, Xf(c.x, c.y), ball.radius);
        CheckNormal(wm, up.x, up.y);
        CHECK(wm.separations[0] == Approx(0.45 - 0.51).margin(kTol));
    }
    SECTION("centre exactly on the segment")
    {
        // The side is undecided (offset 0); Box2D keeps the right-hand normal of point1 ->
        // point2, here -y, so the circle is pushed down.
        CollideSegmentAndCircle(m, ground, Xf(0, 0), ball, Xf(Real(0.5), 0));
        REQUIRE(m.pointCount == 1);
        CHECK(m.localNormal == Vec2(0, -1));
        const WorldManifold wm = World(m, Xf(0, 0), kSkin, Xf(Real(0.5), 0), ball.radius);
        CHECK(wm.separations[0] == Approx(-0.51).margin(kTol));
    }
    SECTION("centre exactly on an end point")
    {
        CollideSegmentAndCircle(m, ground, Xf(0, 0), ball, Xf(-2, 0));
        REQUIRE(m.pointCount == 1);
        CHECK(m.type == Manifold::Type::Circles);
        const WorldManifold wm = World(m, Xf(0, 0), kSkin, Xf(-2, 0), ball.radius);
        CheckNormal(wm, 1, 0); // coincident centres fall back to +x
        CHECK(wm.separations[0] == Approx(-0.51).margin(kTol));
    }
    SECTION("zero-length segment behaves as a point")
    {
        const Segment dot{Vec2(1, 1), Vec2(1, 1), kSkin};
        CollideSegmentAndCircle(m, dot, Xf(0, 0), ball, Xf(Real(1.3), Real(1.4)));
        REQUIRE(m.pointCount == 1);
        CHECK(m.type == Manifold::Type::Circles);
        const WorldManifold wm = World(m, Xf(0, 0), kSkin, Xf(Real(1.3), Real(1.4)), ball.radius);
        CheckNormal(wm, 0.6, 0.8);
        CHECK(wm.separations[0] == Approx(0.5 - 0.51).margin(kTol));
    }
    SECTION("key stable while rolling along the face")
    {
        CollideSegmentAndCircle(m, ground, Xf(0, 0), ball, Xf(Real(0.3), Real(0.49)));
        const auto before = SortedKeys(m);
        CollideSegmentAndCircle(m, ground, Xf(0, 0), ball, Xf(Real(0.31), Real(0.495)));
        CHECK(SortedKeys(m) == before);
    }
}

TEST_CASE("CollideSegmentAndPolygon", "[manifold][segment][polygon]")
{
    const Segment ground{Vec2(-2, 0), Vec2(2, 0), kSkin};
    const Polygon box = Box(Real(0.5), Real(0.5));
    Manifold m;

    SECTION("separated")
    {
        CollideSegmentAndPolygon(m, ground, Xf(0, 0), box, Xf(0, Real(0.53)));
        CHECK(m.pointCount == 0);
        CollideSegmentAndPolygon(m, ground, Xf(0, 0), box, Xf(Real(2.53), 0));
        CHECK(m.pointCount == 0);
    }
    SECTION("resting on top within the skins")
    {
        const Transform xfB = Xf(0, Real(0.51));
        CollideSegmentAndPolygon(m, ground, Xf(0, 0), box, xfB);
        REQUIRE(m.pointCount == 2);
        CHECK(m.type == Manifold::Type::FaceA);
        CHECK(m.localNormal == Vec2(0, 1));
        CHECK(m.points[0].id.Key() == Feature(0, 0, F, V).Key());
        CHECK(m.points[1].id.Key() == Feature(0, 1, F, V).Key());
        const WorldManifold wm = World(m, Xf(0, 0), kSkin, xfB, box.radius);
        CheckNormal(wm, 0, 1);
        CHECK(wm.separations[0] == Approx(0.01 - 0.02).margin(kTol));
        CHECK(wm.separations[1] == Approx(0.01 - 0.02).margin(kTol));
        CheckPoint(wm.points[0], -0.5, 0.005);
        CheckPoint(wm.points[1], 0.5, 0.005);
    }
    SECTION("from below (two-sided)")
    {
        const Transform xfB = Xf(0, Real(-0.51));
        CollideSegmentAndPolygon(m, ground, Xf(0, 0), box, xfB);
        REQUIRE(m.pointCount == 2);
        CHECK(m.type == Manifold::Type::FaceA);
        const WorldManifold wm = World(m, Xf(0, 0), kSkin, xfB, box.radius);
        CheckNormal(wm, 0, -1);
        CHECK(wm.separations[0] == Approx(-0.01).margin(kTol));
    }
    SECTION("deep overlap")
    {
        const Transform xfB = Xf(Real(0.3), Real(0.2));
        CollideSegmentAndPolygon(m, ground, Xf(0, 0), box, xfB);
        REQUIRE(m.pointCount == 2);
        const WorldManifold wm = World(m, Xf(0, 0), kSkin, xfB, box.radius);
        CheckNormal(wm, 0, 1);
        CHECK(wm.separations[0] == Approx(-0.3 - 0.02).margin(kTol));
        CHECK(wm.separations[1] == Approx(-0.3 - 0.02).margin(kTol));
    }
    SECTION("box half over the segment's end: clipped at the bare end")
    {
        // Unlike polygon-polygon clipping, the segment's side planes get no skin: the second
        // point is clipped to x = 2 exactly, with feature (segment vertex 1, polygon face 0).
        const Transform xfB = Xf(2, Real(0.51));
        CollideSegmentAndPolygon(m, ground, Xf(0, 0), box, xfB);
        REQUIRE(m.pointCount == 2);
        CHECK(m.type == Manifold::Type::FaceA);
        const WorldManifold wm = World(m, Xf(0, 0), kSkin, xfB, box.radius);
        CheckNormal(wm, 0, 1);
        CHECK(wm.points[0].x == Approx(1.5).margin(kTol));
        CHECK(wm.points[1].x == Approx(2.0).margin(kTol));
        CHECK(m.points[0].id.Key() == Feature(0, 0, F, V).Key());
        CHECK(m.points[1].id.Key() == Feature(1, 0, V, F).Key());
    }
    SECTION("box beside the end: the polygon's face is the reference")
    {
        // The box's left face is 0.01 right of the end (2, 0) and its bottom level with the
        // segment: the polygon axis (0.01) beats the segment axis (0) by the hysteresis.
        const Transform xfB = Xf(Real(2.51), Real(0.5));
        CollideSegmentAndPolygon(m, ground, Xf(0, 0), box, xfB);
        REQUIRE(m.pointCount == 1);
        CHECK(m.type == Manifold::Type::FaceB);
        CHECK(m.localNormal == Vec2(-1, 0)); // the box's face 3, in the box's frame
        // Segment vertex 1 against box face 3, written as Box2D does: (face 3, vertex 1).
        CHECK(m.points[0].id.Key() == Feature(3, 1, F, V).Key());
        const WorldManifold wm = World(m, Xf(0, 0), kSkin, xfB, box.radius);
        CheckNormal(wm, 1, 0); // from the segment to the box
        CHECK(wm.separations[0] == Approx(0.01 - 0.02).margin(kTol));
        CheckPoint(wm.points[0], 2.005, 0);
    }
    SECTION("turned segment and box")
    {
        const Real angle = -kPi / 5;
        const Transform xfA = Xf(-1, 3, angle);
        const Vec2 up(-std::sin(angle), std::cos(angle));
        const Vec2 along(std::cos(angle), std::sin(angle));
        const Vec2 c = xfA.p + Real(-0.7) * along + Real(0.505) * up;
        const Transform xfB = Xf(c.x, c.y, angle);
        CollideSegmentAndPolygon(m, ground, xfA, box, xfB);
        REQUIRE(m.pointCount == 2);
        const WorldManifold wm = World(m, xfA, kSkin, xfB, box.radius);
        CheckNormal(wm, up.x, up.y);
        CHECK(wm.separations[0] == Approx(0.005 - 0.02).margin(kTol));
        CHECK(wm.separations[1] == Approx(0.005 - 0.02).margin(kTol));
    }
    SECTION("keys stable while sliding and rocking slightly")
    {
        CollideSegmentAndPolygon(m, ground, Xf(0, 0), box, Xf(Real(0.4), Real(0.505)));
        const auto before = SortedKeys(m);
        REQUIRE(before.size() == 2);
        CollideSegmentAndPolygon(m, ground, Xf(0, 0), box,
                                 Xf(Real(0.41), Real(0.503), Real(0.003)));
        CHECK(SortedKeys(m) == before);
    }
}

// ---------------------------------------------------------------------------------------------
// World manifold and clipping

TEST_CASE("WorldManifold leaves its fields alone for an empty manifold", "[manifold]")
{
    Manifold empty;
    empty.pointCount = 0;
    WorldManifold wm;
    wm.normal = Vec2(7, 8);
    wm.separations[0] = 9;
    wm.Initialize(empty, Xf(0, 0), 1, Xf(1, 0), 1);
    CHECK(wm.normal == Vec2(7, 8));
    CHECK(wm.separations[0] == 9);
}

TEST_CASE("ClipSegmentToLine", "[manifold]")
{
    detail::ClipVertex in[2];
    in[0].v = Vec2(-1, 0);
    in[0].id = Feature(4, 5, F, V);
    in[1].v = Vec2(3, 0);
    in[1].id = Feature(4, 6, F, V);
    detail::ClipVertex out[2];

    SECTION("straddling: the crossing point gets (vertex of A, face of B)")
    {
        REQUIRE(detail::ClipSegmentToLine(out, in, Vec2(1, 0), 1, 7) == 2);
        CHECK(out[0].v == Vec2(-1, 0));
        CHECK(out[0].id.Key() == in[0].id.Key());
        CheckPoint(out[1].v, 1, 0);
        CHECK(out[1].id.Key() == Feature(7, 5, V, F).Key());
    }
    SECTION("both inside, one exactly on the line")
    {
        REQUIRE(detail::ClipSegmentToLine(out, in, Vec2(1, 0), 3, 7) == 2);
        CHECK(out[1].v == Vec2(3, 0));
        CHECK(out[1].id.Key() == in[1].id.Key());
    }
    SECTION("both outside")
    {
        CHECK(detail::ClipSegmentToLine(out, in, Vec2(1, 0), -2, 7) == 0);
    }
}
