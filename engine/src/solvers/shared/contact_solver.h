// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Sequential impulses for contacts. Every row — normal and friction — uses the scalar
// effective mass of the seed (effective-mass.md):
//   k = 1/mA + 1/mB + (rA×n)²/IA + (rB×n)²/IB,   λ = −(v·n − bias)/k,
// with accumulated impulses clamped (normal ≥ 0, |friction| ≤ μ·normal). Restitution is the
// seed's P = (1+e)(u2−u1)·m_red written as a velocity bias −e·vn on the normal row.
// Optionally, a two-point manifold's normal rows are solved together (Box2D's block solver).
// Shared: the Box2D back end's contact stage, and the continuous stage's time-of-impact
// sub-steps (dynamics/continuous.cpp) under every back end, as b2Island::SolveTOI.
#pragma once

#include "model/solver_types.h"
#include "solvers/shared/contact_constraint.h"
#include "solvers/shared/island_step.h"

#include <cstdint>
#include <span>
#include <vector>

namespace meff::detail
{

/// Box2D 2.4.1's b2ContactSolver: an island's contacts one by one, in island order.
class ContactSolver final : public ContactStage
{
  public:
    void Prepare(const IslandContacts& island, SolverData& data) override;
    void WarmStart(SolverData& data) override;
    void SolveVelocities(SolverData& data) override;
    void CollectResults() override;
    bool SolvePositions(SolverData& data) override;
    /// One sweep of a time-of-impact sub-step (Box2D's SolveTOIPositionConstraints): only the
    /// two bodies of the event (solver indices toiIndexA, toiIndexB) move, with the stronger
    /// Tolerances::toiBaumgarte; true when no point overlaps more than 1.5·slop.
    bool SolveToiPositions(SolverData& data, std::int32_t toiIndexA, std::int32_t toiIndexB);

    std::span<const SolvedContact> SolvedContacts() const override
    {
        return {m_solved.data(), m_count};
    }
    bool AnyHitEvents() const override { return m_anyHitEvents; }

  private:
    std::vector<ContactVelocityConstraint> m_velocity; ///< reused from step to step
    std::vector<ContactPositionConstraint> m_position;
    std::vector<SolvedContact> m_solved; ///< compact: the post-solve passes read only this
    std::size_t m_count = 0;
    bool m_anyHitEvents = false;
};

} // namespace meff::detail
