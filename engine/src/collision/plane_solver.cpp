// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The mover's plane solver (meff/mover.h). Each plane is one scalar row on the mover's
// translation d with Jacobian n (a unit normal) and an effective mass of 1 — the seed's k for a
// body of unit mass that does not turn — so the row's update is the plain projection
//   push ← clamp(push − (separation + n·d), 0, pushLimit),   d ← d + Δpush·n,
// swept over the planes as Gauss-Seidel sweeps over contact rows.
#include "meff/mover.h"

#include <cmath>

namespace meff
{

PlaneSolverResult SolvePlanes(Vec2 delta, std::span<CollisionPlane> planes, Real tolerance)
{
    constexpr int kMaxSweeps = 20;
    for (CollisionPlane& plane : planes)
    {
        plane.push = 0;
    }
    PlaneSolverResult result;
    result.translation = delta;
    for (int sweep = 0; sweep < kMaxSweeps; ++sweep)
    {
        result.iterations = sweep + 1;
        Real largest = 0;
        for (CollisionPlane& plane : planes)
        {
            const Real separation = plane.separation + Dot(plane.normal, result.translation);
            const Real next = Clamp(plane.push - separation, Real(0), plane.pushLimit);
            const Real change = next - plane.push;
            plane.push = next;
            result.translation += change * plane.normal;
            largest = Max(largest, std::abs(change));
        }
        if (largest <= tolerance)
        {
            break;
        }
    }
    return result;
}

Vec2 ClipVector(Vec2 velocity, std::span<const CollisionPlane> planes)
{
    for (int sweep = 0; sweep < 2; ++sweep)
    {
        for (const CollisionPlane& plane : planes)
        {
            if (plane.push > 0 && plane.clipVelocity)
            {
                velocity -= Min(Dot(velocity, plane.normal), Real(0)) * plane.normal;
            }
        }
    }
    return velocity;
}

} // namespace meff
