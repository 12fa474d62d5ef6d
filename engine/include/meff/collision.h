// Shapes as geometry, their mass, bounding boxes, and contact manifolds between them.
//
// The manifold routines follow the algorithms of Box2D 2.4.1 (reference-face clipping,
// feature ids) so that contact points, and therefore impulses, agree between the two engines.
#pragma once

#include "meff/math.h"

#include <cstdint>
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

/// A convex polygon with counter-clockwise vertices and outward unit normals.
struct Polygon
{
    Vec2 vertices[kMaxPolygonVertices]{};
    Vec2 normals[kMaxPolygonVertices]{};
    Vec2 centroid{}; ///< area centroid in body coordinates (m)
    int count = 0;   ///< number of vertices, 3..kMaxPolygonVertices
    Real radius = 0; ///< collision skin (m); the world sets it to Tolerances::polygonSkin
};

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

AABB ComputeAABB(const Circle& circle, const Transform& xf);
AABB ComputeAABB(const Segment& segment, const Transform& xf);
AABB ComputeAABB(const Polygon& polygon, const Transform& xf);

/// Which feature of each shape a contact point comes from, packed as Box2D 2.4.1's
/// b2ContactFeature so that feature keys agree between the engines.
struct ContactFeature
{
    enum Type : std::uint8_t
    {
        Vertex = 0,
        Face = 1,
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
    enum class Type : std::uint8_t
    {
        Circles,
        FaceA,
        FaceB,
    };
    ManifoldPoint points[2]{};
    Vec2 localNormal{}; ///< FaceA: normal of A's face; FaceB: normal of B's face; Circles: unused
    Vec2 localPoint{};  ///< Circles: centre of A; FaceA: point on A's face; FaceB: on B's face
    Type type = Type::Circles;
    int pointCount = 0;
};

/// A manifold evaluated in world coordinates.
struct WorldManifold
{
    Vec2 normal{};       ///< unit normal from A to B
    Vec2 points[2]{};    ///< contact points, midway between the two surfaces (m)
    Real separations[2]; ///< negative when overlapping (m)

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

} // namespace meff
