// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Engine-internal side of the time of impact (meff/distance.h): the separating-axis function
// the root finder works on, exposed for tests.
#pragma once

#include "meff/distance.h"

namespace meff::detail
{

/// Separation of two sweeping proxies along one axis, chosen from a GJK simplex: the axis
/// between two points, or the normal of a face of A or of B (fixed in that body's frame).
class SeparationFunction
{
  public:
    enum class Type : std::uint8_t
    {
        Points,
        FaceA,
        FaceB,
    };

    /// Sets up the axis from the cache of a distance query at time t1; returns the separation
    /// at t1 (the axis is flipped to make it non-negative).
    Real Initialize(const SimplexCache& cache, const DistanceProxy& proxyA, const Sweep& sweepA,
                    const DistanceProxy& proxyB, const Sweep& sweepB, Real t1);
    /// The deepest pair of points along the axis at time t, with their indices (−1 for the
    /// side whose face defines the axis).
    Real FindMinSeparation(int& indexA, int& indexB, Real t) const;
    /// Separation of a given pair of points along the axis at time t.
    Real Evaluate(int indexA, int indexB, Real t) const;

    Type GetType() const { return m_type; }

  private:
    const DistanceProxy* m_proxyA = nullptr;
    const DistanceProxy* m_proxyB = nullptr;
    Sweep m_sweepA, m_sweepB;
    Type m_type = Type::Points;
    Vec2 m_localPoint;
    Vec2 m_axis;
};

} // namespace meff::detail
