// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Determinism and rollback: a hash of the simulated state, and whole-world snapshots.
//
// Every member of WorldState is a value (pools, lists as indices, the broad phase's node
// vector, the warm-starting impulses in the manifolds), so a snapshot is a copy and restoring
// it is an assignment: nothing is rebuilt, hence stepping on is bit-identical.
#include "core/report_error.h"
#include "dynamics/world_state.h"
#include "meff/world.h"

#include <cstring>
#include <utility>

namespace meff
{

namespace
{

/// 64-bit FNV-1a over raw bytes.
class Fnv1a
{
  public:
    template <typename T>
    void Add(const T& value)
    {
        unsigned char bytes[sizeof(T)];
        std::memcpy(bytes, &value, sizeof(T));
        for (const unsigned char b : bytes)
        {
            m_hash = (m_hash ^ b) * 0x100000001b3ull;
        }
    }
    std::uint64_t Value() const { return m_hash; }

  private:
    std::uint64_t m_hash = 0xcbf29ce484222325ull;
};

} // namespace

std::uint64_t World::GetStateHash() const
{
    Fnv1a hash;
    for (const detail::Body& body : State().bodies)
    {
        if (!body.alive)
        {
            continue;
        }
        hash.Add(body.xf.p.x);
        hash.Add(body.xf.p.y);
        hash.Add(body.xf.q.s);
        hash.Add(body.xf.q.c);
        hash.Add(body.sweep.c.x);
        hash.Add(body.sweep.c.y);
        hash.Add(body.sweep.a);
        hash.Add(body.linearVelocity.x);
        hash.Add(body.linearVelocity.y);
        hash.Add(body.angularVelocity);
        hash.Add(static_cast<unsigned char>(body.awake ? 1 : 0));
        hash.Add(body.sleepTime);
    }
    for (const detail::Contact& contact : State().contacts)
    {
        if (!contact.alive)
        {
            continue;
        }
        for (int i = 0; i < contact.manifold.pointCount; ++i)
        {
            hash.Add(contact.manifold.points[i].normalImpulse);
            hash.Add(contact.manifold.points[i].tangentImpulse);
        }
        if (contact.rollingResistance > 0)
        {
            hash.Add(contact.rollingImpulse);
        }
    }
    return hash.Value();
}

WorldSnapshot World::SaveSnapshot() const
{
    const detail::WorldState& world = State();
    // Half a step is no state to step on from: one saved from the pre-solve callback kept the
    // last step's end-event count over this step's shorter list, and the step after its restore
    // erased past the list's end (AddressSanitizer: negative-size-param).
    if (!detail::RequireNotStepping(world, "World::SaveSnapshot",
                                    "a half-done step cannot be stepped on from: save the "
                                    "snapshot before or after Step"))
    {
        return {};
    }
    WorldSnapshot snapshot;
    auto copy = std::make_shared<detail::WorldState>(world);
    // The callbacks are configuration, not state (RestoreSnapshot keeps the current ones): a
    // snapshot must not keep alive whatever they captured.
    copy->preSolve = nullptr;
    copy->customFilter = nullptr;
    copy->checkedTasks = nullptr;
    snapshot.m_state = std::move(copy);
    return snapshot;
}

void World::RestoreSnapshot(const WorldSnapshot& snapshot)
{
    if (snapshot.IsEmpty())
    {
        detail::ReportError(InvalidArgument("World::RestoreSnapshot: the snapshot is empty"));
        return;
    }
    detail::WorldState& world = State();
    if (!detail::RequireNotWalked(world, "World::RestoreSnapshot"))
    {
        return;
    }
    // Configuration, not state: the current callbacks and task system stay.
    PreSolveCallback preSolve = std::move(world.preSolve);
    CustomFilterCallback customFilter = std::move(world.customFilter);
    std::shared_ptr<detail::CheckedTasks> checkedTasks = std::move(world.checkedTasks);
    world = *snapshot.m_state;
    world.preSolve = std::move(preSolve);
    world.customFilter = std::move(customFilter);
    world.checkedTasks = std::move(checkedTasks);
    world.stepping = false; // as the snapshot's (SaveSnapshot refuses during a step)
    world.callback = nullptr;
}

} // namespace meff
