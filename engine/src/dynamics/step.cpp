// One step of the world, as named stages. The order is Box2D 2.4.1's (b2World::Step,
// b2World::Solve), so the same scene agrees between the two engines:
//
//   find new contacts → collide → solve (the back end SolverSettings::kind chooses:
//   solvers/solver.h) → synchronize shapes → find new contacts → continuous collision (if on)
//   → clear forces
//
// The back end solves the awake bodies (integration, contacts, joints, sleep) and reports the
// contacts it solved; only bodies it moved move in the broad phase, and the narrow phase skips
// contacts whose bodies all sleep.
//
// Events: the narrow phase (collide, and continuous collision's contact updates) records
// contact and sensor begin/end events and calls the pre-solve callback; the back end's solved
// contacts become the contact reports, built when read (contact_reports.h), and hit events
// (events.cpp).
#include "dynamics/step_stages.h"

#include "dynamics/contact_reports.h"
#include "dynamics/events.h"
#include "dynamics/world_state.h"
#include "meff/world.h"

#include <chrono>
#include <exception>
#include <string>

namespace meff
{

using namespace detail;

namespace
{

/// Marks the world as stepping while Step runs; an exception leaving Step (from the pre-solve
/// callback) leaves the step half done, so the world is then frozen as after a non-finite one.
class SteppingGuard
{
  public:
    explicit SteppingGuard(WorldState& world)
        : m_world(world), m_exceptions(std::uncaught_exceptions())
    {
        m_world.stepping = true;
    }
    ~SteppingGuard()
    {
        m_world.stepping = false;
        if (std::uncaught_exceptions() > m_exceptions)
        {
            m_world.failed = true;
        }
    }
    SteppingGuard(const SteppingGuard&) = delete;
    SteppingGuard& operator=(const SteppingGuard&) = delete;

  private:
    WorldState& m_world;
    int m_exceptions;
};

/// Adds the time from its construction to its destruction to `total` (ms): a stage's share of
/// World::GetProfile.
class StageTimer
{
  public:
    explicit StageTimer(double& total) : m_total(total), m_start(std::chrono::steady_clock::now())
    {
    }
    ~StageTimer()
    {
        m_total +=
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - m_start)
                .count();
    }
    StageTimer(const StageTimer&) = delete;
    StageTimer& operator=(const StageTimer&) = delete;

  private:
    double& m_total;
    std::chrono::steady_clock::time_point m_start;
};

template <typename Stage>
void Timed(double& total, Stage&& stage)
{
    const StageTimer timer(total);
    stage();
}

} // namespace

void World::Step(Real dt)
{
    WorldState& world = State();
    if (!(dt > 0) || !meff::IsValid(dt))
    {
        throw InvalidArgument("World::Step: dt must be finite and > 0, got " + std::to_string(dt));
    }
    if (world.stepping)
    {
        throw InvalidArgument("World::Step: called during World::Step (from the pre-solve "
                              "callback); the callback must not change the world");
    }
    if (world.failed)
    {
        throw Error("World::Step: an earlier step failed (a non-finite state, or an exception "
                    "from the pre-solve callback); the world is frozen (read it, then rebuild "
                    "it or restore a snapshot)");
    }
    const SteppingGuard stepping(world);

    StepProfile& profile = world.profile;
    profile = {};
    const StageTimer whole(profile.step);
    const StepContext step = BeginStep(world, dt);
    try
    {
        if (world.newShapes)
        {
            Timed(profile.findContacts, [&] { FindNewContacts(world); });
        }
        Timed(profile.collide, [&] { Collide(world); });

        Timed(profile.solve, [&] { Solve(world, step); });
        Timed(profile.synchronize, [&] { SynchronizeShapes(world); });
        Timed(profile.findContacts, [&] { FindNewContacts(world); });
        if (world.continuous)
        {
            Timed(profile.continuous, [&] { SolveContinuous(world, step); });
        }
    }
    catch (const SimulationError&)
    {
        world.failed = true; // the bodies kept their last good state; stepping is refused
        throw;
    }
    ClearForces(world);
    MarkStepEvents(world);
    world.invDt0 = step.invDt;
    ++world.stepCount;
}

namespace detail
{

StepContext BeginStep(WorldState& world, Real dt)
{
    StepContext step;
    step.dt = dt;
    step.invDt = Real(1) / dt;
    step.dtRatio = world.invDt0 * dt;
    step.solver = world.solver;
    step.tolerances = world.tolerances;
    ClearEvents(world);
    return step;
}

void Solve(WorldState& world, const StepContext& step)
{
    WorldContactSink sink(world);
    SolverWorld view = SolverView(world, sink);
    world.solvers.For(step.solver.kind).Step(view, step);
}

void SynchronizeShapes(WorldState& world)
{
    for (std::int32_t b = world.bodyList; b != kNullIndex; b = world.bodies[b].next)
    {
        Body& body = world.bodies[b];
        // A body outside every island did not move; static bodies never move in a step.
        if (!body.islandFlag || body.type == BodyType::Static)
        {
            continue;
        }
        SynchronizeBodyShapes(world, body);
    }
}

void SynchronizeBodyShapes(WorldState& world, Body& body)
{
    // A body that fell asleep this step gets tight boxes at its resting pose, not boxes
    // covering its last motion (Box2D 2.4.1's b2Body::SynchronizeFixtures).
    Transform xf0 = body.xf;
    if (body.awake)
    {
        xf0.q.Set(body.sweep.a0);
        xf0.p = body.sweep.c0 - Mul(xf0.q, body.sweep.localCenter);
    }
    for (const std::int32_t s : body.shapes)
    {
        Shape& shape = world.shapes[s];
        const AABB box0 = shape.ComputeAABB(xf0);
        const AABB box1 = shape.ComputeAABB(body.xf);
        shape.aabb = Combine(box0, box1);
        world.broadPhase.MoveProxy(shape.proxyId, shape.aabb, box1.GetCenter() - box0.GetCenter());
    }
}

void ClearForces(WorldState& world)
{
    for (Body& body : world.bodies)
    {
        body.force = {0, 0};
        body.torque = 0;
    }
}

} // namespace detail
} // namespace meff
