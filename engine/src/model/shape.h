// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// A shape inside the world: geometry, material and its broad-phase proxy.
#pragma once

#include "meff/collision.h"
#include "meff/shape.h"

#include <cstdint>
#include <initializer_list>

namespace meff::detail
{

struct Shape
{
    std::uint32_t generation = 0;
    bool alive = false;
    std::int32_t body = -1;
    ShapeType type = ShapeType::Circle;
    Circle circle; ///< valid when type == Circle
    /// valid when type == Polygon; for a Capsule, its two-vertex polygon (MakeCapsulePolygon)
    Polygon polygon;
    Capsule capsule; ///< valid when type == Capsule
    /// A polygon with a rounding radius above the skin (Box2D v3's rounded polygon): its
    /// manifolds, mass and ray casts are the rounded shape's, not Box2D 2.4.1's.
    bool rounded = false;
    Segment segment;           ///< valid when type == Segment
    ChainSegment chainSegment; ///< valid when type == ChainSegment
    /// The chain (index into WorldState::chains) a ChainSegment belongs to, or −1 for a
    /// one-sided segment made alone. Box2D 2.4.1 casts rays at a chain's segments from both
    /// sides, and at a lone one-sided edge from its front only.
    std::int32_t chain = -1;
    ShapeDef def;
    std::int32_t proxyId = -1;
    AABB aabb; ///< the box last given to the broad phase (swept over the step: ShapeBoxes)
    /// The largest distance of the shape's core (a polygon's vertices, a circle's centre, a
    /// segment's end points: the shape less its radius) from its body's origin (m), set at
    /// creation: how far a point of the core can move when the body turns (Collide's
    /// recycling bound).
    Real reach = 0;

    /// Collision radius: the circle's radius, or the skin of a polygon or (chain) segment.
    Real Radius() const
    {
        switch (type)
        {
        case ShapeType::Circle:
            return circle.radius;
        case ShapeType::Polygon:
        case ShapeType::Capsule:
            return polygon.radius;
        case ShapeType::Segment:
            return segment.radius;
        case ShapeType::ChainSegment:
            return chainSegment.segment.radius;
        }
        return 0;
    }
    /// The radius the shape rolls on (rolling resistance, as Box2D v3's shape radius): a
    /// circle's or a capsule's, a rounded polygon's rounding; sharp polygons and segments do
    /// not roll (their skin is a contact tolerance, not a rounding).
    Real RollingRadius() const
    {
        switch (type)
        {
        case ShapeType::Circle:
            return circle.radius;
        case ShapeType::Capsule:
            return capsule.radius;
        case ShapeType::Polygon:
            return rounded ? polygon.radius : Real(0);
        default:
            return 0;
        }
    }
    AABB ComputeAABB(const Transform& xf) const
    {
        switch (type)
        {
        case ShapeType::Circle:
            return meff::ComputeAABB(circle, xf);
        case ShapeType::Polygon:
        case ShapeType::Capsule:
            return meff::ComputeAABB(polygon, xf);
        case ShapeType::Segment:
            return meff::ComputeAABB(segment, xf);
        case ShapeType::ChainSegment:
            return meff::ComputeAABB(chainSegment, xf);
        }
        return {};
    }
    /// The core's largest distance from the body origin (`reach`).
    Real ComputeReach() const
    {
        const auto farthest = [](std::initializer_list<Vec2> points)
        {
            Real most = 0;
            for (const Vec2 p : points)
            {
                most = Max(most, p.Length());
            }
            return most;
        };
        switch (type)
        {
        case ShapeType::Circle:
            return circle.center.Length();
        case ShapeType::Polygon:
        case ShapeType::Capsule:
        {
            Real most = 0;
            for (int i = 0; i < polygon.count; ++i)
            {
                most = Max(most, polygon.vertices[i].Length());
            }
            return most;
        }
        case ShapeType::Segment:
            return farthest({segment.point1, segment.point2});
        case ShapeType::ChainSegment:
            return farthest({chainSegment.segment.point1, chainSegment.segment.point2});
        }
        return 0;
    }
    /// Collides as a rounded polygon (CollideRoundedPolygons): a capsule or rounded polygon.
    bool IsRounded() const { return type == ShapeType::Capsule || rounded; }
};

} // namespace meff::detail
