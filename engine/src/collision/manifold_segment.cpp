// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Contact manifolds of a segment against a circle and against a polygon, following
// b2CollideEdgeAndCircle and b2CollideEdgeAndPolygon of Box2D 2.4.1: a two-sided segment
// (m_oneSided == false), or a one-sided segment with ghost vertices (a chain's segment), whose
// back side is culled and whose contacts at the ends are skipped or snapped by the ghosts.
#include "collision/manifold_internal.h"

namespace meff
{

namespace
{

/// A segment as b2EdgeShape sees it: two-sided, or one-sided between its ghosts.
struct Edge
{
    Vec2 v1, v2;
    Real radius = 0;
    bool oneSided = false;
    Vec2 ghost1, ghost2; ///< the neighbours before v1 and after v2 (one-sided only)
};

Edge TwoSided(const Segment& segment)
{
    return {segment.point1, segment.point2, segment.radius, false, {}, {}};
}

Edge OneSided(const ChainSegment& chainSegment)
{
    const Segment& segment = chainSegment.segment;
    return {segment.point1, segment.point2,      segment.radius,
            true,           chainSegment.ghost1, chainSegment.ghost2};
}

void CollideEdgeAndCircle(Manifold& manifold, const Edge& edgeA, const Transform& xfA,
                          const Circle& circleB, const Transform& xfB)
{
    manifold.pointCount = 0;

    // The circle's centre in the segment's frame.
    const Vec2 q = MulT(xfA, Mul(xfB, circleB.center));

    const Vec2 a = edgeA.v1;
    const Vec2 b = edgeA.v2;
    const Vec2 e = b - a;

    // Right-hand normal of a -> b: the solid side of a one-sided segment. A two-sided one
    // only needs its sign relative to q.
    Vec2 n(e.y, -e.x);
    const Real offset = Dot(n, q - a);
    if (edgeA.oneSided && offset < 0)
    {
        return;
    }

    // Barycentric coordinates of q's projection on the segment (unnormalized).
    const Real u = Dot(e, b - q);
    const Real v = Dot(e, q - a);

    const Real radius = edgeA.radius + circleB.radius;

    ContactFeature feature;
    feature.indexB = 0;
    feature.typeB = ContactFeature::Vertex;

    ManifoldPoint& point = manifold.points[0];

    // Beyond end 1 (also taken by a zero-length segment, for which v == 0).
    if (v <= 0)
    {
        const Vec2 d = q - a;
        if (Dot(d, d) > radius * radius)
        {
            return;
        }
        // A circle over the previous segment's interior is that segment's contact.
        if (edgeA.oneSided && Dot(a - edgeA.ghost1, a - q) > 0)
        {
            return;
        }
        feature.indexA = 0;
        feature.typeA = ContactFeature::Vertex;
        manifold.pointCount = 1;
        manifold.type = Manifold::Type::Circles;
        manifold.localNormal = Vec2(0, 0);
        manifold.localPoint = a;
        point.id = feature;
        point.localPoint = circleB.center;
        point.normalImpulse = 0;
        point.tangentImpulse = 0;
        return;
    }

    // Beyond end 2.
    if (u <= 0)
    {
        const Vec2 d = q - b;
        if (Dot(d, d) > radius * radius)
        {
            return;
        }
        // Likewise over the next segment's interior.
        if (edgeA.oneSided && Dot(edgeA.ghost2 - b, q - b) > 0)
        {
            return;
        }
        feature.indexA = 1;
        feature.typeA = ContactFeature::Vertex;
        manifold.pointCount = 1;
        manifold.type = Manifold::Type::Circles;
        manifold.localNormal = Vec2(0, 0);
        manifold.localPoint = b;
        point.id = feature;
        point.localPoint = circleB.center;
        point.normalImpulse = 0;
        point.tangentImpulse = 0;
        return;
    }

    // Over the interior: u, v > 0 imply dot(e, e) > 0.
    const Real den = Dot(e, e);
    const Vec2 p = (Real(1) / den) * (u * a + v * b);
    const Vec2 d = q - p;
    if (Dot(d, d) > radius * radius)
    {
        return;
    }

    if (offset < 0)
    {
        n = Vec2(-n.x, -n.y);
    }
    n.Normalize();

    feature.indexA = 0;
    feature.typeA = ContactFeature::Face;
    manifold.pointCount = 1;
    manifold.type = Manifold::Type::FaceA;
    manifold.localNormal = n;
    manifold.localPoint = a;
    point.id = feature;
    point.localPoint = circleB.center;
    point.normalImpulse = 0;
    point.tangentImpulse = 0;
}

/// A candidate separating axis (b2EPAxis).
struct SeparatingAxis
{
    enum class Type
    {
        Unknown,
        SegmentFace,
        PolygonFace,
    };
    Vec2 normal;
    Type type = Type::Unknown;
    int index = -1;
    Real separation = -kMaxReal;
};

/// Polygon B expressed in the segment's frame.
struct PolygonInFrameA
{
    Vec2 vertices[kMaxPolygonVertices];
    Vec2 normals[kMaxPolygonVertices];
    int count = 0;
};

/// The reference face used for clipping.
struct ReferenceFace
{
    int i1 = 0;
    int i2 = 0;
    Vec2 v1, v2;
    Vec2 normal;
    Vec2 sideNormal1;
    Real sideOffset1 = 0;
    Vec2 sideNormal2;
    Real sideOffset2 = 0;
};

/// The better of the segment's two normals: the one along which the polygon is least deep.
SeparatingAxis ComputeSegmentSeparation(const PolygonInFrameA& polygonB, Vec2 v1, Vec2 normal1)
{
    SeparatingAxis axis;
    axis.type = SeparatingAxis::Type::SegmentFace;
    axis.index = -1;
    axis.separation = -kMaxReal;
    axis.normal = Vec2(0, 0);

    const Vec2 axes[2] = {normal1, -normal1};
    for (int j = 0; j < 2; ++j)
    {
        Real sj = kMaxReal;
        for (int i = 0; i < polygonB.count; ++i)
        {
            const Real si = Dot(axes[j], polygonB.vertices[i] - v1);
            if (si < sj)
            {
                sj = si;
            }
        }

        if (sj > axis.separation)
        {
            axis.index = j;
            axis.separation = sj;
            axis.normal = axes[j];
        }
    }
    return axis;
}

/// The polygon face, reversed, along which the segment is least deep.
SeparatingAxis ComputePolygonSeparation(const PolygonInFrameA& polygonB, Vec2 v1, Vec2 v2)
{
    SeparatingAxis axis;
    axis.type = SeparatingAxis::Type::Unknown;
    axis.index = -1;
    axis.separation = -kMaxReal;
    axis.normal = Vec2(0, 0);

    for (int i = 0; i < polygonB.count; ++i)
    {
        const Vec2 n = -polygonB.normals[i];
        const Real s1 = Dot(n, polygonB.vertices[i] - v1);
        const Real s2 = Dot(n, polygonB.vertices[i] - v2);
        const Real s = Min(s1, s2);

        if (s > axis.separation)
        {
            axis.type = SeparatingAxis::Type::PolygonFace;
            axis.index = i;
            axis.separation = s;
            axis.normal = n;
        }
    }
    return axis;
}

/// Box2D 2.4.1's smooth collision of a one-sided segment (the Gauss map test): a contact
/// whose normal lies in a convex neighbour's range of normals belongs to that neighbour and is
/// skipped (false); at a concave corner it is snapped to the segment's own face.
bool ApplyGhosts(const Edge& edgeA, Vec2 edge1, const SeparatingAxis& segmentAxis,
                 SeparatingAxis& primaryAxis)
{
    Vec2 edge0 = edgeA.v1 - edgeA.ghost1;
    edge0.Normalize();
    const Vec2 normal0(edge0.y, -edge0.x);
    const bool convex1 = Cross(edge0, edge1) >= 0;

    Vec2 edge2 = edgeA.ghost2 - edgeA.v2;
    edge2.Normalize();
    const Vec2 normal2(edge2.y, -edge2.x);
    const bool convex2 = Cross(edge1, edge2) >= 0;

    // Box2D's sinTol: how far (as a sine) a normal may lean past the neighbour's.
    constexpr Real kSinTolerance = Real(0.1);
    const bool side1 = Dot(primaryAxis.normal, edge1) <= 0;
    if (side1)
    {
        if (!convex1)
        {
            primaryAxis = segmentAxis;
            return true;
        }
        return !(Cross(primaryAxis.normal, normal0) > kSinTolerance);
    }
    if (!convex2)
    {
        primaryAxis = segmentAxis;
        return true;
    }
    return !(Cross(normal2, primaryAxis.normal) > kSinTolerance);
}

void CollideEdgeAndPolygon(Manifold& manifold, const Edge& edgeA, const Transform& xfA,
                           const Polygon& polygonB, const Transform& xfB)
{
    manifold.pointCount = 0;

    const Transform xf = MulT(xfA, xfB);

    const Vec2 v1 = edgeA.v1;
    const Vec2 v2 = edgeA.v2;

    Vec2 edge1 = v2 - v1;
    edge1.Normalize();

    // Right-hand normal of v1 -> v2: a one-sided segment ignores polygons whose centroid is
    // behind it.
    const Vec2 normal1(edge1.y, -edge1.x);
    if (edgeA.oneSided && Dot(normal1, Mul(xf, polygonB.centroid) - v1) < 0)
    {
        return;
    }

    PolygonInFrameA tempPolygonB;
    tempPolygonB.count = polygonB.count;
    for (int i = 0; i < polygonB.count; ++i)
    {
        tempPolygonB.vertices[i] = Mul(xf, polygonB.vertices[i]);
        tempPolygonB.normals[i] = Mul(xf.q, polygonB.normals[i]);
    }

    const Real radius = polygonB.radius + edgeA.radius;

    const SeparatingAxis segmentAxis = ComputeSegmentSeparation(tempPolygonB, v1, normal1);
    if (segmentAxis.separation > radius)
    {
        return;
    }

    const SeparatingAxis polygonAxis = ComputePolygonSeparation(tempPolygonB, v1, v2);
    if (polygonAxis.separation > radius)
    {
        return;
    }

    // Hysteresis against jitter: prefer the segment's face unless the polygon's is clearly
    // better (Box2D's k_relativeTol = 0.98 and k_absoluteTol = 0.001).
    constexpr Real kRelativeTolerance = Real(0.98);
    constexpr Real kAbsoluteTolerance = Real(0.001);

    SeparatingAxis primaryAxis;
    if (polygonAxis.separation - radius >
        kRelativeTolerance * (segmentAxis.separation - radius) + kAbsoluteTolerance)
    {
        primaryAxis = polygonAxis;
    }
    else
    {
        primaryAxis = segmentAxis;
    }
    if (edgeA.oneSided && !ApplyGhosts(edgeA, edge1, segmentAxis, primaryAxis))
    {
        return;
    }

    detail::ClipVertex clipPoints[2];
    ReferenceFace ref;
    if (primaryAxis.type == SeparatingAxis::Type::SegmentFace)
    {
        manifold.type = Manifold::Type::FaceA;

        // The incident face: the polygon face most anti-parallel to the segment normal.
        int bestIndex = 0;
        Real bestValue = Dot(primaryAxis.normal, tempPolygonB.normals[0]);
        for (int i = 1; i < tempPolygonB.count; ++i)
        {
            const Real value = Dot(primaryAxis.normal, tempPolygonB.normals[i]);
            if (value < bestValue)
            {
                bestValue = value;
                bestIndex = i;
            }
        }

        const int i1 = bestIndex;
        const int i2 = i1 + 1 < tempPolygonB.count ? i1 + 1 : 0;

        clipPoints[0].v = tempPolygonB.vertices[i1];
        clipPoints[0].id.indexA = 0;
        clipPoints[0].id.indexB = static_cast<std::uint8_t>(i1);
        clipPoints[0].id.typeA = ContactFeature::Face;
        clipPoints[0].id.typeB = ContactFeature::Vertex;

        clipPoints[1].v = tempPolygonB.vertices[i2];
        clipPoints[1].id.indexA = 0;
        clipPoints[1].id.indexB = static_cast<std::uint8_t>(i2);
        clipPoints[1].id.typeA = ContactFeature::Face;
        clipPoints[1].id.typeB = ContactFeature::Vertex;

        // Whichever side is hit, the reference face runs v1 -> v2 and its side planes are the
        // segment's ends, with no skin added (unlike polygon-polygon clipping).
        ref.i1 = 0;
        ref.i2 = 1;
        ref.v1 = v1;
        ref.v2 = v2;
        ref.normal = primaryAxis.normal;
        ref.sideNormal1 = -edge1;
        ref.sideNormal2 = edge1;
    }
    else
    {
        manifold.type = Manifold::Type::FaceB;

        // The segment is the incident face, taken from v2 to v1.
        clipPoints[0].v = v2;
        clipPoints[0].id.indexA = 1;
        clipPoints[0].id.indexB = static_cast<std::uint8_t>(primaryAxis.index);
        clipPoints[0].id.typeA = ContactFeature::Vertex;
        clipPoints[0].id.typeB = ContactFeature::Face;

        clipPoints[1].v = v1;
        clipPoints[1].id.indexA = 0;
        clipPoints[1].id.indexB = static_cast<std::uint8_t>(primaryAxis.index);
        clipPoints[1].id.typeA = ContactFeature::Vertex;
        clipPoints[1].id.typeB = ContactFeature::Face;

        ref.i1 = primaryAxis.index;
        ref.i2 = ref.i1 + 1 < tempPolygonB.count ? ref.i1 + 1 : 0;
        ref.v1 = tempPolygonB.vertices[ref.i1];
        ref.v2 = tempPolygonB.vertices[ref.i2];
        ref.normal = tempPolygonB.normals[ref.i1];

        // Side planes of a counter-clockwise face.
        ref.sideNormal1 = Vec2(ref.normal.y, -ref.normal.x);
        ref.sideNormal2 = -ref.sideNormal1;
    }

    ref.sideOffset1 = Dot(ref.sideNormal1, ref.v1);
    ref.sideOffset2 = Dot(ref.sideNormal2, ref.v2);

    detail::ClipVertex clipPoints1[2];
    detail::ClipVertex clipPoints2[2];

    if (detail::ClipSegmentToLine(clipPoints1, clipPoints, ref.sideNormal1, ref.sideOffset1,
                                  ref.i1) < 2)
    {
        return;
    }
    if (detail::ClipSegmentToLine(clipPoints2, clipPoints1, ref.sideNormal2, ref.sideOffset2,
                                  ref.i2) < 2)
    {
        return;
    }

    if (primaryAxis.type == SeparatingAxis::Type::SegmentFace)
    {
        manifold.localNormal = ref.normal;
        manifold.localPoint = ref.v1;
    }
    else
    {
        manifold.localNormal = polygonB.normals[ref.i1];
        manifold.localPoint = polygonB.vertices[ref.i1];
    }

    int pointCount = 0;
    for (int i = 0; i < 2; ++i)
    {
        const Real separation = Dot(ref.normal, clipPoints2[i].v - ref.v1);
        if (separation <= radius)
        {
            ManifoldPoint& point = manifold.points[pointCount];
            point.normalImpulse = 0;
            point.tangentImpulse = 0;
            if (primaryAxis.type == SeparatingAxis::Type::SegmentFace)
            {
                point.localPoint = MulT(xf, clipPoints2[i].v);
                point.id = clipPoints2[i].id;
            }
            else
            {
                // Box2D swaps A and B here although, for a point made by clipping, both
                // indices then name features of the polygon (its face and its vertex).
                point.localPoint = clipPoints2[i].v;
                point.id.typeA = clipPoints2[i].id.typeB;
                point.id.typeB = clipPoints2[i].id.typeA;
                point.id.indexA = clipPoints2[i].id.indexB;
                point.id.indexB = clipPoints2[i].id.indexA;
            }
            ++pointCount;
        }
    }

    manifold.pointCount = pointCount;
}

} // namespace

void CollideSegmentAndCircle(Manifold& manifold, const Segment& segmentA, const Transform& xfA,
                             const Circle& circleB, const Transform& xfB)
{
    CollideEdgeAndCircle(manifold, TwoSided(segmentA), xfA, circleB, xfB);
}

void CollideSegmentAndPolygon(Manifold& manifold, const Segment& segmentA, const Transform& xfA,
                              const Polygon& polygonB, const Transform& xfB)
{
    CollideEdgeAndPolygon(manifold, TwoSided(segmentA), xfA, polygonB, xfB);
}

void CollideChainSegmentAndCircle(Manifold& manifold, const ChainSegment& segmentA,
                                  const Transform& xfA, const Circle& circleB, const Transform& xfB)
{
    CollideEdgeAndCircle(manifold, OneSided(segmentA), xfA, circleB, xfB);
}

void CollideChainSegmentAndPolygon(Manifold& manifold, const ChainSegment& segmentA,
                                   const Transform& xfA, const Polygon& polygonB,
                                   const Transform& xfB)
{
    CollideEdgeAndPolygon(manifold, OneSided(segmentA), xfA, polygonB, xfB);
}

} // namespace meff
