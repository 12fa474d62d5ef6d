// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Internal pieces shared by the manifold routines (not part of the public API).
#pragma once

#include "meff/collision.h"

#include <cstdint>

namespace meff::detail
{

/// Box2D 2.4.1's b2_linearSlop (m): the collision and constraint tolerance.
inline constexpr Real kCollisionLinearSlop = Real(0.005);

/// The face that last separated two polygons (CollidePolygons' early returns): face `edge` of A
/// (`onB` false) or of B, or none (edge < 0). The narrow phase keeps it per contact and tests it
/// first (FaceSeparation), since a pair of polygons apart last step is most often apart along
/// the same face.
struct SeparatingFace
{
    std::int8_t edge = -1;
    bool onB = false;
};

/// The separation of poly2 from face `edge` of poly1: Box2D 2.4.1's b2FindMaxSeparation for that
/// one face, with the same operations in the same order, so the same bits as that face's value
/// in the full search. The full search's result is the largest face's, so it is at least this:
/// when this exceeds the two radii, so does the search, and CollidePolygons returns no points.
Real FaceSeparation(const Polygon& poly1, const Transform& xf1, int edge, const Polygon& poly2,
                    const Transform& xf2);

/// CollidePolygons, starting from the face that last separated the pair (`separating`, as this
/// left it last time; edge < 0: none), which is tested first, and writing which face separates
/// them when it returns for want of overlap along a face normal (`separating.edge` < 0
/// otherwise). The manifold is the same bits as without the hint.
void CollidePolygons(Manifold& manifold, const Polygon& polygonA, const Transform& xfA,
                     const Polygon& polygonB, const Transform& xfB, SeparatingFace& separating);

/// A vertex of an incident edge being clipped, with the features that produced it.
struct ClipVertex
{
    Vec2 v;
    ContactFeature id;
};

/// Clips the segment input[0]-input[1] to the half-plane dot(normal, p) <= offset
/// (Sutherland-Hodgman), as b2ClipSegmentToLine. A point created by the clip gets the feature
/// (vertex `vertexIndexA`, face input[0].id.indexB). Returns how many points were written
/// to output (0..2). Inline because it runs twice for every polygon contact, where a call would
/// pass the points through memory.
inline int ClipSegmentToLine(ClipVertex output[2], const ClipVertex input[2], Vec2 normal,
                             Real offset, int vertexIndexA)
{
    int count = 0;

    // Signed distances of the two end points to the clipping line.
    const Real distance0 = Dot(normal, input[0].v) - offset;
    const Real distance1 = Dot(normal, input[1].v) - offset;

    // Keep the end points on the inner side (points exactly on the line are kept).
    if (distance0 <= 0)
    {
        output[count++] = input[0];
    }
    if (distance1 <= 0)
    {
        output[count++] = input[1];
    }

    // The end points straddle the line: add the crossing point.
    if (distance0 * distance1 < 0)
    {
        const Real interp = distance0 / (distance0 - distance1);
        output[count].v = input[0].v + interp * (input[1].v - input[0].v);

        // The new point is where a vertex of the reference shape meets the incident face.
        output[count].id.indexA = static_cast<std::uint8_t>(vertexIndexA);
        output[count].id.indexB = input[0].id.indexB;
        output[count].id.typeA = ContactFeature::Vertex;
        output[count].id.typeB = ContactFeature::Face;
        ++count;
    }

    return count;
}

} // namespace meff::detail
