// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
#include "solvers/soft_step/soft_contact_direct.h"

#include "solvers/lanes/graph_colouring.h"

#include <algorithm>
#include <cmath>

namespace meff::detail
{

namespace
{

std::int32_t Find(std::vector<std::int32_t>& parent, std::int32_t i)
{
    while (parent[i] != i)
    {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

/// Row i's part of A on one of its bodies: the sign of its Jacobian there (−1 for A, +1 for B),
/// its lever (r×n) and the body's solver index and inverse masses.
struct RowOnBody
{
    std::int32_t body;
    double sign, lever, invMass, invI;
    bool moves;
};

void RowBodiesOf(const SoftContact& c, const SoftContactPoint& p, RowOnBody out[2])
{
    out[0] = {c.indexA,     -1,           double(Cross(p.rA, c.normal)),
              double(c.mA), double(c.iA), SolverMoves(c.mA, c.iA)};
    out[1] = {c.indexB,
              1,
              double(Cross(p.rB, c.normal)),
              double(c.mB),
              double(c.iB),
              SolverMoves(c.mB, c.iB)};
}

/// A condition test row by row (as Box2D's k11² < 1000·det for its two-point block, looser: a
/// light box under a 1000 times heavier one keeps about 1e-3): a row whose pivot keeps less
/// than this fraction of its diagonal says nearly what the rows before it say, and solving it
/// gave huge, opposed impulses (impact_storm's pile flew apart at 3e5 m/s).
constexpr double kMinPivotFraction = 1e-6;

/// In-place Cholesky factor (lower) of the m×m matrix `a` (row-major); false if a pivot is not
/// positive or keeps less than kMinPivotFraction of its diagonal.
bool Cholesky(int m, double* a)
{
    for (int j = 0; j < m; ++j)
    {
        const double diagonal = a[j * m + j];
        double d = diagonal;
        for (int k = 0; k < j; ++k)
        {
            d -= a[j * m + k] * a[j * m + k];
        }
        if (!(d > kMinPivotFraction * diagonal))
        {
            return false;
        }
        d = std::sqrt(d);
        a[j * m + j] = d;
        for (int i = j + 1; i < m; ++i)
        {
            double s = a[i * m + j];
            for (int k = 0; k < j; ++k)
            {
                s -= a[i * m + k] * a[j * m + k];
            }
            a[i * m + j] = s / d;
        }
    }
    return true;
}

/// Solves L·Lᵀ·x = b in place (b becomes x).
void CholeskySolve(int m, const double* l, double* b)
{
    for (int i = 0; i < m; ++i)
    {
        double s = b[i];
        for (int k = 0; k < i; ++k)
        {
            s -= l[i * m + k] * b[k];
        }
        b[i] = s / l[i * m + i];
    }
    for (int i = m; i-- > 0;)
    {
        double s = b[i];
        for (int k = i + 1; k < m; ++k)
        {
            s -= l[k * m + i] * b[k];
        }
        b[i] = s / l[i * m + i];
    }
}

} // namespace

void SoftContactDirect::Prepare(std::span<const SoftContact> contacts, std::int32_t bodyCount,
                                std::vector<std::uint8_t>& direct)
{
    m_groups.clear();
    m_rows.clear();
    m_groupContacts.clear();
    m_matrices.clear();
    direct.assign(contacts.size(), 0);
    if (contacts.size() < 2)
    {
        return; // no group of two contacts
    }
    const auto bodies = static_cast<std::size_t>(bodyCount);
    m_parent.resize(bodies);
    for (std::size_t i = 0; i < bodies; ++i)
    {
        m_parent[i] = static_cast<std::int32_t>(i);
    }
    // Bodies that move are joined by the contacts between them.
    for (const SoftContact& c : contacts)
    {
        if (SolverMoves(c.mA, c.iA) && SolverMoves(c.mB, c.iB))
        {
            m_parent[Find(m_parent, c.indexA)] = Find(m_parent, c.indexB);
        }
    }
    m_joined.assign(bodies, 0);
    m_rowsOf.assign(bodies, 0);
    m_contactsOf.assign(bodies, 0);
    m_groupOf.assign(bodies, -1);
    const auto rootOf = [&](const SoftContact& c)
    { return Find(m_parent, SolverMoves(c.mA, c.iA) ? c.indexA : c.indexB); };
    // Each group's lightest and heaviest moving body (inverse masses).
    m_minInv.assign(bodies, 1e300);
    m_maxInv.assign(bodies, 0.0);
    for (const SoftContact& c : contacts)
    {
        const std::int32_t root = rootOf(c);
        m_rowsOf[root] += c.pointCount;
        // Two moving bodies or more: a contact between two of them.
        m_joined[root] |= SolverMoves(c.mA, c.iA) && SolverMoves(c.mB, c.iB) ? 1 : 0;
        for (const auto& [m, i] : {std::pair{c.mA, c.iA}, std::pair{c.mB, c.iB}})
        {
            if (SolverMoves(m, i))
            {
                m_minInv[root] = std::min(m_minInv[root], double(m));
                m_maxInv[root] = std::max(m_maxInv[root], double(m));
            }
        }
        m_contactsOf[root] += 1;
    }
    // Groups in the order of their first contact; contacts and rows in island order.
    for (std::size_t k = 0; k < contacts.size(); ++k)
    {
        const std::int32_t root = rootOf(contacts[k]);
        if (m_contactsOf[root] < 2 || m_rowsOf[root] > kMaxDirectRows ||
            (m_joined[root] != 0 && m_maxInv[root] < kMinDirectMassRatio * m_minInv[root]))
        {
            continue;
        }
        if (m_groupOf[root] < 0)
        {
            m_groupOf[root] = static_cast<std::int32_t>(m_groups.size());
            Group g;
            g.contactCount = 0;
            m_groups.push_back(g);
        }
        m_groups[m_groupOf[root]].contactCount += 1;
        direct[k] = 1;
    }
    std::int32_t firstContact = 0;
    for (Group& g : m_groups)
    {
        g.firstContact = firstContact;
        firstContact += g.contactCount;
        g.contactCount = 0;
    }
    m_groupContacts.resize(static_cast<std::size_t>(firstContact));
    for (std::size_t k = 0; k < contacts.size(); ++k)
    {
        if (direct[k] == 0)
        {
            continue;
        }
        Group& g = m_groups[m_groupOf[rootOf(contacts[k])]];
        m_groupContacts[g.firstContact + g.contactCount++] = static_cast<std::int32_t>(k);
    }
    for (Group& g : m_groups)
    {
        g.firstRow = static_cast<std::int32_t>(m_rows.size());
        for (std::int32_t i = 0; i < g.contactCount; ++i)
        {
            const std::int32_t k = m_groupContacts[g.firstContact + i];
            for (int j = 0; j < contacts[k].pointCount; ++j)
            {
                m_rows.push_back({k, j});
            }
        }
        g.rowCount = static_cast<std::int32_t>(m_rows.size()) - g.firstRow;
        // A = J·M⁻¹·Jᵀ over the bodies two rows share.
        const auto n = static_cast<std::size_t>(g.rowCount);
        g.matrix = m_matrices.size();
        m_matrices.resize(g.matrix + n * n, 0.0);
        double* A = &m_matrices[g.matrix];
        for (std::size_t i = 0; i < n; ++i)
        {
            const Row& ri = m_rows[g.firstRow + i];
            const SoftContact& ci = contacts[ri.contact];
            RowOnBody bi[2];
            RowBodiesOf(ci, ci.points[ri.point], bi);
            for (std::size_t j = 0; j < n; ++j)
            {
                const Row& rj = m_rows[g.firstRow + j];
                const SoftContact& cj = contacts[rj.contact];
                RowOnBody bj[2];
                RowBodiesOf(cj, cj.points[rj.point], bj);
                const double dot =
                    double(ci.normal.x) * cj.normal.x + double(ci.normal.y) * cj.normal.y;
                double a = 0;
                for (const RowOnBody& x : bi)
                {
                    for (const RowOnBody& y : bj)
                    {
                        if (x.moves && y.moves && x.body == y.body)
                        {
                            a += x.sign * y.sign * (x.invMass * dot + x.invI * x.lever * y.lever);
                        }
                    }
                }
                A[i * n + j] = a;
            }
        }
        // Rows that say the same thing (a box's corners pressed by two neighbours) make A
        // singular; a relative 1e-9 on the diagonal keeps Cholesky's pivots positive (the
        // condition test then sends such a group to the rows one by one).
        for (std::size_t i = 0; i < n; ++i)
        {
            A[i * n + i] *= 1 + 1e-9;
        }
    }
}

bool SoftContactDirect::SolveLcp(int n, const double* A, const double* q, double* x)
{
    m_free.resize(static_cast<std::size_t>(n));
    m_set.resize(static_cast<std::size_t>(n));
    m_factor.resize(static_cast<std::size_t>(n * n));
    m_rhs.resize(static_cast<std::size_t>(n));
    m_w.resize(static_cast<std::size_t>(n));
    double scale = 0;
    for (int i = 0; i < n; ++i)
    {
        m_free[i] = x[i] > 0 ? 1 : 0;
        scale = std::max(scale, std::abs(q[i]));
    }
    const double tolerance = 1e-10 * scale;
    // Murty's principal pivoting: each guess of the pushing rows is solved exactly, then the
    // largest infeasible row changes sides.
    const int maxPivots = 4 * n + 8;
    for (int pivot = 0; pivot < maxPivots; ++pivot)
    {
        int m = 0;
        for (int i = 0; i < n; ++i)
        {
            if (m_free[i] != 0)
            {
                m_set[m++] = i;
            }
        }
        for (int a = 0; a < m; ++a)
        {
            for (int b = 0; b < m; ++b)
            {
                m_factor[a * m + b] = A[m_set[a] * n + m_set[b]];
            }
            m_rhs[a] = -q[m_set[a]];
        }
        if (!Cholesky(m, m_factor.data()))
        {
            return false;
        }
        CholeskySolve(m, m_factor.data(), m_rhs.data());
        for (int i = 0; i < n; ++i)
        {
            x[i] = 0;
        }
        for (int a = 0; a < m; ++a)
        {
            x[m_set[a]] = m_rhs[a];
        }
        int infeasible = -1;
        for (int i = n; i-- > 0;)
        {
            if (m_free[i] != 0)
            {
                if (x[i] < 0 && -x[i] * A[i * n + i] > tolerance)
                {
                    infeasible = i;
                    break;
                }
                continue;
            }
            double w = q[i];
            for (int a = 0; a < m; ++a)
            {
                w += A[i * n + m_set[a]] * m_rhs[a];
            }
            if (w < -tolerance)
            {
                infeasible = i;
                break;
            }
        }
        if (infeasible < 0)
        {
            for (int i = 0; i < n; ++i)
            {
                x[i] = std::max(x[i], 0.0);
            }
            return true;
        }
        m_free[infeasible] ^= 1;
    }
    return false;
}

void SoftContactDirect::Solve(std::span<SoftContact> contacts, const SoftStepContext& context,
                              std::vector<std::int32_t>& fallback)
{
    SoftBodies& bodies = *context.bodies;
    const Real slop = context.rowSlop;
    for (const Group& g : m_groups)
    {
        const int n = g.rowCount;
        m_q.resize(static_cast<std::size_t>(n));
        m_x.resize(static_cast<std::size_t>(n));
        const double* A = &m_matrices[g.matrix];
        for (int i = 0; i < n; ++i)
        {
            const Row& r = m_rows[g.firstRow + i];
            const SoftContact& c = contacts[r.contact];
            const SoftContactPoint& p = c.points[r.point];
            const RowBodies b =
                LoadRowBodies(bodies.velocities.data(), c.indexA, c.indexB, c.mA, c.iA, c.mB, c.iB);
            const SoftDelta& dA = bodies.deltas[c.indexA];
            const SoftDelta& dB = bodies.deltas[c.indexB];
            const Real C = SeparationOf(p.baseSeparation, c.normal, dA.dp, dA.dq, dB.dp, dB.dq,
                                        p.rA, p.rB, slop);
            // Rigid: a point apart may close by its gap within the sub-step (speculative).
            const RowTarget target = OneSidedTarget(C, false, kRigid, context.invH);
            m_q[i] = double(RowVelocity(PointRow(c.normal, p.rA, p.rB), b)) + target.bias;
            m_x[i] = p.normalImpulse;
        }
        // w = A·(λ' − λ) + b: q = b − A·λ.
        for (int i = 0; i < n; ++i)
        {
            double s = 0;
            for (int j = 0; j < n; ++j)
            {
                s += A[i * n + j] * m_x[j];
            }
            m_q[i] -= s;
        }
        if (!SolveLcp(n, A, m_q.data(), m_x.data()))
        {
            for (std::int32_t i = 0; i < g.contactCount; ++i)
            {
                fallback.push_back(m_groupContacts[g.firstContact + i]);
            }
            continue;
        }
        for (int i = 0; i < n; ++i)
        {
            const Row& r = m_rows[g.firstRow + i];
            SoftContact& c = contacts[r.contact];
            SoftContactPoint& p = c.points[r.point];
            const Real next = Real(m_x[i]);
            const Real applied = next - p.normalImpulse;
            RowBodies b =
                LoadRowBodies(bodies.velocities.data(), c.indexA, c.indexB, c.mA, c.iA, c.mB, c.iB);
            ApplyRowImpulse(PointRow(c.normal, p.rA, p.rB), applied, b);
            StoreRowBodies(bodies.velocities.data(), c.indexA, c.indexB, b);
            p.normalImpulse = next;
            p.totalNormalImpulse += applied;
        }
    }
}

} // namespace meff::detail
