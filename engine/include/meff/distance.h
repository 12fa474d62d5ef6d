// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Distance queries between convex shapes: closest points (GJK), overlap, shape casts and the
// time of impact of two moving shapes (conservative advancement).
//
// The algorithms and their floating-point operation order are Box2D 2.4.1's (b2Distance,
// b2ShapeCast, b2TestOverlap, b2TimeOfImpact), so results agree with Box2D bit for bit in
// float builds; the world's continuous collision is built on TimeOfImpact.
#pragma once

#include "meff/collision.h"
#include "meff/math.h"

#include <cstdint>

namespace meff
{

/// A convex shape as GJK sees it: a point cloud (its convex hull) plus a radius. A circle is
/// one point, a segment two, a polygon its vertices; the radius is the circle's radius or the
/// skin of a polygon or segment.
struct DistanceProxy
{
    Vec2 vertices[kMaxPolygonVertices]{}; ///< the points, in the shape's frame (m)
    int count = 0;                        ///< how many of vertices are used
    Real radius = 0;                      ///< added around the points' hull (m)

    /// Index of the vertex furthest along direction d (the first one on ties).
    int GetSupport(Vec2 d) const
    {
        int bestIndex = 0;
        Real bestValue = Dot(vertices[0], d);
        for (int i = 1; i < count; ++i)
        {
            const Real value = Dot(vertices[i], d);
            if (value > bestValue)
            {
                bestIndex = i;
                bestValue = value;
            }
        }
        return bestIndex;
    }
    /// vertices[index].
    Vec2 GetVertex(int index) const { return vertices[index]; }
};

DistanceProxy MakeProxy(const Circle& circle);
DistanceProxy MakeProxy(const Polygon& polygon);
DistanceProxy MakeProxy(const Segment& segment);
/// The core segment's two ends with the capsule's radius.
DistanceProxy MakeProxy(const Capsule& capsule);
/// The segment's two ends (the ghosts take no part in distance, casts or time of impact).
DistanceProxy MakeProxy(const ChainSegment& segment);

/// The last simplex of a distance query, to warm-start the next query between the same two
/// proxies (as the time-of-impact loop does). Start with count = 0.
struct SimplexCache
{
    Real metric = 0;                    ///< length or area of the simplex
    std::uint16_t count = 0;            ///< 0 (empty) to 3
    std::uint8_t indexA[3] = {0, 0, 0}; ///< the simplex's vertices on proxy A
    std::uint8_t indexB[3] = {0, 0, 0}; ///< the simplex's vertices on proxy B
};

/// The two proxies and where they are, for ShapeDistance.
struct DistanceInput
{
    DistanceProxy proxyA;   ///< the first shape
    DistanceProxy proxyB;   ///< the second shape
    Transform transformA{}; ///< where proxy A is
    Transform transformB{}; ///< where proxy B is
    bool useRadii = false;  ///< measure between the rounded surfaces, not the cores
};

/// What ShapeDistance finds.
struct DistanceOutput
{
    Vec2 pointA{};      ///< closest point on A (m)
    Vec2 pointB{};      ///< closest point on B (m)
    Real distance = 0;  ///< 0 when overlapping (m)
    int iterations = 0; ///< GJK iterations taken
};

/// Closest points of two convex proxies by GJK. `cache` is read (count 0: cold start) and
/// written back with the final simplex.
DistanceOutput ShapeDistance(const DistanceInput& input, SimplexCache& cache);

/// Do the two shapes, radii included, overlap? (Distance below 10·epsilon.)
bool TestOverlap(const DistanceProxy& proxyA, const Transform& xfA, const DistanceProxy& proxyB,
                 const Transform& xfB);

/// The two proxies, where they start and how B moves, for ShapeCast.
struct ShapeCastInput
{
    DistanceProxy proxyA;          ///< the shape that stays
    DistanceProxy proxyB;          ///< the shape that moves
    Transform transformA{};        ///< where proxy A is
    Transform transformB{};        ///< where proxy B starts
    Vec2 translationB{};           ///< B moves by this over the cast; A stays (m)
    Real polygonSkin = Real(0.01); ///< Tolerances::polygonSkin: smallest radius a proxy is given
    Real linearSlop = Real(0.005); ///< Tolerances::linearSlop: half of it is the tolerance
};

/// What ShapeCast finds.
struct ShapeCastOutput
{
    Vec2 point{};       ///< contact point on A at the hit (m)
    Vec2 normal{};      ///< unit normal at the hit
    Real lambda = 1;    ///< fraction of translationB travelled to the hit
    int iterations = 0; ///< iterations taken
};

/// Casts B along translationB against A (GJK ray cast). Returns false when they never touch
/// within the translation, or already overlap at the start.
bool ShapeCast(const ShapeCastInput& input, ShapeCastOutput& output);

/// Two proxies and their motions over a step, for TimeOfImpact.
struct TOIInput
{
    DistanceProxy proxyA;          ///< the first shape, in its body's frame
    DistanceProxy proxyB;          ///< the second shape, in its body's frame
    Sweep sweepA{};                ///< how A's body moves
    Sweep sweepB{};                ///< how B's body moves
    Real tMax = 1;                 ///< end of the sweep interval to search, in [0, 1]
    Real linearSlop = Real(0.005); ///< Tolerances::linearSlop
};

/// What TimeOfImpact finds.
struct TOIOutput
{
    /// How the search ended.
    enum class State : std::uint8_t
    {
        Unknown,    ///< not searched
        Failed,     ///< the root finder ran out of iterations; t is the last safe time
        Overlapped, ///< the cores already overlap at the start; t = 0
        Touching,   ///< t is the time of impact
        Separated,  ///< no impact before tMax; t = tMax
    };
    State state = State::Unknown; ///< how the search ended
    Real t = 0;                   ///< the time found, a fraction of the step (see state)
};

/// The first time in [0, tMax] at which the two sweeps bring the cores of the shapes within
/// max(linearSlop, radiusA + radiusB − 3·linearSlop) of each other (± linearSlop/4), by
/// conservative advancement along separating axes. Rotation is handled; the sweeps are
/// interpolated linearly in position and angle.
TOIOutput TimeOfImpact(const TOIInput& input);

} // namespace meff
