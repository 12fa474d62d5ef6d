// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Contact manifolds of a circle against a circle and against a polygon, following
// b2CollideCircles and b2CollidePolygonAndCircle of Box2D 2.4.1 (same operation order).
#include "collision/manifold_internal.h"

namespace meff
{

namespace
{

/// Fills the single point of a manifold whose point on B is the circle's centre. Box2D gives
/// every circle contact the feature key 0.
void SetCirclePoint(Manifold& manifold, const Circle& circleB)
{
    manifold.pointCount = 1;
    manifold.points[0].localPoint = circleB.center;
    manifold.points[0].id = ContactFeature{};
    manifold.points[0].normalImpulse = 0;
    manifold.points[0].tangentImpulse = 0;
}

} // namespace

void CollideCircles(Manifold& manifold, const Circle& circleA, const Transform& xfA,
                    const Circle& circleB, const Transform& xfB)
{
    manifold.pointCount = 0;

    const Vec2 centerA = Mul(xfA, circleA.center);
    const Vec2 centerB = Mul(xfB, circleB.center);

    const Vec2 d = centerB - centerA;
    const Real distanceSquared = Dot(d, d);
    const Real radius = circleA.radius + circleB.radius;
    if (distanceSquared > radius * radius)
    {
        return;
    }

    manifold.type = Manifold::Type::Circles;
    manifold.localPoint = circleA.center;
    manifold.localNormal = Vec2(0, 0);
    SetCirclePoint(manifold, circleB);
}

void CollidePolygonAndCircle(Manifold& manifold, const Polygon& polygonA, const Transform& xfA,
                             const Circle& circleB, const Transform& xfB)
{
    manifold.pointCount = 0;

    // The circle's centre in the polygon's frame.
    const Vec2 centerWorld = Mul(xfB, circleB.center);
    const Vec2 center = MulT(xfA, centerWorld);

    // The face of least penetration (or greatest separation).
    int normalIndex = 0;
    Real separation = -kMaxReal;
    const Real radius = polygonA.radius + circleB.radius;
    const int count = polygonA.count;
    const Vec2* vertices = polygonA.vertices;
    const Vec2* normals = polygonA.normals;

    for (int i = 0; i < count; ++i)
    {
        const Real s = Dot(normals[i], center - vertices[i]);
        if (s > radius)
        {
            return;
        }
        if (s > separation)
        {
            separation = s;
            normalIndex = i;
        }
    }

    const int index1 = normalIndex;
    const int index2 = index1 + 1 < count ? index1 + 1 : 0;
    const Vec2 v1 = vertices[index1];
    const Vec2 v2 = vertices[index2];

    // Centre inside the polygon (up to epsilon): push out along the face normal.
    if (separation < kEpsilon)
    {
        manifold.type = Manifold::Type::FaceA;
        manifold.localNormal = normals[normalIndex];
        manifold.localPoint = Real(0.5) * (v1 + v2);
        SetCirclePoint(manifold, circleB);
        return;
    }

    // Which Voronoi region of the face the centre lies in.
    const Real u1 = Dot(center - v1, v2 - v1);
    const Real u2 = Dot(center - v2, v1 - v2);
    if (u1 <= 0)
    {
        if (DistanceSquared(center, v1) > radius * radius)
        {
            return;
        }
        // Box2D labels a vertex contact FaceA too, with the normal from the vertex to the
        // centre and the vertex as the plane point.
        manifold.type = Manifold::Type::FaceA;
        manifold.localNormal = center - v1;
        manifold.localNormal.Normalize();
        manifold.localPoint = v1;
        SetCirclePoint(manifold, circleB);
    }
    else if (u2 <= 0)
    {
        if (DistanceSquared(center, v2) > radius * radius)
        {
            return;
        }
        manifold.type = Manifold::Type::FaceA;
        manifold.localNormal = center - v2;
        manifold.localNormal.Normalize();
        manifold.localPoint = v2;
        SetCirclePoint(manifold, circleB);
    }
    else
    {
        const Vec2 faceCenter = Real(0.5) * (v1 + v2);
        const Real s = Dot(center - faceCenter, normals[index1]);
        if (s > radius)
        {
            return;
        }
        manifold.type = Manifold::Type::FaceA;
        manifold.localNormal = normals[index1];
        manifold.localPoint = faceCenter;
        SetCirclePoint(manifold, circleB);
    }
}

} // namespace meff
