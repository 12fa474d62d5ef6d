// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
#include "solvers/shared/island.h"

#include "core/report_error.h"
#include "joints/joint_slot.h"
#include "tasks/parallel_ranges.h"
#include "meff/error.h"

#include <atomic>
#include <span>
#include <string>

namespace meff::detail
{

void ResetIslandFlags(SolverWorld& world)
{
    for (Body& body : world.bodies)
    {
        body.islandFlag = false;
    }
    for (Contact& contact : world.contacts)
    {
        contact.flags &= ~Contact::Island;
    }
    for (JointSlot& joint : world.joints)
    {
        joint.islandFlag = false;
    }
}

void BuildIsland(SolverWorld& world, std::int32_t seed, Island& island)
{
    island.Clear();
    std::vector<std::int32_t>& stack = island.stack;
    stack.clear();
    stack.push_back(seed);
    world.bodies[seed].islandFlag = true;

    while (!stack.empty())
    {
        const std::int32_t bodyIndex = stack.back();
        stack.pop_back();
        Body& body = world.bodies[bodyIndex];
        body.islandIndex = static_cast<std::int32_t>(island.bodies.size());
        island.bodies.push_back(bodyIndex);

        // Static bodies end the search: they do not join the islands they touch.
        if (body.type == BodyType::Static)
        {
            continue;
        }
        // A sleeping body reached from an awake one is solved with it and so is awake again;
        // its rest time carries on (Box2D sets the flag without SetAwake's reset).
        body.awake = true;

        for (std::int32_t key = body.contactList; key != kNullIndex;)
        {
            const std::int32_t contactIndex = EdgeOwner(key);
            Contact& contact = world.contacts[contactIndex];
            const Edge& edge = contact.edges[EdgeSide(key)];
            key = edge.next;
            // Sensor contacts and contacts the pre-solve callback disabled are not solved.
            if ((contact.flags & Contact::Island) != 0 || !contact.IsSolid())
            {
                continue;
            }
            contact.flags |= Contact::Island;
            island.contacts.push_back(contactIndex);
            Body& other = world.bodies[edge.other];
            if (!other.islandFlag)
            {
                other.islandFlag = true;
                stack.push_back(edge.other);
            }
        }

        for (std::int32_t key = body.jointList; key != kNullIndex;)
        {
            const std::int32_t jointIndex = EdgeOwner(key);
            JointSlot& joint = world.joints[jointIndex];
            const Edge& edge = joint.edges[EdgeSide(key)];
            key = edge.next;
            if (joint.islandFlag)
            {
                continue;
            }
            joint.islandFlag = true;
            island.joints.push_back(jointIndex);
            Body& other = world.bodies[edge.other];
            if (!other.islandFlag)
            {
                other.islandFlag = true;
                stack.push_back(edge.other);
            }
        }
    }
}

namespace
{

/// The indices of `items` that `keep` accepts, newest slot first (reverse array order), into
/// `out`, in the order a serial walk from the last slot gives them (StableCompact).
template <typename Item, typename Keep>
void KeepNewestFirst(TaskSystem* tasks, std::vector<std::int32_t>& pieceCounts,
                     std::span<const Item> items, std::vector<std::int32_t>& out, Keep&& keep)
{
    const auto count = static_cast<int>(items.size());
    out.resize(items.size());
    const std::int32_t kept = StableCompact(
        tasks, count, pieceCounts,
        [&](int r) { return keep(items[static_cast<std::size_t>(count - 1 - r)]); },
        [&](int r, std::int32_t position)
        { out[static_cast<std::size_t>(position)] = count - 1 - r; });
    out.resize(static_cast<std::size_t>(kept));
}

} // namespace

bool BuildWorldIsland(SolverWorld& world, Island& island)
{
    island.Clear();
    // Three stable compactions on the world's threads (StableCompact): the same arrays in the
    // same order as one walk through them, whatever the threads.
    std::atomic<bool> asleep{false};
    const auto bodyCount = static_cast<int>(world.bodies.size());
    island.bodies.resize(world.bodies.size());
    const std::int32_t bodies = StableCompact(
        world.tasks, bodyCount, island.pieceCounts,
        [&](int b)
        {
            Body& body = world.bodies[static_cast<std::size_t>(b)];
            if (!body.alive)
            {
                return false;
            }
            const bool moves = body.type != BodyType::Static;
            // A sleeping body joins only the islands that reach it: that takes the search.
            if (moves && !body.awake)
            {
                asleep.store(true, std::memory_order_relaxed);
            }
            body.islandFlag = moves;
            // Static bodies are only read, by the contacts and joints that name them: one
            // without either (a tile no one touches) costs the solve nothing, as in the search.
            return moves || body.contactList != kNullIndex || body.jointList != kNullIndex;
        },
        [&](int b, std::int32_t position)
        {
            world.bodies[static_cast<std::size_t>(b)].islandIndex = position;
            island.bodies[static_cast<std::size_t>(position)] = b;
        });
    island.bodies.resize(static_cast<std::size_t>(bodies));
    if (asleep.load(std::memory_order_relaxed))
    {
        return false;
    }
    // Every contact has a dynamic body (AddPair refuses pairs without one) and every joint
    // gathered here a moving one, so all are reached, as the search from every awake body
    // would reach them. Contacts and joints go in reverse array order, roughly newest first
    // (freed slots are reused) like the lists the search walks: the colouring is greedy in
    // this order, and the oldest-first order colours joint_grid's net so that it flails more
    // (its largest gap to Box2D's order grows from 28 m to 76 m, and the broad phase's work
    // doubles).
    KeepNewestFirst(world.tasks, island.pieceCounts, std::span<const Contact>(world.contacts),
                    island.contacts,
                    [](const Contact& contact) { return contact.alive && contact.IsSolid(); });
    KeepNewestFirst(
        world.tasks, island.pieceCounts, std::span<const JointSlot>(world.joints), island.joints,
        [&](const JointSlot& slot)
        {
            return slot.alive && (world.bodies[slot.joint.bodyA].type != BodyType::Static ||
                                  world.bodies[slot.joint.bodyB].type != BodyType::Static);
        });
    return true;
}

void ReleaseStaticBodies(SolverWorld& world, const Island& island)
{
    for (const std::int32_t bodyIndex : island.bodies)
    {
        Body& body = world.bodies[bodyIndex];
        if (body.type == BodyType::Static)
        {
            body.islandFlag = false;
        }
    }
}

bool CanSeedIsland(const Body& body)
{
    return body.alive && !body.islandFlag && body.awake && body.type != BodyType::Static;
}

void FinishBodies(SolverWorld& world, const Island& island, TaskSystem* tasks)
{
    if (world.failed != nullptr && *world.failed)
    {
        return; // an earlier island failed (reported): the step writes nothing more
    }
    // Checked on the threads, each range up to its first bad body; the error names the first
    // bad body in island order whatever the threads (the smallest such index), and no body is
    // written before all are known good.
    const auto count = static_cast<std::int32_t>(island.bodies.size());
    std::atomic<std::int32_t> firstBad{count};
    ForRanges(
        tasks, count, kMinBodiesPerTask,
        [&](int begin, int end, int)
        {
            for (std::int32_t i = begin; i < end; ++i)
            {
                const Position& p = island.positions[static_cast<std::size_t>(i)];
                const Velocity& v = island.velocities[static_cast<std::size_t>(i)];
                if (!p.c.IsValid() || !meff::IsValid(p.a) || !v.v.IsValid() || !meff::IsValid(v.w))
                {
                    std::int32_t seen = firstBad.load(std::memory_order_relaxed);
                    while (i < seen &&
                           !firstBad.compare_exchange_weak(seen, i, std::memory_order_relaxed))
                    {
                    }
                    return;
                }
            }
        });
    if (const std::int32_t bad = firstBad.load(std::memory_order_relaxed); bad < count)
    {
        const std::int32_t bodyIndex = island.bodies[static_cast<std::size_t>(bad)];
        if (world.failed != nullptr)
        {
            *world.failed = true;
        }
        ReportError(SimulationError("step " + std::to_string(world.stepCount) + ": body " +
                                        std::to_string(bodyIndex) + " (user data " +
                                        std::to_string(world.bodies[bodyIndex].userData) +
                                        ") has a non-finite position or velocity",
                                    world.stepCount, bodyIndex));
        return;
    }
    // Each body is its own: any thread may take any range of them.
    ForEachIndex(tasks, static_cast<int>(island.bodies.size()), kMinBodiesPerTask,
                 [&](int b)
                 {
                     const auto i = static_cast<std::size_t>(b);
                     Body& body = world.bodies[island.bodies[i]];
                     body.sweep.c = island.positions[i].c;
                     body.sweep.a = island.positions[i].a;
                     body.linearVelocity = island.velocities[i].v;
                     body.angularVelocity = island.velocities[i].w;
                     SynchronizeTransform(body);
                 });
}

void UpdateSleep(SolverWorld& world, const Island& island, const StepContext& step,
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

} // namespace meff::detail
