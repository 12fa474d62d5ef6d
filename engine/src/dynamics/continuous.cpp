// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Continuous collision: the stage World::Step runs after the discrete step when
// WorldState::continuous is on. It follows Box2D 2.4.1's b2World::SolveTOI and
// b2Island::SolveTOI, in the same order, so that both engines agree:
//
//   reset the step's time-of-impact state → loop:
//     find the contact with the earliest time of impact (alpha, a fraction of the step; the
//     queue of impact_queue.h finds Box2D's choice from the contacts the last event changed) →
//     move its two bodies back to alpha → refresh the contact; if it does not touch there,
//     disable it for this step and restore the bodies → else build a mini-island of the pair
//     and the static, kinematic or bullet bodies touching them (moved to alpha too) → solve it
//     over the rest of the step: position pass moving only the pair, velocity iterations
//     without warm starting, integration → report its contacts → resynchronize the moved
//     bodies' broad-phase boxes, invalidate their contacts' cached impacts → find new contacts
//
// Only pairs where one side is static, kinematic or a bullet are swept: two ordinary dynamic
// bodies rely on the discrete solver. A contact takes at most kMaxSubSteps + 1 events a step.
#include "dynamics/step_stages.h"

#include "dynamics/contact_reports.h"
#include "dynamics/events.h"
#include "dynamics/impact_event.h"
#include "dynamics/world_state.h"
#include "model/shape_proxy.h"
#include "solvers/shared/island_step.h"
#include "tasks/parallel_ranges.h"

#include <cassert>

namespace meff::detail
{

namespace
{

/// A contact that has had more events than this in one step is not swept again (b2_maxSubSteps).
constexpr int kMaxSubSteps = 8;
/// The fewest impacts a thread is handed at once: a time of impact costs a few microseconds,
/// about what handing a range to a thread does.
constexpr int kMinImpactsPerTask = 16;
/// Capacity of an event's mini-island (b2_maxTOIContacts, and twice that for bodies).
constexpr std::size_t kMaxToiContacts = 32;
constexpr std::size_t kMaxToiBodies = 2 * kMaxToiContacts;
/// Position iterations of an event's sub-step.
constexpr int kToiPositionIterations = 20;

/// Moves a body to fraction alpha of its sweep and makes that its new start (b2Body::Advance);
/// the broad phase is not told.
void AdvanceBody(Body& body, Real alpha)
{
    body.sweep.Advance(alpha);
    body.sweep.c = body.sweep.c0;
    body.sweep.a = body.sweep.a0;
    SynchronizeTransform(body);
}

void RestoreSweep(Body& body, const Sweep& backup)
{
    body.sweep = backup;
    SynchronizeTransform(body);
}

/// Every sweep starts at the beginning of the step, and no contact has a cached impact yet.
/// Contact::Disabled stays: a contact the pre-solve callback refused is not swept either. Only
/// swept contacts get an impact or an event count, and only theirs are read here for an island
/// mark (BuildImpactIsland passes over the others, marked by the discrete islands or not).
void ResetContinuousState(WorldState& world)
{
    for (std::int32_t b = world.bodyList; b != kNullIndex; b = world.bodies[b].next)
    {
        Body& body = world.bodies[b];
        body.islandFlag = false;
        body.sweep.alpha0 = 0;
    }
    for (const std::int32_t c : world.sweptContacts)
    {
        Contact& contact = world.contacts[c];
        contact.flags &= ~(Contact::Toi | Contact::Island);
        contact.toiCount = 0;
        contact.toi = 1;
    }
}

/// The time of impact of a swept contact (Contact::Swept) as a fraction of the whole step, or 1
/// for none; false when neither side is active (asleep or static), and nothing is computed.
bool ComputeImpact(WorldState& world, Contact& contact, const StepContext& step, Real& alpha)
{
    Body& bodyA = world.bodies[contact.bodyA];
    Body& bodyB = world.bodies[contact.bodyB];
    const bool activeA = bodyA.awake && bodyA.type != BodyType::Static;
    const bool activeB = bodyB.awake && bodyB.type != BodyType::Static;
    if (!activeA && !activeB)
    {
        return false;
    }

    // Put both sweeps on the same interval [alpha0, 1] by advancing the one that is behind.
    Real alpha0 = bodyA.sweep.alpha0;
    if (bodyA.sweep.alpha0 < bodyB.sweep.alpha0)
    {
        alpha0 = bodyB.sweep.alpha0;
        bodyA.sweep.Advance(alpha0);
    }
    else if (bodyB.sweep.alpha0 < bodyA.sweep.alpha0)
    {
        alpha0 = bodyA.sweep.alpha0;
        bodyB.sweep.Advance(alpha0);
    }

    TOIInput input;
    input.proxyA = MakeProxy(world.shapes[contact.shapeA]);
    input.proxyB = MakeProxy(world.shapes[contact.shapeB]);
    input.sweepA = bodyA.sweep;
    input.sweepB = bodyB.sweep;
    input.tMax = 1;
    input.linearSlop = step.tolerances.linearSlop;
    const TOIOutput output = TimeOfImpact(input);

    // output.t is a fraction of the remaining interval [alpha0, 1].
    const Real beta = output.t;
    if (output.state == TOIOutput::State::Touching)
    {
        alpha = Min(alpha0 + (Real(1) - alpha0) * beta, Real(1));
    }
    else
    {
        alpha = 1;
    }
    contact.toi = alpha;
    contact.flags |= Contact::Toi;
    return true;
}

/// Whether the search may compute an impact for the contact (b2World::SolveTOI's first tests).
bool MayHaveImpact(const Contact& contact)
{
    return (contact.flags & Contact::Disabled) == 0 && contact.toiCount <= kMaxSubSteps;
}

/// The impacts the step's first search asks for, computed at once on the threads (colour and
/// soft step). Every sweep still starts at alpha0 = 0 (ResetContinuousState), so ComputeImpact
/// advances no sweep: each call reads the bodies and writes only its own contact, and gives
/// what the search, which lists every candidate first (ImpactQueue::Begin), would compute in
/// list order. The search then finds them cached (Contact::Toi).
void ComputeFirstImpacts(WorldState& world, const StepContext& step)
{
    ForEachIndex(world.StageTasks(), static_cast<int>(world.sweptContacts.size()),
                 kMinImpactsPerTask,
                 [&world, &step](int i)
                 {
                     Contact& contact = world.contacts[world.sweptContacts[i]];
                     // What makes the computations independent (ResetContinuousState).
                     assert(world.bodies[contact.bodyA].sweep.alpha0 == 0 &&
                            world.bodies[contact.bodyB].sweep.alpha0 == 0);
                     Real alpha = 1;
                     if (MayHaveImpact(contact))
                     {
                         ComputeImpact(world, contact, step, alpha);
                     }
                 });
}

/// The contact with the earliest impact in the step (kNullIndex for none), and its alpha: what
/// b2World::SolveTOI's walk of the contact list finds, from the contacts the last event may
/// have changed (impact_queue.h).
std::int32_t FindFirstImpact(WorldState& world, const StepContext& step, Real& minAlpha)
{
    ImpactQueue& queue = world.toiQueue;
    for (const std::int32_t c : queue.TakeChanged(world))
    {
        Contact& contact = world.contacts[c];
        Real alpha = 1;
        if (!MayHaveImpact(contact))
        {
            queue.Drop(c);
        }
        else if ((contact.flags & Contact::Toi) != 0)
        {
            queue.Set(world, c, contact.toi); // still valid: neither body has moved since
        }
        else if (ComputeImpact(world, contact, step, alpha))
        {
            queue.Set(world, c, alpha);
        }
        else
        {
            queue.Drop(c);
        }
    }
    return queue.PopFirst(minAlpha);
}

/// Moves the event's two bodies to alpha and refreshes its manifold. Returns false (and
/// restores the bodies, disabling the contact for the rest of the step) when it has no points
/// there or the pre-solve callback refused it.
bool AdvanceToImpact(WorldState& world, std::int32_t contactIndex, Real alpha)
{
    Body& bodyA = world.bodies[world.contacts[contactIndex].bodyA];
    Body& bodyB = world.bodies[world.contacts[contactIndex].bodyB];
    const Sweep backupA = bodyA.sweep;
    const Sweep backupB = bodyB.sweep;
    AdvanceBody(bodyA, alpha);
    AdvanceBody(bodyB, alpha);

    UpdateContact(world, contactIndex);
    Contact& contact = world.contacts[contactIndex];
    contact.flags &= ~Contact::Toi;
    ++contact.toiCount;
    if ((contact.flags & Contact::Disabled) != 0 || !contact.IsTouching())
    {
        contact.flags |= Contact::Disabled;
        RestoreSweep(bodyA, backupA);
        RestoreSweep(bodyB, backupB);
        return false;
    }
    // A solid impact is solved now, so both bodies are awake (and their rest time restarts).
    WakeBody(bodyA);
    WakeBody(bodyB);
    return true;
}

void AddIslandBody(WorldState& world, Island& island, std::int32_t bodyIndex)
{
    Body& body = world.bodies[bodyIndex];
    body.islandIndex = static_cast<std::int32_t>(island.bodies.size());
    body.islandFlag = true;
    island.bodies.push_back(bodyIndex);
}

/// The event's pair (solver indices 0 and 1) and its contact, then, for each dynamic body of
/// the pair, its touching contacts with static, kinematic or bullet bodies (bullets: with any
/// body), those bodies moved to alpha too.
void BuildImpactIsland(WorldState& world, std::int32_t contactIndex, Real alpha, Island& island)
{
    island.Clear();
    Contact& toiContact = world.contacts[contactIndex];
    const std::int32_t pair[2] = {toiContact.bodyA, toiContact.bodyB};
    AddIslandBody(world, island, pair[0]);
    AddIslandBody(world, island, pair[1]);
    island.contacts.push_back(contactIndex);
    toiContact.flags |= Contact::Island;

    for (const std::int32_t bodyIndex : pair)
    {
        const Body& body = world.bodies[bodyIndex];
        if (body.type != BodyType::Dynamic)
        {
            continue;
        }
        for (std::int32_t key = body.contactList; key != kNullIndex;)
        {
            if (island.bodies.size() == kMaxToiBodies || island.contacts.size() == kMaxToiContacts)
            {
                break;
            }
            const std::int32_t c = EdgeOwner(key);
            Contact& contact = world.contacts[c];
            const Edge& edge = contact.edges[EdgeSide(key)];
            key = edge.next;
            if ((contact.flags & Contact::Island) != 0)
            {
                continue;
            }
            Body& other = world.bodies[edge.other];
            if (!ImpactIslandMayTake(body, other, contact))
            {
                continue;
            }

            // Tentatively move the neighbour to the impact time; keep it only if it touches.
            const Sweep backup = other.sweep;
            if (!other.islandFlag)
            {
                AdvanceBody(other, alpha);
            }
            UpdateContact(world, c);
            if ((contact.flags & Contact::Disabled) != 0 || !contact.IsTouching())
            {
                RestoreSweep(other, backup);
                continue;
            }
            contact.flags |= Contact::Island;
            island.contacts.push_back(c);
            if (!other.islandFlag)
            {
                WakeBody(other); // static bodies stay as they are
                AddIslandBody(world, island, edge.other);
            }
        }
    }
}

/// Solves the mini-island over the rest of the step, [alpha, 1] (b2Island::SolveTOI), with
/// Box2D's contact rows whatever the back end: the event has a handful of contacts.
void SolveImpactIsland(WorldState& world, Island& island, const StepContext& step, Real alpha)
{
    StepContext subStep = step;
    subStep.dt = (Real(1) - alpha) * step.dt;
    subStep.invDt = Real(1) / subStep.dt;
    subStep.dtRatio = 1;
    subStep.solver.positionIterations = kToiPositionIterations;
    subStep.solver.warmStarting = false; // the discrete step already applied warm starting

    const std::size_t count = island.bodies.size();
    island.positions.resize(count);
    island.velocities.resize(count);
    for (std::size_t i = 0; i < count; ++i)
    {
        const Body& body = world.bodies[island.bodies[i]];
        island.positions[i] = {body.sweep.c, body.sweep.a};
        island.velocities[i] = {body.linearVelocity, body.angularVelocity};
    }
    SolverData data{subStep, island.positions.data(), island.velocities.data()};
    ContactSolver& contacts = world.toiSolver;
    const IslandContacts islandContacts{island.contacts, world.contacts, world.bodies};

    // Push the pair (solver indices 0 and 1) out of overlap; the neighbours do not move.
    contacts.Prepare(islandContacts, data);
    for (int i = 0; i < subStep.solver.positionIterations; ++i)
    {
        if (contacts.SolveToiPositions(data, 0, 1))
        {
            break;
        }
    }

    // Take the corrected poses as the pair's new sweep start ("leap of faith").
    for (std::size_t i = 0; i < 2; ++i)
    {
        Body& body = world.bodies[island.bodies[i]];
        body.sweep.c0 = island.positions[i].c;
        body.sweep.a0 = island.positions[i].a;
    }

    // Velocity constraints at the corrected poses. Impulses start from zero and are not stored
    // back: impact impulses can be large and would spoil the next step's warm start.
    contacts.Prepare(islandContacts, data);
    for (int i = 0; i < subStep.solver.velocityIterations; ++i)
    {
        contacts.SolveVelocities(data);
    }

    IntegratePositions(island, subStep);
    WorldContactSink sink(world);
    SolverWorld view = SolverView(world, sink);
    FinishBodies(view, island);
    contacts.CollectResults();
    sink.Record(contacts.SolvedContacts(), contacts.AnyHitEvents(), subStep);
}

/// Clears the island flags, moves the broad-phase boxes of the island's dynamic bodies and
/// invalidates the cached impacts of all their contacts.
void SynchronizeImpactIsland(WorldState& world, const Island& island)
{
    for (const std::int32_t bodyIndex : island.bodies)
    {
        Body& body = world.bodies[bodyIndex];
        body.islandFlag = false;
        if (body.type != BodyType::Dynamic)
        {
            continue;
        }
        SynchronizeBodyShapes(world, body);
        for (std::int32_t key = body.contactList; key != kNullIndex;)
        {
            Contact& contact = world.contacts[EdgeOwner(key)];
            contact.flags &= ~(Contact::Toi | Contact::Island);
            key = contact.edges[EdgeSide(key)].next;
        }
    }
}

} // namespace

void SolveContinuous(WorldState& world, const StepContext& step)
{
    ResetContinuousState(world);
    world.toiQueue.Begin(world);
    if (world.StageTasks() != nullptr)
    {
        ComputeFirstImpacts(world, step);
    }
    Island& island = world.toiIsland;
    for (;;)
    {
        Real minAlpha = 1;
        const std::int32_t minContact = FindFirstImpact(world, step, minAlpha);
        if (minContact == kNullIndex)
        {
            break; // no impact left in this step
        }
        // The event moves bodies and refreshes manifolds: the reports it could change, of what
        // was solved so far, are built first, at the transforms the solver left.
        ForEachImpactEventBody(world, minContact,
                               [&world](std::int32_t b) { BuildContactReportsOf(world, b); });
        world.toiQueue.BeforeEvent(world, minContact);
        if (AdvanceToImpact(world, minContact, minAlpha))
        {
            BuildImpactIsland(world, minContact, minAlpha, island);
            SolveImpactIsland(world, island, step, minAlpha);
            SynchronizeImpactIsland(world, island);
            // The moved boxes may overlap new shapes: create those contacts now.
            FindNewContacts(world);
        }
        world.toiQueue.EventDone(world, minContact);
    }
}

} // namespace meff::detail
