// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The contact rows of the soft step. Each manifold point is a normal row (C = separation +
// linearSlop ≥ 0, so that bodies rest linearSlop into each other's skins as in the other back
// ends) and a friction row (|λt| ≤ μ·λn), both on the seed's scalar effective mass with lever
// arms and normal fixed at the step's start (the anchors turn with their bodies only in the
// separation, s = s0 + (dpB − dpA + dqB·rB − dqA·rA)·n). A point still apart (C > 0) only
// keeps the bodies from closing more than C within the sub-step (speculative).
//
// Rigid contacts (SoftContactModel::Rigid): the normal rows are rigid, two-point manifolds
// solved as one 2×2 block; after each sub-step's move, CorrectPositions removes a fraction of
// each point's overlap beyond linearSlop by moving the bodies, not by giving them velocity.
// Soft contacts: the normal rows are soft while solving (SoftStepContext::contact) and rigid
// while relaxing. Either way friction is solved in the relax sweeps, and after the sub-steps
// restitution drives an approaching point to −e·vn (the seed's P = (1+e)·m_red·|vn|, vn
// measured before the step).
#pragma once

#include "solvers/shared/contact_constraint.h"
#include "solvers/soft_step/soft_contact_lanes.h"
#include "solvers/soft_step/soft_row.h"
#include "solvers/soft_step/soft_step_context.h"

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace meff::detail
{

struct Contact;
class SoftContactDirect;

/// The fewest contacts a thread is handed at once when rows are prepared or stored: one costs
/// a world manifold and a few effective masses, so fewer would not pay for the hand-out.
inline constexpr int kMinSoftContactsPerTask = 64;

/// A point's separation + slop now (m) — the normal row's C with the context's rowSlop, the
/// position correction's with linearSlop — from the separation at the step's start and the bodies'
/// motion since (dp, dq): s = base + (dpB − dpA + dqB·rB − dqA·rA)·n. Written once for a Real and
/// for SIMD lanes (soft_contact_lanes.cpp).
template <typename R, typename V, typename Q>
[[gnu::always_inline]] inline R SeparationOf(R base, V n, V dpA, Q dqA, V dpB, Q dqB, V rA, V rB,
                                             R slop)
{
    const V d = (dpB - dpA) + (Mul(dqB, rB) - Mul(dqA, rA));
    return base + Dot(d, n) + slop;
}

struct SoftContactPoint
{
    Vec2 rA, rB;         ///< from each centre of mass to the point at the step's start (m)
    Real baseSeparation; ///< separation at the start minus (rB − rA)·n: s = base + d·n (m)
    Real normalMass = 0, tangentMass = 0;                 ///< 1/k of each row (kg)
    Real normalImpulse = 0, tangentImpulse = 0;           ///< accumulated in this sub-step (N·s)
    Real totalNormalImpulse = 0, totalTangentImpulse = 0; ///< over the whole step (N·s)
    Real relativeVelocity = 0; ///< vn before the step (m/s): restitution and hit events
};

struct SoftContact
{
    SoftContactPoint points[2];
    Vec2 normal; ///< from A to B, fixed for the step
    std::int32_t indexA = 0, indexB = 0;
    Real mA = 0, iA = 0, mB = 0, iB = 0;
    Real friction = 0, restitution = 0, threshold = 0;
    Real tangentSpeed = 0; ///< the friction rows' target (Contact::tangentSpeed, m/s)
    /// The spin row of rolling resistance (SolveRollingRow; 0: none), relaxed with friction:
    /// its sub-step impulse (warm-started) and its total over the step (N·m·s).
    Real rollingResistance = 0, rollingMass = 0, rollingImpulse = 0, totalRollingImpulse = 0;
    Softness softness; ///< soft contacts' normal rows while solving
    Mat22 K, invK;     ///< the normal rows' block, when `block`
    bool block = false;
    int pointCount = 0;
    std::int32_t contactIndex = 0;
};

/// Contact c's impulses (SoftContactImpulses) set to `impulses`, its points' only.
void SetImpulses(SoftContact& c, const SoftContactImpulses& impulses);

class SoftContactSolver
{
  public:
    SoftContactSolver();
    ~SoftContactSolver();
    /// Builds the rows of the island's contacts at the bodies' poses of the step's start, and
    /// packs the coloured ones into SIMD lanes (soft_contact_lanes.h). Every pass below solves
    /// the lanes colour by colour, then the contacts no colour had room for one by one.
    void Prepare(const IslandContacts& island, const SoftStepContext& context);
    void WarmStart(const SoftStepContext& context);
    /// One sweep: solving (`useBias`; soft contacts push overlapping points apart) or relaxing.
    void Solve(const SoftStepContext& context, bool useBias);
    /// Rigid contacts, after the sub-step's move: removes SoftStepContext::contactCorrection of
    /// each point's overlap beyond linearSlop (at most maxPushOut·h) by moving the bodies.
    void CorrectPositions(const SoftStepContext& context);
    /// Call when the island's positions were integrated (SoftContactLanes::BodiesMoved).
    void BodiesMoved() { m_lanes.BodiesMoved(); }
    /// Restitution after the sub-steps: an approaching point that was pushed is driven to
    /// −e·vn, contact after contact in island order (first copying the lanes' impulses into the
    /// contacts, when a contact has restitution).
    void Restitution(const SoftStepContext& context);
    /// Scales the accumulated impulses (a half kick's are half a sub-step's).
    void ScaleImpulses(Real factor);
    /// The accumulated sub-step impulses, kept aside while the step's closing half kick is
    /// solved (its impulses count towards the step's totals, not towards the warm start).
    void SaveImpulses();
    void RestoreImpulses();
    /// Writes the sub-step impulses × substeps into the manifolds (per-step impulses, as the
    /// other back ends store them: next step's warm start) and fills SolvedContacts(), after
    /// Restitution: the coloured contacts' impulses straight from the lanes unless Restitution
    /// copied them into the contacts.
    void Store(std::span<Contact> contacts, const SoftStepContext& context);

    /// Whether every contact is solved row by row (the island is too small for the lanes).
    bool RowByRow() const { return m_lanes.Overflow().size() == m_contacts.size(); }
    /// Whether the island has no contact rows.
    bool Empty() const { return m_contacts.empty(); }
    std::span<const SolvedContact> SolvedContacts() const { return m_solved; }
    bool AnyHitEvents() const { return m_anyHitEvents; }

  private:
    void SolveNormalRows(SoftContact& c, RowBodies& b, const SoftStepContext& context,
                         bool useBias);
    void WarmStartContact(SoftContact& c, const SoftStepContext& context);
    /// One update of contact c's rows; its normal rows only with `normals` (a direct group,
    /// soft_contact_direct.h, solved them already).
    void SolveContact(SoftContact& c, const SoftStepContext& context, bool useBias,
                      bool normals = true);
    void CorrectContact(const SoftContact& c, const SoftStepContext& context);

    std::vector<SoftContact> m_contacts; ///< island order
    SoftContactLanes m_lanes;
    /// Small groups of contacts whose normal rows are solved together (rigid contacts, an
    /// island too small for the lanes): per contact, whether a group solves its normal rows.
    std::unique_ptr<SoftContactDirect> m_direct;
    std::vector<std::uint8_t> m_isDirect;
    std::vector<std::int32_t> m_fallback;
    std::vector<SolvedContact> m_solved;
    /// The overflow's normal and tangent impulse of each point and rolling impulse
    /// (SaveImpulses).
    std::vector<Vec2> m_saved;
    std::vector<Real> m_savedRolling;
    bool m_anyHitEvents = false;
    bool m_anyRestitution = false; ///< whether a contact's restitution is not zero
    bool m_lanesCollected =
        false; ///< whether the contacts hold their lanes' impulses (Restitution)
    std::vector<std::uint8_t> m_needsOfWorker; ///< Prepare: per worker, its contacts' ContactNeeds
};

} // namespace meff::detail
