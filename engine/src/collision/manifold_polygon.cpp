// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Contact manifold between two convex polygons by reference-face clipping, following
// b2CollidePolygons (with b2FindMaxSeparation and b2FindIncidentEdge) of Box2D 2.4.1.
#include "collision/manifold_internal.h"

namespace meff
{

namespace
{

/// How much deeper B's best axis must be before B's face becomes the reference face: Box2D's
/// k_tol = 0.1 * b2_linearSlop. Written as the same float product (not the literal 0.0005,
/// which may round differently) so that the flip decision agrees bit for bit.
constexpr Real kReferenceFaceTolerance = Real(0.1) * detail::kCollisionLinearSlop;

/// Faces of one polygon placed in another polygon's frame, laid out for b2FindMaxSeparation's
/// search: one face per lane of small fixed-size arrays (structure of arrays), so that the
/// compiler can evaluate several faces in one SIMD instruction.
///
/// Box2D's arithmetic is kept bit for bit: every lane performs exactly the scalar operations of
/// b2FindMaxSeparation for its face, in the same order (no reassociation: -ffp-contract=off and
/// no fast-math), and each face's running minimum visits the other polygon's vertices in order
/// with the same strict `<`. Lanes past the polygon's count hold its zero padding; they are
/// computed but never read back.
template <int kLanes>
struct FaceLanes
{
    static_assert(kLanes <= kMaxPolygonVertices);

    Real nx[kLanes];
    Real ny[kLanes];
    Real vx[kLanes];
    Real vy[kLanes];
    Real minSeparation[kLanes];

    /// Face i's normal n = xf.q·normal and first vertex v1 = xf·vertex, written out as
    /// Mul(Rot, Vec2) and Mul(Transform, Vec2) do.
    FaceLanes(const Polygon& poly, const Transform& xf)
    {
        for (int i = 0; i < kLanes; ++i)
        {
            const Vec2 normal = poly.normals[i];
            const Vec2 vertex = poly.vertices[i];
            nx[i] = xf.q.c * normal.x - xf.q.s * normal.y;
            ny[i] = xf.q.s * normal.x + xf.q.c * normal.y;
            vx[i] = (xf.q.c * vertex.x - xf.q.s * vertex.y) + xf.p.x;
            vy[i] = (xf.q.s * vertex.x + xf.q.c * vertex.y) + xf.p.y;
            minSeparation[i] = kMaxReal;
        }
    }

    /// Lowers each face's separation to vertex w of the other polygon if deeper: Dot(n, w − v1).
    void Visit(Vec2 w)
    {
        for (int i = 0; i < kLanes; ++i)
        {
            const Real sij = nx[i] * (w.x - vx[i]) + ny[i] * (w.y - vy[i]);
            minSeparation[i] = sij < minSeparation[i] ? sij : minSeparation[i];
        }
    }

    /// The greatest separation over the first `count` faces; writes the first face reaching it
    /// (Box2D's strict `>`).
    Real MaxSeparation(int count, int& edgeIndex) const
    {
        int bestIndex = 0;
        Real maxSeparation = -kMaxReal;
        for (int i = 0; i < count; ++i)
        {
            if (minSeparation[i] > maxSeparation)
            {
                maxSeparation = minSeparation[i];
                bestIndex = i;
            }
        }
        edgeIndex = bestIndex;
        return maxSeparation;
    }
};

/// The greatest separation of poly2 from poly1 along poly1's face normals; writes the face.
template <int kLanes>
Real FindMaxSeparationLanes(int& edgeIndex, const Polygon& poly1, const Transform& xf1,
                            const Polygon& poly2, const Transform& xf2)
{
    FaceLanes<kLanes> faces(poly1, MulT(xf2, xf1));
    const int count2 = poly2.count;
    if (count2 <= 4)
    {
        // A loop of fixed length four, which the compiler unrolls. A triangle's missing fourth
        // vertex is its last vertex again: a repeated vertex gives the same separation bits,
        // which the strict `<` ignores, so each minimum is the one Box2D's loop finds.
        const int last = count2 - 1;
        for (int j = 0; j < 4; ++j)
        {
            faces.Visit(poly2.vertices[j < last ? j : last]);
        }
    }
    else
    {
        for (int j = 0; j < count2; ++j)
        {
            faces.Visit(poly2.vertices[j]);
        }
    }
    return faces.MaxSeparation(poly1.count, edgeIndex);
}

/// FindMaxSeparationLanes with as few lanes as poly1 needs: four up to four faces, else eight.
Real FindMaxSeparation(int& edgeIndex, const Polygon& poly1, const Transform& xf1,
                       const Polygon& poly2, const Transform& xf2)
{
    if (poly1.count <= 4)
    {
        return FindMaxSeparationLanes<4>(edgeIndex, poly1, xf1, poly2, xf2);
    }
    return FindMaxSeparationLanes<kMaxPolygonVertices>(edgeIndex, poly1, xf1, poly2, xf2);
}

/// The face of poly2 most anti-parallel to face `edge1` of poly1, in world coordinates.
void FindIncidentEdge(detail::ClipVertex incident[2], const Polygon& poly1, const Transform& xf1,
                      int edge1, const Polygon& poly2, const Transform& xf2)
{
    const int count2 = poly2.count;

    // The reference normal in poly2's frame.
    const Vec2 normal1 = MulT(xf2.q, Mul(xf1.q, poly1.normals[edge1]));

    int index = 0;
    Real minDot = kMaxReal;
    for (int i = 0; i < count2; ++i)
    {
        const Real dot = Dot(normal1, poly2.normals[i]);
        if (dot < minDot)
        {
            minDot = dot;
            index = i;
        }
    }

    const int i1 = index;
    const int i2 = i1 + 1 < count2 ? i1 + 1 : 0;

    incident[0].v = Mul(xf2, poly2.vertices[i1]);
    incident[0].id.indexA = static_cast<std::uint8_t>(edge1);
    incident[0].id.indexB = static_cast<std::uint8_t>(i1);
    incident[0].id.typeA = ContactFeature::Face;
    incident[0].id.typeB = ContactFeature::Vertex;

    incident[1].v = Mul(xf2, poly2.vertices[i2]);
    incident[1].id.indexA = static_cast<std::uint8_t>(edge1);
    incident[1].id.indexB = static_cast<std::uint8_t>(i2);
    incident[1].id.typeA = ContactFeature::Face;
    incident[1].id.typeB = ContactFeature::Vertex;
}

} // namespace

namespace detail
{

Real FaceSeparation(const Polygon& poly1, const Transform& xf1, int edge, const Polygon& poly2,
                    const Transform& xf2)
{
    // FaceLanes' constructor and Visit for one lane, written out: the same expressions.
    const Transform xf = MulT(xf2, xf1);
    const Vec2 normal = poly1.normals[edge];
    const Vec2 vertex = poly1.vertices[edge];
    const Real nx = xf.q.c * normal.x - xf.q.s * normal.y;
    const Real ny = xf.q.s * normal.x + xf.q.c * normal.y;
    const Real vx = (xf.q.c * vertex.x - xf.q.s * vertex.y) + xf.p.x;
    const Real vy = (xf.q.s * vertex.x + xf.q.c * vertex.y) + xf.p.y;
    Real minSeparation = kMaxReal;
    for (int j = 0; j < poly2.count; ++j)
    {
        const Vec2 w = poly2.vertices[j];
        const Real sij = nx * (w.x - vx) + ny * (w.y - vy);
        minSeparation = sij < minSeparation ? sij : minSeparation;
    }
    return minSeparation;
}

void CollidePolygons(Manifold& manifold, const Polygon& polygonA, const Transform& xfA,
                     const Polygon& polygonB, const Transform& xfB, SeparatingFace& separating)
{
    manifold.pointCount = 0;
    const Real totalRadius = polygonA.radius + polygonB.radius;
    // The face that separated the pair last time first: when it still separates them, so does
    // the full search below (FaceSeparation), with no points either way.
    if (separating.edge >= 0 &&
        (separating.onB
             ? FaceSeparation(polygonB, xfB, separating.edge, polygonA, xfA)
             : FaceSeparation(polygonA, xfA, separating.edge, polygonB, xfB)) > totalRadius)
    {
        return;
    }
    separating.edge = -1;

    // Box2D's order: B's faces are only searched when A's do not separate the pair (in a
    // crowded scene most pairs the broad phase finds stop here).
    int edgeA = 0;
    const Real separationA = FindMaxSeparation(edgeA, polygonA, xfA, polygonB, xfB);
    if (separationA > totalRadius)
    {
        separating = {static_cast<std::int8_t>(edgeA), false};
        return;
    }

    int edgeB = 0;
    const Real separationB = FindMaxSeparation(edgeB, polygonB, xfB, polygonA, xfA);
    if (separationB > totalRadius)
    {
        separating = {static_cast<std::int8_t>(edgeB), true};
        return;
    }

    // Reference polygon 1 and incident polygon 2. A's face is preferred unless B's is clearly
    // better, so that the reference face does not flicker between the two.
    const bool flip = separationB > separationA + kReferenceFaceTolerance;
    const Polygon& poly1 = flip ? polygonB : polygonA;
    const Polygon& poly2 = flip ? polygonA : polygonB;
    const Transform& xf1 = flip ? xfB : xfA;
    const Transform& xf2 = flip ? xfA : xfB;
    const int edge1 = flip ? edgeB : edgeA;
    manifold.type = flip ? Manifold::Type::FaceB : Manifold::Type::FaceA;

    detail::ClipVertex incidentEdge[2];
    FindIncidentEdge(incidentEdge, poly1, xf1, edge1, poly2, xf2);

    const int count1 = poly1.count;
    const int iv1 = edge1;
    const int iv2 = edge1 + 1 < count1 ? edge1 + 1 : 0;

    Vec2 v11 = poly1.vertices[iv1];
    Vec2 v12 = poly1.vertices[iv2];

    Vec2 localTangent = v12 - v11;
    localTangent.Normalize();

    const Vec2 localNormal = Cross(localTangent, Real(1));
    const Vec2 planePoint = Real(0.5) * (v11 + v12);

    const Vec2 tangent = Mul(xf1.q, localTangent);
    const Vec2 normal = Cross(tangent, Real(1));

    v11 = Mul(xf1, v11);
    v12 = Mul(xf1, v12);

    const Real frontOffset = Dot(normal, v11);

    // The side planes of the reference face, pushed out by the skins.
    const Real sideOffset1 = -Dot(tangent, v11) + totalRadius;
    const Real sideOffset2 = Dot(tangent, v12) + totalRadius;

    detail::ClipVertex clipPoints1[2];
    detail::ClipVertex clipPoints2[2];

    if (detail::ClipSegmentToLine(clipPoints1, incidentEdge, -tangent, sideOffset1, iv1) < 2)
    {
        return;
    }
    if (detail::ClipSegmentToLine(clipPoints2, clipPoints1, tangent, sideOffset2, iv2) < 2)
    {
        return;
    }

    manifold.localNormal = localNormal;
    manifold.localPoint = planePoint;

    int pointCount = 0;
    for (int i = 0; i < 2; ++i)
    {
        const Real separation = Dot(normal, clipPoints2[i].v) - frontOffset;
        if (separation <= totalRadius)
        {
            ManifoldPoint& point = manifold.points[pointCount];
            point.localPoint = MulT(xf2, clipPoints2[i].v);
            point.normalImpulse = 0;
            point.tangentImpulse = 0;
            point.id = clipPoints2[i].id;
            if (flip)
            {
                // The features were found with B as the reference: swap them back to A, B.
                const ContactFeature cf = point.id;
                point.id.indexA = cf.indexB;
                point.id.indexB = cf.indexA;
                point.id.typeA = cf.typeB;
                point.id.typeB = cf.typeA;
            }
            ++pointCount;
        }
    }

    manifold.pointCount = pointCount;
}

} // namespace detail

void CollidePolygons(Manifold& manifold, const Polygon& polygonA, const Transform& xfA,
                     const Polygon& polygonB, const Transform& xfB)
{
    detail::SeparatingFace separating;
    detail::CollidePolygons(manifold, polygonA, xfA, polygonB, xfB, separating);
}

} // namespace meff
