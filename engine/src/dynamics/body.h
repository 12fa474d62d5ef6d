// A body inside the world: its state, mass, and its place in Box2D 2.4.1's intrusive lists
// (world body list, shape list, contact and joint edge lists, all newest first), which fix the
// order in which islands — and so the solver — visit constraints.
#pragma once

#include "meff/body.h"
#include "meff/ids.h"
#include "meff/math.h"

#include <cstdint>
#include <vector>

namespace meff::detail
{

inline constexpr std::int32_t kNullIndex = -1;

struct Body
{
    std::uint32_t generation = 0; ///< matches BodyId::generation while alive
    bool alive = false;
    BodyType type = BodyType::Static;

    Transform xf; ///< body origin transform, kept in sync with the sweep
    Sweep sweep;  ///< centre of mass and angle
    Vec2 linearVelocity;
    Real angularVelocity = 0;
    Vec2 force;      ///< accumulated this step (N)
    Real torque = 0; ///< accumulated this step (N·m)

    Real mass = 0, invMass = 0; ///< kg, 1/kg
    Real I = 0, invI = 0;       ///< about the centre of mass: kg·m², 1/(kg·m²)
    Real linearDamping = 0, angularDamping = 0, gravityScale = 1;
    bool fixedRotation = false;
    bool bullet = false;
    bool allowSleep = true;
    bool awake = true;  ///< static bodies are never awake, as in Box2D
    Real sleepTime = 0; ///< s the body has rested within the sleep tolerances
    std::uint64_t userData = 0;

    std::int32_t prev = kNullIndex, next = kNullIndex; ///< world body list
    std::vector<std::int32_t> shapes;                  ///< shape indices, newest first
    std::vector<ShapeId> shapeIds;                     ///< the same as ids, for the API
    std::int32_t contactList = kNullIndex;             ///< head contact edge key
    std::int32_t jointList = kNullIndex;               ///< head joint edge key

    std::int32_t islandIndex = kNullIndex; ///< solver index while its island is solved
    bool islandFlag = false;
};

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
