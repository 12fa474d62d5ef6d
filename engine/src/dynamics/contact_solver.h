// Sequential impulses for contacts. Every row — normal and friction — uses the scalar
// effective mass of the seed (effective-mass.md):
//   k = 1/mA + 1/mB + (rA×n)²/IA + (rB×n)²/IB,   λ = −(v·n − bias)/k,
// with accumulated impulses clamped (normal ≥ 0, |friction| ≤ μ·normal). Restitution is the
// seed's P = (1+e)(u2−u1)·m_red written as a velocity bias −e·vn on the normal row.
// Optionally, a two-point manifold's normal rows are solved together (Box2D's block solver).
#pragma once

#include "dynamics/colored_contact_solver.h"
#include "dynamics/contact_constraint.h"
#include "dynamics/solver_types.h"

#include <cstdint>
#include <span>
#include <vector>

namespace meff::detail
{

struct Body;
struct Contact;

class ContactSolver
{
  public:
    /// Builds the constraints of one island's contacts. Bodies' islandIndex must be set.
    void Prepare(std::span<const std::int32_t> contactIndices, std::span<const Contact> contacts,
                 std::span<const Body> bodies, SolverData& data);
    void WarmStart(SolverData& data);
    void SolveVelocities(SolverData& data);
    /// Collects the results (CollectResults) and copies the accumulated impulses back into
    /// the manifolds for next step's warm start.
    void StoreImpulses(std::span<Contact> contacts);
    /// Gathers what the rest of the step reads of the solved contacts into SolvedContacts():
    /// their impulses, solved point counts and approach velocities, in island order.
    void CollectResults();
    /// One non-linear Gauss-Seidel sweep; true when no point overlaps more than 3·slop.
    bool SolvePositions(SolverData& data);
    /// One sweep of a time-of-impact sub-step (Box2D's SolveTOIPositionConstraints): only the
    /// two bodies of the event (solver indices toiIndexA, toiIndexB) move, with the stronger
    /// Tolerances::toiBaumgarte; true when no point overlaps more than 1.5·slop.
    bool SolveToiPositions(SolverData& data, std::int32_t toiIndexA, std::int32_t toiIndexB);

    /// The island's contacts after CollectResults.
    std::span<const SolvedContact> SolvedContacts() const { return {m_solved.data(), m_count}; }
    /// Whether any of the island's contacts has a shape that asked for hit events.
    bool AnyHitEvents() const { return m_anyHitEvents; }

  private:
    /// Box2D's b2ContactSolver constructor and InitializeVelocityConstraints for the island's
    /// contact k: the constraints m_velocity[k] and m_position[k].
    void PrepareConstraint(const IslandContacts& island, std::size_t k, const SolverData& data);

    std::vector<ContactVelocityConstraint> m_velocity; ///< reused from step to step
    std::vector<ContactPositionConstraint> m_position;
    std::vector<SolvedContact> m_solved; ///< compact: the post-solve passes read only this
    std::size_t m_count = 0;
    bool m_anyHitEvents = false;
    /// SolverSettings::graphColoring for the island prepared last: the velocity and position
    /// sweeps then run colour by colour in m_coloredSolver.
    bool m_colored = false;
    ColoredContactSolver m_coloredSolver;
};

} // namespace meff::detail
