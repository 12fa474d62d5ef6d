// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Queries against one shape: ray casts, as Box2D 2.4.1's b2CircleShape, b2PolygonShape and
// (two-sided) b2EdgeShape::RayCast, and point containment, as their TestPoint, in the same
// floating-point order so that fractions and normals agree with Box2D bit for bit in float
// builds.
//
// The ray is the segment p1 → p2; a point on it is p1 + t·(p2 − p1) and t is the "fraction".
// A ray that starts inside a shape does not hit it. These functions do not check their
// arguments (they are the inner loop of the world's queries); World::CastRay does.
#pragma once

#include "meff/collision.h"
#include "meff/math.h"

namespace meff
{

/// A ray from p1 towards p2, for the shapes' ray casts.
struct RayCastInput
{
    Vec2 p1{};            ///< start of the ray, world coordinates (m)
    Vec2 p2{};            ///< end of the ray at fraction 1 (m)
    Real maxFraction = 1; ///< hits beyond p1 + maxFraction·(p2 − p1) are not reported
};

/// Where a ray hit a shape.
struct RayCastOutput
{
    Vec2 normal{};     ///< unit surface normal at the hit, world coordinates
    Real fraction = 0; ///< the hit is at p1 + fraction·(p2 − p1), in [0, maxFraction]
};

/// The ray against the solid circle at `xf`. False when it misses, starts inside, is shorter
/// than epsilon, or hits beyond maxFraction.
bool RayCast(const Circle& circle, const Transform& xf, const RayCastInput& input,
             RayCastOutput& output);
/// The ray against the polygon's outline at `xf`. The polygon's radius (skin) is ignored, as
/// Box2D 2.4.1 ignores it: the hit is on the sharp outline, up to polygonSkin (0.01 m) inside
/// the surface the solver keeps other shapes at.
bool RayCast(const Polygon& polygon, const Transform& xf, const RayCastInput& input,
             RayCastOutput& output);
/// The ray against the two-sided segment at `xf`; the normal faces the side the ray comes from.
/// The segment's radius (skin) is ignored, as Box2D 2.4.1 ignores it. A ray parallel to the
/// segment never hits it.
bool RayCast(const Segment& segment, const Transform& xf, const RayCastInput& input,
             RayCastOutput& output);

/// The ray against the one-sided segment at `xf`, as b2EdgeShape::RayCast after SetOneSided:
/// only a ray that starts on the solid side (right of point1 → point2) can hit it; the normal
/// is the segment's. The ghosts play no part.
bool RayCast(const ChainSegment& segment, const Transform& xf, const RayCastInput& input,
             RayCastOutput& output);

/// The ray against the capsule's rounded outline at `xf`: the earliest entry into one of its
/// two sides (the core pushed out by the radius) or its caps. False as for the circle.
bool RayCast(const Capsule& capsule, const Transform& xf, const RayCastInput& input,
             RayCastOutput& output);
/// The ray against a rounded polygon's outline (its `radius` the rounding; count 2 is a
/// capsule): the edges pushed out by the radius and the arcs about the vertices.
bool RayCastRounded(const Polygon& polygon, const Transform& xf, const RayCastInput& input,
                    RayCastOutput& output);

/// Is the world point inside or on the circle at `xf`?
bool TestPoint(const Circle& circle, const Transform& xf, Vec2 point);
/// Is the world point inside or on the polygon's outline at `xf`? The skin is not counted.
bool TestPoint(const Polygon& polygon, const Transform& xf, Vec2 point);
/// Always false: a segment has no inside (as Box2D's b2EdgeShape::TestPoint).
bool TestPoint(const Segment& segment, const Transform& xf, Vec2 point);
bool TestPoint(const ChainSegment& segment, const Transform& xf, Vec2 point);
/// Within the radius of the capsule's core segment.
bool TestPoint(const Capsule& capsule, const Transform& xf, Vec2 point);
/// Inside the core polygon or within its radius of it (the rounded outline).
bool TestPointRounded(const Polygon& polygon, const Transform& xf, Vec2 point);

} // namespace meff
