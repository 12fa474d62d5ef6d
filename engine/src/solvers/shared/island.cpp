// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
#include "solvers/shared/island.h"

#include "core/report_error.h"
#include "joints/joint_slot.h"
#include "tasks/parallel_ranges.h"
#include "meff/error.h"

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

bool BuildWorldIsland(SolverWorld& world, Island& island)
{
    island.Clear();
    for (std::size_t b = 0; b < world.bodies.size(); ++b)
    {
        Body& body = world.bodies[b];
        if (!body.alive)
        {
            continue;
        }
        const bool moves = body.type != BodyType::Static;
        // A sleeping body joins only the islands that reach it: that takes the search.
        if (moves && !body.awake)
        {
            return false;
        }
        body.islandFlag = moves;
        // Static bodies are only read, by the contacts and joints that name them: one
        // without either (a tile no one touches) costs the solve nothing, as in the search.
        if (!moves && body.contactList == kNullIndex && body.jointList == kNullIndex)
        {
            continue;
        }
        body.islandIndex = static_cast<std::int32_t>(island.bodies.size());
        island.bodies.push_back(static_cast<std::int32_t>(b));
    }
    // Every contact has a dynamic body (AddPair refuses pairs without one) and every joint
    // gathered here a moving one, so all are reached, as the search from every awake body
    // would reach them. Contacts and joints go in reverse array order, roughly newest first
    // (freed slots are reused) like the lists the search walks: the colouring is greedy in
    // this order, and the oldest-first order colours joint_grid's net so that it flails more
    // (its largest gap to Box2D's order grows from 28 m to 76 m, and the broad phase's work
    // doubles).
    for (std::size_t c = world.contacts.size(); c-- > 0;)
    {
        const Contact& contact = world.contacts[c];
        if (contact.alive && contact.IsSolid())
        {
            island.contacts.push_back(static_cast<std::int32_t>(c));
        }
    }
    for (std::size_t j = world.joints.size(); j-- > 0;)
    {
        const JointSlot& slot = world.joints[j];
        if (slot.alive && (world.bodies[slot.joint.bodyA].type != BodyType::Static ||
                           world.bodies[slot.joint.bodyB].type != BodyType::Static))
        {
            island.joints.push_back(static_cast<std::int32_t>(j));
        }
    }
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
    // Checked on the calling thread, in island order: the error names the first bad body
    // whatever the threads, and no body is written before all are known good.
    for (std::size_t i = 0; i < island.bodies.size(); ++i)
    {
        const Position& p = island.positions[i];
        const Velocity& v = island.velocities[i];
        if (!p.c.IsValid() || !meff::IsValid(p.a) || !v.v.IsValid() || !meff::IsValid(v.w))
        {
            const std::int32_t bodyIndex = island.bodies[i];
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
