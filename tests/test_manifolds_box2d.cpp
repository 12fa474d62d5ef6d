// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Golden checks of the polygon manifold against Box2D 2.4.1 itself (libbox2d): for random
// convex polygons of 3 to 8 vertices and boxes at random, mostly overlapping poses,
// CollidePolygons must give b2CollidePolygons' manifold bit for bit (type, reference face,
// points, features), and WorldManifold must give b2WorldManifold's world points. The polygon
// search evaluates faces as SIMD lanes and pads triangles to four vertices (manifold_polygon.cpp),
// so each size pairing — box/box, triangle/box, triangle/triangle, large/small — is drawn often.
#ifndef MEFF_DOUBLE

#include "meff/collision.h"

#include <box2d/b2_collision.h>
#include <box2d/b2_polygon_shape.h>

#include <catch2/catch.hpp>

#include "box2d_shape_pair.h"
#include "test_random.h"

#include <memory>

using namespace meff;
using meff::test::Random;
using meff::test::ShapePair;

namespace
{

/// A polygon in both engines: a box (a third of the draws, sometimes offset and turned) or the
/// hull of 3 to 8 random points.
ShapePair RandomPolygon(Random& rng)
{
    if (rng.Index(3) == 0)
    {
        const float hx = rng.Uniform(0.1f, 1.0f);
        const float hy = rng.Uniform(0.1f, 1.0f);
        const bool offset = rng.Index(2) == 0;
        const b2Vec2 center =
            offset ? b2Vec2(rng.Uniform(-0.5f, 0.5f), rng.Uniform(-0.5f, 0.5f)) : b2Vec2(0, 0);
        const float angle = offset ? rng.Uniform(-3.0f, 3.0f) : 0.0f;
        auto shape = std::make_unique<b2PolygonShape>();
        shape->SetAsBox(hx, hy, center, angle);
        ShapePair pair;
        pair.type = ShapeType::Polygon;
        pair.polygon = MakeOffsetBox(hx, hy, {center.x, center.y}, angle);
        pair.polygon.radius = shape->m_radius;
        pair.box2d = std::move(shape);
        return pair;
    }
    for (;;)
    {
        ShapePair pair = meff::test::RandomShape(rng, {0.5f, 0.05f, 1.0f, 1.0f});
        if (pair.type == ShapeType::Polygon)
        {
            return pair;
        }
    }
}

} // namespace

TEST_CASE("CollidePolygons and WorldManifold agree bit for bit with Box2D 2.4.1",
          "[manifold][polygon][box2d]")
{
    Random rng(6);
    int touching = 0, flipped = 0, smallPairs = 0, triangles = 0;
    for (int trial = 0; trial < 20000; ++trial)
    {
        const ShapePair a = RandomPolygon(rng);
        const ShapePair b = RandomPolygon(rng);
        const Vec2 pA(rng.Uniform(-0.3f, 0.3f), rng.Uniform(-0.3f, 0.3f));
        const Vec2 pB(rng.Uniform(-1.5f, 1.5f), rng.Uniform(-1.5f, 1.5f));
        const float angleA = rng.Uniform(-3.2f, 3.2f);
        const float angleB = rng.Uniform(-3.2f, 3.2f);
        Transform xfA, xfB;
        xfA.Set(pA, angleA);
        xfB.Set(pB, angleB);
        b2Transform b2XfA, b2XfB;
        b2XfA.Set(b2Vec2(pA.x, pA.y), angleA);
        b2XfB.Set(b2Vec2(pB.x, pB.y), angleB);

        const auto* b2A = static_cast<const b2PolygonShape*>(a.box2d.get());
        const auto* b2B = static_cast<const b2PolygonShape*>(b.box2d.get());
        b2Manifold expected;
        b2CollidePolygons(&expected, b2A, b2XfA, b2B, b2XfB);
        Manifold m;
        CollidePolygons(m, a.polygon, xfA, b.polygon, xfB);

        INFO("trial " << trial << ": counts " << a.polygon.count << ", " << b.polygon.count);
        smallPairs += a.polygon.count <= 4 && b.polygon.count <= 4 ? 1 : 0;
        triangles += a.polygon.count == 3 || b.polygon.count == 3 ? 1 : 0;
        if (!meff::test::RequireSameManifold(m, expected))
        {
            continue;
        }
        ++touching;
        flipped += m.type == Manifold::Type::FaceB ? 1 : 0;

        const Real radiusA = a.polygon.radius, radiusB = b.polygon.radius;
        b2WorldManifold expectedWorld;
        expectedWorld.Initialize(&expected, b2XfA, radiusA, b2XfB, radiusB);
        WorldManifold world;
        world.Initialize(m, xfA, radiusA, xfB, radiusB);
        REQUIRE(world.normal.x == expectedWorld.normal.x);
        REQUIRE(world.normal.y == expectedWorld.normal.y);
        for (int i = 0; i < m.pointCount; ++i)
        {
            REQUIRE(world.points[i].x == expectedWorld.points[i].x);
            REQUIRE(world.points[i].y == expectedWorld.points[i].y);
            REQUIRE(world.separations[i] == expectedWorld.separations[i]);
        }
    }
    // The draw must reach every branch compared above: touching pairs with either reference
    // face, pairs of small polygons (the fixed-length vertex loop), and triangles (the padded
    // case).
    CHECK(touching > 2000);
    CHECK(flipped > 500);
    CHECK(smallPairs > 2000);
    CHECK(triangles > 2000);
}

#endif // MEFF_DOUBLE
