// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// GJK distance with a Voronoi-region simplex solver in barycentric coordinates (after Christer
// Ericson), and the GJK ray cast (after Gino van den Bergen), in the operation order of Box2D
// 2.4.1's b2_distance.cpp so that both engines agree bit for bit.
#include "meff/distance.h"

namespace meff
{

DistanceProxy MakeProxy(const Circle& circle)
{
    DistanceProxy proxy;
    proxy.vertices[0] = circle.center;
    proxy.count = 1;
    proxy.radius = circle.radius;
    return proxy;
}

DistanceProxy MakeProxy(const Polygon& polygon)
{
    DistanceProxy proxy;
    for (int i = 0; i < polygon.count; ++i)
    {
        proxy.vertices[i] = polygon.vertices[i];
    }
    proxy.count = polygon.count;
    proxy.radius = polygon.radius;
    return proxy;
}

DistanceProxy MakeProxy(const Segment& segment)
{
    DistanceProxy proxy;
    proxy.vertices[0] = segment.point1;
    proxy.vertices[1] = segment.point2;
    proxy.count = 2;
    proxy.radius = segment.radius;
    return proxy;
}

DistanceProxy MakeProxy(const Capsule& capsule)
{
    return MakeProxy(Segment{capsule.center1, capsule.center2, capsule.radius});
}

DistanceProxy MakeProxy(const ChainSegment& segment)
{
    return MakeProxy(segment.segment);
}

namespace
{

struct SimplexVertex
{
    Vec2 wA;    ///< support point of A (world)
    Vec2 wB;    ///< support point of B (world)
    Vec2 w;     ///< wB − wA, a point of the Minkowski difference
    Real a = 0; ///< barycentric coordinate of the closest point
    int indexA = 0;
    int indexB = 0;
};

/// Up to three points of the Minkowski difference B − A, and the closest point of their hull
/// to the origin in barycentric form.
struct Simplex
{
    SimplexVertex v[3];
    int count = 0;

    void ReadCache(const SimplexCache& cache, const DistanceProxy& proxyA, const Transform& xfA,
                   const DistanceProxy& proxyB, const Transform& xfB)
    {
        count = cache.count;
        for (int i = 0; i < count; ++i)
        {
            SimplexVertex& sv = v[i];
            sv.indexA = cache.indexA[i];
            sv.indexB = cache.indexB[i];
            sv.wA = Mul(xfA, proxyA.GetVertex(sv.indexA));
            sv.wB = Mul(xfB, proxyB.GetVertex(sv.indexB));
            sv.w = sv.wB - sv.wA;
            sv.a = 0;
        }

        // A cached simplex whose size changed a lot since it was stored is worse than none.
        if (count > 1)
        {
            const Real metric1 = cache.metric;
            const Real metric2 = GetMetric();
            if (metric2 < Real(0.5) * metric1 || Real(2) * metric1 < metric2 || metric2 < kEpsilon)
            {
                count = 0;
            }
        }

        if (count == 0)
        {
            SimplexVertex& sv = v[0];
            sv.indexA = 0;
            sv.indexB = 0;
            sv.wA = Mul(xfA, proxyA.GetVertex(0));
            sv.wB = Mul(xfB, proxyB.GetVertex(0));
            sv.w = sv.wB - sv.wA;
            sv.a = 1;
            count = 1;
        }
    }

    void WriteCache(SimplexCache& cache) const
    {
        cache.metric = GetMetric();
        cache.count = static_cast<std::uint16_t>(count);
        for (int i = 0; i < count; ++i)
        {
            cache.indexA[i] = static_cast<std::uint8_t>(v[i].indexA);
            cache.indexB[i] = static_cast<std::uint8_t>(v[i].indexB);
        }
    }

    /// Towards the origin from the simplex: from the point, or perpendicular to the segment
    /// on the origin's side.
    Vec2 GetSearchDirection() const
    {
        if (count == 1)
        {
            return -v[0].w;
        }
        const Vec2 e12 = v[1].w - v[0].w;
        const Real sign = Cross(e12, -v[0].w);
        return sign > 0 ? Cross(Real(1), e12) : Cross(e12, Real(1));
    }

    Vec2 GetClosestPoint() const
    {
        switch (count)
        {
        case 1:
            return v[0].w;
        case 2:
            return v[0].a * v[0].w + v[1].a * v[1].w;
        default:
            return {0, 0};
        }
    }

    void GetWitnessPoints(Vec2& pA, Vec2& pB) const
    {
        switch (count)
        {
        case 1:
            pA = v[0].wA;
            pB = v[0].wB;
            break;
        case 2:
            pA = v[0].a * v[0].wA + v[1].a * v[1].wA;
            pB = v[0].a * v[0].wB + v[1].a * v[1].wB;
            break;
        case 3:
            pA = v[0].a * v[0].wA + v[1].a * v[1].wA + v[2].a * v[2].wA;
            pB = pA;
            break;
        default:
            break;
        }
    }

    Real GetMetric() const
    {
        switch (count)
        {
        case 2:
            return Distance(v[0].w, v[1].w);
        case 3:
            return Cross(v[1].w - v[0].w, v[2].w - v[0].w);
        default:
            return 0;
        }
    }

    // The closest point of segment w1w2 to the origin: p = a1·w1 + a2·w2 with a1 + a2 = 1 and
    // p ⟂ e12, so a1 = dot(w2, e12)/d, a2 = −dot(w1, e12)/d with d their sum. A non-positive
    // coordinate means the closest point is the other end alone.
    void Solve2()
    {
        const Vec2 w1 = v[0].w;
        const Vec2 w2 = v[1].w;
        const Vec2 e12 = w2 - w1;

        const Real d12n2 = -Dot(w1, e12);
        if (d12n2 <= 0)
        {
            v[0].a = 1;
            count = 1;
            return;
        }
        const Real d12n1 = Dot(w2, e12);
        if (d12n1 <= 0)
        {
            v[1].a = 1;
            count = 1;
            v[0] = v[1];
            return;
        }
        const Real invD12 = Real(1) / (d12n1 + d12n2);
        v[0].a = d12n1 * invD12;
        v[1].a = d12n2 * invD12;
        count = 2;
    }

    // The closest point of triangle w1w2w3 to the origin, by testing its Voronoi regions in
    // turn: vertex w1, edges 12 and 13, vertices w2 and w3, edge 23, then the interior (the
    // origin is inside: the shapes overlap).
    void Solve3()
    {
        const Vec2 w1 = v[0].w;
        const Vec2 w2 = v[1].w;
        const Vec2 w3 = v[2].w;

        const Vec2 e12 = w2 - w1;
        const Real w1e12 = Dot(w1, e12);
        const Real w2e12 = Dot(w2, e12);
        const Real d12n1 = w2e12;
        const Real d12n2 = -w1e12;

        const Vec2 e13 = w3 - w1;
        const Real w1e13 = Dot(w1, e13);
        const Real w3e13 = Dot(w3, e13);
        const Real d13n1 = w3e13;
        const Real d13n2 = -w1e13;

        const Vec2 e23 = w3 - w2;
        const Real w2e23 = Dot(w2, e23);
        const Real w3e23 = Dot(w3, e23);
        const Real d23n1 = w3e23;
        const Real d23n2 = -w2e23;

        const Real n123 = Cross(e12, e13);
        const Real d123n1 = n123 * Cross(w2, w3);
        const Real d123n2 = n123 * Cross(w3, w1);
        const Real d123n3 = n123 * Cross(w1, w2);

        if (d12n2 <= 0 && d13n2 <= 0)
        {
            v[0].a = 1;
            count = 1;
            return;
        }
        if (d12n1 > 0 && d12n2 > 0 && d123n3 <= 0)
        {
            const Real invD12 = Real(1) / (d12n1 + d12n2);
            v[0].a = d12n1 * invD12;
            v[1].a = d12n2 * invD12;
            count = 2;
            return;
        }
        if (d13n1 > 0 && d13n2 > 0 && d123n2 <= 0)
        {
            const Real invD13 = Real(1) / (d13n1 + d13n2);
            v[0].a = d13n1 * invD13;
            v[2].a = d13n2 * invD13;
            count = 2;
            v[1] = v[2];
            return;
        }
        if (d12n1 <= 0 && d23n2 <= 0)
        {
            v[1].a = 1;
            count = 1;
            v[0] = v[1];
            return;
        }
        if (d13n1 <= 0 && d23n1 <= 0)
        {
            v[2].a = 1;
            count = 1;
            v[0] = v[2];
            return;
        }
        if (d23n1 > 0 && d23n2 > 0 && d123n1 <= 0)
        {
            const Real invD23 = Real(1) / (d23n1 + d23n2);
            v[1].a = d23n1 * invD23;
            v[2].a = d23n2 * invD23;
            count = 2;
            v[0] = v[2];
            return;
        }
        const Real invD123 = Real(1) / (d123n1 + d123n2 + d123n3);
        v[0].a = d123n1 * invD123;
        v[1].a = d123n2 * invD123;
        v[2].a = d123n3 * invD123;
        count = 3;
    }

    void Solve()
    {
        if (count == 2)
        {
            Solve2();
        }
        else if (count == 3)
        {
            Solve3();
        }
    }
};

/// GJK's iteration limit (support-point evaluations).
constexpr int kMaxGjkIterations = 20;

} // namespace

DistanceOutput ShapeDistance(const DistanceInput& input, SimplexCache& cache)
{
    const DistanceProxy& proxyA = input.proxyA;
    const DistanceProxy& proxyB = input.proxyB;
    const Transform xfA = input.transformA;
    const Transform xfB = input.transformB;

    Simplex simplex;
    simplex.ReadCache(cache, proxyA, xfA, proxyB, xfB);

    // The vertices of the previous simplex: a support point already in it means no progress,
    // which ends the search (and prevents cycling).
    int saveA[3], saveB[3];
    int iterations = 0;
    while (iterations < kMaxGjkIterations)
    {
        const int saveCount = simplex.count;
        for (int i = 0; i < saveCount; ++i)
        {
            saveA[i] = simplex.v[i].indexA;
            saveB[i] = simplex.v[i].indexB;
        }

        simplex.Solve();
        if (simplex.count == 3)
        {
            break; // the origin is inside the triangle: overlap
        }

        const Vec2 d = simplex.GetSearchDirection();
        if (d.LengthSquared() < kEpsilon * kEpsilon)
        {
            // The origin is (nearly) on the simplex; the shapes touch or overlap, and a
            // direction this short is not fit to search along.
            break;
        }

        SimplexVertex& vertex = simplex.v[simplex.count];
        vertex.indexA = proxyA.GetSupport(MulT(xfA.q, -d));
        vertex.wA = Mul(xfA, proxyA.GetVertex(vertex.indexA));
        vertex.indexB = proxyB.GetSupport(MulT(xfB.q, d));
        vertex.wB = Mul(xfB, proxyB.GetVertex(vertex.indexB));
        vertex.w = vertex.wB - vertex.wA;
        ++iterations;

        bool duplicate = false;
        for (int i = 0; i < saveCount; ++i)
        {
            if (vertex.indexA == saveA[i] && vertex.indexB == saveB[i])
            {
                duplicate = true;
                break;
            }
        }
        if (duplicate)
        {
            break;
        }
        ++simplex.count;
    }

    DistanceOutput output;
    simplex.GetWitnessPoints(output.pointA, output.pointB);
    output.distance = Distance(output.pointA, output.pointB);
    output.iterations = iterations;
    simplex.WriteCache(cache);

    if (input.useRadii)
    {
        const Real rA = proxyA.radius;
        const Real rB = proxyB.radius;
        if (output.distance > rA + rB && output.distance > kEpsilon)
        {
            // Apart even with the radii: move the witness points out to the surfaces.
            output.distance -= rA + rB;
            Vec2 normal = output.pointB - output.pointA;
            normal.Normalize();
            output.pointA += rA * normal;
            output.pointB -= rB * normal;
        }
        else
        {
            // The rounded shapes overlap: both witness points at the middle, distance 0.
            const Vec2 p = Real(0.5) * (output.pointA + output.pointB);
            output.pointA = p;
            output.pointB = p;
            output.distance = 0;
        }
    }
    return output;
}

bool TestOverlap(const DistanceProxy& proxyA, const Transform& xfA, const DistanceProxy& proxyB,
                 const Transform& xfB)
{
    DistanceInput input;
    input.proxyA = proxyA;
    input.proxyB = proxyB;
    input.transformA = xfA;
    input.transformB = xfB;
    input.useRadii = true;
    SimplexCache cache;
    const DistanceOutput output = ShapeDistance(input, cache);
    return output.distance < Real(10) * kEpsilon;
}

bool ShapeCast(const ShapeCastInput& input, ShapeCastOutput& output)
{
    output.iterations = 0;
    output.lambda = 1;
    output.normal = {0, 0};
    output.point = {0, 0};

    const DistanceProxy& proxyA = input.proxyA;
    const DistanceProxy& proxyB = input.proxyB;
    const Real radiusA = Max(proxyA.radius, input.polygonSkin);
    const Real radiusB = Max(proxyB.radius, input.polygonSkin);
    const Real radius = radiusA + radiusB;
    const Transform xfA = input.transformA;
    const Transform xfB = input.transformB;
    const Vec2 r = input.translationB;
    Vec2 n{0, 0};
    Real lambda = 0;

    Simplex simplex;
    simplex.count = 0;

    // v: the current closest point of A − (B + λ·r) to the origin, seeded with the supports
    // against the cast direction.
    int indexA = proxyA.GetSupport(MulT(xfA.q, -r));
    Vec2 wA = Mul(xfA, proxyA.GetVertex(indexA));
    int indexB = proxyB.GetSupport(MulT(xfB.q, r));
    Vec2 wB = Mul(xfB, proxyB.GetVertex(indexB));
    Vec2 v = wA - wB;

    // The cast stops when the cores are sigma apart (within the tolerance).
    const Real sigma = Max(input.polygonSkin, radius - input.polygonSkin);
    const Real tolerance = Real(0.5) * input.linearSlop;

    int iterations = 0;
    while (iterations < kMaxGjkIterations && v.Length() - sigma > tolerance)
    {
        output.iterations += 1;

        indexA = proxyA.GetSupport(MulT(xfA.q, -v));
        wA = Mul(xfA, proxyA.GetVertex(indexA));
        indexB = proxyB.GetSupport(MulT(xfB.q, v));
        wB = Mul(xfB, proxyB.GetVertex(indexB));
        const Vec2 p = wA - wB;

        // −v is a normal of the difference at p: clip the ray λ·r against that plane.
        v.Normalize();
        const Real vp = Dot(v, p);
        const Real vr = Dot(v, r);
        if (vp - sigma > lambda * vr)
        {
            if (vr <= 0)
            {
                return false; // moving away from the plane: no hit
            }
            lambda = (vp - sigma) / vr;
            if (lambda > 1)
            {
                return false; // the hit lies beyond the translation
            }
            n = -v;
            simplex.count = 0;
        }

        // The simplex works on B − A, so A and B swap roles here; the B side is shifted to the
        // current clip point λ·r (the plane above was formed unshifted).
        SimplexVertex& vertex = simplex.v[simplex.count];
        vertex.indexA = indexB;
        vertex.wA = wB + lambda * r;
        vertex.indexB = indexA;
        vertex.wB = wA;
        vertex.w = vertex.wB - vertex.wA;
        vertex.a = 1;
        simplex.count += 1;

        simplex.Solve();
        if (simplex.count == 3)
        {
            return false; // overlap
        }
        v = simplex.GetClosestPoint();
        ++iterations;
    }

    if (iterations == 0)
    {
        return false; // overlapping at the start
    }

    Vec2 pointA, pointB;
    simplex.GetWitnessPoints(pointB, pointA);
    if (v.LengthSquared() > 0)
    {
        n = -v;
        n.Normalize();
    }
    output.point = pointA + radiusA * n;
    output.normal = n;
    output.lambda = lambda;
    output.iterations = iterations;
    return true;
}

} // namespace meff
