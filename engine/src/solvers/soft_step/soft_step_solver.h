// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The soft-step back end (SolverKind::SoftStep): sub-stepped soft constraints (Box2D v3's
// solver on the seed's scalar effective mass), integrated as velocity Verlet. Collision runs
// once per step; each island's step is cut into `substeps` sub-steps h = dt/substeps:
//
//   prepare contacts and joints at the step's start →
//   for each sub-step: integrate velocities (the first by h/2, with half the warm start),
//     warm start (joints, contacts),
//     solve with the soft position bias (joints, contacts, joint trees), integrate positions,
//     correct contact positions (rigid contacts), relax without bias (joints, contacts, joint
//     trees) →
//   the closing half kick: integrate velocities by h/2, half the warm start, relax (its
//     impulses reported, not kept for the warm start) → restitution → store impulses → finish
//     bodies → report solved contacts → sleep
//
// Kicking h/2 at both ends of the step makes positions second order in h (velocity Verlet;
// docs/soft-step.md), with velocities at the step's end, not half a sub-step off. Islands are
// searched as the Box2D back end does when sleep is on; without it the whole world is one
// island, gathered from the arrays (island.h).
//
// With the world's threads (SolverWorld::tasks) the per-body loops, the contact rows' and the
// joints' preparation, the contact rows' storing, and each colour's lane groups in every sweep
// (contacts and plain revolute joints) are spread over them; the colouring, solving the joints
// that go one by one, the joint trees and restitution stay on the calling thread. A colour's groups
// share no moving body and write their worker's own discard slot, so the results are the same bit
// for bit for any thread count.
#pragma once

#include "joints/joint.h"
#include "solvers/shared/island.h"
#include "solvers/soft_step/soft_bodies.h"
#include "solvers/soft_step/soft_contact_solver.h"
#include "solvers/soft_step/soft_joint.h"
#include "solvers/soft_step/soft_joint_tree.h"
#include "solvers/soft_step/soft_revolute_lanes.h"
#include "solvers/solver.h"

#include <cstdint>
#include <vector>

namespace meff::detail
{

/// The fewest joints a thread is handed at once when they are prepared (a joint's frame, its
/// effective masses and warm start cost hundreds of operations).
inline constexpr int kMinSoftJointsPerTask = 64;

/// A small island (its contacts and joints solved row by row) relaxes until no sweep changes a
/// velocity by more than kSoftRelaxTolerance (m/s, rad/s), at most kMaxSoftRelaxSweeps sweeps.
inline constexpr int kMaxSoftRelaxSweeps = 8;
inline constexpr Real kSoftRelaxTolerance = Real(1e-3);

class SoftStepSolver final : public Solver
{
  public:
    void Step(SolverWorld& world, const StepContext& step) override;
    /// Colour's (ThroughputCollision).
    CollisionPolicy Collision(const Tolerances& tolerances) const override
    {
        return ThroughputCollision(tolerances);
    }

  private:
    void SolveIsland(SolverWorld& world, Island& island, const StepContext& step);
    void PrepareJoints(SolverWorld& world, const Island& island, Real warmScale);
    /// With `useLanes`, moves the lane candidates (m_laneJoints, at m_laneRows of the prepared
    /// joints) to the lanes; without, leaves every joint to the scalar rows.
    void SplitLaneJoints(bool useLanes);
    void SubStep(bool first, const StepContext& step);
    /// Scales every accumulated impulse of the island (contacts and joints).
    void ScaleImpulses(Real factor);
    /// The joints' position pass after a sub-step's move: every joint's rigid rows solved once
    /// (lanes, one by one, trees) on pseudo-velocities that move the bodies and are then
    /// dropped, so a joint's gap is closed by moving the bodies, never by giving them velocity.
    void CorrectJoints(const StepContext& step);
    void WarmStartJoints();
    void SolveJoints(bool useBias);
    /// The closing half kick: velocities by h/2, half of the sub-step's constraint impulses and
    /// one rigid sweep of every row, whose impulses count towards the step's totals but not
    /// towards the warm start.
    void CloseStep();

    SoftStepContext m_context;
    Island m_island;
    SoftBodies m_bodies;
    SoftContactSolver m_contacts;
    /// The joints solved one by one, in island order, and their frames.
    std::vector<Joint*> m_joints;
    std::vector<SoftJointFrame> m_frames;
    /// The positions in m_joints of the joints with rows for the sweeps (SoftJointSweeps).
    std::vector<std::size_t> m_sweeping;
    /// While the joints are prepared: each one's SoftRevoluteLanes::LaneJoint (or null).
    std::vector<RevoluteJoint*> m_candidates;
    /// The plain revolute joints, solved by colour in SIMD lanes (soft_revolute_lanes.h);
    /// while they are prepared, their positions in m_joints and whether the lanes took each.
    SoftRevoluteLanes m_revolutes;
    /// The revolute joints whose point rows are solved together, as trees (soft_joint_tree.h).
    SoftJointTree m_tree;
    std::vector<RevoluteJoint*> m_laneJoints;
    std::vector<std::int32_t> m_laneRows;
    std::vector<std::uint8_t> m_inLanes;
    std::vector<std::int32_t> m_pieceCounts; ///< StableCompact's scratch
    std::vector<Velocity> m_pseudo;          ///< the real velocities while CorrectJoints runs
    std::vector<Velocity> m_before;          ///< the velocities before a relax sweep
};

/// The soft coefficients of one step's sub-steps from the settings (SoftStepSettings): contact
/// and joint stiffness capped at a quarter of the sub-step rate; contacts against a body that
/// cannot move twice as stiff.
SoftStepContext MakeSoftStepContext(const StepContext& step);

} // namespace meff::detail
