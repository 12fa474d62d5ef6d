#include "dynamics/contact.h"

#include "collision/distance.h"
#include "dynamics/shape.h"

namespace meff::detail
{

bool ContactOrder(ShapeType typeA, ShapeType typeB, bool& swap)
{
    // Shape type values rank the "primary" shape of a pair: segments (1, and chain segments,
    // 3) and polygons (2) come before circles (0) as shape A, a segment before a polygon.
    const auto rank = [](ShapeType t)
    {
        switch (t)
        {
        case ShapeType::Segment:
        case ShapeType::ChainSegment:
            return 0;
        case ShapeType::Polygon:
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

static void Evaluate(Manifold& manifold, const Shape& a, const Transform& xfA, const Shape& b,
                     const Transform& xfB)
{
    switch (a.type)
    {
    case ShapeType::Circle:
        CollideCircles(manifold, a.circle, xfA, b.circle, xfB);
        return;
    case ShapeType::Polygon:
        if (b.type == ShapeType::Circle)
        {
            CollidePolygonAndCircle(manifold, a.polygon, xfA, b.circle, xfB);
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
            CollideSegmentAndPolygon(manifold, a.segment, xfA, b.polygon, xfB);
        }
        return;
    case ShapeType::ChainSegment:
        if (b.type == ShapeType::Circle)
        {
            CollideChainSegmentAndCircle(manifold, a.chainSegment, xfA, b.circle, xfB);
        }
        else
        {
            CollideChainSegmentAndPolygon(manifold, a.chainSegment, xfA, b.polygon, xfB);
        }
        return;
    }
}

bool UpdateManifold(Contact& contact, const Shape& shapeA, const Transform& xfA,
                    const Shape& shapeB, const Transform& xfB)
{
    const Manifold oldManifold = contact.manifold;
    Manifold& manifold = contact.manifold;
    Evaluate(manifold, shapeA, xfA, shapeB, xfB);

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
    return manifold.pointCount > 0;
}

bool UpdateSensorOverlap(Contact& contact, const Shape& shapeA, const Transform& xfA,
                         const Shape& shapeB, const Transform& xfB)
{
    contact.manifold.pointCount = 0;
    return TestOverlap(MakeProxy(shapeA), xfA, MakeProxy(shapeB), xfB);
}

} // namespace meff::detail
