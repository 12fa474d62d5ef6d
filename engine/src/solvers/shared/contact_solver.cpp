// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
#include "solvers/shared/contact_solver.h"

#include "model/body.h"
#include "model/contact.h"

namespace meff::detail
{

void ContactSolver::Prepare(const IslandContacts& island, SolverData& data)
{
    m_count = island.contactIndices.size();
    if (m_velocity.size() < m_count)
    {
        m_velocity.resize(m_count);
        m_position.resize(m_count);
        m_solved.resize(m_count);
    }
    m_anyHitEvents = false;
    for (std::size_t k = 0; k < m_count; ++k)
    {
        const bool hitEvents =
            PrepareContactConstraint(island, k, data, m_velocity[k], m_position[k]);
        m_anyHitEvents = m_anyHitEvents || hitEvents;
    }
}

void ContactSolver::WarmStart(SolverData& data)
{
    for (std::size_t k = 0; k < m_count; ++k)
    {
        WarmStartConstraint(m_velocity[k], data.velocities);
    }
}

void ContactSolver::SolveVelocities(SolverData& data)
{
    const bool blockSolver = data.step.solver.blockSolver;
    for (std::size_t i = 0; i < m_count; ++i)
    {
        SolveVelocityConstraint(m_velocity[i], data.velocities, blockSolver);
    }
}

void ContactSolver::CollectResults()
{
    for (std::size_t k = 0; k < m_count; ++k)
    {
        CollectContactResult(m_velocity[k], m_solved[k]);
    }
}

namespace
{

/// One non-linear Gauss-Seidel sweep over the position constraints, with Baumgarte factor
/// `baumgarte` and the inverse masses `masses(pc)` gives; returns the smallest separation seen.
template <typename Masses>
Real SolvePositionSweep(std::span<const ContactPositionConstraint> constraints, Position* positions,
                        const Tolerances& tol, Real baumgarte, Masses&& masses)
{
    Real minSeparation = 0;
    for (const ContactPositionConstraint& pc : constraints)
    {
        minSeparation =
            Min(minSeparation, SolvePositionConstraint(pc, positions, tol, baumgarte, masses(pc)));
    }
    return minSeparation;
}

} // namespace

bool ContactSolver::SolvePositions(SolverData& data)
{
    const Tolerances& tol = data.step.tolerances;
    const Real minSeparation =
        SolvePositionSweep({m_position.data(), m_count}, data.positions, tol, tol.baumgarte,
                           [](const ContactPositionConstraint& pc) {
                               return PositionMasses{pc.invMassA, pc.invMassB, pc.invIA, pc.invIB};
                           });
    // The solver stops pushing at −linearSlop, so −3·slop is "solved".
    return minSeparation >= Real(-3) * tol.linearSlop;
}

bool ContactSolver::SolveToiPositions(SolverData& data, std::int32_t toiIndexA,
                                      std::int32_t toiIndexB)
{
    const Tolerances& tol = data.step.tolerances;
    const auto moves = [&](std::int32_t index) { return index == toiIndexA || index == toiIndexB; };
    const Real minSeparation =
        SolvePositionSweep({m_position.data(), m_count}, data.positions, tol, tol.toiBaumgarte,
                           [&](const ContactPositionConstraint& pc)
                           {
                               PositionMasses m{0, 0, 0, 0};
                               if (moves(pc.indexA))
                               {
                                   m.mA = pc.invMassA;
                                   m.iA = pc.invIA;
                               }
                               if (moves(pc.indexB))
                               {
                                   m.mB = pc.invMassB;
                                   m.iB = pc.invIB;
                               }
                               return m;
                           });
    // Separation is never pushed above −linearSlop, so −1.5·slop counts as solved here.
    return minSeparation >= Real(-1.5) * tol.linearSlop;
}

} // namespace meff::detail
