// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The point rows of revolute joints that join an island's bodies as a tree, solved together
// exactly instead of one joint after another (SoftStepSettings::jointTrees).
//
// Why: a Gauss-Seidel sweep hands a load from joint to joint at about each joint's own
// effective mass, so a chain of light links holding a heavy body stretches by metres before
// the sweeps catch up (docs/soft-step.md, "Where it stops: mass ratios"). Solved together, the
// rows hand on the whole load at once, whatever the masses.
//
// What is solved. With A = J·M⁻¹·Jᵀ the point rows' coupled inverse effective mass (the seed's
// scalar k of every row on its diagonal, effective-mass.md) and Cdot their anchor velocities now,
// one update finds the impulses Δλ of every tree joint at once from
//
//     relaxing (rigid):  A·Δλ = −Cdot
//     solving (soft):    A·Δλ = −(massScale·Cdot + biasScale·C + impulseScale·A·λ)
//
// where λ is what the joints have applied since the sub-step began (their warm start included).
// The soft form is the scalar soft row (softness.h) with its own k replaced by the coupled A:
// for one joint it is exactly SolvePoint's 2×2 block, and for many it makes every joint's gap
// follow the implicit spring C'' = −ω²·C of the joint softness on the mass it actually moves,
// not on its own row's (a light link carrying a heavy body sags by g/ω², not by load/(m_eff·ω²)).
//
// How (Baraff's linear-time method). Bodies (3 unknowns: v, w) and joints (2: the impulse) are the
// nodes of a tree, joints linked to their moving bodies; the saddle-point system
//
//     [ M   −Jᵀ ] [Δv]   [  0   ]
//     [ −J   0  ] [Δλ] = [ −rhs ]
//
// is factored as L·D·Lᵀ leaves first, where every node's block meets only its parent's, so the
// factor and the solve cost one small block operation per node, in double precision. A joint
// node never is a leaf: the tree is rooted at a component's one joint to a body that does not
// move (static or kinematic), or at a body when it has none, so every other joint has its far
// body below it and its pivot block −J·D⁻¹·Jᵀ is invertible. Components with a loop, with two
// or more joints to bodies that do not move (a bridge: a loop through the ground), with a body of
// fixed rotation, or with a single joint (where SolvePoint is already exact) stay with the
// sweeps.
#pragma once

#include "joints/joint.h"
#include "solvers/soft_step/soft_joint.h"
#include "meff/task_system.h"

#include <array>
#include <cstdint>
#include <vector>

namespace meff::detail
{

class SoftJointTree
{
  public:
    /// What Select reads of one joint: solver indices of its bodies, and flags (revolute, A
    /// moves, B moves, A or B of fixed rotation).
    struct SelectionKey
    {
        std::int32_t indexA = 0, indexB = 0, flags = 0;
        friend bool operator==(const SelectionKey&, const SelectionKey&) = default;
    };

    /// Marks SoftJointFrame::pointInTree on the revolute joints among `joints` (frames[k] is
    /// joints[k]'s) that the tree solves; `bodyCount` is the island's solver index count.
    /// Returns how many were marked. Keeping last step's choice is checked and applied with
    /// the joints spread over `tasks` (null: this thread).
    int Select(const std::vector<Joint*>& joints, std::vector<SoftJointFrame>& frames,
               std::size_t bodyCount, TaskSystem* tasks = nullptr);

    /// Orders the marked joints and their bodies for the factorisation; frames must stay where
    /// they are until the step ends.
    void Build(const std::vector<Joint*>& joints, const std::vector<SoftJointFrame>& frames,
               std::size_t bodyCount);

    bool Empty() const { return m_joints.empty(); }

    /// One exact update of every tree joint's point rows on the bodies' velocities now (soft
    /// with `useBias`, rigid without); `accumulate` adds the impulses to the joints' totals (off
    /// in the step's closing sweep, whose impulses are not kept).
    void Solve(const SoftStepContext& context, bool useBias, bool accumulate);

  private:
    using Block = std::array<std::array<double, 3>, 3>;

    struct Node
    {
        std::int32_t parent = -1;     ///< node index, −1 for a root
        std::int32_t body = -1;       ///< a body node: its solver index
        std::int32_t joint = -1;      ///< a joint node: its index in m_joints
        int size = 0;                 ///< unknowns: 3 for a body, 2 for a joint
        double mass = 0, inertia = 0; ///< a body node: kg, kg·m²
    };

    struct TreeJoint
    {
        RevoluteJoint* joint = nullptr;
        const SoftJointFrame* frame = nullptr;
        Vec2 rA, rB; ///< anchors now (m)
        Vec2 d;      ///< anchor B − anchor A now: the point rows' C (m)
    };

    /// The edge from a node to its parent: −J of the joint on the body = sign·[I | lever].
    struct Edge
    {
        double sign = 1;
        std::array<double, 2> lever{};
    };
    Edge ParentEdge(const Node& node) const;
    void Factor();
    /// The right-hand side −rhs of every joint node into m_x (bodies 0); false when it is zero.
    bool SetRightHandSide(const SoftStepContext& context, bool useBias);
    void SolveFactored();

    std::vector<TreeJoint> m_joints;
    bool m_factored = false;       ///< the factors are those of the anchors in m_joints
    std::vector<Node> m_nodes;     ///< children before their parents
    std::vector<Block> m_inverse;  ///< D_i⁻¹
    std::vector<Block> m_lower;    ///< L_i = D_i⁻¹·H_{i,parent}
    std::vector<Block> m_diagonal; ///< D_i while factoring
    std::vector<std::array<double, 3>> m_x;
    std::vector<Velocity> m_moved; ///< per body: the velocity the tree joints' λ gave it
    /// Last Select's inputs and choices (joints[k]'s key and mark).
    std::vector<SelectionKey> m_keys;
    std::vector<std::uint8_t> m_marks;
    int m_marked = 0; ///< how many of m_marks are set
    // Scratch of Select and Build.
    std::vector<std::int32_t> m_union, m_jointRoot;
    std::vector<std::uint8_t> m_bad, m_cycle;
    std::vector<std::int32_t> m_grounds, m_count;
    std::vector<std::int32_t> m_bodyStart, m_bodyJoints, m_parents, m_stack;
    std::vector<std::uint8_t> m_seenJoint, m_seenBody;
};

} // namespace meff::detail
