// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The normal rows of a small group of touching bodies, solved together exactly (rigid contacts,
// SoftContactModel::Rigid): a heavy body on a light one on the ground.
//
// Why: a Gauss-Seidel sweep hands a load from contact to contact at about each row's own
// effective mass, so a 1000 kg box landing on a 1 kg box on the ground gives up a thousandth of
// its momentum per sweep: it sinks into the light box and slides off it (docs/soft-step.md,
// "Mass ratios in contact"). Solved together, the rows stop it in one update, whatever the
// masses.
//
// What is solved. The contacts are grouped by the bodies they move (bodies that do not move —
// static, kinematic — join nothing); a group of two contacts or more with at most
// kMaxDirectRows normal rows, on one moving body or on bodies whose heaviest has at least
// kMinDirectMassRatio times the lightest one's mass, is solved as one linear complementarity
// problem per sweep: with A = J·M⁻¹·Jᵀ its rows' coupled inverse effective mass (each row's seed k
// on its diagonal), λ the impulses accumulated so far and b the rows' velocities now plus their
// speculative bias (a point still apart may close by its gap), find λ' ≥ 0 with
//
//     w = A·(λ' − λ) + b ≥ 0,   λ'ᵢ·wᵢ = 0,
//
// the exact answer the sweeps converge to. It is found by principal pivoting (Murty's rule: the
// set of rows that push is changed one row at a time, the largest infeasible index first, each
// guess solved by Cholesky in double), which ends for every positive definite A. A group whose
// pushing rows say nearly the same thing (a pivot below 1e-6 of its diagonal: a condition test as
// Box2D's for its two-point block) or that does not converge within its pivot budget is left to the
// rows one by one for that sweep. Friction stays with each contact's rows, solved after the
// group's normal rows.
#pragma once

#include "solvers/soft_step/soft_contact_solver.h"

#include <cstdint>
#include <span>
#include <vector>

namespace meff::detail
{

/// The most normal rows a group is solved together with (the dense solve costs about n³/3 per
/// pivot; a pile larger than this stays with the sweeps).
inline constexpr int kMaxDirectRows = 32;

/// The smallest ratio of a group's heaviest to its lightest moving body for which a group of
/// two bodies or more is solved together (a single body's contacts always are: a ragdoll's limb
/// on the ground keeps moving at 0.07 m/s by the sweeps). Bodies of like mass hand a load on
/// within the sweeps: the arch (nine voussoirs) 0.32 mm by the sweeps against 0.26 mm solved
/// together, at 0.29 of the step's instructions; stack10 0.1 mm; docs/soft-step.md, "Accuracy per
/// cost". At 4, a 3.1 kg ball dropped 40 m on a stack of 1 kg boxes (sleeping_wake) pressed in
/// 0.071 m against 0.005 m solved together.
inline constexpr double kMinDirectMassRatio = 2;

class SoftContactDirect
{
  public:
    /// Groups `contacts` (an island's, prepared) by the bodies they move and builds each
    /// group's A; `direct[k]` is set to 1 for every contact whose normal rows a group solves, 0
    /// for the others. `bodyCount` is the island's body count.
    void Prepare(std::span<const SoftContact> contacts, std::int32_t bodyCount,
                 std::vector<std::uint8_t>& direct);
    bool Empty() const { return m_groups.empty(); }
    /// One exact update of every group's normal rows on the bodies' velocities now. Returns
    /// false for a group (and leaves its rows untouched) when it did not converge: `fallback`
    /// then lists its contacts, to be solved one by one.
    void Solve(std::span<SoftContact> contacts, const SoftStepContext& context,
               std::vector<std::int32_t>& fallback);

  private:
    struct Row
    {
        std::int32_t contact = 0; ///< index into the island's contacts
        std::int32_t point = 0;
    };
    struct Group
    {
        std::int32_t firstRow = 0, rowCount = 0;
        std::int32_t firstContact = 0, contactCount = 0; ///< in m_groupContacts
        std::size_t matrix = 0;                          ///< offset of A in m_matrices
    };
    /// Solves LCP(A, q) for n rows from the guess x (≥ 0); true when it converged.
    bool SolveLcp(int n, const double* A, const double* q, double* x);

    std::vector<Group> m_groups;
    std::vector<Row> m_rows;
    std::vector<std::int32_t> m_groupContacts;
    std::vector<double> m_matrices;
    // Scratch.
    std::vector<std::int32_t> m_parent, m_rowsOf, m_contactsOf, m_groupOf;
    std::vector<std::uint8_t> m_joined;     ///< per group root: it has two moving bodies or more
    std::vector<double> m_minInv, m_maxInv; ///< per group root: its moving bodies' 1/m range
    std::vector<double> m_q, m_x, m_w, m_factor, m_rhs;
    std::vector<std::uint8_t> m_free;
    std::vector<int> m_set;
};

} // namespace meff::detail
