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

/// kLanes contacts' rows, one per lane. A lane with one point has a second point whose masses,
/// lever arms and impulses are zero, which the updates leave unchanged; an empty lane has zero
/// masses throughout and writes the discard slot. What the position correction reads comes
/// first, together (it streams less than half of each group), and what most sweeps skip (soft
/// contacts' softness, the spin row, the lanes' sources) last.
struct SoftContactGroup
{
    std::int32_t indexA[kLanes], indexB[kLanes]; ///< solver body indices
    std::int32_t storeA[kLanes], storeB[kLanes]; ///< where to write each body (discard slot)
    bool anyRolling = false;                     ///< a lane has rolling resistance
    RealW invMassA, invIA, invMassB, invIB;      ///< 1/kg, 1/(kg·m²)
    Vec2W normal;
    Vec2W rA[2], rB[2];      ///< lever arms at the step's start (m)
    RealW baseSeparation[2]; ///< separation − (rB − rA)·n at the start (m)
    MaskW hasPoint[2];
    RealW error[2]; ///< each point's C (SeparationOf) at the bodies' last poses (m)
    RealW normalMass[2], tangentMass[2];       ///< 1/k of each row (kg)
    RealW normalImpulse[2], tangentImpulse[2]; ///< accumulated in this sub-step (N·s)
    RealW totalNormalImpulse[2], totalTangentImpulse[2];
    RealW k11, k12, k22; ///< the normal rows' block K (1/kg)
    /// K⁻¹ = [inv11 inv12; inv12 inv22]: K is symmetric, and so is its inverse, bit for bit.
    RealW inv11, inv12, inv22;
    RealW friction, tangentSpeed; ///< μ; the conveyor's speed (m/s)
    MaskW block;                  ///< two-point lanes whose normal rows are solved as the block
    MaskW hasFriction;            ///< lanes with μ > 0
    MaskW valid;                  ///< lanes holding a contact
    RealW softBias, softMass, softImpulse; ///< the normal rows' Softness while solving
    RealW rollingResistance, rollingMass, rollingImpulse, totalRollingImpulse;
    std::int32_t source[kLanes]; ///< the contact's island position, −1: empty
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
                const SoftContactGroup& g = m_groups[static_cast<std::size_t>(i)];
                for (int l = 0; l < kLanes && g.source[l] >= 0; ++l)
                {
                    f(g.source[l], LaneImpulses(g, l));
                }
            });
    }

  private:
    static SoftContactImpulses LaneImpulses(const SoftContactGroup& g, int l)
    {
        return {{g.normalImpulse[0][l], g.normalImpulse[1][l]},
                {g.tangentImpulse[0][l], g.tangentImpulse[1][l]},
                {g.totalNormalImpulse[0][l], g.totalNormalImpulse[1][l]},
                {g.totalTangentImpulse[0][l], g.totalTangentImpulse[1][l]},
                g.rollingImpulse[l],
                g.totalRollingImpulse[l]};
    }
    /// Packs group i from its colour's contacts.
    void PackGroup(std::int32_t i, std::span<const SoftContact> contacts);
    ConstraintColouring m_colouring;
    std::vector<SoftContactGroup> m_groups; ///< colour after colour
    ColourGroups m_groupsOfColour;          ///< where each colour's groups are, and their threads
    std::vector<SoftGroupImpulses> m_saved;
    bool m_errorsKnown = false; ///< whether every group's `error` is at the bodies' poses
};

} // namespace meff::detail
