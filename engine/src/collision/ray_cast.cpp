// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Ray casts against single shapes and point containment: Box2D 2.4.1's b2CircleShape,
// b2PolygonShape and b2EdgeShape (two-sided and one-sided) RayCast and TestPoint, with the same
// floating-point operation order so that World::CastRay agrees with b2World::RayCast bit for bit.
#include "meff/ray_cast.h"

#include "meff/collision.h"

#include <cmath>

namespace meff
{

bool RayCast(const Circle& circle, const Transform& xf, const RayCastInput& input,
             RayCastOutput& output)
{
    // Points x = p1 + t·r on the circle satisfy |s + t·r|² = radius² with s = p1 − centre:
    // rr·t² + 2c·t + b = 0, c = s·r, b = |s|² − radius² (van den Bergen, Collision Detection
    // in Interactive 3D Environments, 3.1.2). The smaller root is the entry point.
    const Vec2 center = xf.p + Mul(xf.q, circle.center);
    const Vec2 s = input.p1 - center;
    const Real b = Dot(s, s) - circle.radius * circle.radius;

    const Vec2 r = input.p2 - input.p1;
    const Real c = Dot(s, r);
    const Real rr = Dot(r, r);
    const Real sigma = c * c - rr * b;

    // No real root (the line misses), or a ray too short to have a direction.
    if (sigma < Real(0) || rr < kEpsilon)
    {
        return false;
    }

    // The entry root, still scaled by rr (dividing only once it is known to be on the ray).
    // From inside the circle (b < 0) it is negative, so such rays do not hit.
    Real t = -(c + std::sqrt(sigma));
    if (Real(0) <= t && t <= input.maxFraction * rr)
    {
        t /= rr;
        output.fraction = t;
        output.normal = s + t * r;
        output.normal.Normalize();
        return true;
    }
    return false;
}

bool RayCast(const Polygon& polygon, const Transform& xf, const RayCastInput& input,
             RayCastOutput& output)
{
    // In the polygon's frame, clip the parameter interval [lower, upper] of p1 + t·d against
    // every edge's half-plane n·(x − v) ≤ 0 (Cyrus–Beck). The hit is where the ray enters the
    // last half-plane it enters, at `lower`, on edge `index`.
    const Vec2 p1 = MulT(xf.q, input.p1 - xf.p);
    const Vec2 p2 = MulT(xf.q, input.p2 - xf.p);
    const Vec2 d = p2 - p1;

    Real lower = 0;
    Real upper = input.maxFraction;
    int index = -1;

    for (int i = 0; i < polygon.count; ++i)
    {
        // On the edge's line: n·(p1 − v) + t·(n·d) = 0, so t = numerator / denominator.
        const Real numerator = Dot(polygon.normals[i], polygon.vertices[i] - p1);
        const Real denominator = Dot(polygon.normals[i], d);

        if (denominator == Real(0))
        {
            // Parallel to the edge: outside its half-plane means a miss.
            if (numerator < Real(0))
            {
                return false;
            }
        }
        else if (denominator < Real(0) && numerator < lower * denominator)
        {
            // Entering this half-plane after `lower` (t > lower, the inequality flipped
            // because the denominator is negative, so no division is needed to decide).
            lower = numerator / denominator;
            index = i;
        }
        else if (denominator > Real(0) && numerator < upper * denominator)
        {
            // Leaving this half-plane before `upper`.
            upper = numerator / denominator;
        }

        if (upper < lower)
        {
            return false;
        }
    }

    // index < 0: the ray starts inside (it never entered a half-plane).
    if (index >= 0)
    {
        output.fraction = lower;
        output.normal = Mul(xf.q, polygon.normals[index]);
        return true;
    }
    return false;
}

namespace
{

/// b2EdgeShape::RayCast: two-sided, or one-sided (only from the right of point1 → point2).
bool RayCastEdge(const Segment& segment, bool oneSided, const Transform& xf,
                 const RayCastInput& input, RayCastOutput& output)
{
    // In the segment's frame: the ray p1 + t·d meets the segment's line where
    // n·(p1 + t·d − v1) = 0, and the segment itself where the point's projection on the
    // segment lies within [0, 1] of its length.
    const Vec2 p1 = MulT(xf.q, input.p1 - xf.p);
    const Vec2 p2 = MulT(xf.q, input.p2 - xf.p);
    const Vec2 d = p2 - p1;

    const Vec2 v1 = segment.point1;
    const Vec2 v2 = segment.point2;
    const Vec2 e = v2 - v1;

    // The normal to the right of v1 → v2.
    Vec2 normal(e.y, -e.x);
    normal.Normalize();

    // The numerator's sign tells the side p1 is on: positive is the left, the back of a
    // one-sided segment, which such a ray cannot hit.
    const Real numerator = Dot(normal, v1 - p1);
    if (oneSided && numerator > Real(0))
    {
        return false;
    }
    const Real denominator = Dot(normal, d);
    if (denominator == Real(0))
    {
        return false;
    }

    const Real t = numerator / denominator;
    if (t < Real(0) || input.maxFraction < t)
    {
        return false;
    }

    const Vec2 q = p1 + t * d;
    const Vec2 r = v2 - v1;
    const Real rr = Dot(r, r);
    if (rr == Real(0))
    {
        return false;
    }
    const Real s = Dot(q - v1, r) / rr;
    if (s < Real(0) || Real(1) < s)
    {
        return false;
    }

    output.fraction = t;
    // Face the side the ray comes from: numerator > 0 means p1 is on the left.
    output.normal = numerator > Real(0) ? -Mul(xf.q, normal) : Mul(xf.q, normal);
    return true;
}

} // namespace

bool RayCast(const Segment& segment, const Transform& xf, const RayCastInput& input,
             RayCastOutput& output)
{
    return RayCastEdge(segment, false, xf, input, output);
}

bool RayCast(const ChainSegment& segment, const Transform& xf, const RayCastInput& input,
             RayCastOutput& output)
{
    return RayCastEdge(segment.segment, true, xf, input, output);
}

bool TestPoint(const Circle& circle, const Transform& xf, Vec2 point)
{
    const Vec2 center = xf.p + Mul(xf.q, circle.center);
    const Vec2 d = point - center;
    return Dot(d, d) <= circle.radius * circle.radius;
}

bool TestPoint(const Polygon& polygon, const Transform& xf, Vec2 point)
{
    // Inside (or on) every edge's half-plane. The skin is not part of the polygon here.
    const Vec2 local = MulT(xf.q, point - xf.p);
    for (int i = 0; i < polygon.count; ++i)
    {
        if (Dot(polygon.normals[i], local - polygon.vertices[i]) > Real(0))
        {
            return false;
        }
    }
    return true;
}

bool TestPoint(const Segment& /*segment*/, const Transform& /*xf*/, Vec2 /*point*/)
{
    return false;
}

bool TestPoint(const ChainSegment& /*segment*/, const Transform& /*xf*/, Vec2 /*point*/)
{
    return false;
}

} // namespace meff
