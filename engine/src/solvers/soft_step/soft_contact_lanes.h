// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The soft step's contact rows by colour in SIMD lanes: the island's contacts are coloured as
// the colour back end colours them (contact_colouring.h: a colour's contacts share no body the
// solver moves) and each colour's contacts are packed kLanes (four; AVX2: eight) to a group, from
// the rows SoftContactSolver prepared one by one. Every pass of the sub-steps — warm start, the
// biased and the relax sweeps, the rigid position correction, the impulses' scaling, saving and
// restoring — then runs group by group, colour after colour, each lane doing a contact's
// operations in the same order as the scalar rows (soft_row.h's templates are the same code),
// so a contact solved in a lane gives the bits it would give solved alone in that order. Only the
// Gauss-Seidel order changes (colour order instead of island order), and it does not depend on
// the lane count: the SSE2 and AVX2 builds give the same results. The contacts no colour had room
// for are left to the caller, which solves them one by one after the lanes. On the world's
// threads a colour's groups are solved at once (ColourGroups), which changes nothing in the
// results: they share no moving body.
#pragma once

#include "solvers/lanes/colour_groups.h"
#include "solvers/lanes/graph_colouring.h"
#include "solvers/lanes/wide_real.h"
#include "solvers/soft_step/soft_step_context.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace meff::detail
{

struct IslandContacts;
struct SoftContact;

/// An island with fewer rows of a kind (contacts; plain revolute joints) than this keeps them
/// scalar, in island order: a handful of lane groups saves little, and island order carries a
/// load along a short chain or stack in fewer sweeps than colour order, whose colours alternate
/// along it (chain20's largest anchor gap: 11.8 mm in island order, 14.6 mm by colour). The
/// threshold counts rows, not groups, so it does not depend on the lane count.
inline constexpr std::size_t kMinSoftLaneRows = 32;

/// Colours `count` rows for the soft step's lanes (ColourConstraints, the rows' bodies from
/// `bodiesOf(i)`), or leaves every row to the overflow, in order, below kMinSoftLaneRows.
template <typename BodiesOf>
void ColourSoftRows(std::size_t count, std::int32_t bodyCount, BodiesOf&& bodiesOf,
                    ConstraintColouring& out)
{
    if (count < kMinSoftLaneRows)
    {
        out.order.clear();
        out.colourStarts.assign(1, 0);
        out.overflow.resize(count);
        for (std::size_t i = 0; i < count; ++i)
        {
            out.overflow[i] = static_cast<std::int32_t>(i);
        }
        return;
    }
    ColourConstraints(count, static_cast<std::size_t>(bodyCount), bodiesOf, out);
}

/// What every pass reads of kLanes contacts besides their rows: the bodies and which lanes hold
/// what, as bits (bit l: lane l). A lane's inverse masses and inertias are its bodies'
/// (SoftBodies::masses, gathered by index). Empty lanes read lane 0's bodies and write the
/// worker's discard slot.
struct SoftContactHeader
{
    std::int32_t indexA[kLanes], indexB[kLanes]; ///< solver body indices
    /// Lanes that write their body (SolverMoves); the others (static or kinematic bodies, empty
    /// lanes) write the worker's discard slot. A lane that does not move one of its bodies is a
    /// contact against a fixed body: its normal rows are soft by SoftStepContext::staticContact.
    std::uint8_t storesA = 0, storesB = 0;
    std::uint8_t valid = 0;        ///< lanes holding a contact
    std::uint8_t hasPoint[2] = {}; ///< lanes with that manifold point
    std::uint8_t block = 0;        ///< two-point lanes whose normal rows are solved as the block
    std::uint8_t hasFriction = 0;  ///< lanes with μ > 0
    std::uint8_t extras = 0;       ///< what the group's SoftContactExtras hold

    static constexpr std::uint8_t kTangentSpeed = 1; ///< a lane's tangentSpeed is not +0
    static constexpr std::uint8_t kRolling = 2;      ///< a lane has rolling resistance
};

/// kLanes contacts' rows, one per lane. A lane with one point has a second point whose lever
/// arms, row masses and impulses are zero, which the updates leave unchanged; an empty lane has
/// zero rows throughout and writes only the discard slot. What the position correction reads
/// comes first, together. The normal rows' block K and K⁻¹ are not kept: a sweep recomputes them
/// from the bodies' masses and the rows' levers with the preparation's operations (RowCoupling,
/// BlockRowsOf), which gives them bit for bit; the softness of the normal rows is the context's,
/// by whether a lane's bodies both move (SoftContactHeader).
struct SoftContactGroup
{
    Vec2W normal;
    Vec2W rA[2], rB[2];      ///< lever arms at the step's start (m)
    RealW baseSeparation[2]; ///< separation − (rB − rA)·n at the start (m)
    RealW error[2];          ///< each point's C (SeparationOf) at the bodies' last poses (m)
    RealW normalMass[2], tangentMass[2];       ///< 1/k of each row (kg)
    RealW normalImpulse[2], tangentImpulse[2]; ///< accumulated in this sub-step (N·s)
    RealW totalNormalImpulse[2], totalTangentImpulse[2];
    RealW friction; ///< μ
};

/// What few groups need (SoftContactHeader::extras), kept beside the rows by group index so that
/// the other groups' sweeps neither read nor stream it. A group without a kind skips it, which
/// changes no bit: its tangentSpeed would be +0 in every lane, whose negation −0 is the bias the
/// friction rows take instead, and a spin row of resistance 0 applies nothing.
struct SoftContactExtras
{
    RealW tangentSpeed; ///< the friction rows' target (the conveyor's speed, m/s)
    /// The spin row (0: none) and its impulse over the step.
    RealW rollingResistance, rollingMass, rollingImpulse, totalRollingImpulse;
};

/// The accumulated impulses of one group, kept aside by SaveImpulses.
struct SoftGroupImpulses
{
    RealW normal[2], tangent[2], rolling;
};

/// A contact's impulses at the step's end (N·s; rolling: N·m·s): its points' last sub-step's
/// (next step's warm start) and the step's totals, as a lane or a scalar row holds them.
struct SoftContactImpulses
{
    Real normal[2], tangent[2], totalNormal[2], totalTangent[2];
    Real rolling, totalRolling;
};

class SoftContactLanes
{
  public:
    /// Colours the island's contacts (island order; ColourSoftRows); `bodyCount` is the
    /// island's. Reads only the island, nothing SoftContactSolver prepares, so it may run while
    /// the contacts are prepared.
    void Colour(const IslandContacts& island, std::int32_t bodyCount);
    /// Packs the prepared contacts (island order) into groups by Colour's colours. The island's
    /// discard slots are bodyCount + each worker of `tasks` (the world's threads, or null), on
    /// which every pass below runs.
    void Pack(std::span<const SoftContact> contacts, std::int32_t bodyCount, TaskSystem* tasks);
    /// Island positions of the contacts no colour had room for, in island order.
    std::span<const std::int32_t> Overflow() const { return m_colouring.overflow; }

    void WarmStart(const SoftStepContext& context);
    void Solve(const SoftStepContext& context, bool useBias);
    void CorrectPositions(const SoftStepContext& context);
    /// Says that bodies moved (positions integrated or corrected): the next sweep measures each
    /// point's separation again. Until then the sweeps reuse the last one's: a sub-step's relax
    /// sweep and the next sub-step's biased sweep (or the closing half kick's) see the same
    /// poses, and measuring costs a fifth of a sweep.
    void BodiesMoved() { m_errorsKnown = false; }
    void ScaleImpulses(Real factor);
    void SaveImpulses();
    void RestoreImpulses();
    /// Copies the lanes' impulses and totals back into their contacts.
    void Collect(std::span<SoftContact> contacts) const;
    /// Calls f(k, impulses) with each lane's contact (its island position k) and impulses, on
    /// the threads: f may write what belongs to contact k alone.
    template <typename F>
    void ForEachLaneImpulses(F&& f) const
    {
        m_groupsOfColour.ForEachGroup(
            [&](std::int32_t i)
            {
                const auto [first, end] = m_groupsOfColour.RowsOf(i, m_colouring);
                for (std::int32_t l = 0; first + l < end; ++l)
                {
                    f(m_colouring.order[first + l], LaneImpulses(i, l));
                }
            });
    }

  private:
    /// Lane l's impulses of group i.
    SoftContactImpulses LaneImpulses(std::int32_t i, int l) const
    {
        const auto at = static_cast<std::size_t>(i);
        const SoftContactGroup& g = m_groups[at];
        // Without rolling resistance a lane's spin impulses are +0, as its contact's.
        const bool rolling = (m_headers[at].extras & SoftContactHeader::kRolling) != 0;
        return {{g.normalImpulse[0][l], g.normalImpulse[1][l]},
                {g.tangentImpulse[0][l], g.tangentImpulse[1][l]},
                {g.totalNormalImpulse[0][l], g.totalNormalImpulse[1][l]},
                {g.totalTangentImpulse[0][l], g.totalTangentImpulse[1][l]},
                rolling ? m_extras[at].rollingImpulse[l] : Real(0),
                rolling ? m_extras[at].totalRollingImpulse[l] : Real(0)};
    }
    /// Packs group i from its colour's contacts.
    void PackGroup(std::int32_t i, std::span<const SoftContact> contacts);
    ConstraintColouring m_colouring;
    std::vector<SoftContactHeader> m_headers; ///< colour after colour
    std::vector<SoftContactGroup> m_groups;   ///< colour after colour
    /// By group index, written only for the groups whose header names extras.
    std::vector<SoftContactExtras> m_extras;
    ColourGroups m_groupsOfColour; ///< where each colour's groups are, and their threads
    std::vector<SoftGroupImpulses> m_saved;
    bool m_errorsKnown = false; ///< whether every group's `error` is at the bodies' poses
};

} // namespace meff::detail
