// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The rigid contact rows every back end uses (shared/contact_constraint.h): Box2D 2.4.1's
// preparation, warm start, sequential-impulse update and position correction of one contact,
// which the Box2D back end runs in island order, the colour back end on its overflow and the
// soft step on its rigid contacts.
#include "solvers/shared/contact_constraint.h"

#include "model/body.h"
#include "model/contact.h"

namespace meff::detail
{

namespace
{

/// The scalar effective mass of one row along direction n (seed: 1/m_eff = Σ 1/m + (r×n)²/I).
Real InverseEffectiveMass(Real mA, Real mB, Real iA, Real iB, Vec2 rA, Vec2 rB, Vec2 n)
{
    const Real rnA = Cross(rA, n);
    const Real rnB = Cross(rB, n);
    return mA + mB + iA * rnA * rnA + iB * rnB * rnB;
}

/// Relative velocity of B's contact point with respect to A's.
Vec2 RelativeVelocity(Vec2 vA, Real wA, Vec2 vB, Real wB, const ContactVelocityPoint& p)
{
    return vB + Cross(wB, p.rB) - vA - Cross(wA, p.rA);
}

/// The body transform from the solver's centre of mass and rotation.
Transform TransformFromCenter(Vec2 c, Rot q, Vec2 localCenter)
{
    Transform xf;
    xf.q = q;
    xf.p = c - Mul(q, localCenter);
    return xf;
}

/// A constraint's two bodies: their solver indices, inverse masses (1/kg) and inverse
/// inertias (1/(kg·m²)). The velocity and position constraints name these members alike.
template <typename Constraint>
void SetBodies(Constraint& c, const Body& bodyA, const Body& bodyB)
{
    c.indexA = bodyA.islandIndex;
    c.indexB = bodyB.islandIndex;
    c.invMassA = bodyA.invMass;
    c.invMassB = bodyB.invMass;
    c.invIA = bodyA.invI;
    c.invIB = bodyB.invI;
}

} // namespace

/// Applies one contact's accumulated impulses of last step (scaled in Prepare).
void WarmStartConstraint(const ContactVelocityConstraint& vc, Velocity* velocities)
{
    Velocity& a = velocities[vc.indexA];
    Velocity& b = velocities[vc.indexB];
    Vec2 vA = a.v, vB = b.v;
    Real wA = a.w, wB = b.w;
    const Vec2 tangent = Cross(vc.normal, Real(1));
    for (int j = 0; j < vc.pointCount; ++j)
    {
        const ContactVelocityPoint& vp = vc.points[j];
        const Vec2 P = vp.normalImpulse * vc.normal + vp.tangentImpulse * tangent;
        wA -= vc.invIA * Cross(vp.rA, P);
        vA -= vc.invMassA * P;
        wB += vc.invIB * Cross(vp.rB, P);
        vB += vc.invMassB * P;
    }
    if (vc.rollingResistance > 0)
    {
        wA -= vc.invIA * vc.rollingImpulse;
        wB += vc.invIB * vc.rollingImpulse;
    }
    a.v = vA;
    a.w = wA;
    b.v = vB;
    b.w = wB;
}

bool PrepareContactConstraint(const IslandContacts& island, std::size_t k, const SolverData& data,
                              ContactVelocityConstraint& vc, ContactPositionConstraint& pc)
{
    const bool warmStarting = data.step.solver.warmStarting;
    const bool blockSolver = data.step.solver.blockSolver;
    const std::int32_t contactIndex = island.contactIndices[k];
    const Contact& contact = island.contacts[contactIndex];
    const Body& bodyA = island.bodies[contact.bodyA];
    const Body& bodyB = island.bodies[contact.bodyB];
    const Manifold& manifold = contact.manifold;

    vc.friction = contact.friction;
    vc.restitution = contact.restitution;
    vc.threshold = contact.restitutionThreshold;
    vc.tangentSpeed = contact.tangentSpeed;
    vc.rollingResistance = contact.rollingResistance;
    vc.rollingImpulse = 0;
    if (vc.rollingResistance > 0)
    {
        const Real k = bodyA.invI + bodyB.invI;
        vc.rollingMass = k > 0 ? Real(1) / k : Real(0);
        vc.rollingImpulse = warmStarting ? data.step.dtRatio * contact.rollingImpulse : Real(0);
    }
    SetBodies(vc, bodyA, bodyB);
    vc.contactIndex = contactIndex;
    vc.pointCount = manifold.pointCount;
    vc.K = Mat22{{0, 0}, {0, 0}};
    vc.normalMass = Mat22{{0, 0}, {0, 0}};

    SetBodies(pc, bodyA, bodyB);
    pc.localCenterA = bodyA.sweep.localCenter;
    pc.localCenterB = bodyB.sweep.localCenter;
    pc.localNormal = manifold.localNormal;
    pc.localPoint = manifold.localPoint;
    pc.type = manifold.type;
    pc.radiusA = contact.radiusA;
    pc.radiusB = contact.radiusB;
    pc.pointCount = manifold.pointCount;

    for (int j = 0; j < manifold.pointCount; ++j)
    {
        const ManifoldPoint& mp = manifold.points[j];
        ContactVelocityPoint& vp = vc.points[j];
        // Impulses are scaled by dt/dt0 so that a changed step size keeps the same force.
        vp.normalImpulse = warmStarting ? data.step.dtRatio * mp.normalImpulse : Real(0);
        vp.tangentImpulse = warmStarting ? data.step.dtRatio * mp.tangentImpulse : Real(0);
        pc.localPoints[j] = mp.localPoint;
    }

    // Position-dependent part: lever arms, effective masses, restitution bias.
    const Real mA = vc.invMassA, mB = vc.invMassB, iA = vc.invIA, iB = vc.invIB;
    const Vec2 cA = data.positions[vc.indexA].c;
    const Vec2 cB = data.positions[vc.indexB].c;
    const Transform xfA =
        TransformFromCenter(cA, Rot(data.positions[vc.indexA].a), pc.localCenterA);
    const Transform xfB =
        TransformFromCenter(cB, Rot(data.positions[vc.indexB].a), pc.localCenterB);
    WorldManifold worldManifold;
    worldManifold.Initialize(manifold, xfA, pc.radiusA, xfB, pc.radiusB);
    vc.normal = worldManifold.normal;
    const Vec2 tangent = Cross(vc.normal, Real(1));
    // The approach velocity for restitution: this step's (gravity already added, as Box2D)
    // or the bodies' velocities at the start of the step (see restitutionFromStepStart).
    const bool fromStepStart = data.step.solver.restitutionFromStepStart;
    const Velocity velA = fromStepStart ? Velocity{bodyA.linearVelocity, bodyA.angularVelocity}
                                        : data.velocities[vc.indexA];
    const Velocity velB = fromStepStart ? Velocity{bodyB.linearVelocity, bodyB.angularVelocity}
                                        : data.velocities[vc.indexB];

    for (int j = 0; j < vc.pointCount; ++j)
    {
        ContactVelocityPoint& vp = vc.points[j];
        vp.rA = worldManifold.points[j] - cA;
        vp.rB = worldManifold.points[j] - cB;
        const Real kNormal = InverseEffectiveMass(mA, mB, iA, iB, vp.rA, vp.rB, vc.normal);
        vp.normalMass = kNormal > 0 ? Real(1) / kNormal : Real(0);
        const Real kTangent = InverseEffectiveMass(mA, mB, iA, iB, vp.rA, vp.rB, tangent);
        vp.tangentMass = kTangent > 0 ? Real(1) / kTangent : Real(0);

        // Restitution (seed: P = (1+e)(u2−u1)·m_red): driving the normal row to the target
        // velocity −e·vn instead of 0 makes the impulse (1+e)·m_red·|vn|.
        vp.velocityBias = 0;
        const Real vRel = Dot(vc.normal, RelativeVelocity(velA.v, velA.w, velB.v, velB.w, vp));
        vp.normalVelocity = vRel;
        if (vRel < -vc.threshold)
        {
            vp.velocityBias = -vc.restitution * vRel;
        }
    }

    if (vc.pointCount == 2 && blockSolver)
    {
        const ContactVelocityPoint& p1 = vc.points[0];
        const ContactVelocityPoint& p2 = vc.points[1];
        const Real rn1A = Cross(p1.rA, vc.normal), rn1B = Cross(p1.rB, vc.normal);
        const Real rn2A = Cross(p2.rA, vc.normal), rn2B = Cross(p2.rB, vc.normal);
        const Real k11 = mA + mB + iA * rn1A * rn1A + iB * rn1B * rn1B;
        const Real k22 = mA + mB + iA * rn2A * rn2A + iB * rn2B * rn2B;
        const Real k12 = mA + mB + iA * rn1A * rn2A + iB * rn1B * rn2B;
        if (k11 * k11 < kMaxConditionNumber * (k11 * k22 - k12 * k12))
        {
            vc.K.ex = {k11, k12};
            vc.K.ey = {k12, k22};
            vc.normalMass = vc.K.GetInverse();
        }
        else
        {
            // Redundant rows: solve only the first point (as Box2D; the second keeps its
            // stored impulse and is not reported this step).
            vc.pointCount = 1;
        }
    }
    return (contact.flags & Contact::HitEvents) != 0;
}

namespace
{

// The two normal rows as one linear complementarity problem (SolveTwoPointBlock); x is the
// total accumulated impulse, so b is corrected by K·a for the impulse a already applied.
void SolveNormalBlock(ContactVelocityConstraint& vc, Vec2& vA, Real& wA, Vec2& vB, Real& wB)
{
    ContactVelocityPoint& p1 = vc.points[0];
    ContactVelocityPoint& p2 = vc.points[1];
    const Vec2 normal = vc.normal;
    const Vec2 a{p1.normalImpulse, p2.normalImpulse};

    const Real vn1 = Dot(RelativeVelocity(vA, wA, vB, wB, p1), normal);
    const Real vn2 = Dot(RelativeVelocity(vA, wA, vB, wB, p2), normal);
    Vec2 b{vn1 - p1.velocityBias, vn2 - p2.velocityBias};
    b -= Mul(vc.K, a);

    const auto apply = [&](Vec2 x)
    {
        const Vec2 d = x - a;
        const Vec2 P1 = d.x * normal;
        const Vec2 P2 = d.y * normal;
        vA -= vc.invMassA * (P1 + P2);
        wA -= vc.invIA * (Cross(p1.rA, P1) + Cross(p2.rA, P2));
        vB += vc.invMassB * (P1 + P2);
        wB += vc.invIB * (Cross(p1.rB, P1) + Cross(p2.rB, P2));
        p1.normalImpulse = x.x;
        p2.normalImpulse = x.y;
    };

    Vec2 x;
    if (SolveTwoPointBlock(vc.K, vc.normalMass, p1.normalMass, p2.normalMass, b, x))
    {
        apply(x);
    }
    // Otherwise no case holds (rare, from round-off): the impulses stay as they are.
}

} // namespace

void SolveVelocityConstraint(ContactVelocityConstraint& vc, Velocity* velocities, bool blockSolver)
{
    Velocity& a = velocities[vc.indexA];
    Velocity& b = velocities[vc.indexB];
    Vec2 vA = a.v, vB = b.v;
    Real wA = a.w, wB = b.w;
    const Real mA = vc.invMassA, mB = vc.invMassB, iA = vc.invIA, iB = vc.invIB;
    const Vec2 normal = vc.normal;
    const Vec2 tangent = Cross(normal, Real(1));
    // Impulse P at the point: −P to A, +P to B.
    const auto applyAtPoint = [&](const ContactVelocityPoint& vp, Vec2 P)
    {
        vA -= mA * P;
        wA -= iA * Cross(vp.rA, P);
        vB += mB * P;
        wB += iB * Cross(vp.rB, P);
    };

    // Friction rows first: non-penetration, solved last, matters more.
    // A scene with friction 0 pays nothing for them.
    if (vc.friction > 0)
    {
        for (int j = 0; j < vc.pointCount; ++j)
        {
            ContactVelocityPoint& vp = vc.points[j];
            // A conveyor's row drives vt to the belt's speed; x − 0 is x, so Box2D's
            // arithmetic is unchanged without one.
            const Real vt = Dot(RelativeVelocity(vA, wA, vB, wB, vp), tangent) - vc.tangentSpeed;
            Real lambda = vp.tangentMass * (-vt);
            const Real maxFriction = vc.friction * vp.normalImpulse;
            const Real newImpulse = Clamp(vp.tangentImpulse + lambda, -maxFriction, maxFriction);
            lambda = newImpulse - vp.tangentImpulse;
            vp.tangentImpulse = newImpulse;
            applyAtPoint(vp, lambda * tangent);
        }
    }

    // Rolling resistance (Box2D v3 solves it after friction): 2.4.1 has none, and a
    // contact without it skips the row, so Box2D's arithmetic is unchanged.
    if (vc.rollingResistance > 0)
    {
        Real totalNormalImpulse = 0;
        for (int j = 0; j < vc.pointCount; ++j)
        {
            totalNormalImpulse += vc.points[j].normalImpulse;
        }
        const Real lambda = SolveRollingRow(vc.rollingMass, vc.rollingResistance,
                                            totalNormalImpulse, wA, wB, vc.rollingImpulse);
        wA -= iA * lambda;
        wB += iB * lambda;
    }

    if (vc.pointCount == 1 || !blockSolver)
    {
        for (int j = 0; j < vc.pointCount; ++j)
        {
            ContactVelocityPoint& vp = vc.points[j];
            const Real vn = Dot(RelativeVelocity(vA, wA, vB, wB, vp), normal);
            Real lambda = -vp.normalMass * (vn - vp.velocityBias);
            const Real newImpulse = Max(vp.normalImpulse + lambda, Real(0));
            lambda = newImpulse - vp.normalImpulse;
            vp.normalImpulse = newImpulse;
            applyAtPoint(vp, lambda * normal);
        }
    }
    else
    {
        SolveNormalBlock(vc, vA, wA, vB, wB);
    }

    a.v = vA;
    a.w = wA;
    b.v = vB;
    b.w = wB;
}

void CollectContactResult(const ContactVelocityConstraint& vc, SolvedContact& solved)
{
    solved.contactIndex = vc.contactIndex;
    solved.pointCount = vc.pointCount;
    solved.rollingImpulse = vc.rollingImpulse;
    for (int j = 0; j < vc.pointCount; ++j)
    {
        solved.normalImpulse[j] = vc.points[j].normalImpulse;
        solved.tangentImpulse[j] = vc.points[j].tangentImpulse;
        solved.normalVelocity[j] = vc.points[j].normalVelocity;
    }
}

namespace
{

/// Normal, point and separation of contact point `index` re-evaluated at the current
/// transforms, from the manifold's local data.
struct PositionPoint
{
    Vec2 normal, point;
    Real separation;
};

PositionPoint EvaluatePositionPoint(const ContactPositionConstraint& pc, const Transform& xfA,
                                    const Transform& xfB, int index)
{
    PositionPoint out{};
    switch (pc.type)
    {
    case Manifold::Type::Circles:
    {
        const Vec2 pointA = Mul(xfA, pc.localPoint);
        const Vec2 pointB = Mul(xfB, pc.localPoints[0]);
        out.normal = pointB - pointA;
        out.normal.Normalize();
        out.point = Real(0.5) * (pointA + pointB);
        out.separation = Dot(pointB - pointA, out.normal) - pc.radiusA - pc.radiusB;
        break;
    }
    case Manifold::Type::FaceA:
    {
        out.normal = Mul(xfA.q, pc.localNormal);
        const Vec2 planePoint = Mul(xfA, pc.localPoint);
        const Vec2 clipPoint = Mul(xfB, pc.localPoints[index]);
        out.separation = Dot(clipPoint - planePoint, out.normal) - pc.radiusA - pc.radiusB;
        out.point = clipPoint;
        break;
    }
    case Manifold::Type::FaceB:
    {
        out.normal = Mul(xfB.q, pc.localNormal);
        const Vec2 planePoint = Mul(xfB, pc.localPoint);
        const Vec2 clipPoint = Mul(xfA, pc.localPoints[index]);
        out.separation = Dot(clipPoint - planePoint, out.normal) - pc.radiusA - pc.radiusB;
        out.point = clipPoint;
        out.normal = -out.normal; // from A to B
        break;
    }
    }
    return out;
}

} // namespace

Real SolvePositionConstraint(const ContactPositionConstraint& pc, Position* positions,
                             const Tolerances& tol, Real baumgarte, const PositionMasses& m)
{
    Position& a = positions[pc.indexA];
    Position& b = positions[pc.indexB];
    Vec2 cA = a.c, cB = b.c;
    Real aA = a.a, aB = b.a;
    const Real mA = m.mA, mB = m.mB, iA = m.iA, iB = m.iB;

    Real minSeparation = 0;
    for (int j = 0; j < pc.pointCount; ++j)
    {
        const Transform xfA = TransformFromCenter(cA, Rot(aA), pc.localCenterA);
        const Transform xfB = TransformFromCenter(cB, Rot(aB), pc.localCenterB);
        const PositionPoint pp = EvaluatePositionPoint(pc, xfA, xfB, j);
        const Vec2 rA = pp.point - cA;
        const Vec2 rB = pp.point - cB;
        minSeparation = Min(minSeparation, pp.separation);

        // Baumgarte-scaled correction that leaves linearSlop of overlap (so contacts
        // persist) and never moves more than maxLinearCorrection at once.
        const Real C =
            Clamp(baumgarte * (pp.separation + tol.linearSlop), -tol.maxLinearCorrection, Real(0));
        const Real K = InverseEffectiveMass(mA, mB, iA, iB, rA, rB, pp.normal);
        const Real impulse = K > 0 ? -C / K : Real(0);
        const Vec2 P = impulse * pp.normal;
        cA -= mA * P;
        aA -= iA * Cross(rA, P);
        cB += mB * P;
        aB += iB * Cross(rB, P);
    }
    a.c = cA;
    a.a = aA;
    b.c = cB;
    b.a = aB;
    return minSeparation;
}

} // namespace meff::detail
