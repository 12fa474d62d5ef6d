// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// A kinematic character's moves, as Box2D v3's mover (b2World_CollideMover, b2SolvePlanes,
// b2ClipVector), written for meff: the game moves a capsule itself and asks the world only
// where it may go. One move of a character at `position` with velocity v over dt:
//
//   target = position + v·dt
//   planes = world.CollideMover(capsule at target)        // what it would touch there
//   fix    = SolvePlanes(planes).translation               // the least push out of them all
//   f      = world.CastMover(capsule at position, target + fix − position)   // no tunnelling
//   position += f·(target + fix − position)
//   v      = ClipVector(v, planes)                          // no speed into what it rests on
//
// World::MoveCharacter does exactly this move (a game may also write its own, with its own
// push limits or steps up, from the pieces).
//
// The planes are linear: each says how far the mover's surface is from one shape's surface
// along that shape's normal, so a translation d changes its separation by normal·d.
#pragma once

#include "meff/math.h"

#include <span>

namespace meff
{

/// One shape near the mover, as a plane the mover must stay on the outside of.
struct CollisionPlane
{
    Vec2 normal{};             ///< unit, from the shape towards the mover
    Real separation = 0;       ///< gap between the surfaces where the mover was collided (m);
                               ///< negative when they overlap
    Real pushLimit = kMaxReal; ///< the most this plane may push the mover (m, ≥ 0): a small
                               ///< value lets a character walk through soft things
    bool clipVelocity = true;  ///< does ClipVector take the speed into this plane away
    Real push = 0;             ///< out: how far SolvePlanes pushed along the normal (m)
};

/// What SolvePlanes finds.
struct PlaneSolverResult
{
    Vec2 translation{}; ///< where to move from where the mover was collided (m)
    int iterations = 0; ///< sweeps over the planes it took
};

/// The translation, closest to `delta` (m; 0 when the mover was collided at its target) in
/// projected Gauss-Seidel's sense, that leaves every plane's separation ≥ 0 — each plane
/// pushing along its normal only, at most its pushLimit. Sweeps over the planes until no
/// push changes by more than `tolerance` (m), at most 20 times. Sets each plane's `push`.
PlaneSolverResult SolvePlanes(Vec2 delta, std::span<CollisionPlane> planes,
                              Real tolerance = Real(1e-4));

/// The most planes World::MoveCharacter gathers for one move: it needs no memory of its own,
/// and a capsule rarely touches more than a handful of shapes at once.
inline constexpr int kMaxMoverPlanes = 16;

/// One move of World::MoveCharacter.
struct CharacterMove
{
    Vec2 translation{}; ///< how far the mover goes this move (m)
    Vec2 velocity{};    ///< its velocity for the next move, clipped by the planes (m/s)
    int planeCount = 0; ///< the planes it met at its target (at most kMaxMoverPlanes)
};

/// The velocity without its parts into the planes that pushed (push > 0, clipVelocity):
/// v ← v − min(0, v·n)·n for each, in two sweeps so that a corner of two planes stops it.
Vec2 ClipVector(Vec2 velocity, std::span<const CollisionPlane> planes);

} // namespace meff
