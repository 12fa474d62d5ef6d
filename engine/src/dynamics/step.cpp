// One step of the world, as named stages. The order is Box2D 2.4.1's (b2World::Step,
// b2World::Solve, b2Island::Solve), so the same scene agrees between the two engines:
//
//   find new contacts → collide → for each island: integrate velocities, prepare, warm start,
//   solve velocities, integrate positions, correct positions, finish bodies, report contacts,
//   report hits, sleep → synchronize shapes → find new contacts → continuous collision (if on) →
//   clear forces
//
// Solving by colour without sleep, the awake world is one island (island.h). Otherwise only
// awake bodies seed islands, so a sleeping island costs no solver work; the narrow phase
// skips contacts whose bodies all sleep, and only bodies solved this step move in the broad
// phase.
//
// Events: the narrow phase (collide, and continuous collision's contact updates) records
// contact and sensor begin/end events and calls the pre-solve callback; the report stages
// record the solved contacts, whose reports are built when read (contact_reports.h), and hit
// events (events.cpp).
#include "dynamics/step_stages.h"

#include "dynamics/contact_reports.h"
#include "dynamics/events.h"
#include "dynamics/world_state.h"
#include "meff/world.h"

#include <string>

namespace meff
{

using namespace detail;

void World::Step(Real dt)
{
    WorldState& world = *m_state;
    if (!(dt > 0) || !meff::IsValid(dt))
    {
        throw InvalidArgument("World::Step: dt must be finite and > 0, got " + std::to_string(dt));
    }
    if (world.failed)
    {
        throw Error("World::Step: an earlier step produced a non-finite state; the world is "
                    "frozen (read it, then rebuild it)");
    }

    const StepContext step = BeginStep(world, dt);
    if (world.newShapes)
    {
        FindNewContacts(world);
    }
    Collide(world);

    SolveIslands(world, step);
    SynchronizeShapes(world);
    FindNewContacts(world);
    if (world.continuous)
    {
        SolveContinuous(world, step);
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

void SolveIslands(WorldState& world, const StepContext& step)
{
    // Without sleep and Box2D's order, islands would only split the colouring's work.
    if (step.solver.graphColoring && !world.allowSleep && BuildWorldIsland(world, world.island))
    {
        SolveIsland(world, world.island, step);
        return;
    }
    ResetIslandFlags(world);
    for (std::int32_t seed = world.bodyList; seed != kNullIndex; seed = world.bodies[seed].next)
    {
        if (CanSeedIsland(world.bodies[seed]))
        {
            BuildIsland(world, seed, world.island);
            SolveIsland(world, world.island, step);
            ReleaseStaticBodies(world, world.island);
        }
    }
}

bool CanSeedIsland(const Body& body)
{
    return body.alive && !body.islandFlag && body.awake && body.type != BodyType::Static;
}

void SolveIsland(WorldState& world, Island& island, const StepContext& step)
{
    SolverData data{step, nullptr, nullptr};
    IntegrateVelocities(world, island, step);
    data.positions = island.positions.data();
    data.velocities = island.velocities.data();
    data.discardIndex = static_cast<std::int32_t>(island.bodies.size());

    world.contactSolver.Prepare(island.contacts, world.contacts, world.bodies, data);
    if (step.solver.warmStarting)
    {
        world.contactSolver.WarmStart(data);
    }
    world.jointSolver.Prepare(island.joints, world.joints, world.bodies, data);

    for (int i = 0; i < step.solver.velocityIterations; ++i)
    {
        world.jointSolver.SolveVelocities(data);
        world.contactSolver.SolveVelocities(data);
    }
    world.contactSolver.StoreImpulses(world.contacts);
    world.jointSolver.StoreImpulses();

    IntegratePositions(island, step);
    const bool positionSolved = CorrectPositions(world, data);
    FinishBodies(world, island);
    RecordContactReports(world);
    ReportHitEvents(world, step);
    if (world.allowSleep)
    {
        UpdateSleep(world, island, step, positionSolved);
    }
}

void IntegrateVelocities(WorldState& world, Island& island, const StepContext& step)
{
    const std::size_t count = island.bodies.size();
    // One slot more than the island's bodies: SolverData::discardIndex.
    island.positions.resize(count + 1);
    island.velocities.resize(count + 1);
    const Real h = step.dt;
    for (std::size_t i = 0; i < count; ++i)
    {
        Body& body = world.bodies[island.bodies[i]];
        Vec2 v = body.linearVelocity;
        Real w = body.angularVelocity;
        body.sweep.c0 = body.sweep.c;
        body.sweep.a0 = body.sweep.a;
        if (body.type == BodyType::Dynamic)
        {
            // Semi-implicit Euler: v += h·(g + F/m), then the damping ODE dv/dt = −c·v solved
            // implicitly (stable for any c·h).
            v += h * body.invMass * (body.gravityScale * body.mass * world.gravity + body.force);
            w += h * body.invI * body.torque;
            v *= Real(1) / (Real(1) + h * body.linearDamping);
            w *= Real(1) / (Real(1) + h * body.angularDamping);
        }
        island.positions[i] = {body.sweep.c, body.sweep.a};
        island.velocities[i] = {v, w};
    }
}

void IntegratePositions(Island& island, const StepContext& step)
{
    const Real h = step.dt;
    const Tolerances& tol = step.tolerances;
    const Real maxTranslationSquared = tol.maxTranslation * tol.maxTranslation;
    const Real maxRotationSquared = tol.maxRotation * tol.maxRotation;
    for (std::size_t i = 0; i < island.bodies.size(); ++i)
    {
        Vec2 c = island.positions[i].c;
        Real a = island.positions[i].a;
        Vec2 v = island.velocities[i].v;
        Real w = island.velocities[i].w;

        // Clamp the motion of one step: a body cannot outrun the broad phase's margins.
        const Vec2 translation = h * v;
        if (Dot(translation, translation) > maxTranslationSquared)
        {
            v *= tol.maxTranslation / translation.Length();
        }
        const Real rotation = h * w;
        if (rotation * rotation > maxRotationSquared)
        {
            w *= tol.maxRotation / std::abs(rotation);
        }

        c += h * v;
        a += h * w;
        island.positions[i] = {c, a};
        island.velocities[i] = {v, w};
    }
}

bool CorrectPositions(WorldState& world, SolverData& data)
{
    for (int i = 0; i < data.step.solver.positionIterations; ++i)
    {
        const bool contactsOkay = world.contactSolver.SolvePositions(data);
        const bool jointsOkay = world.jointSolver.SolvePositions(data);
        if (contactsOkay && jointsOkay)
        {
            return true; // every constraint within tolerance: later sweeps would only add drift
        }
    }
    return false;
}

void FinishBodies(WorldState& world, Island& island)
{
    // Refuse a non-finite state before any of this island is written back, so the bodies keep
    // their last good state and stay readable.
    for (std::size_t i = 0; i < island.bodies.size(); ++i)
    {
        const Position& p = island.positions[i];
        const Velocity& v = island.velocities[i];
        if (!p.c.IsValid() || !meff::IsValid(p.a) || !v.v.IsValid() || !meff::IsValid(v.w))
        {
            world.failed = true;
            const std::int32_t bodyIndex = island.bodies[i];
            throw SimulationError("step " + std::to_string(world.stepCount) + ": body " +
                                      std::to_string(bodyIndex) + " (user data " +
                                      std::to_string(world.bodies[bodyIndex].userData) +
                                      ") has a non-finite position or velocity",
                                  world.stepCount, bodyIndex);
        }
    }
    for (std::size_t i = 0; i < island.bodies.size(); ++i)
    {
        Body& body = world.bodies[island.bodies[i]];
        body.sweep.c = island.positions[i].c;
        body.sweep.a = island.positions[i].a;
        body.linearVelocity = island.velocities[i].v;
        body.angularVelocity = island.velocities[i].w;
        SynchronizeTransform(body);
    }
}

void UpdateSleep(WorldState& world, const Island& island, const StepContext& step,
                 bool positionSolved)
{
    // Speeds are compared squared, as Box2D does, so that no square root changes the verdict.
    const Tolerances& tol = step.tolerances;
    const Real linearToleranceSquared = tol.linearSleepTolerance * tol.linearSleepTolerance;
    const Real angularToleranceSquared = tol.angularSleepTolerance * tol.angularSleepTolerance;
    Real minSleepTime = kMaxReal;
    for (const std::int32_t bodyIndex : island.bodies)
    {
        Body& body = world.bodies[bodyIndex];
        if (body.type == BodyType::Static)
        {
            continue;
        }
        if (!body.allowSleep ||
            body.angularVelocity * body.angularVelocity > angularToleranceSquared ||
            Dot(body.linearVelocity, body.linearVelocity) > linearToleranceSquared)
        {
            body.sleepTime = 0; // moving, or never allowed to sleep: keeps the island awake
            minSleepTime = 0;
        }
        else
        {
            body.sleepTime += step.dt;
            minSleepTime = Min(minSleepTime, body.sleepTime);
        }
    }
    // The island sleeps as a whole: one body put to sleep alone would be woken at once by the
    // island search through its touching neighbours.
    if (minSleepTime >= tol.timeToSleep && positionSolved)
    {
        for (const std::int32_t bodyIndex : island.bodies)
        {
            PutBodyToSleep(world.bodies[bodyIndex]);
        }
    }
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
