// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
#include "solvers/soft_step/soft_bodies.h"

#include "model/body.h"
#include "solvers/soft_step/soft_delta_lanes.h"
#include "tasks/parallel_ranges.h"

#include <cmath>
#include <cstring>

namespace meff::detail
{

Rot SmallRotation(Real angle)
{
    if (std::abs(angle) > Real(0.5))
    {
        return Rot(angle);
    }
    Rot q;
    if (std::abs(angle) <= kShortSeriesAngle)
    {
        ShortRotationSeries(angle, q.s, q.c);
        return q;
    }
    SmallRotationSeries(angle, q.s, q.c);
    return q;
}

namespace
{

/// The damping ODE dv/dt = −c·v solved implicitly over a kick of `dt` (stable for any c·dt):
/// v ← v / (1 + dt·c), linear and angular; exactly 1 where the body has no damping.
Velocity DampingOver(Real dt, const Body& body)
{
    const Real linear = Real(1) / (Real(1) + dt * body.linearDamping);
    return {{linear, linear}, Real(1) / (Real(1) + dt * body.angularDamping)};
}

/// Runs f(i) for each body i of [0, count), at least kMinBodiesPerTask to a range on `tasks`.
template <typename F>
void ForBodies(TaskSystem* tasks, std::size_t count, F&& f)
{
    ForEachIndex(tasks, static_cast<int>(count), kMinBodiesPerTask,
                 [&](int i) { f(static_cast<std::size_t>(i)); });
}

/// Body `body`'s state into slot i of `bodies`, its sweep's start set to now.
void GatherSoftBody(const SolverWorld& world, Body& body, Real h, std::size_t i, SoftBodies& bodies)
{
    body.sweep.c0 = body.sweep.c;
    body.sweep.a0 = body.sweep.a;
    bodies.start[i] = {body.sweep.c, body.sweep.a};
    bodies.masses[i] = {body.invMass, body.invI, body.sweep.localCenter};
    bodies.velocities[i] = {body.linearVelocity, body.angularVelocity};
    // Static and kinematic bodies keep their velocities: no forces, no damping.
    if (body.type != BodyType::Dynamic)
    {
        bodies.kick[i] = {};
        bodies.wholeDamping[i] = bodies.halfDamping[i] = {{1, 1}, 1};
        return;
    }
    bodies.kick[i] = {h * body.invMass *
                          (body.gravityScale * body.mass * world.gravity + body.force),
                      h * body.invI * body.torque};
    bodies.wholeDamping[i] = DampingOver(h, body);
    bodies.halfDamping[i] = DampingOver(Real(0.5) * h, body);
}

} // namespace

void GatherSoftBodies(SolverWorld& world, const Island& island, Real h, SoftBodies& bodies)
{
    const std::size_t count = island.bodies.size();
    const auto discardSlots = static_cast<std::size_t>(WorkerCount(world.tasks));
    bodies.velocities.resize(count + discardSlots);
    bodies.deltas.assign(count + discardSlots, SoftDelta{});
    bodies.start.resize(count);
    bodies.masses.resize(count);
    bodies.kick.resize(count);
    bodies.wholeDamping.resize(count);
    bodies.halfDamping.resize(count);
    ForBodies(world.tasks, count,
              [&](std::size_t i)
              { GatherSoftBody(world, world.bodies[island.bodies[i]], h, i, bodies); });
    for (std::size_t slot = count; slot < count + discardSlots; ++slot)
    {
        bodies.velocities[slot] = {};
    }
    bodies.h = h;
}

void IntegrateSoftVelocities(SoftBodies& bodies, bool half, TaskSystem* tasks)
{
    // Semi-implicit Euler: v ← (v + fraction·Δv)·damping (DampingOver). A body's velocity, kick
    // and damping are each one Real4 (x, y, angular, padding): one vector operation per step.
    const Real fraction = half ? Real(0.5) : Real(1);
    const Velocity* damping = half ? bodies.halfDamping.data() : bodies.wholeDamping.data();
    ForBodies(tasks, bodies.start.size(),
              [&](std::size_t i)
              {
                  Real4 v, kick, factor;
                  std::memcpy(&v, &bodies.velocities[i], sizeof(Real4));
                  std::memcpy(&kick, &bodies.kick[i], sizeof(Real4));
                  std::memcpy(&factor, &damping[i], sizeof(Real4));
                  v = (v + fraction * kick) * factor;
                  std::memcpy(static_cast<void*>(&bodies.velocities[i]), &v, sizeof(Real4));
              });
}

namespace
{

/// The speed limits of IntegrateSoftPositions (per second).
struct SpeedLimits
{
    Real linear, angular;
};

/// One body's sub-step of motion: the speeds clamped, dp ← dp + h·v, dq ← R(h·w)·dq.
void IntegrateSoftPosition(Velocity& v, SoftDelta& d, Real h, SpeedLimits limits)
{
    // A body cannot outrun the broad phase's margins (Box2D's per-step clamp, per second).
    const Real speedSquared = Dot(v.v, v.v);
    if (speedSquared > limits.linear * limits.linear)
    {
        v.v *= limits.linear / std::sqrt(speedSquared);
    }
    if (v.w * v.w > limits.angular * limits.angular)
    {
        v.w *= limits.angular / std::abs(v.w);
    }
    d.dp += h * v.v;
    // Rotate dq by the angle h·w itself (not its tangent, as normalizing q + h·w·q⊥ would):
    // the angle the rows see is the angle integrated, and the pendulum keeps its period.
    d.dq = Mul(SmallRotation(h * v.w), d.dq);
}

/// IntegrateSoftPosition for kLanes consecutive bodies from `first`, in SIMD lanes with the same
/// operations per lane; bodies that must be slowed down go one by one (rare: only the clamp
/// needs a square root).
void IntegrateSoftPositionsW(SoftBodies& bodies, std::int32_t first, Real h, SpeedLimits limits)
{
    std::int32_t index[kLanes];
    for (int l = 0; l < kLanes; ++l)
    {
        index[l] = first + l;
    }
    const BodyStateW v = Gather(bodies.velocities.data(), index);
    const MaskW tooFast = (Dot(v.linear, v.linear) > limits.linear * limits.linear) |
                          (v.angular * v.angular > limits.angular * limits.angular);
    if (AnyLane(tooFast))
    {
        for (int l = 0; l < kLanes; ++l)
        {
            IntegrateSoftPosition(bodies.velocities[first + l], bodies.deltas[first + l], h,
                                  limits);
        }
        return;
    }
    DeltaW d = GatherDeltas(bodies.deltas.data(), index);
    const RealW hW = Splat(h);
    d.dp = d.dp + Vec2W{hW * v.linear.x, hW * v.linear.y};
    d.dq = MulRot(SmallRotationW(hW * v.angular), d.dq);
    ScatterDeltas(bodies.deltas.data(), index, d);
}

} // namespace

void IntegrateSoftPositions(SoftBodies& bodies, Real h, const StepContext& step, TaskSystem* tasks)
{
    const Tolerances& tol = step.tolerances;
    const SpeedLimits limits{tol.maxTranslation * step.invDt, tol.maxRotation * step.invDt};
    const auto count = static_cast<std::int32_t>(bodies.start.size());
    // Whole blocks of kLanes bodies on the threads, the rest one by one.
    const std::int32_t blocks = count / kLanes;
    ForEachIndex(tasks, blocks, kMinBodiesPerTask / kLanes,
                 [&](std::int32_t b) { IntegrateSoftPositionsW(bodies, b * kLanes, h, limits); });
    for (std::int32_t i = blocks * kLanes; i < count; ++i)
    {
        IntegrateSoftPosition(bodies.velocities[i], bodies.deltas[i], h, limits);
    }
}

void ScatterSoftBodies(const SoftBodies& bodies, Island& island, TaskSystem* tasks)
{
    const std::size_t count = bodies.start.size();
    island.positions.resize(count);
    island.velocities.resize(count);
    ForBodies(
        tasks, count,
        [&](std::size_t i)
        {
            const SoftDelta& d = bodies.deltas[i];
            island.positions[i] = {bodies.start[i].c + d.dp, bodies.start[i].a + d.dq.GetAngle()};
            island.velocities[i] = bodies.velocities[i];
        });
}

} // namespace meff::detail
