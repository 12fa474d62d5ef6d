// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The bodies of one island as the soft step moves them: velocities, and each body's motion
// since the step began — the translation dp of its centre of mass and the rotation dq — so
// that every sub-step's rows measure their position error from the step's start without
// recomputing transforms (Box2D v3's body state).
#pragma once

#include "model/solver_types.h"
#include "solvers/lanes/lane_bodies.h"
#include "solvers/shared/island.h"
#include "solvers/solver.h"

#include <cstdint>
#include <vector>

namespace meff::detail
{

/// A body's motion since the step began: translation of the centre of mass (m) and rotation.
/// Four Reals, aligned to one SIMD vector like Velocity.
struct alignas(4 * sizeof(Real)) SoftDelta
{
    Vec2 dp;
    Rot dq;
};

struct SoftBodies
{
    /// By solver index (the island's order), with a slot more for each worker of the world's
    /// threads, written by the lanes that must not move their body: DiscardIndex() + worker.
    std::vector<Velocity> velocities;
    std::vector<SoftDelta> deltas;
    std::vector<Position> start; ///< centre of mass and angle when the step began
    /// Each body's inverse mass, inverse inertia and local centre, as the lanes gather them by
    /// their body indices (GatherBodyMass) instead of keeping a copy per row.
    std::vector<BodyMass> masses;
    /// Per sub-step, as a Velocity: h·(F/m + gravityScale·g) (m/s) and h·T/I (rad/s).
    std::vector<Velocity> kick;
    /// The damping of a whole sub-step's kick and of a half kick, as a Velocity: each component's
    /// factor 1/(1 + kick·c) for the body's linear and angular damping rates c (1/s), exactly 1
    /// where c = 0. Computed once per step: the kicks are the same in every sub-step.
    std::vector<Velocity> wholeDamping, halfDamping;
    Real h = 0; ///< the sub-step (s)

    /// Worker 0's discard slot: the island's body count.
    std::int32_t DiscardIndex() const { return static_cast<std::int32_t>(start.size()); }
};

// Each of these works body by body, so it spreads the bodies over `tasks` (the world's threads,
// or null) in ranges: the results do not depend on the thread count.

/// Copies the island's bodies in (their sweeps' start c0, a0 set to now) for sub-steps of h,
/// with a discard slot for each of world.tasks' workers.
void GatherSoftBodies(SolverWorld& world, const Island& island, Real h, SoftBodies& bodies);
/// v ← damping·(v + fraction·Δv) for every dynamic body (static and kinematic bodies keep
/// theirs): `fraction` 1 for a whole sub-step, ½ (`half`) for velocity Verlet's half kicks.
void IntegrateSoftVelocities(SoftBodies& bodies, bool half, TaskSystem* tasks);
/// dp ← dp + h·v, dq ← the rotation by h·w after dq, with the speeds clamped so a body moves at
/// most maxTranslation and maxRotation per step, as the Box2D back end clamps them.
void IntegrateSoftPositions(SoftBodies& bodies, Real h, const StepContext& step, TaskSystem* tasks);
/// The island's state at the step's end, into island.positions and island.velocities.
void ScatterSoftBodies(const SoftBodies& bodies, Island& island, TaskSystem* tasks);

/// Below this angle (rad) SmallRotation's series stops at the 5th and 4th power: the first term
/// left out is under (1/16)⁶/720 < 2e-10, far below float's rounding, and most turns within a
/// sub-step (a position correction, a slow spin) are this small.
inline constexpr Real kShortSeriesAngle = Real(0.0625);

/// Sine and cosine of `angle` (rad) by their Taylor series to the 5th and 4th power, for
/// |angle| ≤ kShortSeriesAngle. Written once for a Real and for SIMD lanes (RealW).
template <typename R>
[[gnu::always_inline]] inline void ShortRotationSeries(R angle, R& s, R& c)
{
    const R a2 = angle * angle;
    c = Real(1) - a2 / Real(2) * (Real(1) - a2 / Real(12));
    s = angle * (Real(1) - a2 / Real(6) * (Real(1) - a2 / Real(20)));
}

/// Sine and cosine of `angle` (rad) by their Taylor series to the 9th and 8th power: below
/// |angle| = 0.5 the first term left out is under 0.5¹⁰/10! < 3e-10, far below float's rounding.
/// Written once for a Real and for SIMD lanes (RealW).
template <typename R>
[[gnu::always_inline]] inline void SmallRotationSeries(R angle, R& s, R& c)
{
    const R a2 = angle * angle;
    c = Real(1) -
        a2 / Real(2) *
            (Real(1) - a2 / Real(12) * (Real(1) - a2 / Real(30) * (Real(1) - a2 / Real(56))));
    s = angle *
        (Real(1) -
         a2 / Real(6) *
             (Real(1) - a2 / Real(20) * (Real(1) - a2 / Real(42) * (Real(1) - a2 / Real(72)))));
}

/// The rotation by `angle` (rad), by its Taylor series where that is exact to float precision
/// (|angle| ≤ 0.5; a shorter one to kShortSeriesAngle) and std::sin/std::cos beyond.
Rot SmallRotation(Real angle);

/// The relative rotation of B with respect to A since the step began (rad), from their
/// rotations dqA and dqB.
inline Real RelativeRotation(Rot dqA, Rot dqB)
{
    return MulT(dqA, dqB).GetAngle();
}

} // namespace meff::detail
