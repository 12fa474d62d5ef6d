// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Shape definitions: material and filtering of one piece of geometry attached to a body.
#pragma once

#include "meff/math.h"

#include <cstdint>

namespace meff
{

/// Collision filtering, as Box2D: two shapes collide when each one's category is in the other's
/// mask, unless they share a non-zero group (positive: always collide, negative: never).
struct Filter
{
    std::uint16_t categoryBits = 0x0001; ///< what this shape is (usually one bit)
    std::uint16_t maskBits = 0xFFFF;     ///< the categories it collides with
    std::int16_t groupIndex = 0;         ///< non-zero: a group that always/never collides
};

/// Everything but the geometry needed to create a shape.
struct ShapeDef
{
    Real density = 1;              ///< kg/m² (area density); 0 gives the shape no mass
    Real friction = Real(0.6);     ///< Coulomb coefficient, ≥ 0; mixed as sqrt(μA·μB)
    Real restitution = 0;          ///< coefficient e in [0,1]; mixed as max(eA, eB)
    Real restitutionThreshold = 1; ///< m/s; slower approaches do not bounce; mixed as min
    /// Conveyor belt: the shape's surface slides over the body at this speed (m/s), clockwise
    /// round the shape (on a belt's top face, whose outward normal is +y, positive moves +x).
    /// Friction drives a contact's tangential relative velocity to the two shapes' sum, as
    /// Box2D v3's tangentSpeed (2.4.1: b2Contact::SetTangentSpeed with sA + sB). Finite.
    Real tangentSpeed = 0;
    /// Rolling resistance c (dimensionless, ≥ 0; Box2D v3's rollingResistance): a contact
    /// resists the two bodies' relative spin with a torque of at most c·r·N, N its normal
    /// force and r the larger rolling radius of the two shapes (a circle's or a capsule's
    /// radius, a rounded polygon's rounding; 0 for sharp polygons and segments, which do not
    /// roll). A disc rolling on flat ground then slows at
    /// (2/3)·c·g and stops. Mixed as max(cA, cB). Box2D 2.4.1 has none (meff validate refuses it).
    Real rollingResistance = 0;
    Filter filter{}; ///< which shapes it collides with
    /// Detects overlap, never collides (Box2D 2.4.1's sensor fixture): its contacts are never
    /// solved; they touch while the shapes overlap (GJK distance < 10·epsilon, radii included)
    /// and are reported by World::GetSensorBeginEvents/GetSensorEndEvents, not among the
    /// contact events. A sensor's density still counts towards its body's mass, as in Box2D.
    bool isSensor = false;
    /// Report this shape's contacts that hit faster than Tolerances::hitEventThreshold in
    /// World::GetContactHitEvents (Box2D v3's enableHitEvents; either shape of a pair enables).
    bool enableHitEvents = false;
    std::uint64_t userData = 0; ///< yours; meff never reads it
};

} // namespace meff
