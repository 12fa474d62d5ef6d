// Internal pieces shared by the manifold routines (not part of the public API).
#pragma once

#include "meff/collision.h"

namespace meff::detail
{

/// Box2D 2.4.1's b2_linearSlop (m): the collision and constraint tolerance.
inline constexpr Real kCollisionLinearSlop = Real(0.005);

/// A vertex of an incident edge being clipped, with the features that produced it.
struct ClipVertex
{
    Vec2 v;
    ContactFeature id;
};

/// Clips the segment input[0]-input[1] to the half-plane dot(normal, p) <= offset
/// (Sutherland-Hodgman), as b2ClipSegmentToLine. A point created by the clip gets the feature
/// (vertex `vertexIndexA`, face input[0].id.indexB). Returns how many points were written
/// to output (0..2).
int ClipSegmentToLine(ClipVertex output[2], const ClipVertex input[2], Vec2 normal, Real offset,
                      int vertexIndexA);

} // namespace meff::detail
