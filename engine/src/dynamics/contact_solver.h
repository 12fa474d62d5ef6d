// Sequential impulses for contacts. Every row — normal and friction — uses the scalar
// effective mass of the seed (effective-mass.md):
//   k = 1/mA + 1/mB + (rA×n)²/IA + (rB×n)²/IB,   λ = −(v·n − bias)/k,
// with accumulated impulses clamped (normal ≥ 0, |friction| ≤ μ·normal). Restitution is the
// seed's P = (1+e)(u2−u1)·m_red written as a velocity bias −e·vn on the normal row.
// Optionally, a two-point manifold's normal rows are solved together (Box2D's block solver).
#pragma once

#include "dynamics/solver_types.h"

#include <cstdint>
#include <span>
#include <vector>

namespace meff::detail
{

struct Body;
struct Contact;
struct Shape;

struct ContactVelocityPoint
{
    Vec2 rA, rB; ///< from each centre of mass to the contact point (m)
    Real normalImpulse = 0, tangentImpulse = 0;
    Real normalMass = 0, tangentMass = 0; ///< 1/k of the row (kg)
    Real velocityBias = 0;                ///< restitution target −e·vn (m/s)
    Real normalVelocity = 0; ///< vn before impulses, as restitution measures it (m/s); hit events
};

struct ContactVelocityConstraint
{
    ContactVelocityPoint points[2];
    Vec2 normal;
    Mat22 normalMass, K; ///< block solver: K and K⁻¹
    std::int32_t indexA = 0, indexB = 0;
    Real invMassA = 0, invMassB = 0, invIA = 0, invIB = 0;
    Real friction = 0, restitution = 0, threshold = 0;
    int pointCount = 0;
    std::int32_t contactIndex = 0; ///< world contact index
};

struct ContactPositionConstraint
{
    Vec2 localPoints[2];
    Vec2 localNormal, localPoint;
    std::int32_t indexA = 0, indexB = 0;
    Real invMassA = 0, invMassB = 0, invIA = 0, invIB = 0;
    Vec2 localCenterA, localCenterB;
    Manifold::Type type = Manifold::Type::Circles;
    Real radiusA = 0, radiusB = 0;
    int pointCount = 0;
};

class ContactSolver
{
  public:
    /// Builds the constraints of one island's contacts. Bodies' islandIndex must be set.
    void Prepare(std::span<const std::int32_t> contactIndices, std::span<Contact> contacts,
                 std::span<const Body> bodies, std::span<const Shape> shapes, SolverData& data);
    void WarmStart(SolverData& data);
    void SolveVelocities(SolverData& data);
    /// Copies the accumulated impulses back into the manifolds for next step's warm start.
    void StoreImpulses(std::span<Contact> contacts) const;
    /// One non-linear Gauss-Seidel sweep; true when no point overlaps more than 3·slop.
    bool SolvePositions(SolverData& data);
    /// One sweep of a time-of-impact sub-step (Box2D's SolveTOIPositionConstraints): only the
    /// two bodies of the event (solver indices toiIndexA, toiIndexB) move, with the stronger
    /// Tolerances::toiBaumgarte; true when no point overlaps more than 1.5·slop.
    bool SolveToiPositions(SolverData& data, std::int32_t toiIndexA, std::int32_t toiIndexB);

    std::span<const ContactVelocityConstraint> VelocityConstraints() const
    {
        return {m_velocity.data(), m_count};
    }

  private:
    void SolveNormalBlock(ContactVelocityConstraint& vc, Vec2& vA, Real& wA, Vec2& vB,
                          Real& wB) const;

    std::vector<ContactVelocityConstraint> m_velocity; ///< reused from step to step
    std::vector<ContactPositionConstraint> m_position;
    std::size_t m_count = 0;
};

} // namespace meff::detail
