// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "solvers/colour/colour_solver.h"

namespace meff::detail
{

void ColourSolver::Step(SolverWorld& world, const StepContext& step)
{
    const auto solve = [&](Island& island)
    { SolveIsland(world, island, step, m_contacts, m_joints); };
    // Without sleep, islands would only split the colouring's work.
    if (!world.allowSleep && BuildWorldIsland(world, m_island))
    {
        solve(m_island);
        return;
    }
    ForEachAwakeIsland(world, m_island, solve);
}

} // namespace meff::detail
