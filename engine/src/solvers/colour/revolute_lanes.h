// Revolute joints in SIMD lanes, colour by colour (SolverKind::Colour): the joints whose only rows
// are the point constraint (no limit, no motor — a hinge or a chain link, the bulk of a cloth or a
// rope) are coloured (graph_colouring.h) and solved kLanes (four; AVX2: eight) at a time in SIMD
// lanes, with the same 2×2 block row, K and position step as RevoluteJoint's scalar code
// (revolute_joint.cpp) and Box2D 2.4.1's b2RevoluteJoint. Only the Gauss-Seidel order changes: the
// joints of a colour share no moving body, so solving them together equals solving them one after
// another.
#pragma once

#include "dynamics/solver_types.h"
#include "solvers/colour/graph_colouring.h"
#include "solvers/lanes/wide_real.h"

#include <cstdint>
#include <span>
#include <vector>

namespace meff::detail
{

struct RevoluteJoint;

/// kLanes revolute joints' point rows, one per lane; an empty lane has zero masses throughout.
struct RevoluteJointGroup
{
    std::int32_t indexA[kLanes], indexB[kLanes]; ///< solver body indices (0 in empty lanes)
    std::int32_t storeA[kLanes], storeB[kLanes]; ///< where to write each body (Scatter)
    RealW invMassA, invMassB, invIA, invIB;      ///< 1/kg, 1/(kg·m²)
    Vec2W rA, rB;             ///< anchors from the centres of mass at the step's start (m)
    RealW k11, k12, k21, k22; ///< point-row K (1/kg)
    RealW invDetK;            ///< 1/det K, 0 when K is singular (as Mat22::Solve)
    Vec2W impulse;            ///< accumulated point impulse (N·s)
    Vec2W anchorA, anchorB;   ///< local anchors relative to the local centres (m)
};

class RevoluteLanes
{
  public:
    /// Colours the joints (their bodies stored by StoreJointBodies and summarised in `bodies`,
    /// one per joint: the colouring then reads a compact array instead of the joints), packs
    /// them kLanes to a group and prepares the groups: lever arms, K and the warm start
    /// (RevoluteJoint's InitVelocityConstraints, kLanes at a time).
    void Prepare(std::span<RevoluteJoint* const> joints, std::span<const ConstraintBodies> bodies,
                 const SolverData& data);
    /// Positions in Prepare's `joints` of the joints no colour had room for, in their order:
    /// the caller prepares and solves them one by one.
    std::span<const std::int32_t> Overflow() const { return m_colouring.overflow; }
    void SolveVelocities(Velocity* velocities);
    /// Copies the lanes' accumulated impulses back into the joints.
    void StoreImpulses() const;
    /// One position sweep; true when every anchor gap is within linearSlop.
    bool SolvePositions(Position* positions, const Tolerances& tolerances);

  private:
    ConstraintColouring m_colouring;
    std::vector<RevoluteJointGroup> m_groups;
    std::vector<RevoluteJoint*> m_sources; ///< each group's joints, kLanes per group (or null)
};

} // namespace meff::detail
