// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Everything a World owns. Pools are dense vectors indexed by id.index, reused through free
// lists so that a warmed-up world does not allocate per step.
#pragma once

#include "collision/broad_phase.h"
#include "dynamics/contact_reports.h"
#include "dynamics/impact_queue.h"
#include "dynamics/pair_set.h"
#include "dynamics/step_scratch.h"
#include "joints/joint.h"
#include "joints/joint_slot.h"
#include "model/body.h"
#include "model/contact.h"
#include "model/pool.h"
#include "model/shape.h"
#include "solvers/shared/contact_solver.h"
#include "solvers/shared/island.h"
#include "solvers/solver.h"
#include "tasks/checked_tasks.h"
#include "meff/callbacks.h"
#include "meff/events.h"
#include "meff/profile.h"
#include "meff/settings.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace meff::detail
{

/// A chain (World::CreateChain): the ChainSegment shapes it made, in order along the chain.
struct ChainSlot
{
    std::uint32_t generation = 0;
    bool alive = false;
    std::int32_t body = kNullIndex;
    std::vector<ShapeId> segments;
    bool loop = false; ///< Chain::loop (World::IsChainLoop)
};

struct WorldState
{
    explicit WorldState(const WorldDef& def)
        : gravity(def.gravity), solver(def.solver), tolerances(def.tolerances),
          continuous(def.continuous), allowSleep(def.allowSleep),
          broadPhase(def.tolerances.aabbMargin)
    {
    }

    Vec2 gravity;
    SolverSettings solver;
    Tolerances tolerances;
    bool continuous = true; ///< run SolveContinuous after the discrete step
    bool allowSleep = false;

    Pool<Body, BodyTag> bodies;
    std::vector<BodyId> bodyIds;        ///< live bodies, creation order
    std::int32_t bodyList = kNullIndex; ///< newest first, as b2World::m_bodyList

    Pool<Shape, ShapeTag> shapes;
    Pool<ChainSlot, ChainTag> chains;

    Pool<JointSlot, JointTag> joints;
    std::vector<JointId> jointIds; ///< live joints, creation order
    std::int32_t jointList = kNullIndex;

    std::vector<Contact> contacts;
    std::vector<std::int32_t> freeContacts;
    std::int32_t contactList = kNullIndex; ///< newest first, as b2ContactManager::m_contactList
    int contactCount = 0;
    std::uint64_t contactSerial = 0; ///< the last contact's Contact::serial
    /// The contacts with Contact::Swept, in no order: the continuous stage's candidates.
    std::vector<std::int32_t> sweptContacts;
    /// ShapePairKey of every contact's two shapes (contact_manager.cpp): does a pair have one?
    PairSet contactPairs;

    BroadPhase broadPhase;
    /// What the current back end asks of the broad and narrow phases (Solver::Collision),
    /// set with the solver settings.
    CollisionPolicy collision;
    bool newShapes = false; ///< find new contacts before the next narrow phase
    StepScratch scratch;    ///< the threaded collision stages' working memory (not state)

    SolverSet solvers;       ///< the back ends (SolverSettings::kind picks one each step)
    Island toiIsland;        ///< the mini-island of one time-of-impact event
    ContactSolver toiSolver; ///< its contact rows: Box2D's, whatever the back end
    ImpactQueue toiQueue;    ///< the candidate impacts of the continuous stage (not state)

    std::vector<ContactPointReport> contactReports; ///< built when read (contact_reports.h)
    RecordedContacts recorded;                      ///< solved, not yet in contactReports
    std::vector<ContactEvent> beginEvents;
    std::vector<ContactEvent> endEvents;
    std::vector<SensorEvent> sensorBeginEvents;
    std::vector<SensorEvent> sensorEndEvents;
    std::vector<ContactHitEvent> hitEvents;
    /// How many end events the last step itself recorded; those after it came from destroying
    /// shapes or bodies between steps and are carried into the next step's lists.
    std::size_t stepEndEventCount = 0;
    std::size_t stepSensorEndEventCount = 0;
    PreSolveCallback preSolve;         ///< the user's, or empty; kept across RestoreSnapshot
    CustomFilterCallback customFilter; ///< the user's, or empty; kept across RestoreSnapshot
    /// The user's threads (World::SetTaskSystem) behind the checks of their contract, or null;
    /// configuration, not state: kept across RestoreSnapshot, outside snapshots and the state
    /// hash. Shared so that WorldState stays copyable (a snapshot leaves it out).
    std::shared_ptr<CheckedTasks> checkedTasks;
    /// checkedTasks, as the stages take it (null: the calling thread).
    TaskSystem* Tasks() const { return checkedTasks.get(); }
    /// The threads the shared stages may use: the user's where the back end's collision policy
    /// allows them (not Box2D's, which steps on one thread, bit for bit Box2D 2.4.1).
    TaskSystem* StageTasks() const { return collision.threadedStages ? Tasks() : nullptr; }

    Real invDt0 = 0; ///< 1/dt of the previous step, for warm-start scaling
    std::uint64_t stepCount = 0;
    StepProfile profile; ///< the last step's stage timings (World::GetProfile)
    /// A step failed (a non-finite state, or an exception from the pre-solve callback left it
    /// half done); stepping is refused until RestoreSnapshot.
    bool failed = false;
    bool stepping = false; ///< inside World::Step: the world must not be changed
    /// The user's callback running now ("the pre-solve callback", "the custom filter"), or
    /// null: the world must not be changed either, and a refusal names it.
    const char* callback = nullptr;
};

/// Inside World::Step, or inside one of the user's callbacks it calls.
inline bool InStep(const WorldState& world)
{
    return world.stepping || world.callback != nullptr;
}

/// Every call that changes the world (bodies, shapes, joints, settings, the callbacks and
/// threads themselves, a snapshot's restore, Step) is refused while a step walks it: from the
/// pre-solve callback or the custom filter, whose messages name it. A callback that replaced
/// itself was destroyed while it ran. Throws InvalidArgument "CALL: called during World::Step
/// (from CALLBACK); ...". Returns false after reporting it (core/report_error.h).
/// `why` ends the message; SaveSnapshot, which changes nothing, says its own.
[[nodiscard]] bool RequireNotStepping(const WorldState& world, const char* call,
                                      const char* why = "the callback must not change the world");

/// RequireNotStepping, and also refused while a query or Draw on this thread walks the world
/// (InWalk): the calls that add, remove or move what a walk reads (bodies, shapes, joints,
/// tree nodes, the broad phase's rules), a snapshot's restore and Step. A body destroyed from
/// an overlap callback had freed the tree nodes the query was on. Impulses, velocities and the
/// other settings stay allowed there (pushing what an overlap query finds is a common use).
/// Throws InvalidArgument "CALL: called while a query or World::Draw walks the
/// world (from its callback); ...".
[[nodiscard]] bool RequireNotWalked(const WorldState& world, const char* call);

/// Marks `world` as inside the user's callback `name` for its lifetime (WorldState::callback).
class InUserCallback
{
  public:
    InUserCallback(WorldState& world, const char* name) : m_world(world), m_outer(world.callback)
    {
        world.callback = name;
    }
    ~InUserCallback() { m_world.callback = m_outer; }
    InUserCallback(const InUserCallback&) = delete;
    InUserCallback& operator=(const InUserCallback&) = delete;

  private:
    WorldState& m_world;
    const char* m_outer;
};

/// Marks `world` as walked by a query or Draw on this thread for the walk's lifetime: the walks
/// a thread is inside form a chain (a query from another query's callback, perhaps of another
/// world), innermost first. Kept per thread, not in the world, so that queries write nothing
/// shared and several threads may query one world at once.
class InWalk
{
  public:
    explicit InWalk(const WorldState& world);
    ~InWalk();
    InWalk(const InWalk&) = delete;
    InWalk& operator=(const InWalk&) = delete;

    /// Whether this thread is inside a walk of `world` (RequireNotWalked).
    [[nodiscard]] static bool Walking(const WorldState& world);

  private:
    const WorldState& m_world;
    const InWalk* m_outer;
};

/// What a solver back end sees of the world (solvers/solver.h).
inline SolverWorld SolverView(WorldState& world, SolvedContactSink& solvedContacts)
{
    return SolverWorld{world.bodies.Slots(), world.contacts,   world.joints.Slots(), world.bodyList,
                       world.gravity,        world.allowSleep, world.stepCount,      solvedContacts,
                       world.Tasks(),        &world.failed};
}

/// Wakes body `bodyIndex` (see WakeBody(Body&)): the helper for any world change — a joint
/// setter, say — that must wake the bodies it affects.
inline void WakeBody(WorldState& world, std::int32_t bodyIndex)
{
    WakeBody(world.bodies[bodyIndex]);
}

} // namespace meff::detail
