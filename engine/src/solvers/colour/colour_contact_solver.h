// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The contact rows of an island by colour (SolverKind::Colour): the coloured contacts in SIMD
// lanes (contact_lanes.h), then the contacts no colour had room for one by one in island order,
// with Box2D's scalar rows (shared/contact_constraint.h).
#pragma once

#include "solvers/colour/contact_lanes.h"
#include "solvers/shared/island_step.h"

#include <cstdint>
#include <span>
#include <vector>

namespace meff::detail
{

class ColourContactSolver final : public ContactStage
{
  public:
    void Arrange(const IslandContacts& island, std::size_t bodyCount) override
    {
        m_lanes.Colour(island, bodyCount);
    }
    void Prepare(const IslandContacts& island, SolverData& data) override;
    void WarmStart(SolverData& data) override;
    void SolveVelocities(SolverData& data) override;
    void CollectResults() override;
    bool SolvePositions(SolverData& data) override;
    std::span<const SolvedContact> SolvedContacts() const override
    {
        return {m_solved.data(), m_count};
    }
    bool AnyHitEvents() const override { return m_anyHitEvents; }

  private:
    std::span<const std::int32_t> Overflow() const { return m_lanes.Colouring().overflow; }

    ContactLanes m_lanes;
    /// The overflow's rows, at the contact's island position k (other slots unused).
    std::vector<ContactVelocityConstraint> m_velocity;
    std::vector<ContactPositionConstraint> m_position;
    std::vector<SolvedContact> m_solved; ///< island order
    std::size_t m_count = 0;
    bool m_anyHitEvents = false;
    bool m_blockSolver = true;
    TaskSystem* m_tasks = nullptr; ///< the world's threads of the last Prepare (CollectResults)
};

} // namespace meff::detail
