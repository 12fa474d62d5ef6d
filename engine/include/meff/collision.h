// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Shapes as geometry, their mass, bounding boxes, and contact manifolds between them.
//
// The manifold routines follow the algorithms of Box2D 2.4.1 (reference-face clipping,
// feature ids) so that contact points, and therefore impulses, agree between the two engines.
#pragma once

#include "meff/math.h"

#include <cstdint>
#include <optional>
#include <span>

namespace meff
{

/// The most vertices a convex polygon may have.
inline constexpr int kMaxPolygonVertices = 8;

enum class ShapeType : std::uint8_t
{
    Circle = 0,
    Segment = 1,
    Polygon = 2,
    ChainSegment = 3, ///< a one-sided segment with ghost vertices, alone or in a chain
    Capsule = 4,      ///< a segment rounded by a radius (Box2D v3's b2Capsule)
};

/// A solid circle.
struct Circle
{
    Vec2 center{};   ///< centre in body coordinates (m)
    Real radius = 0; ///< radius (m), > 0
};

/// A line segment, for static ground. Two-sided.
struct Segment
{
    Vec2 point1{};   ///< first end in body coordinates (m)
    Vec2 point2{};   ///< second end in body coordinates (m)
    Real radius = 0; ///< collision skin (m); the world sets it to Tolerances::polygonSkin
};

/// A one-sided segment with ghost vertices: Box2D 2.4.1's b2EdgeShape after SetOneSided, and
/// each child of a b2ChainShape (Box2D v3's b2ChainSegment). Only the side to the right of
/// point1 → point2 collides (the outside of a counter-clockwise loop; the top of ground listed
/// from right to left); a shape whose centre is behind it passes through. The ghosts are the
/// neighbouring vertices of the chain it belongs to: a contact whose normal points into a
/// neighbour's territory is skipped, or turned to the segment's own normal at a concave
/// corner, so a box sliding over the joint between two segments does not catch on the vertex
/// (https://box2d.org/posts/2020/06/ghost-collisions/).
struct ChainSegment
{
    Vec2 ghost1{};     ///< the vertex before segment.point1 (m), Box2D's m_vertex0
    Segment segment{}; ///< the solid part; its radius is set by the world (polygonSkin)
    Vec2 ghost2{};     ///< the vertex after segment.point2 (m), Box2D's m_vertex3
};

/// A chain of one-sided segments through `points` (Box2D 2.4.1's b2ChainShape), for terrain:
/// World::CreateChain makes one ChainSegment shape per pair of consecutive points, each with
/// its neighbours as ghosts, so that shapes slide over the joints without catching. The solid
/// side is to the right of the direction of travel: list ground from right to left, and a
/// loop counter-clockwise to keep things out (clockwise to keep them in).
struct Chain
{
    /// The vertices in body coordinates (m): at least 2 for an open chain, 3 for a loop;
    /// consecutive points (and, for a loop, the last and the first) further apart than the
    /// linear slop.
    std::span<const Vec2> points{};
    /// Close the chain: a segment also joins the last point to the first (Box2D's CreateLoop).
    bool loop = false;
    /// Open chains: the ghost vertex before points[0] (Box2D's prevVertex), which decides how
    /// the first segment's start meets what lies beyond it. Unset: points[0] + (points[0] −
    /// points[1]), the first segment continued in a straight line. Loops take their ghosts
    /// from their own points and refuse these.
    std::optional<Vec2> prev{};
    /// Open chains: the ghost vertex after the last point (Box2D's nextVertex). Unset: the last
    /// segment continued in a straight line.
    std::optional<Vec2> next{};
};

/// A convex polygon with counter-clockwise vertices and outward unit normals.
struct Polygon
{
    Vec2 vertices[kMaxPolygonVertices]{}; ///< counter-clockwise, body coordinates (m)
    Vec2 normals[kMaxPolygonVertices]{};  ///< outward unit normal of edge i (vertex i to i + 1)
    Vec2 centroid{};                      ///< area centroid in body coordinates (m)
    int count = 0;                        ///< number of vertices, 3..kMaxPolygonVertices
    /// Collision radius (m). Up to Tolerances::polygonSkin (MakePolygon and MakeBox give 0) the
    /// polygon is sharp and the world sets it to the skin, as Box2D 2.4.1 does; above it the
    /// polygon is rounded (Box2D v3's rounded polygon): its surface is every point within
    /// `radius` of the core polygon the vertices span, and its mass, manifolds and ray casts
    /// are the rounded shape's.
    Real radius = 0;
};

/// Two half-discs joined by a rectangle: every point within `radius` of the segment from
/// center1 to center2 (Box2D v3's b2Capsule). The world treats it as a rounded polygon of two
/// vertices (MakeCapsulePolygon).
struct Capsule
{
    Vec2 center1{};  ///< centre of the first cap, body coordinates (m)
    Vec2 center2{};  ///< centre of the second cap (m), further than the linear slop from center1
    Real radius = 0; ///< m, finite and > 0
};

/// The capsule as the collision routines see it: a polygon of two vertices (the caps'
/// centres; normals[0] is the right of center1 → center2, normals[1] its opposite), its
/// centroid the middle, with the capsule's radius. No checks: see CheckCapsule.
Polygon MakeCapsulePolygon(const Capsule& capsule);

/// Mass properties of a shape or body.
struct MassData
{
    Real mass = 0;              ///< kg
    Vec2 center{};              ///< centre of mass in body coordinates (m)
    Real rotationalInertia = 0; ///< about the body origin (kg·m²)
};

/// Points closer than this are welded into one when a polygon is built (m): Box2D's
/// 0.5·linearSlop.
inline constexpr Real kPolygonWeldTolerance = Real(0.0025);

/// Builds a convex polygon from points in any order by taking their convex hull.
/// Throws InvalidArgument for fewer than 3 or more than kMaxPolygonVertices points, non-finite
/// coordinates, or points that are collinear or coincide (a hull of zero area).
Polygon MakePolygon(std::span<const Vec2> points);
/// An axis-aligned box centred on the body origin. Throws InvalidArgument unless both
/// half-extents are finite and > 0.
Polygon MakeBox(Real halfWidth, Real halfHeight);
/// A box centred at `center` and turned by `angle` (rad), in body coordinates.
Polygon MakeOffsetBox(Real halfWidth, Real halfHeight, Vec2 center, Real angle);

MassData ComputeMass(const Circle& circle, Real density);
MassData ComputeMass(const Polygon& polygon, Real density);
/// The exact mass of a capsule: the rectangle 2r × L and the two half-discs, m = ρ(πr² + 2rL).
MassData ComputeMass(const Capsule& capsule, Real density);
/// The exact mass of a rounded polygon (its `radius` the rounding; count 2 is a capsule): the
/// core polygon, a rectangle of width r outside each edge and a disc sector at each vertex,
/// their inertias added about the body origin by the parallel-axis theorem.
MassData ComputeRoundedMass(const Polygon& polygon, Real density);

AABB ComputeAABB(const Circle& circle, const Transform& xf);
AABB ComputeAABB(const Segment& segment, const Transform& xf);
AABB ComputeAABB(const Polygon& polygon, const Transform& xf);
AABB ComputeAABB(const ChainSegment& segment, const Transform& xf);
AABB ComputeAABB(const Capsule& capsule, const Transform& xf);

/// Which feature of each shape a contact point comes from, packed as Box2D 2.4.1's
/// b2ContactFeature so that feature keys agree between the engines.
struct ContactFeature
{
    /// What kind of feature an index names.
    enum Type : std::uint8_t
    {
        Vertex = 0, ///< a vertex
        Face = 1,   ///< a face (edge)
    };
    std::uint8_t indexA = 0; ///< feature index on shape A
    std::uint8_t indexB = 0; ///< feature index on shape B
    std::uint8_t typeA = 0;  ///< Vertex or Face
    std::uint8_t typeB = 0;  ///< Vertex or Face

    /// The four bytes as one key (indexA in the low byte, as b2ContactID::key on x86).
    std::uint32_t Key() const
    {
        return std::uint32_t(indexA) | std::uint32_t(indexB) << 8 | std::uint32_t(typeA) << 16 |
               std::uint32_t(typeB) << 24;
    }
};

/// One contact point of a manifold, in the local frame the manifold type names.
struct ManifoldPoint
{
    Vec2 localPoint{};       ///< Circles: centre of B; FaceA: point on B; FaceB: point on A
    Real normalImpulse = 0;  ///< accumulated normal impulse (N·s), carried between steps
    Real tangentImpulse = 0; ///< accumulated friction impulse (N·s), carried between steps
    ContactFeature id{};     ///< the features that made this point, to match it next step
};

/// Up to two contact points between two shapes, stored in the local frame of one of them so
/// that the position solver can re-evaluate them as the bodies move.
struct Manifold
{
    /// Which frame the manifold is stored in.
    enum class Type : std::uint8_t
    {
        Circles, ///< two circles: localPoint is A's centre
        FaceA,   ///< a face of A: localNormal and localPoint are on it
        FaceB,   ///< a face of B: localNormal and localPoint are on it
    };
    ManifoldPoint points[2]{}; ///< the first pointCount are used
    Vec2 localNormal{}; ///< FaceA: normal of A's face; FaceB: normal of B's face; Circles: unused
    Vec2 localPoint{};  ///< Circles: centre of A; FaceA: point on A's face; FaceB: on B's face
    Type type = Type::Circles; ///< the frame of localNormal and localPoint
    int pointCount = 0;        ///< 0, 1 or 2
};

/// A manifold evaluated in world coordinates.
struct WorldManifold
{
    Vec2 normal{};       ///< unit normal from A to B
    Vec2 points[2]{};    ///< contact points, midway between the two surfaces (m)
    Real separations[2]; ///< negative when overlapping (m)

    /// Evaluates `manifold` at the two shapes' transforms and radii (Box2D 2.4.1's
    /// b2WorldManifold::Initialize).
    void Initialize(const Manifold& manifold, const Transform& xfA, Real radiusA,
                    const Transform& xfB, Real radiusB);
};

// Manifold routines. Each writes pointCount = 0 when the shapes do not touch (within their
// skins). The normal points from A to B.
void CollideCircles(Manifold& manifold, const Circle& circleA, const Transform& xfA,
                    const Circle& circleB, const Transform& xfB);
void CollidePolygonAndCircle(Manifold& manifold, const Polygon& polygonA, const Transform& xfA,
                             const Circle& circleB, const Transform& xfB);
void CollidePolygons(Manifold& manifold, const Polygon& polygonA, const Transform& xfA,
                     const Polygon& polygonB, const Transform& xfB);
void CollideSegmentAndCircle(Manifold& manifold, const Segment& segmentA, const Transform& xfA,
                             const Circle& circleB, const Transform& xfB);
void CollideSegmentAndPolygon(Manifold& manifold, const Segment& segmentA, const Transform& xfA,
                              const Polygon& polygonB, const Transform& xfB);
/// One-sided, with ghosts: b2CollideEdgeAndCircle and b2CollideEdgeAndPolygon of Box2D 2.4.1
/// for an edge with m_oneSided (a circle or polygon whose centre is behind the segment gets no
/// points; the ghosts skip or snap contacts at the ends).
void CollideChainSegmentAndCircle(Manifold& manifold, const ChainSegment& segmentA,
                                  const Transform& xfA, const Circle& circleB,
                                  const Transform& xfB);
void CollideChainSegmentAndPolygon(Manifold& manifold, const ChainSegment& segmentA,
                                   const Transform& xfA, const Polygon& polygonB,
                                   const Transform& xfB);

/// Rounded polygons (Box2D v3's b2CollidePolygons, written for 2.4.1's local manifolds): any
/// two polygons with any radii, capsules (MakeCapsulePolygon) and segments (two vertices)
/// among them. The deepest face of either core is the reference face and the other core's
/// facing edge is clipped against it (FaceA or FaceB, as CollidePolygons); when the cores are
/// apart and their closest features are two vertices, the one contact point is between those
/// vertices along the line joining them (Circles, localPoint a vertex of A and the point's
/// localPoint a vertex of B), so a rounded corner rolls over a corner instead of meeting it
/// along a face normal.
void CollideRoundedPolygons(Manifold& manifold, const Polygon& polygonA, const Transform& xfA,
                            const Polygon& polygonB, const Transform& xfB);
/// A one-sided segment with ghosts against a rounded polygon or capsule: CollideRoundedPolygons
/// with the segment as polygon A, no points when B's centroid is behind the segment, and a
/// contact at an end of the segment kept only when its normal lies between the segment's
/// normal and the neighbour's (a convex joint); at a flat or concave joint only the segment's
/// own normal is kept, so a capsule slides over the joints of a chain without catching.
void CollideChainSegmentAndRounded(Manifold& manifold, const ChainSegment& segmentA,
                                   const Transform& xfA, const Polygon& polygonB,
                                   const Transform& xfB);

} // namespace meff
