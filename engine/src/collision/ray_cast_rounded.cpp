// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Ray casts and point tests against rounded outlines: capsules and rounded polygons (Box2D
// v3's shapes). The rounded outline is the core polygon's edges pushed out by the radius,
// joined by arcs of that radius about the vertices, so the ray's entry is the earliest entry
// into one of those offset edges or vertex circles.
#include "meff/collision.h"
#include "meff/ray_cast.h"

#include <cmath>

namespace meff
{

namespace
{

/// Squared distance from the point to the core segment from a to b.
Real DistanceSquaredToSegment(Vec2 p, Vec2 a, Vec2 b)
{
    const Vec2 ab = b - a;
    const Real t = Clamp(Dot(p - a, ab) / Dot(ab, ab), 0, 1);
    return DistanceSquared(p, a + t * ab);
}

/// Inside or on the rounded outline (local coordinates): inside the core (3 vertices or more),
/// or within the radius of one of its edges.
bool InsideRounded(const Polygon& core, Vec2 p)
{
    if (core.count >= 3)
    {
        bool inside = true;
        for (int i = 0; i < core.count && inside; ++i)
        {
            inside = Dot(core.normals[i], p - core.vertices[i]) <= 0;
        }
        if (inside)
        {
            return true;
        }
    }
    const Real r2 = core.radius * core.radius;
    for (int i = 0; i < core.count; ++i)
    {
        const int next = i + 1 < core.count ? i + 1 : 0;
        if (DistanceSquaredToSegment(p, core.vertices[i], core.vertices[next]) <= r2)
        {
            return true;
        }
    }
    return false;
}

} // namespace

bool RayCastRounded(const Polygon& polygon, const Transform& xf, const RayCastInput& input,
                    RayCastOutput& output)
{
    const Vec2 p1 = MulT(xf.q, input.p1 - xf.p);
    const Vec2 p2 = MulT(xf.q, input.p2 - xf.p);
    const Vec2 d = p2 - p1;
    const Real dd = Dot(d, d);
    if (dd < kEpsilon || InsideRounded(polygon, p1))
    {
        return false; // no direction, or starting inside (as for the other shapes)
    }
    const Real r = polygon.radius;
    Real best = input.maxFraction;
    Vec2 normal{};
    bool hit = false;
    for (int i = 0; i < polygon.count; ++i)
    {
        // The edge pushed out by r: n·(x − v) = r, entered while moving against n, and only
        // between the perpendiculars through its ends.
        const int next = i + 1 < polygon.count ? i + 1 : 0;
        const Vec2 n = polygon.normals[i];
        const Real rate = Dot(n, d);
        if (rate < 0)
        {
            const Real t = (r - Dot(n, p1 - polygon.vertices[i])) / rate;
            const Vec2 edge = polygon.vertices[next] - polygon.vertices[i];
            const Real along = Dot(p1 + t * d - polygon.vertices[i], edge);
            if (0 <= t && t <= best && 0 <= along && along <= Dot(edge, edge))
            {
                best = t;
                normal = n;
                hit = true;
            }
        }
        // The arc about vertex i: |p1 + t·d − v|² = r², the smaller root (entry).
        const Vec2 s = p1 - polygon.vertices[i];
        const Real b = Dot(s, d);
        const Real c = Dot(s, s) - r * r;
        const Real sigma = b * b - dd * c;
        if (sigma >= 0)
        {
            const Real t = -(b + std::sqrt(sigma)) / dd;
            if (0 <= t && t <= best)
            {
                best = t;
                normal = s + t * d;
                normal.Normalize();
                hit = true;
            }
        }
    }
    if (!hit)
    {
        return false;
    }
    output.fraction = best;
    output.normal = Mul(xf.q, normal);
    return true;
}

bool RayCast(const Capsule& capsule, const Transform& xf, const RayCastInput& input,
             RayCastOutput& output)
{
    return RayCastRounded(MakeCapsulePolygon(capsule), xf, input, output);
}

bool TestPointRounded(const Polygon& polygon, const Transform& xf, Vec2 point)
{
    return InsideRounded(polygon, MulT(xf.q, point - xf.p));
}

bool TestPoint(const Capsule& capsule, const Transform& xf, Vec2 point)
{
    return TestPointRounded(MakeCapsulePolygon(capsule), xf, point);
}

} // namespace meff
