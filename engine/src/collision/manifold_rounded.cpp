// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Manifolds between rounded polygons: capsules, polygons with a rounding radius, and segments
// meeting them. The algorithm is Box2D v3's (separating axes on the cores, reference-face
// clipping, and a single vertex-vertex point when the cores are apart at two corners), written
// for meff's local manifolds (FaceA, FaceB, Circles) so that every solver reads them as it
// reads Box2D 2.4.1's.
#include "collision/manifold_internal.h"

#include <cmath>
#include <utility>

namespace meff
{

namespace
{

using detail::ClipVertex;
using detail::kCollisionLinearSlop;

/// The largest separation of `other`'s vertices along `poly`'s face normals (both in one
/// frame): the separating-axis test over `poly`'s faces. Writes the face that gives it.
Real MaxFaceSeparation(const Polygon& poly, const Polygon& other, int& face)
{
    face = 0;
    Real best = -kMaxReal;
    for (int i = 0; i < poly.count; ++i)
    {
        Real deepest = kMaxReal;
        for (int j = 0; j < other.count; ++j)
        {
            deepest = Min(deepest, Dot(poly.normals[i], other.vertices[j] - poly.vertices[i]));
        }
        if (deepest > best)
        {
            best = deepest;
            face = i;
        }
    }
    return best;
}

/// The face of `poly` whose normal is most opposed to `normal`.
int IncidentFace(const Polygon& poly, Vec2 normal)
{
    int face = 0;
    Real least = kMaxReal;
    for (int i = 0; i < poly.count; ++i)
    {
        const Real d = Dot(normal, poly.normals[i]);
        if (d < least)
        {
            least = d;
            face = i;
        }
    }
    return face;
}

/// Closest points of segments p1q1 and p2q2 as fractions s (along the first) and t (along the
/// second), each clamped to [0, 1] so that an end is exactly 0 or 1 (the minimisation of
/// |p1 + s·d1 − p2 − t·d2|², Ericson, Real-Time Collision Detection, 5.1.9). Both segments are
/// longer than the weld tolerance (polygon edges, a capsule's core).
struct SegmentPair
{
    Real s = 0, t = 0, distanceSquared = 0;
};
SegmentPair ClosestOnSegments(Vec2 p1, Vec2 q1, Vec2 p2, Vec2 q2)
{
    const Vec2 d1 = q1 - p1;
    const Vec2 d2 = q2 - p2;
    const Vec2 r = p1 - p2;
    const Real a = Dot(d1, d1);
    const Real e = Dot(d2, d2);
    const Real b = Dot(d1, d2);
    const Real c = Dot(d1, r);
    const Real f = Dot(d2, r);
    const Real denominator = a * e - b * b; // ≥ 0; 0 when parallel
    SegmentPair pair;
    pair.s = denominator > 0 ? Clamp((b * f - c * e) / denominator, 0, 1) : Real(0);
    pair.t = (b * pair.s + f) / e;
    if (pair.t < 0)
    {
        pair.t = 0;
        pair.s = Clamp(-c / a, 0, 1);
    }
    else if (pair.t > 1)
    {
        pair.t = 1;
        pair.s = Clamp((b - c) / a, 0, 1);
    }
    pair.distanceSquared = DistanceSquared(p1 + pair.s * d1, p2 + pair.t * d2);
    return pair;
}

/// The incident edge of `inc` clipped to the side planes of `ref`'s face `refFace` (both
/// polygons in A's frame), as Box2D 2.4.1's b2CollidePolygons clips but at the face's own
/// ends, as Box2D v3 does (beyond them a rounded corner is met by the vertex-vertex point):
/// the points within totalRadius of the reference face, with their separations and features.
struct Clipped
{
    ClipVertex points[2];
    Real separations[2] = {0, 0};
    int count = 0;
    Vec2 normal{};     ///< the reference face's normal (A's frame)
    Vec2 planePoint{}; ///< the middle of the reference face (A's frame)
};
Clipped ClipToFace(const Polygon& ref, int refFace, const Polygon& inc, Real totalRadius)
{
    Clipped out;
    const int i1 = refFace;
    const int i2 = i1 + 1 < ref.count ? i1 + 1 : 0;
    const Vec2 v11 = ref.vertices[i1];
    const Vec2 v12 = ref.vertices[i2];
    Vec2 tangent = v12 - v11;
    tangent.Normalize();
    out.normal = Cross(tangent, Real(1));
    out.planePoint = Real(0.5) * (v11 + v12);

    const int j1 = IncidentFace(inc, out.normal);
    const int j2 = j1 + 1 < inc.count ? j1 + 1 : 0;
    ClipVertex incident[2];
    incident[0].v = inc.vertices[j1];
    incident[0].id = {std::uint8_t(i1), std::uint8_t(j1), ContactFeature::Face,
                      ContactFeature::Vertex};
    incident[1].v = inc.vertices[j2];
    incident[1].id = {std::uint8_t(i1), std::uint8_t(j2), ContactFeature::Face,
                      ContactFeature::Vertex};

    ClipVertex clip1[2], clip2[2];
    const Real side1 = -Dot(tangent, v11);
    if (detail::ClipSegmentToLine(clip1, incident, -tangent, side1, i1) < 2)
    {
        return out;
    }
    const Real side2 = Dot(tangent, v12);
    if (detail::ClipSegmentToLine(clip2, clip1, tangent, side2, i2) < 2)
    {
        return out;
    }
    const Real front = Dot(out.normal, v11);
    for (const ClipVertex& cv : clip2)
    {
        const Real separation = Dot(out.normal, cv.v) - front;
        if (separation <= totalRadius)
        {
            out.points[out.count] = cv;
            out.separations[out.count] = separation;
            ++out.count;
        }
    }
    return out;
}

/// Writes a face manifold from clipped points (A's frame). `flip`: the reference face is B's.
/// `xf` takes B's frame to A's.
void WriteFace(Manifold& manifold, const Clipped& clipped, bool flip, const Transform& xf)
{
    manifold.pointCount = 0;
    if (flip)
    {
        manifold.type = Manifold::Type::FaceB;
        manifold.localNormal = MulT(xf.q, clipped.normal);
        manifold.localPoint = MulT(xf, clipped.planePoint);
    }
    else
    {
        manifold.type = Manifold::Type::FaceA;
        manifold.localNormal = clipped.normal;
        manifold.localPoint = clipped.planePoint;
    }
    for (int k = 0; k < clipped.count; ++k)
    {
        ManifoldPoint& point = manifold.points[k];
        ContactFeature id = clipped.points[k].id;
        if (flip)
        {
            // The features were named reference first: put them back as A's and B's.
            std::swap(id.indexA, id.indexB);
            std::swap(id.typeA, id.typeB);
        }
        point.localPoint = flip ? clipped.points[k].v : MulT(xf, clipped.points[k].v);
        point.normalImpulse = 0;
        point.tangentImpulse = 0;
        point.id = id;
    }
    manifold.pointCount = clipped.count;
}

/// `poly` moved into A's frame by `xf` (B's frame to A's).
Polygon InFrameA(const Polygon& poly, const Transform& xf)
{
    Polygon moved = poly;
    for (int i = 0; i < poly.count; ++i)
    {
        moved.vertices[i] = Mul(xf, poly.vertices[i]);
        moved.normals[i] = Mul(xf.q, poly.normals[i]);
    }
    moved.centroid = Mul(xf, poly.centroid);
    return moved;
}

/// The segment as a polygon of two vertices, its radius its skin.
Polygon SegmentPolygon(const Segment& segment)
{
    return MakeCapsulePolygon({segment.point1, segment.point2, segment.radius});
}

} // namespace

void CollideRoundedPolygons(Manifold& manifold, const Polygon& polygonA, const Transform& xfA,
                            const Polygon& polygonB, const Transform& xfB)
{
    manifold.pointCount = 0;
    const Transform xf = MulT(xfA, xfB);
    const Polygon b = InFrameA(polygonB, xf);
    const Polygon& a = polygonA;
    const Real totalRadius = a.radius + b.radius;

    int faceA = 0, faceB = 0;
    const Real separationA = MaxFaceSeparation(a, b, faceA);
    if (separationA > totalRadius)
    {
        return;
    }
    const Real separationB = MaxFaceSeparation(b, a, faceB);
    if (separationB > totalRadius)
    {
        return;
    }

    // Box2D's preference for A's face unless B's is clearly deeper keeps the reference face
    // from flickering between two near-parallel faces.
    const Real tolerance = Real(0.1) * kCollisionLinearSlop;
    const bool flip = separationB > separationA + tolerance;
    const Polygon& ref = flip ? b : a;
    const Polygon& inc = flip ? a : b;
    const int refFace = flip ? faceB : faceA;
    const Clipped clipped = ClipToFace(ref, refFace, inc, totalRadius);

    if (Max(separationA, separationB) > tolerance)
    {
        // The cores are apart: when the closest features of the reference face and the
        // incident edge are two vertices, and their gap is clearly smaller than the clipped
        // points' separations, the rounded corners touch along the line between the vertices.
        const int i1 = refFace;
        const int i2 = i1 + 1 < ref.count ? i1 + 1 : 0;
        const int j1 = IncidentFace(inc, clipped.normal);
        const int j2 = j1 + 1 < inc.count ? j1 + 1 : 0;
        const SegmentPair pair = ClosestOnSegments(ref.vertices[i1], ref.vertices[i2],
                                                   inc.vertices[j1], inc.vertices[j2]);
        const Real distance = std::sqrt(pair.distanceSquared);
        if (distance > totalRadius)
        {
            return;
        }
        const bool vertexPair = (pair.s == 0 || pair.s == 1) && (pair.t == 0 || pair.t == 1);
        Real least = kMaxReal;
        for (int k = 0; k < clipped.count; ++k)
        {
            least = Min(least, clipped.separations[k]);
        }
        if (vertexPair && distance + tolerance < least)
        {
            const int refVertex = pair.s == 0 ? i1 : i2;
            const int incVertex = pair.t == 0 ? j1 : j2;
            const int vertexA = flip ? incVertex : refVertex;
            const int vertexB = flip ? refVertex : incVertex;
            manifold.type = Manifold::Type::Circles;
            manifold.localPoint = polygonA.vertices[vertexA];
            manifold.localNormal = Vec2{0, 0};
            ManifoldPoint& point = manifold.points[0];
            point.localPoint = polygonB.vertices[vertexB];
            point.normalImpulse = 0;
            point.tangentImpulse = 0;
            point.id = {std::uint8_t(vertexA), std::uint8_t(vertexB), ContactFeature::Vertex,
                        ContactFeature::Vertex};
            manifold.pointCount = 1;
            return;
        }
    }
    WriteFace(manifold, clipped, flip, xf);
}

namespace
{

/// Which end of the segment (0: point1, 1: point2) a manifold's contact is nearest, from its
/// points on A (A's frame).
int NearestEnd(const Manifold& manifold, Vec2 p1, Vec2 p2)
{
    Vec2 onA{0, 0};
    if (manifold.type == Manifold::Type::Circles)
    {
        onA = manifold.localPoint;
    }
    else // FaceB: the points are A's
    {
        for (int k = 0; k < manifold.pointCount; ++k)
        {
            onA += (Real(1) / Real(manifold.pointCount)) * manifold.points[k].localPoint;
        }
    }
    return Dot(onA - p1, p2 - p1) < Real(0.5) * DistanceSquared(p1, p2) ? 0 : 1;
}

/// The contact normal (A's frame, from A to B) of a non-empty manifold.
Vec2 NormalInA(const Manifold& manifold, const Transform& xf)
{
    switch (manifold.type)
    {
    case Manifold::Type::FaceA:
        return manifold.localNormal;
    case Manifold::Type::FaceB:
        return -Mul(xf.q, manifold.localNormal);
    case Manifold::Type::Circles:
        break;
    }
    Vec2 d = Mul(xf, manifold.points[0].localPoint) - manifold.localPoint;
    d.Normalize();
    return d;
}

} // namespace

void CollideChainSegmentAndRounded(Manifold& manifold, const ChainSegment& segmentA,
                                   const Transform& xfA, const Polygon& polygonB,
                                   const Transform& xfB)
{
    manifold.pointCount = 0;
    const Vec2 p1 = segmentA.segment.point1;
    const Vec2 p2 = segmentA.segment.point2;
    const Vec2 edge = p2 - p1;
    Vec2 normal = Cross(edge, Real(1));
    normal.Normalize();

    const Transform xf = MulT(xfA, xfB);
    const Polygon b = InFrameA(polygonB, xf);
    if (Dot(normal, b.centroid - p1) < 0)
    {
        return; // behind the one-sided segment
    }
    const Polygon a = SegmentPolygon(segmentA.segment);
    CollideRoundedPolygons(manifold, a, xfA, polygonB, xfB);
    if (manifold.pointCount == 0)
    {
        return;
    }
    const Vec2 d = NormalInA(manifold, xf);
    // Within 0.8° of the segment's own normal the contact is the face's: kept as found.
    if (Dot(d, normal) >= Real(0.9999))
    {
        return;
    }
    if (manifold.type == Manifold::Type::FaceA)
    {
        manifold.pointCount = 0; // the back face of a one-sided segment
        return;
    }

    // A contact at an end, turned from the segment's normal. Towards the neighbour, inside
    // the normal cone of a convex joint, it is this segment's corner: kept. Beyond that cone
    // it is the neighbour's to report. Anything else (a flat or concave joint, or a normal
    // turned back over this segment) is snapped to the segment's face, so that nothing
    // catches on the joint.
    const bool atEnd1 = NearestEnd(manifold, p1, p2) == 0;
    const Vec2 neighbourEdge = atEnd1 ? p1 - segmentA.ghost1 : segmentA.ghost2 - p2;
    Vec2 neighbourNormal = Cross(neighbourEdge, Real(1));
    neighbourNormal.Normalize();
    const bool convex = atEnd1 ? Cross(neighbourEdge, edge) > 0 : Cross(edge, neighbourEdge) > 0;
    const bool towardsNeighbour = atEnd1 ? Cross(d, normal) > 0 : Cross(normal, d) > 0;
    if (convex && towardsNeighbour)
    {
        const bool inCone =
            atEnd1 ? Cross(neighbourNormal, d) >= 0 : Cross(d, neighbourNormal) >= 0;
        if (!inCone)
        {
            manifold.pointCount = 0;
        }
        return;
    }
    const Real totalRadius = a.radius + b.radius;
    WriteFace(manifold, ClipToFace(a, 0, b, totalRadius), false, xf);
}

} // namespace meff
