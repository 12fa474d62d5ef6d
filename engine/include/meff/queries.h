// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// What the world's queries take and give: the query filter, ray and shape cast results and
// callbacks, overlap callbacks, and explosions.
#pragma once

#include "meff/function_ref.h"
#include "meff/ids.h"
#include "meff/math.h"

#include <cstdint>

namespace meff
{

/// Which shapes a world query sees, as Box2D v3's b2QueryFilter: a shape is seen when its
/// Filter::categoryBits share a bit with maskBits and its Filter::maskBits share a bit with
/// categoryBits. The default sees every shape that can collide with anything (a shape whose
/// categoryBits or maskBits are 0 is never seen). Group indices are not looked at.
struct QueryFilter
{
    std::uint16_t categoryBits = 0xFFFF; ///< what the query is
    std::uint16_t maskBits = 0xFFFF;     ///< what it wants to find
};

/// A radial impulse at one instant (Box2D v3's b2ExplosionDef, World::Explode).
struct ExplosionDef
{
    Vec2 position{};                 ///< centre (m)
    Real radius = 1;                 ///< full strength up to this distance from a shape (m, ≥ 0)
    Real falloff = 0;                ///< then fading linearly to 0 over this distance (m, ≥ 0)
    Real impulsePerLength = 1;       ///< N·s per metre of the shape's width facing the centre;
                                     ///< negative pulls in (an implosion)
    std::uint16_t maskBits = 0xFFFF; ///< only shapes whose category is in the mask
};

/// The closest hit of a ray or shape cast.
struct RayResult
{
    ShapeId shape{}; ///< null when nothing was hit
    Vec2 point{};    ///< world point on the hit shape's surface (m)
    Vec2 normal{};   ///< unit normal of that surface at the point
    /// Of the translation travelled to the hit, in [0, 1] (a CastRay callback that returns
    /// more than 1 lengthens the ray, as in Box2D, and can report fractions beyond 1).
    Real fraction = 0;
    bool hit = false; ///< false when nothing was hit
};

/// Called for each shape a ray or shape cast hits, in broad-phase order (not sorted by
/// distance), with the hit point, surface normal and fraction of the translation. What it
/// returns steers the cast, as Box2D's b2RayCastCallback::ReportFixture:
///   −1 (any negative): ignore this shape and go on, the ray unchanged;
///    0: stop the cast now;
///    the fraction it was given: clip the ray there, so only closer hits are reported next
///    (returning fraction for every call finds the closest hit);
///    1: go on with the whole ray (all hits).
/// Any positive value clips the ray to that fraction, as Box2D.
using CastCallback = FunctionRef<Real(ShapeId shape, Vec2 point, Vec2 normal, Real fraction)>;

/// Called for each shape an overlap query finds; return false to stop the query.
using OverlapCallback = FunctionRef<bool(ShapeId shape)>;

} // namespace meff
