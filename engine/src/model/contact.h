// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// A contact: a pair of shapes whose fattened boxes overlap. It owns the manifold, whose
// impulses carry from step to step (warm starting), and sits on both bodies' edge lists.
#pragma once

#include "collision/manifold_internal.h"
#include "meff/collision.h"

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace meff::detail
{

struct Shape;

/// Links a contact or joint into one body's edge list. An edge key is index·2 + side, where
/// side 0 lives on the first body's list and side 1 on the second's.
struct Edge
{
    std::int32_t other = -1; ///< the body at the other end
    std::int32_t prev = -1;  ///< previous edge key on this body's list
    std::int32_t next = -1;  ///< next edge key on this body's list
};

inline std::int32_t EdgeKey(std::int32_t index, int side)
{
    return index * 2 + side;
}
inline std::int32_t EdgeOwner(std::int32_t key)
{
    return key >> 1;
}
inline int EdgeSide(std::int32_t key)
{
    return key & 1;
}

struct Contact
{
    enum Flags : std::uint32_t
    {
        Touching = 1u << 0,  ///< the manifold has points
        Filter = 1u << 1,    ///< re-check filtering before the next narrow phase
        Island = 1u << 2,    ///< already added to an island this step
        Toi = 1u << 3,       ///< `toi` holds a valid time of impact for this step
        Disabled = 1u << 4,  ///< not solved until its manifold is next updated: the pre-solve
                             ///< callback refused it, or a time-of-impact event found it not
                             ///< touching (Box2D: !IsEnabled())
        Sensor = 1u << 5,    ///< a shape is a sensor: overlap test only, never solved
        HitEvents = 1u << 6, ///< a shape asked for hit events
        PoseKept = 1u << 7,  ///< keptPose is the pose the manifold was computed at
        /// The continuous stage sweeps it: no sensor, and a body static, kinematic or a bullet.
        /// Set at creation and fixed: types, bullets and sensors never change.
        Swept = 1u << 8,
    };

    // What the list walks read (the narrow phase's, the islands') comes first, together, so
    // that a walk touches one or two cache lines of each contact, not three.
    bool alive = false;
    std::uint32_t flags = 0;
    std::int32_t shapeA = -1, shapeB = -1;
    std::int32_t bodyA = -1, bodyB = -1;
    std::int32_t prev = -1, next = -1; ///< world contact list
    Edge edges[2];                     ///< [0] on bodyA's list, [1] on bodyB's
    Manifold manifold;
    Real friction = 0;             ///< sqrt(μA·μB)
    Real restitution = 0;          ///< max(eA, eB)
    Real restitutionThreshold = 0; ///< min of the two (m/s)
    /// The friction rows' target tangential speed of B's surface over A's along
    /// cross(normal, 1): sA + sB (ShapeDef::tangentSpeed; each turns clockwise round its
    /// own shape, and A's outward normal is B's reversed, hence the sum) (m/s).
    Real tangentSpeed = 0;
    /// max(cA, cB)·max(rA, rB) (ShapeDef::rollingResistance, rolling radii: Shape's
    /// RollingRadius) (m): the spin row's impulse is at most this × the normal impulse.
    Real rollingResistance = 0;
    Real rollingImpulse = 0; ///< the spin row's, kept for the next step's warm start (N·m·s)
    /// The shapes' collision radii (Shape::Radius), copied at creation (a shape never changes
    /// its own), so that the solver and the reports need not visit the shapes.
    Real radiusA = 0, radiusB = 0;
    /// Creation order (WorldState::contactSerial): the list holds newer contacts first.
    std::uint64_t serial = 0;
    std::int32_t sweptSlot = -1; ///< with Swept: its index in WorldState::sweptContacts
    int toiCount = 0;            ///< time-of-impact events this step
    Real toi = 1;                ///< cached time of impact (fraction of the step)
    std::uint64_t hitStep = 0;   ///< 1 + the step count when hitEvent was last written
    std::int32_t hitEvent = -1;  ///< its index in WorldState::hitEvents during that step
    /// Two sharp polygons apart at the last update: the face that separated them, tested first
    /// at the next (UpdateManifold; exact, so Box2D's back end uses it too).
    SeparatingFace separatingFace;
    /// With PoseKept: body B's transform in body A's frame (MulT(xfA, xfB)) when the manifold
    /// was last computed, for Collide's recycling (CollisionPolicy::recycleDistance).
    Transform keptPose;

    bool IsTouching() const { return (flags & Touching) != 0; }
    bool IsSensor() const { return (flags & Sensor) != 0; }
    /// Touching, enabled and not a sensor: what the solver takes (Box2D's island test).
    bool IsSolid() const { return (flags & (Touching | Disabled | Sensor)) == Touching; }
};
static_assert(offsetof(Contact, edges) + sizeof(Contact::edges) <= 64,
              "the walked fields fit in one cache line's length");

/// Box2D 2.4.1's mixing rules.
inline Real MixFriction(Real a, Real b)
{
    return std::sqrt(a * b);
}
inline Real MixRestitution(Real a, Real b)
{
    return a > b ? a : b;
}
inline Real MixRestitutionThreshold(Real a, Real b)
{
    return a < b ? a : b;
}

/// Recomputes the manifold for the shapes' current transforms and carries the old impulses
/// over to points with the same feature key. Returns the new touching state.
bool UpdateManifold(Contact& contact, const Shape& shapeA, const Transform& xfA,
                    const Shape& shapeB, const Transform& xfB);

/// How far any point of body B's core, at most `reach` from B's origin, can have moved relative
/// to body A between two relative poses of B in A's frame (MulT(xfA, xfB)) `kept` and `now`:
/// a point b goes from kept.q·b + kept.p to now.q·b + now.p, so it moves by at most
/// |now.p − kept.p| + ‖now.q − kept.q‖·reach, the difference of two rotations being a rotation
/// scaled by √(Δc² + Δs²). Collide's recycling bound (CollisionPolicy::recycleDistance).
inline Real RelativeMotionBound(const Transform& kept, const Transform& now, Real reach)
{
    const Real dc = now.q.c - kept.q.c;
    const Real ds = now.q.s - kept.q.s;
    return (now.p - kept.p).Length() + std::sqrt(dc * dc + ds * ds) * reach;
}

/// Sensor contacts (Box2D's b2TestOverlap): the shapes touch when the GJK distance between
/// them, radii included, is below 10·epsilon. The manifold is emptied: sensors have no points.
bool UpdateSensorOverlap(Contact& contact, const Shape& shapeA, const Transform& xfA,
                         const Shape& shapeB, const Transform& xfB);

/// Does the pair of shape types produce contacts, and which one is A? Box2D puts the polygon
/// before the circle and the segment (or chain segment) before anything; two segments (of any
/// kind) never collide.
bool ContactOrder(ShapeType typeA, ShapeType typeB, bool& swap);

} // namespace meff::detail
