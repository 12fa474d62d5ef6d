// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
#include "model/contact.h"

#include "model/shape.h"
#include "model/shape_proxy.h"

namespace meff::detail
{

bool ContactOrder(ShapeType typeA, ShapeType typeB, bool& swap)
{
    // Segments and chain segments come first as shape A, then polygons and capsules, then
    // circles: a segment before a polygon, a polygon before a circle, as Box2D orders them.
    const auto rank = [](ShapeType t)
    {
        switch (t)
        {
        case ShapeType::Segment:
        case ShapeType::ChainSegment:
            return 0;
        case ShapeType::Polygon:
        case ShapeType::Capsule:
            return 1;
        case ShapeType::Circle:
            return 2;
        }
        return 3;
    };
    // Box2D registers no contact between edges and chains in any combination.
    const auto isSegment = [](ShapeType t)
    { return t == ShapeType::Segment || t == ShapeType::ChainSegment; };
    if (isSegment(typeA) && isSegment(typeB))
    {
        return false;
    }
    swap = rank(typeA) > rank(typeB);
    return true;
}

/// A (chain) segment against a polygon or capsule: Box2D 2.4.1's routines for a sharp
/// polygon, the rounded ones otherwise.
static void EvaluateSegment(Manifold& manifold, const Shape& a, const Transform& xfA,
                            const Shape& b, const Transform& xfB)
{
    if (a.type == ShapeType::Segment)
    {
        if (b.IsRounded())
        {
            const Segment& s = a.segment;
            CollideRoundedPolygons(manifold, MakeCapsulePolygon({s.point1, s.point2, s.radius}),
                                   xfA, b.polygon, xfB);
        }
        else
        {
            CollideSegmentAndPolygon(manifold, a.segment, xfA, b.polygon, xfB);
        }
    }
    else if (b.IsRounded())
    {
        CollideChainSegmentAndRounded(manifold, a.chainSegment, xfA, b.polygon, xfB);
    }
    else
    {
        CollideChainSegmentAndPolygon(manifold, a.chainSegment, xfA, b.polygon, xfB);
    }
}

static void Evaluate(Manifold& manifold, const Shape& a, const Transform& xfA, const Shape& b,
                     const Transform& xfB)
{
    switch (a.type)
    {
    case ShapeType::Circle:
        CollideCircles(manifold, a.circle, xfA, b.circle, xfB);
        return;
    case ShapeType::Polygon:
    case ShapeType::Capsule:
        // Box2D 2.4.1's polygon-circle routine is exact for any radius (its vertex regions),
        // so a capsule or rounded polygon uses it too.
        if (b.type == ShapeType::Circle)
        {
            CollidePolygonAndCircle(manifold, a.polygon, xfA, b.circle, xfB);
        }
        else if (a.IsRounded() || b.IsRounded())
        {
            CollideRoundedPolygons(manifold, a.polygon, xfA, b.polygon, xfB);
        }
        else
        {
            CollidePolygons(manifold, a.polygon, xfA, b.polygon, xfB);
        }
        return;
    case ShapeType::Segment:
        if (b.type == ShapeType::Circle)
        {
            CollideSegmentAndCircle(manifold, a.segment, xfA, b.circle, xfB);
        }
        else
        {
            EvaluateSegment(manifold, a, xfA, b, xfB);
        }
        return;
    case ShapeType::ChainSegment:
        if (b.type == ShapeType::Circle)
        {
            CollideChainSegmentAndCircle(manifold, a.chainSegment, xfA, b.circle, xfB);
        }
        else
        {
            EvaluateSegment(manifold, a, xfA, b, xfB);
        }
        return;
    }
}

bool UpdateManifold(Contact& contact, const Shape& shapeA, const Transform& xfA,
                    const Shape& shapeB, const Transform& xfB)
{
    const Manifold oldManifold = contact.manifold;
    Manifold& manifold = contact.manifold;
    if (shapeA.type == ShapeType::Polygon && shapeB.type == ShapeType::Polygon && !shapeA.rounded &&
        !shapeB.rounded)
    {
        // Box2D 2.4.1's CollidePolygons, but the face that separated the pair at the last update
        // is tested first: most of a crowd's pairs are apart, and stay apart along the same face
        // from step to step (exact, so Box2D's back end uses it too).
        CollidePolygons(manifold, shapeA.polygon, xfA, shapeB.polygon, xfB, contact.separatingFace);
    }
    else
    {
        Evaluate(manifold, shapeA, xfA, shapeB, xfB);
    }

    // Warm starting: a point keeps the impulses of last step's point with the same features.
    for (int i = 0; i < manifold.pointCount; ++i)
    {
        ManifoldPoint& point = manifold.points[i];
        point.normalImpulse = 0;
        point.tangentImpulse = 0;
        const std::uint32_t key = point.id.Key();
        for (int j = 0; j < oldManifold.pointCount; ++j)
        {
            if (oldManifold.points[j].id.Key() == key)
            {
                point.normalImpulse = oldManifold.points[j].normalImpulse;
                point.tangentImpulse = oldManifold.points[j].tangentImpulse;
                break;
            }
        }
    }
    if (manifold.pointCount == 0)
    {
        contact.rollingImpulse = 0; // apart: nothing to warm start when they touch again
    }
    return manifold.pointCount > 0;
}

bool UpdateSensorOverlap(Contact& contact, const Shape& shapeA, const Transform& xfA,
                         const Shape& shapeB, const Transform& xfB)
{
    contact.manifold.pointCount = 0;
    return TestOverlap(MakeProxy(shapeA), xfA, MakeProxy(shapeB), xfB);
}

} // namespace meff::detail
