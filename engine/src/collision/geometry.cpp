// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Building polygons, and the mass and bounding boxes of shapes. Follows b2PolygonShape::Set,
// SetAsBox, ComputeMass and ComputeAABB, b2CircleShape and b2EdgeShape of Box2D 2.4.1, with
// the same floating-point operation order; where Box2D asserts on bad input we throw.
#include "collision/manifold_internal.h"
#include "core/report_error.h"
#include "meff/error.h"
#include "meff/validity.h"

#include <optional>
#include <string>

namespace meff
{

using detail::Refuse;
using detail::ReportError;

namespace
{

/// The area centroid of a convex counter-clockwise polygon, as Box2D's ComputeCentroid: a fan
/// of triangles from the first vertex. Writes the area (the caller rejects a zero one).
Vec2 ComputeCentroid(const Vec2* vertices, int count, Real& area)
{
    Vec2 c(0, 0);
    area = 0;

    // Triangles are formed relative to the first vertex to reduce round-off.
    const Vec2 s = vertices[0];
    const Real inv3 = Real(1) / Real(3);

    for (int i = 0; i < count; ++i)
    {
        const Vec2 p1 = vertices[0] - s;
        const Vec2 p2 = vertices[i] - s;
        const Vec2 p3 = i + 1 < count ? vertices[i + 1] - s : vertices[0] - s;

        const Vec2 e1 = p2 - p1;
        const Vec2 e2 = p3 - p1;

        const Real d = Cross(e1, e2);
        const Real triangleArea = Real(0.5) * d;
        area += triangleArea;

        c += triangleArea * inv3 * (p1 + p2 + p3);
    }

    // Meaningless for a zero area; MakePolygon checks the area before using the result.
    c = (Real(1) / area) * c + s;
    return c;
}

/// The box of b2PolygonShape::SetAsBox before any offset: vertices counter-clockwise from the
/// lower left, normals of the faces below, right, above and left. None (reported) for bad
/// half-extents.
std::optional<Polygon> MakeCenteredBox(Real halfWidth, Real halfHeight, const char* caller)
{
    if (!IsValid(halfWidth) || !IsValid(halfHeight) || !(halfWidth > 0) || !(halfHeight > 0))
    {
        ReportError(InvalidArgument(
            std::string(caller) + ": half-extents must be finite and > 0, got halfWidth = " +
            NumberText(halfWidth) + ", halfHeight = " + NumberText(halfHeight)));
        return std::nullopt;
    }

    Polygon box;
    box.count = 4;
    box.vertices[0] = Vec2(-halfWidth, -halfHeight);
    box.vertices[1] = Vec2(halfWidth, -halfHeight);
    box.vertices[2] = Vec2(halfWidth, halfHeight);
    box.vertices[3] = Vec2(-halfWidth, halfHeight);
    box.normals[0] = Vec2(0, -1);
    box.normals[1] = Vec2(1, 0);
    box.normals[2] = Vec2(0, 1);
    box.normals[3] = Vec2(-1, 0);
    box.centroid = Vec2(0, 0);
    return box;
}

/// What the Make functions return, World::CreateShape accepts: the one rule of
/// meff/validity.h, with its reason (a box too large for its area to be a float, or too thin
/// for its edges to have a direction). A refused polygon is reported, and the empty Polygon
/// (no vertices, which World::CreateShape refuses) returned.
Polygon Accepted(Polygon polygon, const char* caller)
{
    if (const std::optional<Refusal> refusal = CheckPolygon(polygon))
    {
        ReportError(RefusedArgument(std::string(caller) + ": " + refusal->reason, *refusal));
        return {};
    }
    return polygon;
}

[[nodiscard]] bool CheckDensity(Real density, const char* caller)
{
    return (IsValid(density) && density >= 0) ||
           Refuse(InvalidArgument(std::string(caller) + ": density must be finite and >= 0, got " +
                                  NumberText(density)));
}

} // namespace

Polygon MakePolygon(std::span<const Vec2> points)
{
    const std::size_t pointCount = points.size();
    if (pointCount < 3 || pointCount > std::size_t(kMaxPolygonVertices))
    {
        ReportError(InvalidArgument("MakePolygon: needs 3 to " +
                                    std::to_string(kMaxPolygonVertices) + " points, got " +
                                    std::to_string(pointCount)));
        return {};
    }
    for (std::size_t i = 0; i < pointCount; ++i)
    {
        if (!points[i].IsValid())
        {
            ReportError(InvalidArgument("MakePolygon: point " + std::to_string(i) +
                                        " has a non-finite coordinate " + NumberText(points[i])));
            return {};
        }
    }

    const int n = static_cast<int>(pointCount);

    // Weld points closer than the tolerance: each point is compared with the points kept so
    // far and dropped if it is near one of them (so the first of a cluster survives).
    const Real weldSquared = kPolygonWeldTolerance * kPolygonWeldTolerance;
    Vec2 ps[kMaxPolygonVertices];
    int uniqueCount = 0;
    for (int i = 0; i < n; ++i)
    {
        const Vec2 v = points[i];
        bool unique = true;
        for (int j = 0; j < uniqueCount; ++j)
        {
            if (DistanceSquared(v, ps[j]) < weldSquared)
            {
                unique = false;
                break;
            }
        }
        if (unique)
        {
            ps[uniqueCount++] = v;
        }
    }

    if (uniqueCount < 3)
    {
        ReportError(InvalidArgument("MakePolygon: only " + std::to_string(uniqueCount) +
                                    " distinct point(s) remain after welding points closer than " +
                                    NumberText(kPolygonWeldTolerance) + " m; need 3"));
        return {};
    }

    // Convex hull by gift wrapping. Start at the right-most point (lowest on a tie).
    int i0 = 0;
    Real x0 = ps[0].x;
    for (int i = 1; i < uniqueCount; ++i)
    {
        const Real x = ps[i].x;
        if (x > x0 || (x == x0 && ps[i].y < ps[i0].y))
        {
            i0 = i;
            x0 = x;
        }
    }

    int hull[kMaxPolygonVertices];
    int m = 0;
    int ih = i0;
    for (;;)
    {
        // A hull cannot have more vertices than there are points; more means round-off made
        // the wrap cycle (Box2D asserts here).
        if (m >= uniqueCount)
        {
            ReportError(
                InvalidArgument("MakePolygon: the convex hull of the points is ill-conditioned "
                                "(gift wrapping did not close)"));
            return {};
        }
        hull[m] = ih;

        // The next hull point: every other point lies to its left. Of exactly collinear
        // candidates the farthest wins, so points in the middle of a hull edge are dropped.
        int ie = 0;
        for (int j = 1; j < uniqueCount; ++j)
        {
            if (ie == ih)
            {
                ie = j;
                continue;
            }

            const Vec2 r = ps[ie] - ps[hull[m]];
            const Vec2 v = ps[j] - ps[hull[m]];
            const Real c = Cross(r, v);
            if (c < 0)
            {
                ie = j;
            }
            if (c == 0 && v.LengthSquared() > r.LengthSquared())
            {
                ie = j;
            }
        }

        ++m;
        ih = ie;
        if (ie == i0)
        {
            break;
        }
    }

    if (m < 3)
    {
        ReportError(
            InvalidArgument("MakePolygon: the points are collinear (their convex hull has " +
                            std::to_string(m) + " vertices)"));
        return {};
    }

    Polygon polygon;
    polygon.count = m;
    for (int i = 0; i < m; ++i)
    {
        polygon.vertices[i] = ps[hull[i]];
    }

    // Outward normals: each edge turned a quarter turn clockwise. Welding keeps edges at least
    // kPolygonWeldTolerance long, so none is zero.
    for (int i = 0; i < m; ++i)
    {
        const int i1 = i;
        const int i2 = i + 1 < m ? i + 1 : 0;
        const Vec2 edge = polygon.vertices[i2] - polygon.vertices[i1];
        polygon.normals[i] = Cross(edge, Real(1));
        polygon.normals[i].Normalize();
    }

    Real area = 0;
    polygon.centroid = ComputeCentroid(polygon.vertices, m, area);
    // Box2D asserts area > b2_epsilon: nearly collinear points give a sliver it cannot use.
    if (!(area > kEpsilon))
    {
        ReportError(InvalidArgument("MakePolygon: the points are (nearly) collinear: hull area " +
                                    NumberText(area) + " m^2 is not above " +
                                    NumberText(kEpsilon)));
        return {};
    }
    return Accepted(polygon, "MakePolygon");
}

Polygon MakeBox(Real halfWidth, Real halfHeight)
{
    const std::optional<Polygon> box = MakeCenteredBox(halfWidth, halfHeight, "MakeBox");
    return box ? Accepted(*box, "MakeBox") : Polygon{};
}

Polygon MakeOffsetBox(Real halfWidth, Real halfHeight, Vec2 center, Real angle)
{
    const std::optional<Polygon> centred = MakeCenteredBox(halfWidth, halfHeight, "MakeOffsetBox");
    if (!centred)
    {
        return {};
    }
    if (!center.IsValid() || !IsValid(angle))
    {
        ReportError(InvalidArgument("MakeOffsetBox: center and angle must be finite, got center " +
                                    NumberText(center) + ", angle " + NumberText(angle)));
        return {};
    }
    Polygon box = *centred;

    box.centroid = center;

    Transform xf;
    xf.p = center;
    xf.q.Set(angle);
    for (int i = 0; i < box.count; ++i)
    {
        box.vertices[i] = Mul(xf, box.vertices[i]);
        box.normals[i] = Mul(xf.q, box.normals[i]);
    }
    return Accepted(box, "MakeOffsetBox");
}

MassData ComputeMass(const Circle& circle, Real density)
{
    if (!CheckDensity(density, "ComputeMass(Circle)"))
    {
        return {};
    }

    MassData massData;
    massData.mass = density * kPi * circle.radius * circle.radius;
    massData.center = circle.center;
    // Inertia about the body origin: the disc's own plus the parallel-axis term.
    massData.rotationalInertia = massData.mass * (Real(0.5) * circle.radius * circle.radius +
                                                  Dot(circle.center, circle.center));
    return massData;
}

MassData ComputeMass(const Polygon& polygon, Real density)
{
    if (!CheckDensity(density, "ComputeMass(Polygon)"))
    {
        return {};
    }
    if (polygon.count < 3 || polygon.count > kMaxPolygonVertices)
    {
        ReportError(InvalidArgument("ComputeMass(Polygon): polygon has " +
                                    std::to_string(polygon.count) +
                                    " vertices; build it with MakePolygon or MakeBox"));
        return {};
    }

    // Sum over a fan of triangles (s, v[i], v[i+1]) from the first vertex s. For one triangle
    // with edges e1, e2 from s and D = cross(e1, e2):
    //   area = D / 2,  centroid - s = (e1 + e2) / 3,
    //   integral of |p - s|^2 dA = (D / 12) * (e1.e1 + e1.e2 + e2.e2)   (per axis summed).
    Vec2 center(0, 0);
    Real area = 0;
    Real inertia = 0;

    const Vec2 s = polygon.vertices[0];
    const Real inv3 = Real(1) / Real(3);

    for (int i = 0; i < polygon.count; ++i)
    {
        const Vec2 e1 = polygon.vertices[i] - s;
        const Vec2 e2 =
            i + 1 < polygon.count ? polygon.vertices[i + 1] - s : polygon.vertices[0] - s;

        const Real d = Cross(e1, e2);

        const Real triangleArea = Real(0.5) * d;
        area += triangleArea;

        center += triangleArea * inv3 * (e1 + e2);

        const Real ex1 = e1.x, ey1 = e1.y;
        const Real ex2 = e2.x, ey2 = e2.y;

        const Real intx2 = ex1 * ex1 + ex2 * ex1 + ex2 * ex2;
        const Real inty2 = ey1 * ey1 + ey2 * ey1 + ey2 * ey2;

        inertia += (Real(0.25) * inv3 * d) * (intx2 + inty2);
    }

    MassData massData;
    massData.mass = density * area;

    center *= Real(1) / area;
    massData.center = center + s;

    // Inertia about s, moved to the centre of mass and from there to the body origin.
    massData.rotationalInertia = density * inertia;
    massData.rotationalInertia +=
        massData.mass * (Dot(massData.center, massData.center) - Dot(center, center));
    return massData;
}

AABB ComputeAABB(const Circle& circle, const Transform& xf)
{
    const Vec2 p = xf.p + Mul(xf.q, circle.center);
    AABB aabb;
    aabb.lowerBound = Vec2(p.x - circle.radius, p.y - circle.radius);
    aabb.upperBound = Vec2(p.x + circle.radius, p.y + circle.radius);
    return aabb;
}

AABB ComputeAABB(const Segment& segment, const Transform& xf)
{
    const Vec2 v1 = Mul(xf, segment.point1);
    const Vec2 v2 = Mul(xf, segment.point2);

    const Vec2 lower = Min(v1, v2);
    const Vec2 upper = Max(v1, v2);

    const Vec2 r(segment.radius, segment.radius);
    AABB aabb;
    aabb.lowerBound = lower - r;
    aabb.upperBound = upper + r;
    return aabb;
}

AABB ComputeAABB(const Polygon& polygon, const Transform& xf)
{
    Vec2 lower = Mul(xf, polygon.vertices[0]);
    Vec2 upper = lower;
    for (int i = 1; i < polygon.count; ++i)
    {
        const Vec2 v = Mul(xf, polygon.vertices[i]);
        lower = Min(lower, v);
        upper = Max(upper, v);
    }

    const Vec2 r(polygon.radius, polygon.radius);
    AABB aabb;
    aabb.lowerBound = lower - r;
    aabb.upperBound = upper + r;
    return aabb;
}

AABB ComputeAABB(const ChainSegment& segment, const Transform& xf)
{
    // The ghosts do not collide: the box is the solid part's (b2ChainShape::ComputeAABB).
    return ComputeAABB(segment.segment, xf);
}

} // namespace meff
