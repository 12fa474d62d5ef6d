// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
#include "solvers/soft_step/soft_contact_solver.h"

#include "solvers/soft_step/soft_contact_direct.h"

#include "model/body.h"
#include "model/contact.h"
#include "tasks/parallel_ranges.h"

namespace meff::detail
{

namespace
{

RowBodies LoadBodies(const SoftContact& c, const SoftStepContext& context)
{
    return LoadRowBodies(context.bodies->velocities.data(), c.indexA, c.indexB, c.mA, c.iA, c.mB,
                         c.iB);
}

void StoreBodies(const SoftContact& c, const RowBodies& b, const SoftStepContext& context)
{
    StoreRowBodies(context.bodies->velocities.data(), c.indexA, c.indexB, b);
}

Vec2 Tangent(Vec2 normal)
{
    return Cross(normal, Real(1));
}

/// A point's separation + slop now (m): the normal row's C with SoftStepContext::rowSlop, the
/// position correction's with linearSlop.
Real NormalError(const SoftContact& c, const SoftContactPoint& p, const SoftDelta& dA,
                 const SoftDelta& dB, Real slop)
{
    return SeparationOf(p.baseSeparation, c.normal, dA.dp, dA.dq, dB.dp, dB.dq, p.rA, p.rB, slop);
}

/// Turns a body's rotation dq further by `angle` (rad).
void Turn(SoftDelta& d, Real angle)
{
    d.dq = Mul(SmallRotation(angle), d.dq);
}

/// What a prepared contact asks of the step after its sub-steps (bits of
/// SoftContactSolver::m_needsOfWorker).
enum ContactNeeds : std::uint8_t
{
    kNeedsHitEvents = 1,   ///< it asked for hit events
    kNeedsRestitution = 2, ///< its restitution is not zero
};

/// The rows of island contact k at the bodies' poses of the step's start; returns what the
/// contact needs after the sub-steps (ContactNeeds).
std::uint8_t PrepareContact(const IslandContacts& island, std::size_t k, Real warmScale,
                            const SoftStepContext& context, SoftContact& c)
{
    const std::int32_t contactIndex = island.contactIndices[k];
    const Contact& contact = island.contacts[contactIndex];
    const Body& bodyA = island.bodies[contact.bodyA];
    const Body& bodyB = island.bodies[contact.bodyB];
    c.contactIndex = contactIndex;
    c.indexA = bodyA.islandIndex;
    c.indexB = bodyB.islandIndex;
    c.mA = bodyA.invMass;
    c.iA = bodyA.invI;
    c.mB = bodyB.invMass;
    c.iB = bodyB.invI;
    c.friction = contact.friction;
    c.restitution = contact.restitution;
    c.threshold = contact.restitutionThreshold;
    c.tangentSpeed = contact.tangentSpeed;
    c.rollingResistance = contact.rollingResistance;
    c.rollingImpulse = c.totalRollingImpulse = 0;
    if (c.rollingResistance > 0)
    {
        c.rollingMass = RowMass(c.iA + c.iB);
        c.rollingImpulse = warmScale * contact.rollingImpulse;
    }
    const bool againstFixed = (c.mA == 0 && c.iA == 0) || (c.mB == 0 && c.iB == 0);
    c.softness = againstFixed ? context.staticContact : context.contact;

    const Manifold& manifold = contact.manifold;
    WorldManifold wm;
    wm.Initialize(manifold, bodyA.xf, contact.radiusA, bodyB.xf, contact.radiusB);
    c.normal = wm.normal;
    c.pointCount = manifold.pointCount;
    const Vec2 tangent = Tangent(c.normal);
    const RowBodies masses{{}, 0, {}, 0, c.mA, c.iA, c.mB, c.iB};
    RowJacobian normalRows[2];
    for (int j = 0; j < c.pointCount; ++j)
    {
        SoftContactPoint& p = c.points[j];
        p.rA = wm.points[j] - bodyA.sweep.c;
        p.rB = wm.points[j] - bodyB.sweep.c;
        p.baseSeparation = wm.separations[j] - Dot(p.rB - p.rA, c.normal);
        normalRows[j] = PointRow(c.normal, p.rA, p.rB);
        p.normalMass = RowMass(InverseEffectiveMass(normalRows[j], masses));
        p.tangentMass = RowMass(InverseEffectiveMass(PointRow(tangent, p.rA, p.rB), masses));
        p.normalImpulse = warmScale * manifold.points[j].normalImpulse;
        p.tangentImpulse = warmScale * manifold.points[j].tangentImpulse;
        p.totalNormalImpulse = 0;
        p.totalTangentImpulse = 0;
        // The approach speed before the step: restitution's vn and the hit events'.
        const Vec2 vA = bodyA.linearVelocity + Cross(bodyA.angularVelocity, p.rA);
        const Vec2 vB = bodyB.linearVelocity + Cross(bodyB.angularVelocity, p.rB);
        p.relativeVelocity = Dot(vB - vA, c.normal);
    }
    // The two normal rows' block K (its diagonal the rows' scalar k), unless they are
    // nearly parallel (Box2D's condition test): then the points go one by one.
    c.block = false;
    if (c.pointCount == 2 && context.blockSolver)
    {
        const RowJacobian& J1 = normalRows[0];
        const RowJacobian& J2 = normalRows[1];
        const Real k11 = InverseEffectiveMass(J1, masses);
        const Real k22 = InverseEffectiveMass(J2, masses);
        const Real k12 = RowCoupling(J1.aA, J1.aB, J2.aA, J2.aB, c.mA, c.iA, c.mB, c.iB);
        if (k11 * k11 < kMaxConditionNumber * (k11 * k22 - k12 * k12))
        {
            c.K.ex = {k11, k12};
            c.K.ey = {k12, k22};
            c.invK = c.K.GetInverse();
            c.block = true;
        }
    }
    return static_cast<std::uint8_t>(
        ((contact.flags & Contact::HitEvents) != 0 ? kNeedsHitEvents : 0) |
        (c.restitution != 0 ? kNeedsRestitution : 0));
}

} // namespace

SoftContactSolver::SoftContactSolver() : m_direct(std::make_unique<SoftContactDirect>()) {}

SoftContactSolver::~SoftContactSolver() = default;

void SoftContactSolver::Prepare(const IslandContacts& island, const SoftStepContext& context)
{
    const StepContext& step = *context.step;
    const std::size_t count = island.contactIndices.size();
    m_contacts.resize(count);
    // Stored impulses are per step; the rows work per sub-step.
    const Real warmScale =
        step.solver.warmStarting ? step.dtRatio / Real(context.substeps) : Real(0);
    const std::int32_t bodyCount = context.bodies->DiscardIndex();
    // Each contact's rows are its own: any thread may take any range of them. The colouring
    // reads only the island, so one thread colours while the others prepare.
    m_needsOfWorker.assign(static_cast<std::size_t>(WorkerCount(context.tasks)), 0);
    ForRangesBeside(
        context.tasks, static_cast<int>(count), kMinSoftContactsPerTask,
        [&] { m_lanes.Colour(island, bodyCount); },
        [&](int begin, int end, int worker)
        {
            std::uint8_t needs = 0;
            for (auto k = static_cast<std::size_t>(begin); k < static_cast<std::size_t>(end); ++k)
            {
                needs |= PrepareContact(island, k, warmScale, context, m_contacts[k]);
            }
            m_needsOfWorker[static_cast<std::size_t>(worker)] |= needs;
        });
    std::uint8_t needs = 0;
    for (const std::uint8_t n : m_needsOfWorker)
    {
        needs |= n;
    }
    m_anyHitEvents = (needs & kNeedsHitEvents) != 0;
    m_anyRestitution = (needs & kNeedsRestitution) != 0;
    m_lanes.Pack(m_contacts, bodyCount, context.tasks);
    // An island small enough to go row by row: its groups of touching bodies are solved
    // together (heavy on light).
    if (context.contactModel == SoftContactModel::Rigid && m_lanes.Overflow().size() == count)
    {
        m_direct->Prepare(m_contacts, bodyCount, m_isDirect);
    }
    else
    {
        m_direct->Prepare({}, 0, m_isDirect);
        m_isDirect.assign(count, 0);
    }
}

void SoftContactSolver::WarmStart(const SoftStepContext& context)
{
    m_lanes.WarmStart(context);
    for (const std::int32_t k : m_lanes.Overflow())
    {
        WarmStartContact(m_contacts[k], context);
    }
}

void SoftContactSolver::WarmStartContact(SoftContact& c, const SoftStepContext& context)
{
    RowBodies b = LoadBodies(c, context);
    const Vec2 tangent = Tangent(c.normal);
    for (int j = 0; j < c.pointCount; ++j)
    {
        SoftContactPoint& p = c.points[j];
        ApplyPointImpulse(p.normalImpulse * c.normal + p.tangentImpulse * tangent, p.rA, p.rB, b);
        p.totalNormalImpulse += p.normalImpulse;
        p.totalTangentImpulse += p.tangentImpulse;
    }
    b.wA -= c.iA * c.rollingImpulse;
    b.wB += c.iB * c.rollingImpulse;
    c.totalRollingImpulse += c.rollingImpulse;
    StoreBodies(c, b, context);
}

void SoftContactSolver::SolveNormalRows(SoftContact& c, RowBodies& b,
                                        const SoftStepContext& context, bool useBias)
{
    const Real slop = context.rowSlop;
    const SoftDelta& dA = context.bodies->deltas[c.indexA];
    const SoftDelta& dB = context.bodies->deltas[c.indexB];
    // Rigid contacts leave the overlap to CorrectPositions; soft ones push it out here.
    const bool pushOut = useBias && context.contactModel == SoftContactModel::Soft;
    RowTarget targets[2];
    bool allRigid = true;
    for (int j = 0; j < c.pointCount; ++j)
    {
        const Real C = NormalError(c, c.points[j], dA, dB, slop);
        targets[j] = OneSidedTarget(C, pushOut, c.softness, context.invH, context.maxPushOut);
        allRigid =
            allRigid && targets[j].softness.massScale == 1 && targets[j].softness.impulseScale == 0;
    }
    if (c.block && allRigid)
    {
        SoftContactPoint& p1 = c.points[0];
        SoftContactPoint& p2 = c.points[1];
        const RowJacobian J1 = PointRow(c.normal, p1.rA, p1.rB);
        const RowJacobian J2 = PointRow(c.normal, p2.rA, p2.rB);
        const Vec2 a{p1.normalImpulse, p2.normalImpulse};
        const Vec2 v{RowVelocity(J1, b) + targets[0].bias, RowVelocity(J2, b) + targets[1].bias};
        Vec2 x;
        if (SolveTwoPointBlock(c.K, c.invK, p1.normalMass, p2.normalMass, v - Mul(c.K, a), x))
        {
            const Vec2 applied = x - a;
            ApplyRowImpulse(J1, applied.x, b);
            ApplyRowImpulse(J2, applied.y, b);
            p1.normalImpulse = x.x;
            p2.normalImpulse = x.y;
            p1.totalNormalImpulse += applied.x;
            p2.totalNormalImpulse += applied.y;
        }
        return;
    }
    for (int j = 0; j < c.pointCount; ++j)
    {
        SoftContactPoint& p = c.points[j];
        p.totalNormalImpulse += SolveRow(PointRow(c.normal, p.rA, p.rB), p.normalMass, targets[j],
                                         p.normalImpulse, b, 0, kMaxReal);
    }
}

void SoftContactSolver::Solve(const SoftStepContext& context, bool useBias)
{
    m_lanes.Solve(context, useBias);
    if (m_direct->Empty())
    {
        for (const std::int32_t k : m_lanes.Overflow())
        {
            SolveContact(m_contacts[k], context, useBias);
        }
        return;
    }
    // The groups' normal rows first, then every contact's friction (and the normal rows of the
    // contacts in no group, or in a group that did not converge).
    m_fallback.clear();
    m_direct->Solve(m_contacts, context, m_fallback);
    for (const std::int32_t k : m_fallback)
    {
        m_isDirect[k] = 0;
    }
    for (const std::int32_t k : m_lanes.Overflow())
    {
        SolveContact(m_contacts[k], context, useBias, m_isDirect[k] == 0);
    }
    for (const std::int32_t k : m_fallback)
    {
        m_isDirect[k] = 1;
    }
}

void SoftContactSolver::SolveContact(SoftContact& c, const SoftStepContext& context, bool useBias,
                                     bool normals)
{
    const bool friction = !useBias || context.frictionInSolve;
    RowBodies b = LoadBodies(c, context);
    // Normal rows first, so that friction is bounded by this sweep's normal impulses.
    if (normals)
    {
        SolveNormalRows(c, b, context, useBias);
    }
    if (friction && c.friction > 0)
    {
        const Vec2 tangent = Tangent(c.normal);
        // Rigid, driven to the conveyor's speed: J·v + bias = vt − s → 0.
        const RowTarget conveyor{-c.tangentSpeed, kRigid};
        for (int j = 0; j < c.pointCount; ++j)
        {
            SoftContactPoint& p = c.points[j];
            const Real maxFriction = c.friction * p.normalImpulse;
            p.totalTangentImpulse +=
                SolveRow(PointRow(tangent, p.rA, p.rB), p.tangentMass, conveyor, p.tangentImpulse,
                         b, -maxFriction, maxFriction);
        }
    }
    if (friction && c.rollingResistance > 0)
    {
        const Real normal =
            c.points[0].normalImpulse + (c.pointCount > 1 ? c.points[1].normalImpulse : Real(0));
        const Real lambda = SolveRollingRow(c.rollingMass, c.rollingResistance, normal, b.wA, b.wB,
                                            c.rollingImpulse);
        b.wA -= c.iA * lambda;
        b.wB += c.iB * lambda;
        c.totalRollingImpulse += lambda;
    }
    StoreBodies(c, b, context);
}

void SoftContactSolver::CorrectPositions(const SoftStepContext& context)
{
    m_lanes.CorrectPositions(context);
    for (const std::int32_t k : m_lanes.Overflow())
    {
        CorrectContact(m_contacts[k], context);
    }
    m_lanes.BodiesMoved();
}

void SoftContactSolver::CorrectContact(const SoftContact& c, const SoftStepContext& context)
{
    const Real slop = context.step->tolerances.linearSlop;
    const Real maxCorrection = context.maxPushOut * context.h;
    std::vector<SoftDelta>& deltas = context.bodies->deltas;
    SoftDelta& dA = deltas[c.indexA];
    SoftDelta& dB = deltas[c.indexB];
    for (int j = 0; j < c.pointCount; ++j)
    {
        const SoftContactPoint& p = c.points[j];
        // Non-linear Gauss-Seidel on the separation: each point sees the last one's move.
        const Real C = Clamp(context.contactCorrection * NormalError(c, p, dA, dB, slop),
                             -maxCorrection, Real(0));
        if (C == 0)
        {
            continue;
        }
        const Vec2 rA = Mul(dA.dq, p.rA);
        const Vec2 rB = Mul(dB.dq, p.rB);
        const RowBodies masses{{}, 0, {}, 0, c.mA, c.iA, c.mB, c.iB};
        const RowJacobian J = PointRow(c.normal, rA, rB);
        const Real lambda = -C * RowMass(InverseEffectiveMass(J, masses));
        const Vec2 P = lambda * c.normal;
        dA.dp -= c.mA * P;
        Turn(dA, -c.iA * lambda * J.aA);
        dB.dp += c.mB * P;
        Turn(dB, c.iB * lambda * J.aB);
    }
}

void SoftContactSolver::Restitution(const SoftStepContext& context)
{
    // Without restitution the lanes' impulses stay in the lanes, and Store reads them there:
    // copying them into the contacts first would write every contact once more.
    m_lanesCollected = m_anyRestitution;
    if (!m_anyRestitution)
    {
        return;
    }
    m_lanes.Collect(m_contacts);
    for (SoftContact& c : m_contacts)
    {
        if (c.restitution == 0)
        {
            continue;
        }
        RowBodies b = LoadBodies(c, context);
        for (int j = 0; j < c.pointCount; ++j)
        {
            SoftContactPoint& p = c.points[j];
            // Only points that approached fast enough and were pushed bounce.
            if (p.relativeVelocity > -c.threshold || p.totalNormalImpulse <= 0)
            {
                continue;
            }
            const RowTarget target{c.restitution * p.relativeVelocity, kRigid};
            p.totalNormalImpulse += SolveRow(PointRow(c.normal, p.rA, p.rB), p.normalMass, target,
                                             p.normalImpulse, b, 0, kMaxReal);
        }
        StoreBodies(c, b, context);
    }
}

void SoftContactSolver::ScaleImpulses(Real factor)
{
    m_lanes.ScaleImpulses(factor);
    for (const std::int32_t k : m_lanes.Overflow())
    {
        SoftContact& c = m_contacts[k];
        for (int j = 0; j < c.pointCount; ++j)
        {
            c.points[j].normalImpulse *= factor;
            c.points[j].tangentImpulse *= factor;
        }
        c.rollingImpulse *= factor;
    }
}

void SoftContactSolver::SaveImpulses()
{
    m_lanes.SaveImpulses();
    m_saved.clear();
    m_savedRolling.clear();
    for (const std::int32_t k : m_lanes.Overflow())
    {
        const SoftContact& c = m_contacts[k];
        m_savedRolling.push_back(c.rollingImpulse);
        for (int j = 0; j < c.pointCount; ++j)
        {
            m_saved.push_back({c.points[j].normalImpulse, c.points[j].tangentImpulse});
        }
    }
}

void SoftContactSolver::RestoreImpulses()
{
    m_lanes.RestoreImpulses();
    std::size_t i = 0;
    const std::span<const std::int32_t> overflow = m_lanes.Overflow();
    for (std::size_t o = 0; o < overflow.size(); ++o)
    {
        SoftContact& c = m_contacts[overflow[o]];
        c.rollingImpulse = m_savedRolling[o];
        for (int j = 0; j < c.pointCount; ++j, ++i)
        {
            c.points[j].normalImpulse = m_saved[i].x;
            c.points[j].tangentImpulse = m_saved[i].y;
        }
    }
}

void SetImpulses(SoftContact& c, const SoftContactImpulses& impulses)
{
    c.rollingImpulse = impulses.rolling;
    c.totalRollingImpulse = impulses.totalRolling;
    for (int j = 0; j < c.pointCount; ++j)
    {
        SoftContactPoint& p = c.points[j];
        p.normalImpulse = impulses.normal[j];
        p.tangentImpulse = impulses.tangent[j];
        p.totalNormalImpulse = impulses.totalNormal[j];
        p.totalTangentImpulse = impulses.totalTangent[j];
    }
}

namespace
{

/// The impulses a scalar row holds (the overflow's, or every contact's once collected).
SoftContactImpulses ImpulsesOf(const SoftContact& c)
{
    SoftContactImpulses impulses{};
    for (int j = 0; j < c.pointCount; ++j)
    {
        const SoftContactPoint& p = c.points[j];
        impulses.normal[j] = p.normalImpulse;
        impulses.tangent[j] = p.tangentImpulse;
        impulses.totalNormal[j] = p.totalNormalImpulse;
        impulses.totalTangent[j] = p.totalTangentImpulse;
    }
    impulses.rolling = c.rollingImpulse;
    impulses.totalRolling = c.totalRollingImpulse;
    return impulses;
}

/// Contact c's sub-step impulses × perStep into its manifold (next step's warm start), and its
/// step's totals into `solved`.
void StoreContact(const SoftContact& c, const SoftContactImpulses& impulses, Real perStep,
                  Contact& contact, SolvedContact& solved)
{
    solved.contactIndex = c.contactIndex;
    solved.pointCount = c.pointCount;
    solved.rollingImpulse = impulses.totalRolling;
    contact.rollingImpulse = perStep * impulses.rolling;
    Manifold& manifold = contact.manifold;
    for (int j = 0; j < c.pointCount; ++j)
    {
        manifold.points[j].normalImpulse = perStep * impulses.normal[j];
        manifold.points[j].tangentImpulse = perStep * impulses.tangent[j];
        solved.normalImpulse[j] = impulses.totalNormal[j];
        solved.tangentImpulse[j] = impulses.totalTangent[j];
        solved.normalVelocity[j] = c.points[j].relativeVelocity;
    }
}

} // namespace

void SoftContactSolver::Store(std::span<Contact> contacts, const SoftStepContext& context)
{
    m_solved.resize(m_contacts.size());
    const Real perStep = Real(context.substeps);
    const auto store = [&](std::int32_t k, const SoftContactImpulses& impulses)
    {
        const SoftContact& c = m_contacts[static_cast<std::size_t>(k)];
        StoreContact(c, impulses, perStep, contacts[c.contactIndex],
                     m_solved[static_cast<std::size_t>(k)]);
    };
    // Each row writes its own contact and its own SolvedContact.
    if (m_lanesCollected)
    {
        ForEachIndex(context.tasks, static_cast<int>(m_contacts.size()), kMinSoftContactsPerTask,
                     [&](int k) { store(k, ImpulsesOf(m_contacts[static_cast<std::size_t>(k)])); });
        return;
    }
    m_lanes.ForEachLaneImpulses(store);
    const std::span<const std::int32_t> overflow = m_lanes.Overflow();
    ForEachIndex(context.tasks, static_cast<int>(overflow.size()), kMinSoftContactsPerTask,
                 [&](int o)
                 {
                     const std::int32_t k = overflow[static_cast<std::size_t>(o)];
                     store(k, ImpulsesOf(m_contacts[static_cast<std::size_t>(k)]));
                 });
}

} // namespace meff::detail
