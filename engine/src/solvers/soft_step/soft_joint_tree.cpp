// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "solvers/soft_step/soft_joint_tree.h"

#include "solvers/shared/island.h"
#include "tasks/parallel_ranges.h"

#include <algorithm>
#include <atomic>
#include <numeric>
#include <variant>

namespace meff::detail
{

namespace
{

bool Moves(Real invMass)
{
    return invMass > 0;
}

std::int32_t Find(std::vector<std::int32_t>& parent, std::int32_t i)
{
    while (parent[i] != i)
    {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

using Block = std::array<std::array<double, 3>, 3>;

/// The inverse of the symmetric n×n (n = 2 or 3) block; zero when it is singular (rows that
/// cannot move anything: no impulse rather than a non-finite one).
Block Inverse(const Block& m, int n)
{
    Block inv{};
    if (n == 2)
    {
        const double det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
        if (det == 0)
        {
            return inv;
        }
        const double f = 1 / det;
        inv[0][0] = f * m[1][1];
        inv[0][1] = -f * m[0][1];
        inv[1][0] = -f * m[1][0];
        inv[1][1] = f * m[0][0];
        return inv;
    }
    const double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
    const double c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
    const double c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    const double det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
    if (det == 0)
    {
        return inv;
    }
    const double f = 1 / det;
    inv[0][0] = f * c00;
    inv[1][0] = f * c01;
    inv[2][0] = f * c02;
    inv[0][1] = f * (m[0][2] * m[2][1] - m[0][1] * m[2][2]);
    inv[1][1] = f * (m[0][0] * m[2][2] - m[0][2] * m[2][0]);
    inv[2][1] = f * (m[0][1] * m[2][0] - m[0][0] * m[2][1]);
    inv[0][2] = f * (m[0][1] * m[1][2] - m[0][2] * m[1][1]);
    inv[1][2] = f * (m[0][2] * m[1][0] - m[0][0] * m[1][2]);
    inv[2][2] = f * (m[0][0] * m[1][1] - m[0][1] * m[1][0]);
    return inv;
}

/// What the selection reads of a joint: its kind, its bodies and whether each moves and turns.
[[gnu::always_inline]] inline SoftJointTree::SelectionKey KeyOf(const Joint& joint,
                                                                const SoftJointFrame& f)
{
    const auto flags = static_cast<std::int32_t>(
        (std::holds_alternative<RevoluteJoint>(joint.data) ? 1 : 0) | (Moves(f.mA) ? 2 : 0) |
        (Moves(f.mB) ? 4 : 0) | (f.iA == 0 ? 8 : 0) | (f.iB == 0 ? 16 : 0));
    return {f.indexA, f.indexB, flags};
}

} // namespace

int SoftJointTree::Select(const std::vector<Joint*>& joints, std::vector<SoftJointFrame>& frames,
                          std::size_t bodyCount, TaskSystem* tasks)
{
    // The same joints on the same bodies as last time (a net or a chain from step to step):
    // the same choice, without the search (it cost a joint net of 20,000 hinges 6 % of its
    // step). Each joint reads and writes only its own key, mark and frame (and costs about
    // what a body's copy does); a joint that matches takes last time's mark at once, since
    // where any does not, the search below sets every joint's.
    const auto count = static_cast<int>(joints.size());
    std::atomic<bool> same{m_keys.size() == joints.size() && m_marks.size() == joints.size()};
    if (same.load(std::memory_order_relaxed))
    {
        ForRanges(tasks, count, kMinBodiesPerTask,
                  [&](int begin, int end, int)
                  {
                      for (auto k = static_cast<std::size_t>(begin);
                           k < static_cast<std::size_t>(end); ++k)
                      {
                          if (!(m_keys[k] == KeyOf(*joints[k], frames[k])))
                          {
                              same.store(false, std::memory_order_relaxed);
                              return;
                          }
                          frames[k].pointInTree = m_marks[k] != 0;
                      }
                  });
        if (same.load(std::memory_order_relaxed))
        {
            return m_marked;
        }
    }
    m_keys.clear();
    m_marks.clear();
    for (std::size_t k = 0; k < joints.size(); ++k)
    {
        m_keys.push_back(KeyOf(*joints[k], frames[k]));
    }
    // Union-find over the moving bodies the revolute joints join; a joint between two bodies
    // already joined closes a loop.
    m_union.resize(bodyCount);
    std::iota(m_union.begin(), m_union.end(), 0);
    m_cycle.assign(joints.size(), 0);
    // A revolute joint (flag 1) with a moving body (flags 2, 4): KeyOf has read both.
    const auto candidate = [&](std::size_t k)
    { return (m_keys[k].flags & 1) != 0 && (m_keys[k].flags & 6) != 0; };
    for (std::size_t k = 0; k < joints.size(); ++k)
    {
        const SoftJointFrame& f = frames[k];
        if (!candidate(k) || !Moves(f.mA) || !Moves(f.mB))
        {
            continue;
        }
        const std::int32_t a = Find(m_union, f.indexA);
        const std::int32_t b = Find(m_union, f.indexB);
        if (a == b)
        {
            m_cycle[k] = 1;
        }
        else
        {
            m_union[a] = b;
        }
    }
    m_bad.assign(bodyCount, 0);
    m_grounds.assign(bodyCount, 0);
    m_count.assign(bodyCount, 0);
    m_jointRoot.assign(joints.size(), -1);
    for (std::size_t k = 0; k < joints.size(); ++k)
    {
        if (!candidate(k))
        {
            continue;
        }
        const SoftJointFrame& f = frames[k];
        const std::int32_t root = Find(m_union, Moves(f.mA) ? f.indexA : f.indexB);
        m_jointRoot[k] = root;
        ++m_count[root];
        m_grounds[root] += Moves(f.mA) && Moves(f.mB) ? 0 : 1;
        const bool fixedRotation = (Moves(f.mA) && f.iA == 0) || (Moves(f.mB) && f.iB == 0);
        m_bad[root] = m_bad[root] != 0 || m_cycle[k] != 0 || fixedRotation ? 1 : 0;
    }
    int marked = 0;
    for (std::size_t k = 0; k < joints.size(); ++k)
    {
        const std::int32_t root = m_jointRoot[k];
        frames[k].pointInTree =
            root >= 0 && m_bad[root] == 0 && m_grounds[root] <= 1 && m_count[root] >= 2;
        marked += frames[k].pointInTree ? 1 : 0;
        m_marks.push_back(frames[k].pointInTree ? 1 : 0);
    }
    m_marked = marked;
    return marked;
}

void SoftJointTree::Build(const std::vector<Joint*>& joints,
                          const std::vector<SoftJointFrame>& frames, std::size_t bodyCount)
{
    m_joints.clear();
    m_nodes.clear();
    m_factored = false;
    for (std::size_t k = 0; k < joints.size(); ++k)
    {
        if (frames[k].pointInTree)
        {
            m_joints.push_back(
                {std::get_if<RevoluteJoint>(&joints[k]->data), &frames[k], {}, {}, {}});
        }
    }
    if (m_joints.empty())
    {
        return;
    }
    // Each moving body's tree joints (compressed rows).
    m_bodyStart.assign(bodyCount + 1, 0);
    for (const TreeJoint& j : m_joints)
    {
        m_bodyStart[j.frame->indexA + 1] += Moves(j.frame->mA) ? 1 : 0;
        m_bodyStart[j.frame->indexB + 1] += Moves(j.frame->mB) ? 1 : 0;
    }
    std::partial_sum(m_bodyStart.begin(), m_bodyStart.end(), m_bodyStart.begin());
    m_bodyJoints.resize(static_cast<std::size_t>(m_bodyStart.back()));
    m_parents.assign(m_bodyStart.begin(), m_bodyStart.end() - 1); // fill cursors
    for (std::size_t j = 0; j < m_joints.size(); ++j)
    {
        const SoftJointFrame& f = *m_joints[j].frame;
        if (Moves(f.mA))
        {
            m_bodyJoints[m_parents[f.indexA]++] = static_cast<std::int32_t>(j);
        }
        if (Moves(f.mB))
        {
            m_bodyJoints[m_parents[f.indexB]++] = static_cast<std::int32_t>(j);
        }
    }

    // Vertices on the stack: a joint j as j, a body b as −1 − b. 0 unseen, 1 in a component
    // already searched for its root, 2 placed in the tree.
    m_seenJoint.assign(m_joints.size(), 0);
    m_seenBody.assign(bodyCount, 0);
    const auto neighbours = [&](std::int32_t vertex, auto&& visit)
    {
        if (vertex >= 0)
        {
            const SoftJointFrame& f = *m_joints[vertex].frame;
            if (Moves(f.mA))
            {
                visit(-1 - f.indexA);
            }
            if (Moves(f.mB))
            {
                visit(-1 - f.indexB);
            }
            return;
        }
        const std::int32_t body = -1 - vertex;
        for (std::int32_t i = m_bodyStart[body]; i < m_bodyStart[body + 1]; ++i)
        {
            visit(m_bodyJoints[i]);
        }
    };
    const auto seen = [&](std::int32_t vertex) -> std::uint8_t&
    { return vertex >= 0 ? m_seenJoint[vertex] : m_seenBody[-1 - vertex]; };

    for (std::size_t first = 0; first < m_joints.size(); ++first)
    {
        if (m_seenJoint[first] != 0)
        {
            continue;
        }
        // The component's joint to a body that does not move is its root (Select let at most
        // one through); without one, the first joint's first moving body.
        const SoftJointFrame& f0 = *m_joints[first].frame;
        std::int32_t root = Moves(f0.mA) ? -1 - f0.indexA : -1 - f0.indexB;
        m_stack.assign(1, static_cast<std::int32_t>(first));
        seen(static_cast<std::int32_t>(first)) = 1;
        while (!m_stack.empty())
        {
            const std::int32_t vertex = m_stack.back();
            m_stack.pop_back();
            if (vertex >= 0 &&
                !(Moves(m_joints[vertex].frame->mA) && Moves(m_joints[vertex].frame->mB)))
            {
                root = vertex;
            }
            neighbours(vertex,
                       [&](std::int32_t next)
                       {
                           if (seen(next) == 0)
                           {
                               seen(next) = 1;
                               m_stack.push_back(next);
                           }
                       });
        }
        // Depth first from the root, parents before children; reversed below.
        m_stack.assign(1, root);
        m_parents.assign(1, -1); // the parent node of each stacked vertex
        seen(root) = 2;
        while (!m_stack.empty())
        {
            const std::int32_t vertex = m_stack.back();
            const std::int32_t parent = m_parents.back();
            m_stack.pop_back();
            m_parents.pop_back();
            Node node;
            node.parent = parent;
            if (vertex >= 0)
            {
                node.joint = vertex;
                node.size = 2;
            }
            else
            {
                node.body = -1 - vertex;
                node.size = 3;
                const TreeJoint& any = m_joints[m_bodyJoints[m_bodyStart[node.body]]];
                const bool isA = any.frame->indexA == node.body;
                node.mass = 1 / double(isA ? any.frame->mA : any.frame->mB);
                node.inertia = 1 / double(isA ? any.frame->iA : any.frame->iB);
            }
            const auto index = static_cast<std::int32_t>(m_nodes.size());
            m_nodes.push_back(node);
            neighbours(vertex,
                       [&](std::int32_t next)
                       {
                           if (seen(next) != 2)
                           {
                               seen(next) = 2;
                               m_stack.push_back(next);
                               m_parents.push_back(index);
                           }
                       });
        }
    }
    // Reversed, every node comes after all of its descendants.
    const auto n = static_cast<std::int32_t>(m_nodes.size());
    std::reverse(m_nodes.begin(), m_nodes.end());
    for (Node& node : m_nodes)
    {
        node.parent = node.parent < 0 ? -1 : n - 1 - node.parent;
    }
    m_inverse.resize(m_nodes.size());
    m_lower.resize(m_nodes.size());
    m_diagonal.resize(m_nodes.size());
    m_x.resize(m_nodes.size());
}

SoftJointTree::Edge SoftJointTree::ParentEdge(const Node& node) const
{
    // J of joint j on body b (2×3, Cdot = J·[v; w]) is ±[I | q] with q = (−r.y, r.x): + for
    // body B with its anchor rB, − for body A with rA. The saddle-point matrix holds −J.
    const Node& parent = m_nodes[node.parent];
    const TreeJoint& j = m_joints[node.joint >= 0 ? node.joint : parent.joint];
    const std::int32_t body = node.joint >= 0 ? parent.body : node.body;
    const bool isB = j.frame->indexB == body;
    const Vec2 r = isB ? j.rB : j.rA;
    return {isB ? -1.0 : 1.0, {-double(r.y), double(r.x)}};
}

namespace
{

/// A body below a joint: with H = −Jᵀ = s·[I | q]ᵀ (3×2), L = D⁻¹·H and the joint's D −= Hᵀ·L,
/// written out so the zeros of H cost nothing.
void EliminateBody(const Block& inverse, double s, const std::array<double, 2>& q, Block& lower,
                   Block& parent)
{
    for (int r = 0; r < 3; ++r)
    {
        for (int c = 0; c < 2; ++c)
        {
            lower[r][c] = s * (inverse[r][c] + inverse[r][2] * q[c]);
        }
    }
    for (int r = 0; r < 2; ++r)
    {
        for (int c = 0; c < 2; ++c)
        {
            parent[r][c] -= s * (lower[r][c] + q[r] * lower[2][c]);
        }
    }
}

/// A joint below a body: with H = −J = s·[I | q] (2×3), L = D⁻¹·H and the body's D −= Hᵀ·L.
void EliminateJoint(const Block& inverse, double s, const std::array<double, 2>& q, Block& lower,
                    Block& parent)
{
    for (int r = 0; r < 2; ++r)
    {
        lower[r][0] = s * inverse[r][0];
        lower[r][1] = s * inverse[r][1];
        lower[r][2] = s * (inverse[r][0] * q[0] + inverse[r][1] * q[1]);
    }
    for (int c = 0; c < 3; ++c)
    {
        parent[0][c] -= s * lower[0][c];
        parent[1][c] -= s * lower[1][c];
        parent[2][c] -= s * (q[0] * lower[0][c] + q[1] * lower[1][c]);
    }
}

/// x_parent −= Lᵀ·x (forward substitution).
template <int N, int P>
void Forward(const Block& lower, const std::array<double, 3>& x, std::array<double, 3>& parent)
{
    for (int c = 0; c < P; ++c)
    {
        double sum = 0;
        for (int k = 0; k < N; ++k)
        {
            sum += lower[k][c] * x[k];
        }
        parent[c] -= sum;
    }
}

template <int N>
void Scale(const Block& inverse, std::array<double, 3>& x)
{
    std::array<double, 3> y{};
    for (int r = 0; r < N; ++r)
    {
        for (int k = 0; k < N; ++k)
        {
            y[r] += inverse[r][k] * x[k];
        }
    }
    x = y;
}

/// x −= L·x_parent (back substitution).
template <int N, int P>
void Back(const Block& lower, const std::array<double, 3>& parent, std::array<double, 3>& x)
{
    for (int r = 0; r < N; ++r)
    {
        double sum = 0;
        for (int c = 0; c < P; ++c)
        {
            sum += lower[r][c] * parent[c];
        }
        x[r] -= sum;
    }
}

} // namespace

void SoftJointTree::Factor()
{
    for (std::size_t i = 0; i < m_nodes.size(); ++i)
    {
        const Node& node = m_nodes[i];
        Block& d = m_diagonal[i];
        d = Block{};
        if (node.body >= 0)
        {
            d[0][0] = node.mass;
            d[1][1] = node.mass;
            d[2][2] = node.inertia;
        }
    }
    // Bodies and joints alternate along every path: a body's parent is a joint and a joint's a
    // body.
    for (std::size_t i = 0; i < m_nodes.size(); ++i)
    {
        const Node& node = m_nodes[i];
        m_inverse[i] = Inverse(m_diagonal[i], node.size);
        if (node.parent < 0)
        {
            continue;
        }
        const Edge edge = ParentEdge(node);
        if (node.body >= 0)
        {
            EliminateBody(m_inverse[i], edge.sign, edge.lever, m_lower[i], m_diagonal[node.parent]);
        }
        else
        {
            EliminateJoint(m_inverse[i], edge.sign, edge.lever, m_lower[i],
                           m_diagonal[node.parent]);
        }
    }
}

bool SoftJointTree::SetRightHandSide(const SoftStepContext& context, bool useBias)
{
    SoftBodies& bodies = *context.bodies;
    const Softness& soft = context.joint;
    // A·λ is taken back only by a row that takes back impulse (not the position pass's).
    const bool takeBack = useBias && soft.impulseScale != 0;
    if (takeBack)
    {
        // A·λ: the anchor velocities that the joints' impulses so far gave on their own.
        m_moved.resize(bodies.velocities.size());
        for (const TreeJoint& j : m_joints)
        {
            m_moved[j.frame->indexA] = {};
            m_moved[j.frame->indexB] = {};
        }
    }
    for (TreeJoint& j : m_joints)
    {
        const SoftJointFrame& f = *j.frame;
        const SoftAnchors at = AnchorsNow(f, bodies.deltas[f.indexA], bodies.deltas[f.indexB]);
        // The factors hold while the anchors do: between a sub-step's relax sweep and the next
        // sub-step's solve, and into the closing sweep, nothing moves the bodies.
        m_factored = m_factored && at.rA == j.rA && at.rB == j.rB;
        j.rA = at.rA;
        j.rB = at.rB;
        j.d = at.d;
        if (takeBack)
        {
            RowBodies moved =
                LoadRowBodies(m_moved.data(), f.indexA, f.indexB, f.mA, f.iA, f.mB, f.iB);
            ApplyPointImpulse(j.joint->impulse, at.rA, at.rB, moved);
            StoreRowBodies(m_moved.data(), f.indexA, f.indexB, moved);
        }
    }
    bool any = false;
    for (std::size_t i = 0; i < m_nodes.size(); ++i)
    {
        m_x[i] = {};
        const Node& node = m_nodes[i];
        if (node.joint < 0)
        {
            continue;
        }
        const TreeJoint& j = m_joints[node.joint];
        const SoftJointFrame& f = *j.frame;
        const RowBodies b =
            LoadRowBodies(bodies.velocities.data(), f.indexA, f.indexB, f.mA, f.iA, f.mB, f.iB);
        Vec2 target = AnchorVelocity(j.rA, j.rB, b); // the rigid row: A·Δλ = −Cdot
        if (useBias)
        {
            target = soft.massScale * target + BiasOf(soft, j.d);
        }
        if (takeBack)
        {
            const RowBodies moved =
                LoadRowBodies(m_moved.data(), f.indexA, f.indexB, f.mA, f.iA, f.mB, f.iB);
            target += soft.impulseScale * AnchorVelocity(j.rA, j.rB, moved);
        }
        // The joint rows of the system read −J·Δv = −rhs, and rhs = −target.
        m_x[i] = {double(target.x), double(target.y), 0};
        any = any || target.x != 0 || target.y != 0;
    }
    return any;
}

void SoftJointTree::SolveFactored()
{
    // Forward substitution and the diagonal in one pass: a node's x is final once its
    // children (all before it) have passed theirs on.
    const std::size_t n = m_nodes.size();
    for (std::size_t i = 0; i < n; ++i)
    {
        const Node& node = m_nodes[i];
        if (node.body >= 0)
        {
            if (node.parent >= 0)
            {
                Forward<3, 2>(m_lower[i], m_x[i], m_x[node.parent]);
            }
            Scale<3>(m_inverse[i], m_x[i]);
        }
        else
        {
            if (node.parent >= 0)
            {
                Forward<2, 3>(m_lower[i], m_x[i], m_x[node.parent]);
            }
            Scale<2>(m_inverse[i], m_x[i]);
        }
    }
    for (std::size_t i = n; i-- > 0;)
    {
        const Node& node = m_nodes[i];
        if (node.parent >= 0)
        {
            if (node.body >= 0)
            {
                Back<3, 2>(m_lower[i], m_x[node.parent], m_x[i]);
            }
            else
            {
                Back<2, 3>(m_lower[i], m_x[node.parent], m_x[i]);
            }
        }
    }
}

void SoftJointTree::Solve(const SoftStepContext& context, bool useBias, bool accumulate)
{
    if (m_joints.empty())
    {
        return;
    }
    // Nothing to take up (the position pass of joints within their push-out speed, bodies the
    // other joints did not move): the update is zero, and its factor and solve are saved.
    if (!SetRightHandSide(context, useBias))
    {
        return;
    }
    if (!m_factored)
    {
        Factor();
        m_factored = true;
    }
    SolveFactored();
    SoftBodies& bodies = *context.bodies;
    for (const Node& node : m_nodes)
    {
        if (node.joint < 0)
        {
            continue;
        }
        TreeJoint& j = m_joints[node.joint];
        const SoftJointFrame& f = *j.frame;
        const Vec2 impulse{Real(m_x[&node - m_nodes.data()][0]),
                           Real(m_x[&node - m_nodes.data()][1])};
        RowBodies b =
            LoadRowBodies(bodies.velocities.data(), f.indexA, f.indexB, f.mA, f.iA, f.mB, f.iB);
        ApplyPointImpulse(impulse, j.rA, j.rB, b);
        StoreRowBodies(bodies.velocities.data(), f.indexA, f.indexB, b);
        if (accumulate)
        {
            j.joint->impulse += impulse;
        }
    }
}

} // namespace meff::detail
