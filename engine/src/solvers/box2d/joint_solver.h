// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The joint rows of an island in Box2D 2.4.1's order: every joint one by one, in island order,
// with its own rows (engine/src/joints/: InitVelocityConstraints, SolveVelocityConstraints,
// SolvePositionConstraints of each joint type).
#pragma once

#include "joints/joint.h"
#include "model/solver_types.h"
#include "solvers/shared/island_step.h"
#include "solvers/shared/sequential_joints.h"

#include <cstdint>
#include <span>
#include <vector>

namespace meff::detail
{

struct Body;
struct Joint;
struct JointSlot;

class JointSolver final : public JointStage
{
  public:
    void Prepare(std::span<const std::int32_t> jointIndices, std::span<JointSlot> joints,
                 std::span<const Body> bodies, SolverData& data) override;
    void SolveVelocities(SolverData& data) override;
    void StoreImpulses() override {} ///< the joints accumulate in place
    bool SolvePositions(SolverData& data) override;

  private:
    std::vector<Joint*> m_joints; ///< the island's joints, in island order
};

} // namespace meff::detail
