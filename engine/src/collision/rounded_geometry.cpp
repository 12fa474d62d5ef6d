// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Capsules and rounded polygons (Box2D v3's shapes; Box2D 2.4.1 has neither): the capsule as
// a two-vertex rounded polygon, exact mass properties of the rounded outline, and bounding boxes.
#include "meff/collision.h"

#include "core/report_error.h"
#include "meff/error.h"
#include "meff/validity.h"

#include <cmath>

namespace meff
{

using detail::Refuse;
using detail::ReportError;

Polygon MakeCapsulePolygon(const Capsule& capsule)
{
    Polygon polygon;
    polygon.count = 2;
    polygon.vertices[0] = capsule.center1;
    polygon.vertices[1] = capsule.center2;
    Vec2 normal = Cross(capsule.center2 - capsule.center1, Real(1));
    normal.Normalize();
    polygon.normals[0] = normal;
    polygon.normals[1] = -normal;
    polygon.centroid = Real(0.5) * (capsule.center1 + capsule.center2);
    polygon.radius = capsule.radius;
    return polygon;
}

namespace
{

/// One piece of a rounded outline: its mass, centroid and inertia about that centroid.
struct Piece
{
    Real mass = 0;
    Vec2 center{};
    Real centralInertia = 0;
};

/// The rectangle of width r standing outside the edge from v1 to v2 (outward normal n):
/// m = ρ·L·r, centred r/2 outside the edge's middle, I = m(L² + r²)/12 about its centre.
Piece EdgeBand(Vec2 v1, Vec2 v2, Vec2 n, Real r, Real density)
{
    const Real length = Distance(v1, v2);
    Piece piece;
    piece.mass = density * length * r;
    piece.center = Real(0.5) * (v1 + v2) + (Real(0.5) * r) * n;
    piece.centralInertia = piece.mass * (length * length + r * r) / Real(12);
    return piece;
}

/// The disc sector of radius r at vertex v between the outward normals nBefore and nAfter of
/// the edges meeting there (angle θ, counter-clockwise). m = ρθr²/2; its centroid lies
/// 4r·sin(θ/2)/(3θ) from v along the bisector, and I about v is m·r²/2, so about the centroid
/// m·r²/2 − m·d² (parallel-axis theorem).
Piece CornerSector(Vec2 v, Vec2 nBefore, Vec2 nAfter, Real r, Real density)
{
    // A convex outline turns left at every vertex, so the sine is ≥ 0 (exactly 0 and the
    // cosine −1 at a capsule's caps, θ = π).
    const Real theta = std::atan2(Max(Cross(nBefore, nAfter), Real(0)), Dot(nBefore, nAfter));
    const Real half = Real(0.5) * theta;
    const Vec2 bisector{std::cos(half) * nBefore.x - std::sin(half) * nBefore.y,
                        std::sin(half) * nBefore.x + std::cos(half) * nBefore.y};
    const Real d = Real(4) * r * std::sin(half) / (Real(3) * theta);
    Piece piece;
    piece.mass = density * Real(0.5) * theta * r * r;
    piece.center = v + d * bisector;
    piece.centralInertia = piece.mass * (Real(0.5) * r * r - d * d);
    return piece;
}

void Add(MassData& total, Vec2& moment, const Piece& piece)
{
    total.mass += piece.mass;
    moment += piece.mass * piece.center;
    total.rotationalInertia += piece.centralInertia + piece.mass * Dot(piece.center, piece.center);
}

} // namespace

MassData ComputeRoundedMass(const Polygon& polygon, Real density)
{
    if (!(density >= 0) || !std::isfinite(double(density)))
    {
        ReportError(InvalidArgument("ComputeRoundedMass: density must be finite and >= 0, got " +
                                    NumberText(density)));
        return {};
    }
    if (polygon.count < 2 || polygon.count > kMaxPolygonVertices)
    {
        ReportError(InvalidArgument("ComputeRoundedMass: polygon has " +
                                    std::to_string(polygon.count) +
                                    " vertices; build it with MakePolygon, MakeBox or "
                                    "MakeCapsulePolygon"));
        return {};
    }
    MassData total;
    Vec2 moment{0, 0};
    if (polygon.count >= 3)
    {
        // The core: Box2D's polygon mass, already about the body origin.
        const MassData core = ComputeMass(polygon, density);
        total.mass = core.mass;
        moment = core.mass * core.center;
        total.rotationalInertia = core.rotationalInertia;
    }
    const Real r = polygon.radius;
    const int n = polygon.count;
    for (int i = 0; i < n; ++i)
    {
        const int next = i + 1 < n ? i + 1 : 0;
        const int before = i > 0 ? i - 1 : n - 1;
        Add(total, moment,
            EdgeBand(polygon.vertices[i], polygon.vertices[next], polygon.normals[i], r, density));
        Add(total, moment,
            CornerSector(polygon.vertices[i], polygon.normals[before], polygon.normals[i], r,
                         density));
    }
    total.center = total.mass > 0 ? (Real(1) / total.mass) * moment : polygon.centroid;
    return total;
}

MassData ComputeMass(const Capsule& capsule, Real density)
{
    return ComputeRoundedMass(MakeCapsulePolygon(capsule), density);
}

AABB ComputeAABB(const Capsule& capsule, const Transform& xf)
{
    const Vec2 v1 = Mul(xf, capsule.center1);
    const Vec2 v2 = Mul(xf, capsule.center2);
    const Vec2 r(capsule.radius, capsule.radius);
    AABB aabb;
    aabb.lowerBound = Min(v1, v2) - r;
    aabb.upperBound = Max(v1, v2) + r;
    return aabb;
}

} // namespace meff
