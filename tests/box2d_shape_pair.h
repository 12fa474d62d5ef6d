// Random shapes built identically in meff and in Box2D 2.4.1, for golden tests that compare
// distance, shape cast and time of impact between the engines.
#pragma once

#ifndef MEFF_DOUBLE

#include "meff/collision.h"
#include "meff/distance.h"
#include "meff/error.h"

#include <box2d/b2_circle_shape.h>
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

} // namespace meff::test

#endif
