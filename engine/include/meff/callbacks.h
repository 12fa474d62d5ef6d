// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The callbacks a game installs in a world to take part in its step: pre-solve and the custom
// contact filter.
#pragma once

#include "meff/collision.h"
#include "meff/ids.h"

#include <functional>

namespace meff
{

/// What a pre-solve callback sees of one touching contact (Box2D 2.4.1's PreSolve).
struct PreSolveContact
{
    ShapeId shapeA{};                   ///< the contact's first shape
    ShapeId shapeB{};                   ///< the contact's second shape
    BodyId bodyA{};                     ///< shapeA's body
    BodyId bodyB{};                     ///< shapeB's body
    const Manifold* manifold = nullptr; ///< the fresh manifold (≥ 1 point), body frames
    WorldManifold worldManifold{};      ///< its normal (A to B), points and separations (world)
};

/// Called inside World::Step for every touching, non-sensor contact each time its manifold is
/// updated; returning false disables the contact until its next update (not solved, not
/// reported, no hit event). Contact begin/end events are geometric and are not affected.
using PreSolveCallback = std::function<bool(const PreSolveContact& contact)>;

/// Decides whether two shapes get a contact (Box2D 2.4.1's b2ContactFilter::ShouldCollide,
/// Box2D v3's custom filter). Asked only for pairs the built-in rules let through — filter
/// bits and groups, a dynamic body among the two, no joint between them without
/// collideConnected, not on one body — so it adds to them and never overrides them, as a
/// b2ContactFilter that calls the base class first. Returning false: no contact; the pair is
/// asked again the next time the broad phase finds it (when a shape's fat box moves).
using CustomFilterCallback = std::function<bool(ShapeId shapeA, ShapeId shapeB)>;

} // namespace meff
