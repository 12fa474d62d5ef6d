#include "solvers/soft_step/soft_bodies.h"

#include "dynamics/body.h"
#include "solvers/soft_step/soft_delta_lanes.h"

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

void GatherSoftBodies(SolverWorld& world, const Island& island, Real h, SoftBodies& bodies)
{
    const std::size_t count = island.bodies.size();
    bodies.velocities.resize(count + 1);
    bodies.deltas.assign(count + 1, SoftDelta{});
    bodies.start.resize(count);
    bodies.kick.resize(count);
    bodies.damping.resize(count);
    for (std::size_t i = 0; i < count; ++i)
    {
        Body& body = world.bodies[island.bodies[i]];
        body.sweep.c0 = body.sweep.c;
        body.sweep.a0 = body.sweep.a;
        bodies.start[i] = {body.sweep.c, body.sweep.a};
        bodies.velocities[i] = {body.linearVelocity, body.angularVelocity};
        // Static and kinematic bodies keep their velocities: no forces, no damping.
        if (body.type != BodyType::Dynamic)
        {
            bodies.kick[i] = {};
            bodies.damping[i] = {};
            continue;
        }
        bodies.kick[i] = {h * body.invMass *
                              (body.gravityScale * body.mass * world.gravity + body.force),
                          h * body.invI * body.torque};
        bodies.damping[i] = {{body.linearDamping, body.linearDamping}, body.angularDamping};
    }
    bodies.velocities[count] = {};
    bodies.h = h;
}

void IntegrateSoftVelocities(SoftBodies& bodies, Real fraction)
{
    // Semi-implicit Euler, the damping ODE dv/dt = −c·v solved implicitly over the kick
    // (stable for any c·h): v ← (v + fraction·Δv) / (1 + fraction·h·c). A body's velocity is one
    // Real4 (v.x, v.y, w, padding), so the three components take one vector operation each
    // step; where c = 0 the factor is exactly 1 and leaves v's bits as they are.
    const Real h = fraction * bodies.h;
    for (std::size_t i = 0; i < bodies.start.size(); ++i)
    {
        Real4 v, kick, c;
        std::memcpy(&v, &bodies.velocities[i], sizeof(Real4));
        std::memcpy(&kick, &bodies.kick[i], sizeof(Real4));
        std::memcpy(&c, &bodies.damping[i], sizeof(Real4));
        v = (v + fraction * kick) * (Real(1) / (Real(1) + h * c));
        std::memcpy(static_cast<void*>(&bodies.velocities[i]), &v, sizeof(Real4));
    }
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

void IntegrateSoftPositions(SoftBodies& bodies, Real h, const StepContext& step)
{
    const Tolerances& tol = step.tolerances;
    const SpeedLimits limits{tol.maxTranslation * step.invDt, tol.maxRotation * step.invDt};
    const auto count = static_cast<std::int32_t>(bodies.start.size());
    std::int32_t i = 0;
    for (; i + kLanes <= count; i += kLanes)
    {
        IntegrateSoftPositionsW(bodies, i, h, limits);
    }
    for (; i < count; ++i)
    {
        IntegrateSoftPosition(bodies.velocities[i], bodies.deltas[i], h, limits);
    }
}

void ScatterSoftBodies(const SoftBodies& bodies, Island& island)
{
    const std::size_t count = bodies.start.size();
    island.positions.resize(count);
    island.velocities.resize(count);
    for (std::size_t i = 0; i < count; ++i)
    {
        const SoftDelta& d = bodies.deltas[i];
        island.positions[i] = {bodies.start[i].c + d.dp, bodies.start[i].a + d.dq.GetAngle()};
        island.velocities[i] = bodies.velocities[i];
    }
}

} // namespace meff::detail
