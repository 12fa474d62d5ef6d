// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The joint rows of an island by colour (SolverKind::Colour): revolute joints whose only rows
// are the point block (no limit, no motor, blockJoints on) go by colour in SIMD lanes
// (revolute_lanes.h); every other joint, and the lane joints no colour had room for, are solved
// one by one in island order after the lanes, with their own rows (shared/sequential_joints.h).
#pragma once

#include "solvers/colour/revolute_lanes.h"
#include "solvers/shared/island_step.h"

#include <cstdint>
#include <span>
#include <vector>

namespace meff::detail
{

struct Joint;
struct RevoluteJoint;

/// The fewest joints a thread is handed at once when the lane joints are picked and their
/// bodies read (a joint costs two bodies' reads, mostly waiting on memory).
inline constexpr int kMinLaneJointPicksPerTask = 256;

class ColourJointSolver final : public JointStage
{
  public:
    void Prepare(std::span<const std::int32_t> jointIndices, std::span<JointSlot> joints,
                 std::span<const Body> bodies, SolverData& data) override;
    void SolveVelocities(SolverData& data) override;
    void StoreImpulses() override;
    bool SolvePositions(SolverData& data) override;

  private:
    std::vector<Joint*> m_sequential; ///< solved one by one, in island order
    /// The joints the lanes can take, as joints and as revolute joints.
    std::vector<Joint*> m_candidates;
    std::vector<RevoluteJoint*> m_candidateRevolutes;
    std::vector<ConstraintBodies> m_candidateBodies;
    /// While preparing, by island position: the joint's lane revolute (or null) and its bodies.
    std::vector<RevoluteJoint*> m_laneOf;
    std::vector<ConstraintBodies> m_bodiesOf;
    std::vector<std::int32_t> m_pieceCounts; ///< StableCompact's scratch
    bool m_lanesInUse = false;
    RevoluteLanes m_lanes;
    TaskSystem* m_tasks = nullptr; ///< the world's threads of the last Prepare (StoreImpulses)
};

} // namespace meff::detail
