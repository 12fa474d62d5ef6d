// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The soft step's plain revolute joints by colour in SIMD lanes: a revolute joint whose only rows
// are the point block (no limit, motor or spring; SolverSettings::blockJoints on) — a hinge, a
// chain link, the bulk of a cloth — is coloured (graph_colouring.h) and solved kLanes (four;
// AVX2: eight) at a time, each lane doing what the scalar SolvePoint (soft_row.h) does for one
// joint, with the same operations in the same order: anchors turned with their bodies since the
// step's start, the soft 2×2 point block on the seed's scalar effective masses, the warm start,
// and the closing half kick's relax on half the impulses. Only the Gauss-Seidel order changes
// (colour order, independent of the lane count). The joints no colour had room for go back to
// the caller's scalar rows.
#pragma once

#include "solvers/lanes/graph_colouring.h"
#include "solvers/lanes/wide_real.h"
#include "solvers/soft_step/soft_contact_lanes.h"
#include "solvers/soft_step/soft_joint.h"

#include <cstdint>
#include <span>
#include <vector>

namespace meff::detail
{

/// kLanes joints' point rows, one per lane; an empty lane has zero masses and writes the discard
/// slot.
struct SoftRevoluteGroup
{
    std::int32_t indexA[kLanes], indexB[kLanes]; ///< solver body indices
    std::int32_t storeA[kLanes], storeB[kLanes]; ///< where to write each body (discard slot)
    RealW invMassA, invIA, invMassB, invIB;      ///< 1/kg, 1/(kg·m²)
    Vec2W rA0, rB0;    ///< anchors from the centres of mass at the step's start (m)
    Vec2W deltaCenter; ///< cB − cA at the step's start (m)
    Vec2W impulse;     ///< accumulated point impulse of the sub-step (N·s)
};

class SoftRevoluteLanes
{
  public:
    /// Whether the lanes can take this joint: a revolute joint with the point block only.
    static RevoluteJoint* LaneJoint(Joint& joint, const SoftStepContext& context);

    /// Colours the prepared joints and packs the coloured ones into groups: joint i is
    /// `joints[i]`, its frame `frames[rows[i]]`. `bodyCount` is the island's; its discard slots
    /// are bodyCount + each worker of `tasks` (the world's threads, or null), on which every
    /// pass below runs, a colour's groups at once.
    void Prepare(std::span<RevoluteJoint* const> joints, std::span<const SoftJointFrame> frames,
                 std::span<const std::int32_t> rows, std::int32_t bodyCount, TaskSystem* tasks);
    /// Positions i in Prepare's `joints` of the joints no colour had room for, in their order.
    std::span<const std::int32_t> Overflow() const { return m_colouring.overflow; }

    void WarmStart(const SoftStepContext& context);
    void Solve(const SoftStepContext& context, bool useBias);
    void ScaleImpulses(Real factor);
    /// The joints' position pass (context.correcting): one update of every group on the
    /// pseudo-velocities in context.bodies, from impulses of zero; the groups' impulses are kept.
    void Correct(const SoftStepContext& context);
    /// The step's closing half kick: half of the sub-step's impulses applied and relaxed, joint
    /// by joint, its impulses then forgotten (the next warm start keeps the sub-step's).
    void CloseStep(const SoftStepContext& context);
    /// Writes the impulses × `factor` into the joints (per step, as the other back ends store
    /// them).
    void Store(Real factor) const;

  private:
    /// Packs group i from its colour's joints.
    void PackGroup(std::int32_t i, std::span<RevoluteJoint* const> joints,
                   std::span<const SoftJointFrame> frames, std::span<const std::int32_t> rows);

    ConstraintColouring m_colouring;
    std::vector<ConstraintBodies> m_bodies; ///< scratch: the joints' bodies
    ColouringInputs m_colouredFrom;         ///< what m_colouring was computed from
    std::vector<SoftRevoluteGroup> m_groups;
    ColourGroups m_groupsOfColour;         ///< where each colour's groups are, and their threads
    std::vector<RevoluteJoint*> m_sources; ///< each group's joints, kLanes per group (or null)
};

} // namespace meff::detail
