// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Evaluating a manifold in world space. Follows b2WorldManifold::Initialize of Box2D 2.4.1 with
// the same floating-point operation order. (The segment clipping shared by the manifold routines,
// b2ClipSegmentToLine, is inline in manifold_internal.h.)
#include "collision/manifold_internal.h"

namespace meff
{

void WorldManifold::Initialize(const Manifold& manifold, const Transform& xfA, Real radiusA,
                               const Transform& xfB, Real radiusB)
{
    // As Box2D, an empty manifold leaves every field untouched.
    if (manifold.pointCount == 0)
    {
        return;
    }

    switch (manifold.type)
    {
    case Manifold::Type::Circles:
    {
        normal = Vec2(1, 0);
        const Vec2 centerA = Mul(xfA, manifold.localPoint);
        const Vec2 centerB = Mul(xfB, manifold.points[0].localPoint);
        // Coincident centres keep the arbitrary +x normal.
        if (DistanceSquared(centerA, centerB) > kEpsilon * kEpsilon)
        {
            normal = centerB - centerA;
            normal.Normalize();
        }

        const Vec2 surfaceA = centerA + radiusA * normal;
        const Vec2 surfaceB = centerB - radiusB * normal;
        points[0] = Real(0.5) * (surfaceA + surfaceB);
        separations[0] = Dot(surfaceB - surfaceA, normal);
        break;
    }

    case Manifold::Type::FaceA:
    {
        normal = Mul(xfA.q, manifold.localNormal);
        const Vec2 planePoint = Mul(xfA, manifold.localPoint);

        for (int i = 0; i < manifold.pointCount; ++i)
        {
            const Vec2 clipPoint = Mul(xfB, manifold.points[i].localPoint);
            const Vec2 surfaceA =
                clipPoint + (radiusA - Dot(clipPoint - planePoint, normal)) * normal;
            const Vec2 surfaceB = clipPoint - radiusB * normal;
            points[i] = Real(0.5) * (surfaceA + surfaceB);
            separations[i] = Dot(surfaceB - surfaceA, normal);
        }
        break;
    }

    case Manifold::Type::FaceB:
    {
        normal = Mul(xfB.q, manifold.localNormal);
        const Vec2 planePoint = Mul(xfB, manifold.localPoint);

        for (int i = 0; i < manifold.pointCount; ++i)
        {
            const Vec2 clipPoint = Mul(xfA, manifold.points[i].localPoint);
            const Vec2 surfaceB =
                clipPoint + (radiusB - Dot(clipPoint - planePoint, normal)) * normal;
            const Vec2 surfaceA = clipPoint - radiusA * normal;
            points[i] = Real(0.5) * (surfaceA + surfaceB);
            separations[i] = Dot(surfaceA - surfaceB, normal);
        }

        // The reference face belongs to B, so its normal points from B to A: turn it round.
        normal = -normal;
        break;
    }
    }
}

} // namespace meff
