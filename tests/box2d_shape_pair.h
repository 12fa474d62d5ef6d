// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Random shapes and poses built identically in meff and in Box2D 2.4.1, for golden tests that
// compare distance, shape cast, time of impact and manifolds between the engines.
#pragma once

#ifndef MEFF_DOUBLE

#include "meff/collision.h"
#include "meff/distance.h"
#include "meff/error.h"

#include <box2d/b2_circle_shape.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_polygon_shape.h>

#include <catch2/catch.hpp>

#include "test_random.h"

#include <memory>
#include <vector>

namespace meff::test
{

/// One random shape in both engines.
struct ShapePair
{
    std::unique_ptr<b2Shape> box2d;
    DistanceProxy proxy;
    // The shape itself in meff (only the one `type` names is set).
    ShapeType type = ShapeType::Circle;
    Circle circle;
    Segment segment;
    Polygon polygon;
};

/// The ranges random shapes are drawn from (m).
struct ShapeSizes
{
    float centerRange; ///< circle centres within ±centerRange of the origin
    float minRadius;   ///< circle radius range
    float maxRadius;
    float polygonRange; ///< polygon points within ±polygonRange
};

/// A circle, a two-sided segment (ends within ±2 m) or the hull of 3 to 8 random points.
inline ShapePair RandomShape(Random& rng, const ShapeSizes& sizes)
{
    ShapePair pair;
    switch (rng.Index(3))
    {
    case 0:
    {
        auto circle = std::make_unique<b2CircleShape>();
        circle->m_p.Set(rng.Uniform(-sizes.centerRange, sizes.centerRange),
                        rng.Uniform(-sizes.centerRange, sizes.centerRange));
        circle->m_radius = rng.Uniform(sizes.minRadius, sizes.maxRadius);
        pair.type = ShapeType::Circle;
        pair.circle = Circle{{circle->m_p.x, circle->m_p.y}, circle->m_radius};
        pair.proxy = MakeProxy(pair.circle);
        pair.box2d = std::move(circle);
        break;
    }
    case 1:
    {
        auto edge = std::make_unique<b2EdgeShape>();
        const b2Vec2 v1(rng.Uniform(-2, 2), rng.Uniform(-2, 2));
        const b2Vec2 v2(rng.Uniform(-2, 2), rng.Uniform(-2, 2));
        edge->SetTwoSided(v1, v2);
        pair.type = ShapeType::Segment;
        pair.segment = Segment{{v1.x, v1.y}, {v2.x, v2.y}, edge->m_radius};
        pair.proxy = MakeProxy(pair.segment);
        pair.box2d = std::move(edge);
        break;
    }
    default:
    {
        // A hull of random points; the same points give the same hull in both engines.
        for (;;)
        {
            const int count = 3 + rng.Index(6);
            std::vector<Vec2> points(count);
            std::vector<b2Vec2> b2Points(count);
            for (int i = 0; i < count; ++i)
            {
                points[i] = {rng.Uniform(-sizes.polygonRange, sizes.polygonRange),
                             rng.Uniform(-sizes.polygonRange, sizes.polygonRange)};
                b2Points[i].Set(points[i].x, points[i].y);
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
            auto shape = std::make_unique<b2PolygonShape>();
            shape->Set(b2Points.data(), count);
            REQUIRE(shape->m_count == polygon.count);
            for (int i = 0; i < polygon.count; ++i)
            {
                REQUIRE(shape->m_vertices[i].x == polygon.vertices[i].x);
                REQUIRE(shape->m_vertices[i].y == polygon.vertices[i].y);
            }
            polygon.radius = shape->m_radius;
            pair.type = ShapeType::Polygon;
            pair.polygon = polygon;
            pair.proxy = MakeProxy(polygon);
            pair.box2d = std::move(shape);
            break;
        }
        break;
    }
    }
    return pair;
}

/// One pose in both engines.
struct Pose
{
    Transform meff;
    b2Transform box2d;
};

/// Position within ±range of the origin (m), angle within ±angleRange (rad).
inline Pose RandomPose(Random& rng, float range, float angleRange = 4)
{
    const Vec2 p{rng.Uniform(-range, range), rng.Uniform(-range, range)};
    const float angle = rng.Uniform(-angleRange, angleRange);
    Pose pose;
    pose.meff.Set(p, angle);
    pose.box2d.Set(b2Vec2(p.x, p.y), angle);
    return pose;
}

/// The transform equals Box2D's bit for bit.
inline void RequireSameTransform(const Transform& xf, const b2Transform& expected)
{
    REQUIRE(xf.p.x == expected.p.x);
    REQUIRE(xf.p.y == expected.p.y);
    REQUIRE(xf.q.s == expected.q.s);
    REQUIRE(xf.q.c == expected.q.c);
}

/// The manifold equals Box2D's bit for bit: type, normal, reference point, every point and its
/// feature key. Returns whether it has points.
inline bool RequireSameManifold(const Manifold& m, const b2Manifold& expected)
{
    REQUIRE(m.pointCount == expected.pointCount);
    if (m.pointCount == 0)
    {
        return false;
    }
    REQUIRE(static_cast<int>(m.type) == static_cast<int>(expected.type));
    REQUIRE(m.localNormal.x == expected.localNormal.x);
    REQUIRE(m.localNormal.y == expected.localNormal.y);
    REQUIRE(m.localPoint.x == expected.localPoint.x);
    REQUIRE(m.localPoint.y == expected.localPoint.y);
    for (int i = 0; i < m.pointCount; ++i)
    {
        REQUIRE(m.points[i].localPoint.x == expected.points[i].localPoint.x);
        REQUIRE(m.points[i].localPoint.y == expected.points[i].localPoint.y);
        REQUIRE(m.points[i].id.Key() == expected.points[i].id.key);
    }
    return true;
}

} // namespace meff::test

#endif
