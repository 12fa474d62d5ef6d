// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
#include "solvers/box2d/box2d_solver.h"

namespace meff::detail
{

void Box2DSolver::Step(SolverWorld& world, const StepContext& step)
{
    // Box2D 2.4.1 steps on one thread, and so does its mirror: the world's threads are not
    // handed to the shared island step (its per-body loops would take them).
    SolverWorld oneThread = world;
    oneThread.tasks = nullptr;
    ForEachAwakeIsland(oneThread, m_island,
                       [&](Island& island)
                       { SolveIsland(oneThread, island, step, m_contacts, m_joints); });
}

} // namespace meff::detail
