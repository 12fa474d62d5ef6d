// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
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

#include "core/report_error.h"
#include "dynamics/contact_reports.h"
#include "dynamics/events.h"
#include "dynamics/world_state.h"
#include "tasks/parallel_ranges.h"
#include "meff/validity.h"
#include "meff/world.h"

#include <chrono>
#include <exception>
#include <string>
#include <vector>

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
    if (const std::optional<Refusal> refusal = CheckStepDt(dt))
    {
        ReportError(InvalidArgument("World::Step: dt " + refusal->reason));
        return;
    }
    if (!RequireNotWalked(world, "World::Step"))
    {
        return;
    }
    if (world.failed)
    {
        ReportError(Error("World::Step: an earlier step failed (a non-finite state, an "
                          "exception from a callback, or a task system that broke its contract); "
                          "the world is frozen (read it, then rebuild it or restore a snapshot)"));
        return;
    }
    if (world.checkedTasks != nullptr)
    {
        // Per-worker scratch is sized by the count the world was given (CheckedTasks).
        const int given = world.checkedTasks->ThreadCount();
        if (const int now = world.checkedTasks->User().ThreadCount(); now != given)
        {
            ReportError(InvalidArgument("World::Step: the task system's ThreadCount() is " +
                                        std::to_string(now) + ", was " + std::to_string(given) +
                                        " at World::SetTaskSystem; it must not change "
                                        "while a world uses it (give it to the world again)"));
            return;
        }
    }
    const SteppingGuard stepping(world);

    StepProfile& profile = world.profile;
    profile = {};
    const StageTimer whole(profile.step);
    const StepContext step = BeginStep(world, dt);
    // A body that became non-finite stops the step (FinishBodies): a thrown SimulationError, or
    // without exceptions the error handler and world.failed.
    const auto stages = [&]
    {
        if (world.newShapes)
        {
            Timed(profile.findContacts, [&] { FindNewContacts(world); });
        }
        Timed(profile.collide, [&] { Collide(world); });

        Timed(profile.solve, [&] { Solve(world, step); });
        if (world.failed)
        {
            return;
        }
        Timed(profile.synchronize, [&] { SynchronizeShapes(world); });
        Timed(profile.findContacts, [&] { FindNewContacts(world); });
        if (world.continuous)
        {
            Timed(profile.continuous, [&] { SolveContinuous(world, step); });
        }
    };
#if MEFF_EXCEPTIONS
    try
    {
        stages();
    }
    catch (const SimulationError&)
    {
        world.failed = true; // the bodies kept their last good state; stepping is refused
        throw;
    }
#else
    stages();
    if (world.failed)
    {
        return; // reported; the bodies kept their last good state; stepping is refused
    }
#endif
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

namespace
{

/// Bodies to a range of the threaded SynchronizeShapes: a body's boxes cost little (two boxes
/// per shape), so ranges are as long as the island step's per-body loops.
constexpr int kMinBodiesPerSyncTask = 512;

/// Did the body move in the step? A body outside every island did not; static bodies never do.
bool Moved(const Body& body)
{
    return body.islandFlag && body.type != BodyType::Static;
}

/// The pose whose boxes, with the present pose's, cover the body's motion over the step. A body
/// that fell asleep this step gets tight boxes at its resting pose, not boxes covering its last
/// motion (Box2D 2.4.1's b2Body::SynchronizeFixtures).
[[gnu::always_inline]] inline Transform StartPose(const Body& body)
{
    Transform xf0 = body.xf;
    if (body.awake)
    {
        xf0.q.Set(body.sweep.a0);
        xf0.p = body.sweep.c0 - Mul(xf0.q, body.sweep.localCenter);
    }
    return xf0;
}

/// Sets the shape's box to cover its motion from xf0 to xf1 (`swept`) or its end pose xf1
/// alone, and returns that motion's displacement (the broad phase stretches the fat box along
/// it: MoveProxy); unswept, the body origin's.
[[gnu::always_inline]] inline Vec2 SweepShapeBox(Shape& shape, const Transform& xf0,
                                                 const Transform& xf1, bool swept)
{
    const AABB box1 = shape.ComputeAABB(xf1);
    if (!swept)
    {
        shape.aabb = box1;
        return xf1.p - xf0.p;
    }
    const AABB box0 = shape.ComputeAABB(xf0);
    shape.aabb = Combine(box0, box1);
    return box1.GetCenter() - box0.GetCenter();
}

/// Whether the moved shapes' boxes cover their motion (CollisionPolicy::shapeBoxes).
bool SweepsBoxes(const WorldState& world)
{
    return world.collision.shapeBoxes == ShapeBoxes::Swept || world.continuous;
}

/// The moved bodies, in body-list order.
void ListMovedBodies(const WorldState& world, std::vector<std::int32_t>& moved)
{
    moved.clear();
    for (std::int32_t b = world.bodyList; b != kNullIndex; b = world.bodies[b].next)
    {
        if (Moved(world.bodies[b]))
        {
            moved.push_back(b);
        }
    }
}

/// The threaded SynchronizeShapes. On the threads, by moved body — Read: the bodies' poses, the
/// broad phase's leaves. Written: the body's shapes' boxes, their leaves' fat boxes where they
/// need new ones and the marks on the leaves' ancestors (BroadPhase::SetFatBoxForRebuild),
/// scratch.shapeNewBox of its shapes, scratch.newBoxes of the body. Then on this thread, in
/// body-list order, the shapes that took new fat boxes go to the move buffer — Read: the
/// scratch. Written: the move buffer — so that the tree and the move buffer are the serial
/// walk's.
void SynchronizeShapesOnThreads(WorldState& world)
{
    StepScratch& scratch = world.scratch;
    ListMovedBodies(world, scratch.movedBodies);
    scratch.newBoxes.resize(scratch.movedBodies.size());
    scratch.shapeNewBox.resize(world.shapes.size());
    const bool swept = SweepsBoxes(world);
    ForEachIndex(world.Tasks(), static_cast<int>(scratch.movedBodies.size()), kMinBodiesPerSyncTask,
                 [&world, &scratch, swept](int i)
                 {
                     const Body& body = world.bodies[scratch.movedBodies[std::size_t(i)]];
                     const Transform xf0 = StartPose(body);
                     bool newBox = false;
                     for (const std::int32_t s : body.shapes)
                     {
                         Shape& shape = world.shapes[s];
                         const Vec2 displacement = SweepShapeBox(shape, xf0, body.xf, swept);
                         AABB fat;
                         const bool moves = world.broadPhase.NeedsNewBox(shape.proxyId, shape.aabb,
                                                                         displacement, fat);
                         if (moves)
                         {
                             world.broadPhase.SetFatBoxForRebuild(shape.proxyId, fat);
                         }
                         scratch.shapeNewBox[std::size_t(s)] = moves ? 1 : 0;
                         newBox = newBox || moves;
                     }
                     scratch.newBoxes[std::size_t(i)] = newBox ? 1 : 0;
                 });
    for (std::size_t i = 0; i < scratch.movedBodies.size(); ++i)
    {
        if (scratch.newBoxes[i] == 0)
        {
            continue;
        }
        for (const std::int32_t s : world.bodies[scratch.movedBodies[i]].shapes)
        {
            if (scratch.shapeNewBox[std::size_t(s)] != 0)
            {
                world.broadPhase.BufferRebuiltMove(world.shapes[s].proxyId);
            }
        }
    }
}

} // namespace

void SynchronizeShapes(WorldState& world)
{
    // Box2D's back end stays on one thread, its walk Box2D 2.4.1's.
    if (world.StageTasks() != nullptr &&
        world.collision.treeUpdate == TreeUpdate::EnlargeAndRebuild)
    {
        SynchronizeShapesOnThreads(world);
        return;
    }
    for (std::int32_t b = world.bodyList; b != kNullIndex; b = world.bodies[b].next)
    {
        Body& body = world.bodies[b];
        if (Moved(body))
        {
            SynchronizeBodyShapes(world, body);
        }
    }
}

void SynchronizeBodyShapes(WorldState& world, Body& body)
{
    const Transform xf0 = StartPose(body);
    const bool swept = SweepsBoxes(world);
    for (const std::int32_t s : body.shapes)
    {
        Shape& shape = world.shapes[s];
        const Vec2 displacement = SweepShapeBox(shape, xf0, body.xf, swept);
        world.broadPhase.MoveProxy(shape.proxyId, shape.aabb, displacement);
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
