#include "solvers/soft_step/soft_bodies.h"

#include "dynamics/body.h"

#include <cmath>

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
    bodies.linearDelta.resize(count);
    bodies.angularDelta.resize(count);
    bodies.linearDamping.resize(count);
    bodies.angularDamping.resize(count);
    for (std::size_t i = 0; i < count; ++i)
    {
        Body& body = world.bodies[island.bodies[i]];
        body.sweep.c0 = body.sweep.c;
        body.sweep.a0 = body.sweep.a;
        bodies.start[i] = {body.sweep.c, body.sweep.a};
        bodies.velocities[i] = {body.linearVelocity, body.angularVelocity};
        const bool dynamic = body.type == BodyType::Dynamic;
        // Static and kinematic bodies keep their velocities: no forces, no damping.
        bodies.linearDelta[i] =
            dynamic
                ? h * body.invMass * (body.gravityScale * body.mass * world.gravity + body.force)
                : Vec2{};
        bodies.angularDelta[i] = dynamic ? h * body.invI * body.torque : Real(0);
        bodies.linearDamping[i] = dynamic ? body.linearDamping : Real(0);
        bodies.angularDamping[i] = dynamic ? body.angularDamping : Real(0);
    }
    bodies.velocities[count] = {};
    bodies.h = h;
}

void IntegrateSoftVelocities(SoftBodies& bodies, Real fraction)
{
    // Semi-implicit Euler, the damping ODE dv/dt = −c·v solved implicitly over the kick
    // (stable for any c·h).
    const Real h = fraction * bodies.h;
    for (std::size_t i = 0; i < bodies.start.size(); ++i)
    {
        Velocity& v = bodies.velocities[i];
        v.v += fraction * bodies.linearDelta[i];
        v.w += fraction * bodies.angularDelta[i];
        if (bodies.linearDamping[i] > 0)
        {
            v.v *= Real(1) / (Real(1) + h * bodies.linearDamping[i]);
        }
        if (bodies.angularDamping[i] > 0)
        {
            v.w *= Real(1) / (Real(1) + h * bodies.angularDamping[i]);
        }
    }
}

void IntegrateSoftPositions(SoftBodies& bodies, Real h, const StepContext& step)
{
    const Tolerances& tol = step.tolerances;
    const Real maxSpeed = tol.maxTranslation * step.invDt;
    const Real maxAngularSpeed = tol.maxRotation * step.invDt;
    for (std::size_t i = 0; i < bodies.start.size(); ++i)
    {
        Velocity& v = bodies.velocities[i];
        // A body cannot outrun the broad phase's margins (Box2D's per-step clamp, per second).
        const Real speedSquared = Dot(v.v, v.v);
        if (speedSquared > maxSpeed * maxSpeed)
        {
            v.v *= maxSpeed / std::sqrt(speedSquared);
        }
        if (v.w * v.w > maxAngularSpeed * maxAngularSpeed)
        {
            v.w *= maxAngularSpeed / std::abs(v.w);
        }
        SoftDelta& d = bodies.deltas[i];
        d.dp += h * v.v;
        // Rotate dq by the angle h·w itself (not its tangent, as normalizing q + h·w·q⊥ would):
        // the angle the rows see is the angle integrated, and the pendulum keeps its period.
        d.dq = Mul(SmallRotation(h * v.w), d.dq);
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
