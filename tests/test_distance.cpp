// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// GJK distance, overlap and shape cast (meff/distance.h): analytic cases, and golden checks
// against Box2D 2.4.1 itself (libbox2d): for random pairs of circles, polygons and segments at
// random poses, b2Distance, b2TestOverlap and b2ShapeCast must give bit-identical results.
#include "meff/distance.h"
#include "meff/error.h"

#include <box2d/b2_circle_shape.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_distance.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_polygon_shape.h>

#include <catch2/catch.hpp>

#include "box2d_shape_pair.h"
#include "test_random.h"

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

using namespace meff;

namespace
{

Transform MakeTransform(Vec2 p, Real angle)
{
    Transform xf;
    xf.Set(p, angle);
    return xf;
}

} // namespace

TEST_CASE("ShapeDistance of two circles is centre distance minus radii", "[distance]")
{
    DistanceInput input;
    input.proxyA = MakeProxy(Circle{{0, 0}, Real(0.5)});
    input.proxyB = MakeProxy(Circle{{0, 0}, Real(0.25)});
    input.transformA = MakeTransform({1, 1}, 0);
    input.transformB = MakeTransform({4, 5}, Real(0.3));
    input.useRadii = true;
    SimplexCache cache;
    const DistanceOutput out = ShapeDistance(input, cache);
    CHECK(out.distance == Approx(5 - 0.75).epsilon(1e-6));
    CHECK(out.pointA.x == Approx(1 + 0.5 * 0.6).epsilon(1e-6));
    CHECK(out.pointA.y == Approx(1 + 0.5 * 0.8).epsilon(1e-6));
    CHECK(out.pointB.x == Approx(4 - 0.25 * 0.6).epsilon(1e-6));
    CHECK(out.pointB.y == Approx(5 - 0.25 * 0.8).epsilon(1e-6));
    CHECK(cache.count == 1);

    input.useRadii = false;
    SimplexCache cold;
    CHECK(ShapeDistance(input, cold).distance == Approx(5).epsilon(1e-6));
}

TEST_CASE("ShapeDistance of two boxes, face to face and corner to corner", "[distance]")
{
    Polygon box = MakeBox(1, 1);
    box.radius = 0;
    DistanceInput input;
    input.proxyA = MakeProxy(box);
    input.proxyB = MakeProxy(box);
    input.transformA = MakeTransform({0, 0}, 0);
    input.transformB = MakeTransform({3, Real(0.5)}, 0);
    SimplexCache cache;
    DistanceOutput out = ShapeDistance(input, cache);
    CHECK(out.distance == Approx(1).epsilon(1e-6));
    CHECK(out.pointA.x == Approx(1).epsilon(1e-6));
    CHECK(out.pointB.x == Approx(2).epsilon(1e-6));

    // B turned 45° (corners on its axes at ±√2): its edge x + y = 6 + √2 faces A's corner
    // (1, 1), at a distance of (4 + √2)/√2 = 1 + 2√2 along the diagonal.
    const Real h = std::sqrt(Real(2));
    input.transformB = MakeTransform({3 + h, 3 + h}, kPi / 4);
    cache = {};
    out = ShapeDistance(input, cache);
    CHECK(out.pointA.x == Approx(1).epsilon(1e-5));
    CHECK(out.pointA.y == Approx(1).epsilon(1e-5));
    CHECK(out.pointB.x == Approx(out.pointB.y).epsilon(1e-5));
    CHECK(out.distance == Approx(1 + 2 * std::sqrt(2.0)).epsilon(1e-5));
    CHECK(cache.count == 2);
}

TEST_CASE("TestOverlap of shapes, radii included", "[distance]")
{
    const DistanceProxy circle = MakeProxy(Circle{{0, 0}, Real(0.5)});
    Polygon box = MakeBox(1, 1);
    box.radius = Real(0.01);
    const DistanceProxy boxProxy = MakeProxy(box);
    const DistanceProxy segment = MakeProxy(Segment{{-1, 0}, {1, 0}, Real(0.01)});

    CHECK(TestOverlap(circle, MakeTransform({1.4f, 0}, 0), boxProxy, MakeTransform({0, 0}, 0)));
    CHECK_FALSE(
        TestOverlap(circle, MakeTransform({1.6f, 0}, 0), boxProxy, MakeTransform({0, 0}, 0)));
    CHECK(TestOverlap(segment, MakeTransform({0, 0}, 0), circle, MakeTransform({0, 0.5f}, 0)));
    CHECK_FALSE(
        TestOverlap(segment, MakeTransform({0, 0}, 0), circle, MakeTransform({0, 0.52f}, 0)));
    // Deep overlap (the origin inside the Minkowski difference).
    CHECK(TestOverlap(boxProxy, MakeTransform({0, 0}, 0), boxProxy, MakeTransform({0.3f, 0}, 1)));
}

TEST_CASE("ShapeCast of a circle onto a box", "[distance][shape_cast]")
{
    ShapeCastInput input;
    Polygon box = MakeBox(1, 1);
    input.proxyA = MakeProxy(box);
    input.proxyB = MakeProxy(Circle{{0, 0}, Real(0.5)});
    input.transformA = MakeTransform({0, 0}, 0);
    input.transformB = MakeTransform({-5, 0}, 0);
    input.translationB = {10, 0};
    ShapeCastOutput out;
    REQUIRE(ShapeCast(input, out));
    // The cores stop ~0.5 + skin apart: the circle's centre at x ≈ −1.5.
    CHECK(double(-5 + 10 * out.lambda) == Approx(-1.5).margin(0.01));
    CHECK(out.normal.x == Approx(-1).margin(1e-5));
    CHECK(out.point.x == Approx(-1).margin(0.02));

    input.translationB = {0, 10}; // parallel to the box: never hits
    CHECK_FALSE(ShapeCast(input, out));
}

#ifndef MEFF_DOUBLE

namespace
{

using meff::test::Random;

using meff::test::ShapePair;

/// Random shapes at this test's sizes (see box2d_shape_pair.h).
ShapePair RandomShape(Random& rng)
{
    return meff::test::RandomShape(rng, {0.5f, 0.05f, 1.0f, 1.0f});
}

using meff::test::Pose;
using meff::test::RandomPose;

b2Vec2 ToB2(Vec2 v)
{
    return {v.x, v.y};
}

} // namespace

TEST_CASE("ShapeDistance agrees bit for bit with Box2D 2.4.1's b2Distance", "[distance][box2d]")
{
    Random rng(2024);
    int overlapping = 0, cached = 0;
    for (int trial = 0; trial < 3000; ++trial)
    {
        const ShapePair a = RandomShape(rng);
        const ShapePair b = RandomShape(rng);
        const Pose poseA = RandomPose(rng, 1.5f);
        Pose poseB = RandomPose(rng, 3.0f);
        const bool useRadii = rng.Index(2) == 0;

        b2DistanceInput b2Input;
        b2Input.proxyA.Set(a.box2d.get(), 0);
        b2Input.proxyB.Set(b.box2d.get(), 0);
        b2Input.transformA = poseA.box2d;
        b2Input.transformB = poseB.box2d;
        b2Input.useRadii = useRadii;
        DistanceInput input;
        input.proxyA = a.proxy;
        input.proxyB = b.proxy;
        input.transformA = poseA.meff;
        input.transformB = poseB.meff;
        input.useRadii = useRadii;

        b2SimplexCache b2Cache;
        b2Cache.count = 0;
        SimplexCache cache;
        // A cold query, then a warm one from its cache at a slightly moved pose.
        for (int pass = 0; pass < 2; ++pass)
        {
            b2DistanceOutput b2Out;
            b2Distance(&b2Out, &b2Cache, &b2Input);
            const DistanceOutput out = ShapeDistance(input, cache);
            INFO("trial " << trial << " pass " << pass);
            REQUIRE(out.distance == b2Out.distance);
            REQUIRE(out.pointA.x == b2Out.pointA.x);
            REQUIRE(out.pointA.y == b2Out.pointA.y);
            REQUIRE(out.pointB.x == b2Out.pointB.x);
            REQUIRE(out.pointB.y == b2Out.pointB.y);
            REQUIRE(out.iterations == b2Out.iterations);
            REQUIRE(cache.count == b2Cache.count);
            REQUIRE(cache.metric == b2Cache.metric);
            for (int i = 0; i < cache.count; ++i)
            {
                REQUIRE(cache.indexA[i] == b2Cache.indexA[i]);
                REQUIRE(cache.indexB[i] == b2Cache.indexB[i]);
            }
            overlapping += out.distance == 0 ? 1 : 0;
            cached += pass == 1 && cache.count > 1 ? 1 : 0;

            const Vec2 shift{rng.Uniform(-0.05f, 0.05f), rng.Uniform(-0.05f, 0.05f)};
            const float angle = poseB.meff.q.GetAngle() + rng.Uniform(-0.05f, 0.05f);
            const Vec2 p = poseB.meff.p + shift;
            poseB.meff.Set(p, angle);
            poseB.box2d.Set(ToB2(p), angle);
            input.transformB = poseB.meff;
            b2Input.transformB = poseB.box2d;
        }

        const bool overlap = TestOverlap(a.proxy, poseA.meff, b.proxy, poseB.meff);
        REQUIRE(overlap ==
                b2TestOverlap(a.box2d.get(), 0, b.box2d.get(), 0, poseA.box2d, poseB.box2d));
    }
    // The sample exercises both outcomes and the warm-started path.
    CHECK(overlapping > 100);
    CHECK(cached > 100);
}

TEST_CASE("ShapeCast agrees bit for bit with Box2D 2.4.1's b2ShapeCast", "[distance][box2d]")
{
    Random rng(77);
    int hits = 0;
    for (int trial = 0; trial < 3000; ++trial)
    {
        const ShapePair a = RandomShape(rng);
        const ShapePair b = RandomShape(rng);
        const Pose poseA = RandomPose(rng, 1.0f);
        const Pose poseB = RandomPose(rng, 5.0f);
        // Mostly towards A, so that many casts hit.
        const Vec2 target{rng.Uniform(-2, 2), rng.Uniform(-2, 2)};
        const Vec2 translation = rng.Uniform(0.5f, 2.5f) * (target - poseB.meff.p);

        b2ShapeCastInput b2Input;
        b2Input.proxyA.Set(a.box2d.get(), 0);
        b2Input.proxyB.Set(b.box2d.get(), 0);
        b2Input.transformA = poseA.box2d;
        b2Input.transformB = poseB.box2d;
        b2Input.translationB = ToB2(translation);
        ShapeCastInput input;
        input.proxyA = a.proxy;
        input.proxyB = b.proxy;
        input.transformA = poseA.meff;
        input.transformB = poseB.meff;
        input.translationB = translation;

        b2ShapeCastOutput b2Out;
        const bool b2Hit = b2ShapeCast(&b2Out, &b2Input);
        ShapeCastOutput out;
        const bool hit = ShapeCast(input, out);
        INFO("trial " << trial);
        REQUIRE(hit == b2Hit);
        REQUIRE(out.iterations == b2Out.iterations);
        REQUIRE(out.lambda == b2Out.lambda);
        REQUIRE(out.normal.x == b2Out.normal.x);
        REQUIRE(out.normal.y == b2Out.normal.y);
        REQUIRE(out.point.x == b2Out.point.x);
        REQUIRE(out.point.y == b2Out.point.y);
        hits += hit ? 1 : 0;
    }
    CHECK(hits > 300);
}

#endif // MEFF_DOUBLE
