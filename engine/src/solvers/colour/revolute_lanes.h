// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Revolute joints in SIMD lanes, colour by colour (SolverKind::Colour): the joints whose only rows
// are the point constraint (no limit, no motor — a hinge or a chain link, the bulk of a cloth or a
// rope) are coloured (graph_colouring.h) and solved kLanes (four; AVX2: eight) at a time in SIMD
// lanes, with the same 2×2 block row, K and position step as RevoluteJoint's scalar code
// (revolute_joint.cpp) and Box2D 2.4.1's b2RevoluteJoint. Only the Gauss-Seidel order changes: the
// joints of a colour share no moving body, so solving them together equals solving them one after
// another.
//
// With the world's TaskSystem a colour's groups are also spread over threads
// (colour_groups.h), at least kMinJointGroupsPerTask to a range; the largest anchor gap is kept
// per group and reduced in group order, so the results are the same bit for bit for any thread
// count. The groups' rows (K, lever arms) are prepared all at once (that only reads the bodies),
// their warm start colour by colour.
#pragma once

#include "model/solver_types.h"
#include "solvers/lanes/colour_groups.h"
#include "solvers/lanes/wide_real.h"

#include <cstdint>
#include <span>
#include <vector>

namespace meff::detail
{

struct RevoluteJoint;

/// The fewest joint groups a thread is handed at once. A joint group's velocity row (one 2×2
/// block) costs less than a contact group's (two points' normal and friction rows), so a range
/// needs more of them than kMinGroupsPerTask to outweigh a thread's wake-up and its share of
/// the job.
inline constexpr int kMinJointGroupsPerTask = 128;

/// kLanes revolute joints' point rows, one per lane; an empty lane has zero masses throughout.
struct RevoluteJointGroup
{
    /// Solver body indices; an empty lane reads lane 0's body A as both of its bodies (a body
    /// no other group of the colour writes, and a zero anchor gap).
    std::int32_t indexA[kLanes], indexB[kLanes];
    std::int32_t storeA[kLanes], storeB[kLanes]; ///< where to write each body (Scatter)
    RealW invMassA, invMassB, invIA, invIB;      ///< 1/kg, 1/(kg·m²)
    Vec2W rA, rB;           ///< anchors from the centres of mass at the step's start (m)
    RealW k11, k12, k22;    ///< point-row K (1/kg), symmetric: its k21 is k12
    RealW invDetK;          ///< 1/det K, 0 when K is singular (as Mat22::Solve)
    Vec2W impulse;          ///< accumulated point impulse (N·s)
    Vec2W anchorA, anchorB; ///< local anchors relative to the local centres (m)
};

class RevoluteLanes
{
  public:
    /// Colours the joints (their bodies stored by StoreJointBodies and summarised in `bodies`,
    /// one per joint: the colouring then reads a compact array instead of the joints), packs
    /// them kLanes to a group and prepares the groups: lever arms, K and the warm start
    /// (RevoluteJoint's InitVelocityConstraints, kLanes at a time), on the world's threads.
    void Prepare(std::span<RevoluteJoint* const> joints, std::span<const ConstraintBodies> bodies,
                 const SolverData& data);
    /// Positions in Prepare's `joints` of the joints no colour had room for, in their order:
    /// the caller prepares and solves them one by one.
    std::span<const std::int32_t> Overflow() const { return m_colouring.overflow; }
    /// One velocity sweep, colour after colour (a colour's groups on the world's threads).
    void SolveVelocities(const SolverData& data);
    /// Copies the lanes' accumulated impulses back into the joints, groups spread over `tasks`
    /// (null: this thread).
    void StoreImpulses(TaskSystem* tasks) const;
    /// One position sweep, as SolveVelocities; true when every anchor gap is within linearSlop.
    bool SolvePositions(const SolverData& data);

  private:
    /// Packs group i (of colour `colour`) from its joints and prepares its rows.
    void PrepareGroup(std::int32_t i, int colour, std::span<RevoluteJoint* const> joints,
                      const SolverData& data);

    ConstraintColouring m_colouring;
    ColouringInputs m_colouredFrom; ///< what m_colouring was computed from
    std::vector<RevoluteJointGroup> m_groups;
    std::vector<RevoluteJoint*> m_sources; ///< each group's joints, kLanes per group (or null)
    /// Colour c's groups are [m_groupStarts[c], m_groupStarts[c + 1]) of m_groups.
    std::vector<std::int32_t> m_groupStarts;
    /// Each group's largest |C|² per lane in the last position sweep.
    std::vector<RealW> m_groupLargestSquared;
};

} // namespace meff::detail
