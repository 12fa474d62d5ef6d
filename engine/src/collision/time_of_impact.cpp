// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Time of impact by conservative advancement on local separating axes, in the operation order
// of Box2D 2.4.1's b2_time_of_impact.cpp: GJK gives an axis at the current safe time t1, the
// deepest points along it at t2 are pushed back by a root finder (bisection alternating with
// the secant rule) until the axis holds over [t1, t2], and t1 advances to t2.
#include "collision/time_of_impact.h"

#include <cmath>

namespace meff
{

namespace detail
{

Real SeparationFunction::Initialize(const SimplexCache& cache, const DistanceProxy& proxyA,
                                    const Sweep& sweepA, const DistanceProxy& proxyB,
                                    const Sweep& sweepB, Real t1)
{
    m_proxyA = &proxyA;
    m_proxyB = &proxyB;
    m_sweepA = sweepA;
    m_sweepB = sweepB;
    const Transform xfA = m_sweepA.GetTransform(t1);
    const Transform xfB = m_sweepB.GetTransform(t1);

    if (cache.count == 1)
    {
        m_type = Type::Points;
        const Vec2 pointA = Mul(xfA, proxyA.GetVertex(cache.indexA[0]));
        const Vec2 pointB = Mul(xfB, proxyB.GetVertex(cache.indexB[0]));
        m_axis = pointB - pointA;
        return m_axis.Normalize();
    }
    if (cache.indexA[0] == cache.indexA[1])
    {
        // One point of A against an edge of B: the axis is that edge's normal.
        m_type = Type::FaceB;
        const Vec2 localPointB1 = proxyB.GetVertex(cache.indexB[0]);
        const Vec2 localPointB2 = proxyB.GetVertex(cache.indexB[1]);
        m_axis = Cross(localPointB2 - localPointB1, Real(1));
        m_axis.Normalize();
        const Vec2 normal = Mul(xfB.q, m_axis);
        m_localPoint = Real(0.5) * (localPointB1 + localPointB2);
        const Vec2 pointB = Mul(xfB, m_localPoint);
        const Vec2 pointA = Mul(xfA, proxyA.GetVertex(cache.indexA[0]));
        Real s = Dot(pointA - pointB, normal);
        if (s < 0)
        {
            m_axis = -m_axis;
            s = -s;
        }
        return s;
    }
    // An edge of A against one or two points of B: the axis is A's edge normal.
    m_type = Type::FaceA;
    const Vec2 localPointA1 = proxyA.GetVertex(cache.indexA[0]);
    const Vec2 localPointA2 = proxyA.GetVertex(cache.indexA[1]);
    m_axis = Cross(localPointA2 - localPointA1, Real(1));
    m_axis.Normalize();
    const Vec2 normal = Mul(xfA.q, m_axis);
    m_localPoint = Real(0.5) * (localPointA1 + localPointA2);
    const Vec2 pointA = Mul(xfA, m_localPoint);
    const Vec2 pointB = Mul(xfB, proxyB.GetVertex(cache.indexB[0]));
    Real s = Dot(pointB - pointA, normal);
    if (s < 0)
    {
        m_axis = -m_axis;
        s = -s;
    }
    return s;
}

Real SeparationFunction::FindMinSeparation(int& indexA, int& indexB, Real t) const
{
    const Transform xfA = m_sweepA.GetTransform(t);
    const Transform xfB = m_sweepB.GetTransform(t);
    switch (m_type)
    {
    case Type::Points:
    {
        const Vec2 axisA = MulT(xfA.q, m_axis);
        const Vec2 axisB = MulT(xfB.q, -m_axis);
        indexA = m_proxyA->GetSupport(axisA);
        indexB = m_proxyB->GetSupport(axisB);
        const Vec2 pointA = Mul(xfA, m_proxyA->GetVertex(indexA));
        const Vec2 pointB = Mul(xfB, m_proxyB->GetVertex(indexB));
        return Dot(pointB - pointA, m_axis);
    }
    case Type::FaceA:
    {
        const Vec2 normal = Mul(xfA.q, m_axis);
        const Vec2 pointA = Mul(xfA, m_localPoint);
        const Vec2 axisB = MulT(xfB.q, -normal);
        indexA = -1;
        indexB = m_proxyB->GetSupport(axisB);
        const Vec2 pointB = Mul(xfB, m_proxyB->GetVertex(indexB));
        return Dot(pointB - pointA, normal);
    }
    case Type::FaceB:
    {
        const Vec2 normal = Mul(xfB.q, m_axis);
        const Vec2 pointB = Mul(xfB, m_localPoint);
        const Vec2 axisA = MulT(xfA.q, -normal);
        indexB = -1;
        indexA = m_proxyA->GetSupport(axisA);
        const Vec2 pointA = Mul(xfA, m_proxyA->GetVertex(indexA));
        return Dot(pointA - pointB, normal);
    }
    }
    indexA = -1;
    indexB = -1;
    return 0;
}

Real SeparationFunction::Evaluate(int indexA, int indexB, Real t) const
{
    const Transform xfA = m_sweepA.GetTransform(t);
    const Transform xfB = m_sweepB.GetTransform(t);
    switch (m_type)
    {
    case Type::Points:
    {
        const Vec2 pointA = Mul(xfA, m_proxyA->GetVertex(indexA));
        const Vec2 pointB = Mul(xfB, m_proxyB->GetVertex(indexB));
        return Dot(pointB - pointA, m_axis);
    }
    case Type::FaceA:
    {
        const Vec2 normal = Mul(xfA.q, m_axis);
        const Vec2 pointA = Mul(xfA, m_localPoint);
        const Vec2 pointB = Mul(xfB, m_proxyB->GetVertex(indexB));
        return Dot(pointB - pointA, normal);
    }
    case Type::FaceB:
    {
        const Vec2 normal = Mul(xfB.q, m_axis);
        const Vec2 pointB = Mul(xfB, m_localPoint);
        const Vec2 pointA = Mul(xfA, m_proxyA->GetVertex(indexA));
        return Dot(pointA - pointB, normal);
    }
    }
    return 0;
}

} // namespace detail

namespace
{

/// Separating axes tried before giving up (outer loop).
constexpr int kMaxToiIterations = 20;
/// Root-finder steps per push-back.
constexpr int kMaxRootIterations = 50;

} // namespace

TOIOutput TimeOfImpact(const TOIInput& input)
{
    TOIOutput output;
    output.state = TOIOutput::State::Unknown;
    output.t = input.tMax;

    const DistanceProxy& proxyA = input.proxyA;
    const DistanceProxy& proxyB = input.proxyB;

    // Large angles make the root finder fail: bring them near zero first.
    Sweep sweepA = input.sweepA;
    Sweep sweepB = input.sweepB;
    sweepA.Normalize();
    sweepB.Normalize();

    const Real tMax = input.tMax;
    const Real slop = input.linearSlop;
    // Stop with the cores slightly inside the skins, so that the contact that follows has
    // points; never closer than one slop.
    const Real totalRadius = proxyA.radius + proxyB.radius;
    const Real target = Max(slop, totalRadius - Real(3) * slop);
    const Real tolerance = Real(0.25) * slop;

    Real t1 = 0;
    int iterations = 0;

    SimplexCache cache;
    cache.count = 0;
    DistanceInput distanceInput;
    distanceInput.proxyA = input.proxyA;
    distanceInput.proxyB = input.proxyB;
    distanceInput.useRadii = false;

    for (;;)
    {
        distanceInput.transformA = sweepA.GetTransform(t1);
        distanceInput.transformB = sweepB.GetTransform(t1);
        const DistanceOutput distanceOutput = ShapeDistance(distanceInput, cache);

        if (distanceOutput.distance <= 0)
        {
            // The cores overlap already: continuous collision cannot help.
            output.state = TOIOutput::State::Overlapped;
            output.t = 0;
            break;
        }
        if (distanceOutput.distance < target + tolerance)
        {
            output.state = TOIOutput::State::Touching;
            output.t = t1;
            break;
        }

        detail::SeparationFunction fcn;
        fcn.Initialize(cache, proxyA, sweepA, proxyB, sweepB, t1);

        // Resolve the deepest point along the axis at t2 until the axis is safe up to t2;
        // bounded by the number of vertices.
        bool done = false;
        Real t2 = tMax;
        int pushBackIterations = 0;
        for (;;)
        {
            int indexA, indexB;
            Real s2 = fcn.FindMinSeparation(indexA, indexB, t2);

            if (s2 > target + tolerance)
            {
                // Still apart at t2 along this axis.
                output.state = TOIOutput::State::Separated;
                output.t = tMax;
                done = true;
                break;
            }
            if (s2 > target - tolerance)
            {
                t1 = t2; // within tolerance at t2: advance the safe time
                break;
            }

            Real s1 = fcn.Evaluate(indexA, indexB, t1);
            if (s1 < target - tolerance)
            {
                // Too deep at t1 already (the root finder ran out of iterations earlier).
                output.state = TOIOutput::State::Failed;
                output.t = t1;
                done = true;
                break;
            }
            if (s1 <= target + tolerance)
            {
                output.state = TOIOutput::State::Touching;
                output.t = t1;
                done = true;
                break;
            }

            // The root of s(t) = target in [t1, t2] for this pair of points.
            int rootIterations = 0;
            Real a1 = t1, a2 = t2;
            for (;;)
            {
                Real t;
                if ((rootIterations & 1) != 0)
                {
                    t = a1 + (target - s1) * (a2 - a1) / (s2 - s1); // secant: fast
                }
                else
                {
                    t = Real(0.5) * (a1 + a2); // bisection: guaranteed progress
                }
                ++rootIterations;

                const Real s = fcn.Evaluate(indexA, indexB, t);
                if (std::abs(s - target) < tolerance)
                {
                    t2 = t;
                    break;
                }
                if (s > target)
                {
                    a1 = t;
                    s1 = s;
                }
                else
                {
                    a2 = t;
                    s2 = s;
                }
                if (rootIterations == kMaxRootIterations)
                {
                    break;
                }
            }

            ++pushBackIterations;
            if (pushBackIterations == kMaxPolygonVertices)
            {
                break;
            }
        }

        ++iterations;
        if (done)
        {
            break;
        }
        if (iterations == kMaxToiIterations)
        {
            // The root finder is stuck: report the last safe time.
            output.state = TOIOutput::State::Failed;
            output.t = t1;
            break;
        }
    }
    return output;
}

} // namespace meff
