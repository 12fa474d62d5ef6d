#include "solvers/colour/revolute_lanes.h"

#include "joints/joint.h"
#include "solvers/lanes/lane_bodies.h"

#include <algorithm>
#include <cmath>

namespace meff::detail
{

namespace
{

/// Copies what the lanes need of one joint whose bodies are stored (StoreJointBodies).
void PackLane(RevoluteJointGroup& g, int l, RevoluteJoint& joint, std::int32_t discardIndex)
{
    PackLaneBodies(g, l, joint, discardIndex);
    g.impulse.x[l] = joint.impulse.x;
    g.impulse.y[l] = joint.impulse.y;
    const Vec2 anchorA = joint.localAnchorA - joint.localCenterA;
    const Vec2 anchorB = joint.localAnchorB - joint.localCenterB;
    g.anchorA.x[l] = anchorA.x;
    g.anchorA.y[l] = anchorA.y;
    g.anchorB.x[l] = anchorB.x;
    g.anchorB.y[l] = anchorB.y;
    // No motor, no limit and no spring: their impulses are zero (as InitVelocityConstraints
    // leaves them), so that the joint's reaction torque is zero too.
    joint.motorImpulse = 0;
    joint.lowerImpulse = 0;
    joint.upperImpulse = 0;
    joint.springImpulse = 0;
}

/// RevoluteJoint's InitVelocityConstraints for kLanes joints: lever arms at the step's start,
/// the point rows' K = J·M⁻¹·Jᵀ and its inverse determinant (K is fixed over the velocity
/// iterations, so it is inverted once here, not in every Mat22::Solve), then the warm start.
void PrepareGroup(RevoluteJointGroup& g, const SolverData& data)
{
    const RealW aA = Gather(data.positions, g.indexA).angular;
    const RealW aB = Gather(data.positions, g.indexB).angular;
    g.rA = Mul(SinCosW(aA), g.anchorA);
    g.rB = Mul(SinCosW(aB), g.anchorB);
    const Vec2W rA = g.rA, rB = g.rB;
    const RealW mA = g.invMassA, mB = g.invMassB, iA = g.invIA, iB = g.invIB;
    g.k11 = mA + mB + rA.y * rA.y * iA + rB.y * rB.y * iB;
    g.k12 = -rA.y * rA.x * iA - rB.y * rB.x * iB;
    g.k21 = g.k12;
    g.k22 = mA + mB + rA.x * rA.x * iA + rB.x * rB.x * iB;
    g.invDetK = InverseDeterminant(g.k11, g.k12, g.k21, g.k22);

    if (data.step.solver.warmStarting)
    {
        // Impulses are force·dt: rescale last step's to this step's dt.
        g.impulse = Splat(data.step.dtRatio) * g.impulse;
        BodyStateW a = Gather(data.velocities, g.indexA);
        BodyStateW b = Gather(data.velocities, g.indexB);
        ApplyImpulseW({mA, iA, mB, iB}, a, b, rA, rB, g.impulse);
        Scatter(data.velocities, g.storeA, a);
        Scatter(data.velocities, g.storeB, b);
    }
    else
    {
        g.impulse = Vec2W{};
    }
}

/// x = K⁻¹·b for the lanes' 2×2 K, as Mat22::Solve (0 where det K = 0).
[[gnu::always_inline]] inline Vec2W SolveK(RealW k11, RealW k12, RealW k21, RealW k22, RealW invDet,
                                           Vec2W b)
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
    const Vec2W x = SolveK(k11, k12, k12, k22, InverseDeterminant(k11, k12, k12, k22), C);
    ApplyImpulseW({mA, iA, mB, iB}, a, b, rA, rB, Vec2W{-x.x, -x.y});
    Scatter(positions, g.storeA, a);
    Scatter(positions, g.storeB, b);
    return C.x * C.x + C.y * C.y;
}

} // namespace

void RevoluteLanes::Prepare(std::span<RevoluteJoint* const> joints,
                            std::span<const ConstraintBodies> bodies, const SolverData& data)
{
    // The island's bodies are the solver indices below the discard slot.
    const std::int32_t discardIndex = data.discardIndex;
    ColourConstraints(
        joints.size(), static_cast<std::size_t>(discardIndex),
        [&](std::size_t i) { return bodies[i]; }, m_colouring);
    m_groups.clear();
    m_sources.clear();
    for (int colour = 0; colour < m_colouring.ColourCount(); ++colour)
    {
        const std::int32_t begin = m_colouring.colourStarts[colour];
        const std::int32_t end = m_colouring.colourStarts[colour + 1];
        for (std::int32_t first = begin; first < end; first += kLanes)
        {
            // Empty lanes read body 0 and write the discard slot; all their masses are zero.
            RevoluteJointGroup& g = m_groups.emplace_back(RevoluteJointGroup{});
            std::fill(std::begin(g.storeA), std::end(g.storeA), discardIndex);
            std::fill(std::begin(g.storeB), std::end(g.storeB), discardIndex);
            for (int l = 0; l < kLanes; ++l)
            {
                RevoluteJoint* joint =
                    first + l < end ? joints[m_colouring.order[first + l]] : nullptr;
                m_sources.push_back(joint);
                if (joint != nullptr)
                {
                    PackLane(g, l, *joint, discardIndex);
                }
            }
            PrepareGroup(g, data);
        }
    }
}

void RevoluteLanes::SolveVelocities(Velocity* velocities)
{
    for (RevoluteJointGroup& group : m_groups)
    {
        SolveVelocityGroup(group, velocities);
    }
}

void RevoluteLanes::StoreImpulses() const
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

bool RevoluteLanes::SolvePositions(Position* positions, const Tolerances& tolerances)
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
