// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Islands: groups of bodies linked by touching contacts and joints, found by a depth-first
// search in Box2D 2.4.1's order. Each back end solves island by island, and every back end ends
// an island the same way: write the bodies back (refusing a non-finite state), then sleep.
//
// Islands exist for sleep (an island sleeps as a whole) and for Box2D's solver order. When
// neither is wanted (no sleep, a back end other than Box2D's) and every moving body is awake,
// the whole world is one island, gathered by a walk through the arrays instead of the search's
// walk through each body's contact and joint lists (a cache miss per edge).
#pragma once

#include "model/body.h"
#include "model/solver_types.h"
#include "solvers/solver.h"

#include <cstdint>
#include <vector>

namespace meff::detail
{

struct Island
{
    std::vector<std::int32_t> bodies;      ///< world body indices, solver order
    std::vector<std::int32_t> contacts;    ///< world contact indices, solver order
    std::vector<std::int32_t> joints;      ///< world joint indices, solver order
    std::vector<Position> positions;       ///< by solver index
    std::vector<Velocity> velocities;      ///< by solver index
    std::vector<std::int32_t> stack;       ///< depth-first search scratch
    std::vector<std::int32_t> pieceCounts; ///< BuildWorldIsland's scratch (StableCompact)

    void Clear()
    {
        bodies.clear();
        contacts.clear();
        joints.clear();
    }
};

/// Clears every island flag before a step's islands are built.
void ResetIslandFlags(SolverWorld& world);
/// Fills `island` with the island grown from `seed` (a non-static body with no island yet).
void BuildIsland(SolverWorld& world, std::int32_t seed, Island& island);
/// Fills `island` with every moving body, every static body that a contact or joint names,
/// every solid contact and every joint with a moving body (bodies in array order, contacts and
/// joints in reverse array order) when every moving body is awake; otherwise returns false
/// and leaves the search to BuildIsland. Sets the bodies' island flags as the search would
/// (static bodies unflagged), so needs no ResetIslandFlags; the contacts' and joints' flags
/// are left as they were (the searches reset them before use).
bool BuildWorldIsland(SolverWorld& world, Island& island);
/// Lets static bodies join later islands again.
void ReleaseStaticBodies(SolverWorld& world, const Island& island);

/// Can `body` seed an island: alive, awake, moving and in no island yet.
bool CanSeedIsland(const Body& body);

/// Box2D 2.4.1's island loop: every island grown from an awake body (seeds in world body list
/// order), each built into `island` and handed to `solve(island)`.
template <typename SolveIsland>
void ForEachAwakeIsland(SolverWorld& world, Island& island, SolveIsland&& solve);

/// The fewest bodies a thread is handed at once by the per-body loops (integration, writing
/// the bodies back): a body costs tens of operations, so a range of fewer would cost less
/// than waking a thread for it.
inline constexpr int kMinBodiesPerTask = 512;

/// Writes the island's solved state (island.positions, island.velocities) into its bodies and
/// their transforms, bodies spread over `tasks` (null: the calling thread alone). Refuses a
/// non-finite state first, reporting SimulationError naming the first such body (in island
/// order) and the step, so the bodies keep their last good state and stay readable: thrown, or
/// without exceptions handed to the error handler with world.failed set, after which this and
/// every later call of the step writes nothing.
void FinishBodies(SolverWorld& world, const Island& island, TaskSystem* tasks = nullptr);

/// After an island is solved (b2Island::Solve's sleep pass): advances each body's rest time
/// and puts the whole island to sleep once every body has rested timeToSleep and the position
/// pass converged (`positionSolved`; a back end without one passes true).
void UpdateSleep(SolverWorld& world, const Island& island, const StepContext& step,
                 bool positionSolved);

template <typename SolveIsland>
void ForEachAwakeIsland(SolverWorld& world, Island& island, SolveIsland&& solve)
{
    ResetIslandFlags(world);
    for (std::int32_t seed = world.bodyList; seed != kNullIndex; seed = world.bodies[seed].next)
    {
        if (CanSeedIsland(world.bodies[seed]))
        {
            BuildIsland(world, seed, island);
            solve(island);
            ReleaseStaticBodies(world, island);
        }
    }
}

} // namespace meff::detail
