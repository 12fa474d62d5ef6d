// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// A body inside the world: its state, mass, and its place in Box2D 2.4.1's intrusive lists
// (world body list, shape list, contact and joint edge lists, all newest first), which fix the
// order in which islands — and so the solver — visit constraints.
#pragma once

#include "meff/body.h"
#include "meff/ids.h"
#include "meff/math.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace meff::detail
{

inline constexpr std::int32_t kNullIndex = -1;

struct Body
{
    // What the island search, the contact preparation and the solver read of a body comes
    // first, together (within 64 bytes), so that visiting a body costs one cache line, not
    // three: the preparation by colour visits bodies in an order that is no use to the cache.
    std::int32_t islandIndex = kNullIndex; ///< solver index while its island is solved
    bool islandFlag = false;
    bool alive = false;
    BodyType type = BodyType::Static;
    bool awake = true;                     ///< static bodies are never awake, as in Box2D
    Real invMass = 0, invI = 0;            ///< 1/kg, 1/(kg·m²) about the centre of mass
    Sweep sweep;                           ///< centre of mass and angle
    std::int32_t contactList = kNullIndex; ///< head contact edge key
    std::int32_t jointList = kNullIndex;   ///< head joint edge key
    std::uint32_t generation = 0;          ///< matches BodyId::generation while alive

    Transform xf; ///< body origin transform, kept in sync with the sweep
    Vec2 linearVelocity;
    Real angularVelocity = 0;
    Vec2 force;      ///< accumulated this step (N)
    Real torque = 0; ///< accumulated this step (N·m)

    Real mass = 0; ///< kg
    Real I = 0;    ///< about the centre of mass: kg·m²
    Real linearDamping = 0, angularDamping = 0, gravityScale = 1;
    bool fixedRotation = false;
    bool bullet = false;
    bool allowSleep = true;
    Real sleepTime = 0; ///< s the body has rested within the sleep tolerances
    std::uint64_t userData = 0;

    std::int32_t prev = kNullIndex, next = kNullIndex; ///< world body list
    std::vector<std::int32_t> shapes;                  ///< shape indices, newest first
    std::vector<ShapeId> shapeIds;                     ///< the same as ids, for the API
};
// In float builds; with MEFF_DOUBLE the masses and the sweep double in size and spill over.
static_assert(sizeof(Real) != sizeof(float) ||
                  offsetof(Body, generation) + sizeof(Body::generation) <= 64,
              "the fields read per visit fit in one cache line's length");

/// Wakes a body and restarts its rest time (Box2D 2.4.1's b2Body::SetAwake(true)); static
/// bodies stay as they are. Every wake rule — API calls, contacts that begin or end, joint
/// changes, continuous collision — goes through here.
inline void WakeBody(Body& body)
{
    if (body.type == BodyType::Static)
    {
        return;
    }
    body.awake = true;
    body.sleepTime = 0;
}

/// Puts a body to sleep (Box2D 2.4.1's b2Body::SetAwake(false)): a sleeping body keeps no
/// velocity, force or rest time, so waking it later starts from rest.
inline void PutBodyToSleep(Body& body)
{
    if (body.type == BodyType::Static)
    {
        return;
    }
    body.awake = false;
    body.sleepTime = 0;
    body.linearVelocity = {0, 0};
    body.angularVelocity = 0;
    body.force = {0, 0};
    body.torque = 0;
}

/// Sets xf from the sweep's current centre and angle.
inline void SynchronizeTransform(Body& body)
{
    body.xf.q.Set(body.sweep.a);
    body.xf.p = body.sweep.c - Mul(body.xf.q, body.sweep.localCenter);
}

} // namespace meff::detail
