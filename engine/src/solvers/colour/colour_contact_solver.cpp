// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "solvers/colour/colour_contact_solver.h"

namespace meff::detail
{

void ColourContactSolver::Prepare(const IslandContacts& island, SolverData& data)
{
    m_count = island.contactIndices.size();
    m_blockSolver = data.step.solver.blockSolver;
    m_tasks = data.tasks;
    if (m_solved.size() < m_count)
    {
        m_velocity.resize(m_count);
        m_position.resize(m_count);
        m_solved.resize(m_count);
    }
    m_anyHitEvents = m_lanes.Prepare(island, {m_solved.data(), m_count}, data);
    for (const std::int32_t k : Overflow())
    {
        const bool hitEvents = PrepareContactConstraint(island, static_cast<std::size_t>(k), data,
                                                        m_velocity[k], m_position[k]);
        m_anyHitEvents = m_anyHitEvents || hitEvents;
    }
}

void ColourContactSolver::WarmStart(SolverData& data)
{
    m_lanes.WarmStart(data);
    for (const std::int32_t k : Overflow())
    {
        WarmStartConstraint(m_velocity[k], data.velocities);
    }
}

void ColourContactSolver::SolveVelocities(SolverData& data)
{
    m_lanes.SolveVelocities(data);
    for (const std::int32_t k : Overflow())
    {
        SolveVelocityConstraint(m_velocity[k], data.velocities, m_blockSolver);
    }
}

void ColourContactSolver::CollectResults()
{
    m_lanes.CollectResults({m_solved.data(), m_count}, m_tasks);
    for (const std::int32_t k : Overflow())
    {
        CollectContactResult(m_velocity[k], m_solved[k]);
    }
}

bool ColourContactSolver::SolvePositions(SolverData& data)
{
    const Tolerances& tol = data.step.tolerances;
    Real minSeparation = m_lanes.SolvePositions(data);
    for (const std::int32_t k : Overflow())
    {
        const ContactPositionConstraint& pc = m_position[k];
        minSeparation = Min(
            minSeparation, SolvePositionConstraint(pc, data.positions, tol, tol.baumgarte,
                                                   {pc.invMassA, pc.invMassB, pc.invIA, pc.invIB}));
    }
    // The solver stops pushing at −linearSlop, so −3·slop is "solved".
    return minSeparation >= Real(-3) * tol.linearSlop;
}

} // namespace meff::detail
