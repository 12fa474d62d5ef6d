// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Contacts in SIMD lanes, colour by colour (SolverKind::Colour): the same rows, effective
// masses, clamps, block solver and position pass as Box2D's ContactSolver (Box2D 2.4.1's
// algorithm, with the same iteration counts), visited in another order: colour after colour,
// each colour's contacts kLanes at a time (four; AVX2: eight) in SIMD lanes (wide_real.h). Contacts
// no colour could take are left to the caller (ColourContactSolver solves them one by one after the
// lanes). A colour's contacts share no moving body, so lanes never write the same body. What
// changes is the Gauss-Seidel order, so results differ from Box2D's — by round-off in a single
// contact, by the order's effect on convergence in a pile — and are validated by settled-state
// checks instead of bit for bit.
//
// With the world's TaskSystem (SolverData::tasks) a colour's groups are spread over threads,
// at least kMinGroupsPerTask to a range: they share no moving body, each writes only its own
// bodies, its own rows and its worker's discard slot, and the smallest separation is kept per
// group and reduced in group order afterwards, so the results are the same bit for bit for any
// thread count. The preparation spreads every group likewise (it only reads the bodies).
#pragma once

#include "solvers/lanes/colour_groups.h"
#include "solvers/lanes/contact_colouring.h"
#include "solvers/lanes/lane_bodies.h"
#include "solvers/lanes/wide_real.h"
#include "solvers/shared/contact_constraint.h"

#include <cstdint>
#include <span>
#include <vector>

namespace meff::detail
{

/// What both sweeps read of kLanes contacts besides their rows: the bodies and which lanes hold
/// what, as bits (bit l: lane l). A lane's masses and local centres are its bodies'
/// (ContactLanes::m_bodies, gathered by index). Empty lanes read lane 0's bodies, which only this
/// group of its colour writes.
struct ContactGroupHeader
{
    std::int32_t indexA[kLanes], indexB[kLanes]; ///< solver body indices
    /// Lanes that write their body (SolverMoves); the others (static or kinematic bodies, empty
    /// lanes) write the worker's discard slot.
    std::uint8_t storesA = 0, storesB = 0;
    std::uint8_t valid = 0;        ///< lanes holding a contact
    std::uint8_t hasPoint[2] = {}; ///< lanes with that manifold point
    /// Lanes whose second normal row is solved: with two points, unless the block solver's
    /// condition test dropped it (the row's normal mass is 0 in the others).
    std::uint8_t solvesTwo = 0;
    std::uint8_t block = 0;   ///< lanes whose normal rows are solved as the 2×2 block
    std::uint8_t circles = 0; ///< manifold type Circles
    std::uint8_t faceB = 0;   ///< manifold type FaceB (FaceA where neither bit is set)
    std::uint8_t extras = 0; ///< what the group's ContactGroupExtras hold (kTangentSpeed, kRolling)

    static constexpr std::uint8_t kTangentSpeed = 1; ///< a lane's tangentSpeed is not +0
    static constexpr std::uint8_t kRolling = 2;      ///< a lane has rolling resistance
    static constexpr std::uint8_t kRestitution = 4;  ///< a lane's velocityBias is not +0
};

/// kLanes contacts' velocity rows, one per lane. A lane with one point has a second point with
/// zero row masses and lever arms, which the updates leave unchanged; an empty lane has zero rows
/// throughout and writes only the discard slot.
/// Neither the normal rows' masses nor K⁻¹ of the block solver are kept: a sweep recomputes them
/// from K (k11 and k22 are the normal rows' k) with the preparation's operations (RowMass, as
/// Mat22::GetInverse), which gives them bit for bit, in fewer bytes to stream than they take.
struct ContactVelocityGroup
{
    RealW friction;
    Vec2W normal;
    Vec2W rA[2], rB[2];
    RealW tangentMass[2];                      ///< 1/k of each friction row (kg)
    RealW normalImpulse[2], tangentImpulse[2]; ///< accumulated (N·s)
    RealW k11, k12, k22;                       ///< block matrix K
};

/// What few groups need (ContactGroupHeader::extras), kept beside the rows by group index so
/// that the other groups' sweeps neither read nor stream it. Where a group has none of a kind,
/// its sweeps skip subtracting the +0 they would hold, which would change no bit.
struct ContactGroupExtras
{
    RealW tangentSpeed; ///< the friction rows' target (Contact::tangentSpeed, m/s)
    RealW rollingResistance, rollingMass, rollingImpulse; ///< the spin row (0: none)
    RealW velocityBias[2]; ///< each normal row's restitution target −e·vn (m/s)
};

/// kLanes contacts' position constraints, one per lane (the manifold in its local frames).
struct ContactPositionGroup
{
    Vec2W localNormal, localPoint;
    Vec2W localPoints[2];
    RealW radiusA, radiusB;
};

class ContactLanes
{
  public:
    /// Colours the island's contacts (ColourContacts); `bodyCount` is the island's.
    void Colour(const IslandContacts& island, std::size_t bodyCount);
    /// Prepares the contacts Colour coloured kLanes at a time, in lanes
    /// (contact_lanes_prepare.cpp): the same world manifold, lever arms, effective masses,
    /// restitution bias and block K as ContactSolver's scalar preparation, which the overflow
    /// gets instead. A coloured contact's rows live in the lanes; its `solved[k]` gets the
    /// contact index, the solved point count and each point's normal velocity. Returns whether
    /// any coloured contact has hit events.
    bool Prepare(const IslandContacts& island, std::span<SolvedContact> solved,
                 const SolverData& data);
    /// Applies the lanes' warm-start impulses.
    void WarmStart(SolverData& data);
    /// One velocity sweep of the lanes, colour after colour (a colour's groups on the
    /// world's threads).
    void SolveVelocities(SolverData& data);
    /// Copies the lanes' accumulated impulses into their contacts' `solved[k]`, groups spread
    /// over `tasks` (null: this thread).
    void CollectResults(std::span<SolvedContact> solved, TaskSystem* tasks) const;
    /// One position sweep of the lanes; returns the smallest separation seen (≤ 0).
    Real SolvePositions(SolverData& data);

    const ConstraintColouring& Colouring() const { return m_colouring; }

  private:
    /// The colours of the prepared groups (none when the island has no contact).
    int GroupColourCount() const { return static_cast<int>(m_groupStarts.size()) - 1; }
    /// Prepares group i (of colour `colour`), returns whether a contact of it has hit events.
    bool PrepareGroup(std::int32_t i, int colour, const IslandContacts& island,
                      std::span<SolvedContact> solved, const SolverData& data);
    /// Fills m_bodies from the island's bodies.
    void GatherBodies(const IslandContacts& island, const SolverData& data);
    /// Runs solve(group, discard) on each of colour c's groups, spread over the world's threads.
    template <typename Solve>
    void ForEachGroupOfColour(int c, const SolverData& data, Solve&& solve)
    {
        detail::ForEachGroupOfColour(m_groupStarts, c, data, kMinGroupsPerTask, solve);
    }

    ConstraintColouring m_colouring;
    std::vector<BodyMass> m_bodies; ///< the island's bodies' constants, by solver index
    std::vector<ContactGroupHeader> m_headers;
    std::vector<ContactVelocityGroup> m_velocityGroups;
    std::vector<ContactPositionGroup> m_positionGroups;
    /// By group index, written only for the groups whose header names extras.
    std::vector<ContactGroupExtras> m_extras;
    /// Colour c's groups are [m_groupStarts[c], m_groupStarts[c + 1]) of the group arrays.
    std::vector<std::int32_t> m_groupStarts;
    /// Each position group's smallest separation per lane in the last position sweep.
    std::vector<RealW> m_groupMinSeparation;
};

} // namespace meff::detail
