#include "dynamics/colored_joint_solver.h"

#include "dynamics/lane_bodies.h"
#include "joints/joint.h"

#include <algorithm>
#include <cmath>

namespace meff::detail
{

namespace
{

bool Moves(Real invMass, Real invI)
{
    return invMass > 0 || invI > 0;
}

void PackLane(RevoluteJointGroup& g, int l, const RevoluteJoint& joint, std::int32_t discardIndex)
{
    g.indexA[l] = joint.indexA;
    g.indexB[l] = joint.indexB;
    g.storeA[l] = Moves(joint.invMassA, joint.invIA) ? joint.indexA : discardIndex;
    g.storeB[l] = Moves(joint.invMassB, joint.invIB) ? joint.indexB : discardIndex;
    g.invMassA[l] = joint.invMassA;
    g.invMassB[l] = joint.invMassB;
    g.invIA[l] = joint.invIA;
    g.invIB[l] = joint.invIB;
    g.rA.x[l] = joint.rA.x;
    g.rA.y[l] = joint.rA.y;
    g.rB.x[l] = joint.rB.x;
    g.rB.y[l] = joint.rB.y;
    const Mat22& K = joint.K;
    g.k11[l] = K.ex.x;
    g.k12[l] = K.ey.x;
    g.k21[l] = K.ex.y;
    g.k22[l] = K.ey.y;
    // K is fixed over the velocity iterations, so its determinant is inverted once here
    // instead of in every Mat22::Solve; the same float operations give the same value.
    const Real det = K.ex.x * K.ey.y - K.ey.x * K.ex.y;
    g.invDetK[l] = det != 0 ? Real(1) / det : Real(0);
    g.impulse.x[l] = joint.impulse.x;
    g.impulse.y[l] = joint.impulse.y;
    const Vec2 anchorA = joint.localAnchorA - joint.localCenterA;
    const Vec2 anchorB = joint.localAnchorB - joint.localCenterB;
    g.anchorA.x[l] = anchorA.x;
    g.anchorA.y[l] = anchorA.y;
    g.anchorB.x[l] = anchorB.x;
    g.anchorB.y[l] = anchorB.y;
}

/// x = K⁻¹·b for the lanes' 2×2 K, as Mat22::Solve (0 where det K = 0).
Vec2W SolveK(RealW k11, RealW k12, RealW k21, RealW k22, RealW invDet, Vec2W b)
{
    return {invDet * (k22 * b.x - k12 * b.y), invDet * (k11 * b.y - k21 * b.x)};
}

/// The point rows as one 2×2 block (RevoluteJoint's SolveVelocityConstraints with
/// blockJoints): Cdot = vB + wB×rB − vA − wA×rA, λ = −K⁻¹·Cdot.
void SolveVelocityGroup(RevoluteJointGroup& g, Velocity* velocities)
{
    BodyStateW a = Gather(velocities, g.indexA);
    BodyStateW b = Gather(velocities, g.indexB);
    const Vec2W cdot = b.linear + Cross(b.angular, g.rB) - a.linear - Cross(a.angular, g.rA);
    const Vec2W impulse = SolveK(g.k11, g.k12, g.k21, g.k22, g.invDetK, Vec2W{-cdot.x, -cdot.y});
    g.impulse = g.impulse + impulse;
    ApplyImpulseW({g.invMassA, g.invIA, g.invMassB, g.invIB}, a, b, g.rA, g.rB, impulse);
    Scatter(velocities, g.storeA, a);
    Scatter(velocities, g.storeB, b);
}

/// One Newton step on the anchor gap C = cB + rB − cA − rA with K from the current lever arms
/// (RevoluteJoint's SolvePositionConstraints with blockJoints). Returns each lane's |C|².
RealW SolvePositionGroup(const RevoluteJointGroup& g, Position* positions)
{
    BodyStateW a = Gather(positions, g.indexA);
    BodyStateW b = Gather(positions, g.indexB);
    const Vec2W rA = Mul(SinCosW(a.angular), g.anchorA);
    const Vec2W rB = Mul(SinCosW(b.angular), g.anchorB);
    const Vec2W C = b.linear + rB - a.linear - rA;

    const RealW mA = g.invMassA, mB = g.invMassB, iA = g.invIA, iB = g.invIB;
    const RealW k11 = mA + mB + iA * rA.y * rA.y + iB * rB.y * rB.y;
    const RealW k12 = -iA * rA.x * rA.y - iB * rB.x * rB.y;
    const RealW k22 = mA + mB + iA * rA.x * rA.x + iB * rB.x * rB.x;
    const RealW det = k11 * k22 - k12 * k12;
    const MaskW invertible = det != 0;
    const RealW invDet = Select(invertible, Splat(1) / Select(invertible, det, Splat(1)), Splat(0));
    const Vec2W x = SolveK(k11, k12, k12, k22, invDet, C);
    ApplyImpulseW({mA, iA, mB, iB}, a, b, rA, rB, Vec2W{-x.x, -x.y});
    Scatter(positions, g.storeA, a);
    Scatter(positions, g.storeB, b);
    return C.x * C.x + C.y * C.y;
}

} // namespace

void ColoredJointSolver::Prepare(std::span<RevoluteJoint* const> joints, std::int32_t discardIndex)
{
    std::int32_t bodyCount = 0;
    for (const RevoluteJoint* joint : joints)
    {
        bodyCount = std::max({bodyCount, joint->indexA + 1, joint->indexB + 1});
    }
    ColorConstraints(
        joints.size(), static_cast<std::size_t>(bodyCount),
        [&](std::size_t i)
        {
            const RevoluteJoint& joint = *joints[i];
            return ConstraintBodies{joint.indexA, joint.indexB, Moves(joint.invMassA, joint.invIA),
                                    Moves(joint.invMassB, joint.invIB)};
        },
        m_coloring);
    m_groups.clear();
    m_sources.clear();
    for (int color = 0; color < m_coloring.ColorCount(); ++color)
    {
        const std::int32_t begin = m_coloring.colorStarts[color];
        const std::int32_t end = m_coloring.colorStarts[color + 1];
        for (std::int32_t first = begin; first < end; first += kLanes)
        {
            // Empty lanes read body 0 and write the discard slot; all their masses are zero.
            RevoluteJointGroup& g = m_groups.emplace_back(RevoluteJointGroup{});
            std::fill(std::begin(g.storeA), std::end(g.storeA), discardIndex);
            std::fill(std::begin(g.storeB), std::end(g.storeB), discardIndex);
            for (int l = 0; l < kLanes; ++l)
            {
                RevoluteJoint* joint =
                    first + l < end ? joints[m_coloring.order[first + l]] : nullptr;
                m_sources.push_back(joint);
                if (joint != nullptr)
                {
                    PackLane(g, l, *joint, discardIndex);
                }
            }
        }
    }
}

void ColoredJointSolver::SolveVelocities(Velocity* velocities)
{
    for (RevoluteJointGroup& group : m_groups)
    {
        SolveVelocityGroup(group, velocities);
    }
}

void ColoredJointSolver::StoreImpulses() const
{
    for (std::size_t i = 0; i < m_sources.size(); ++i)
    {
        if (RevoluteJoint* joint = m_sources[i])
        {
            const RevoluteJointGroup& g = m_groups[i / kLanes];
            const int l = static_cast<int>(i % kLanes);
            joint->impulse = {g.impulse.x[l], g.impulse.y[l]};
        }
    }
}

bool ColoredJointSolver::SolvePositions(Position* positions, const Tolerances& tolerances)
{
    RealW largestSquared = Splat(0);
    for (const RevoluteJointGroup& group : m_groups)
    {
        largestSquared = MaxW(largestSquared, SolvePositionGroup(group, positions));
    }
    Real largest = 0;
    for (int l = 0; l < kLanes; ++l)
    {
        largest = Max(largest, largestSquared[l]);
    }
    // √ is monotonic and correctly rounded, so √(max |C|²) is the largest |C| exactly.
    return std::sqrt(largest) <= tolerances.linearSlop;
}

} // namespace meff::detail
