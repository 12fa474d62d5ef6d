// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Graph colouring of an island's constraints (Box2D v3's constraint graph, built per island and
// step): constraints of one colour share no body that the solver moves, so a colour's
// constraints can be solved at the same time — kLanes (four; AVX2: eight) to a SIMD group, and on
// several threads (contact_lanes.h) — without two of them writing the same body. Static and
// kinematic bodies (zero inverse mass and inertia) are only read, so any number of a colour's
// constraints may touch one. Contacts (contact_colouring.h) and joints (colour/revolute_lanes.h)
// are coloured apart, because they are solved in separate passes.
#pragma once

#include "meff/math.h"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace meff::detail
{

/// At most this many colours (one bit each per body); constraints that find every colour taken
/// at one of their bodies go to the overflow and are solved one by one.
inline constexpr int kMaxColours = 64;

struct ConstraintColouring
{
    std::vector<std::int32_t> order; ///< constraint indices, colour after colour
    std::vector<std::int32_t>
        colourStarts;                   ///< colour c is order[colourStarts[c], colourStarts[c+1])
    std::vector<std::int32_t> overflow; ///< constraint indices no colour had room for
    std::vector<std::uint64_t> bodyColours; ///< scratch: colours taken at each solver body
    std::vector<std::int8_t> colourOf;      ///< scratch: each constraint's colour, −1 overflow
    std::vector<std::int32_t> next;         ///< scratch: next free slot of each colour in order

    int ColourCount() const { return static_cast<int>(colourStarts.size()) - 1; }
};

/// True when the solver can change a body with this inverse mass (1/kg) and inverse inertia
/// (1/(kg·m²)): static and kinematic bodies have both zero.
inline bool SolverMoves(Real invMass, Real invI)
{
    return invMass > 0 || invI > 0;
}

/// What the colouring needs to know of one constraint.
struct ConstraintBodies
{
    std::int32_t indexA = 0, indexB = 0; ///< solver body indices
    bool movesA = false, movesB = false; ///< whether the solver changes that body's state

    bool operator==(const ConstraintBodies&) const = default;
};

/// What a colouring was computed from, so that it can be kept: ColourConstraints is a function
/// of the constraints' bodies and the island's body count alone, so when both are the last
/// colouring's (a grid, a chain or a net whose joints and islands did not change) that colouring
/// is kept as it is — comparing them costs less than colouring again.
class ColouringInputs
{
  public:
    /// Whether `bodies` and `bodyCount` differ from what Keep was last given (true before any).
    bool Changed(std::span<const ConstraintBodies> bodies, std::size_t bodyCount) const
    {
        return !m_kept || bodyCount != m_bodyCount ||
               !std::equal(bodies.begin(), bodies.end(), m_bodies.begin(), m_bodies.end());
    }
    void Keep(std::span<const ConstraintBodies> bodies, std::size_t bodyCount)
    {
        m_bodies.assign(bodies.begin(), bodies.end());
        m_bodyCount = bodyCount;
        m_kept = true;
    }

  private:
    std::vector<ConstraintBodies> m_bodies;
    std::size_t m_bodyCount = 0;
    bool m_kept = false;
};

/// Greedy colouring in the given order: constraint i (of `count`, described by
/// `bodiesOf(i)`) takes the lowest colour free at both of its moving bodies. Within a colour,
/// constraints keep their order. `bodyCount` bounds the solver body indices.
template <typename BodiesOf>
void ColourConstraints(std::size_t count, std::size_t bodyCount, BodiesOf&& bodiesOf,
                       ConstraintColouring& out)
{
    out.bodyColours.assign(bodyCount, 0);
    out.colourOf.resize(count);
    out.overflow.clear();

    int colourCount = 0;
    // Counts per colour, shifted by one so that a prefix sum turns them into colour starts.
    out.colourStarts.assign(kMaxColours + 1, 0);
    for (std::size_t i = 0; i < count; ++i)
    {
        const ConstraintBodies bodies = bodiesOf(i);
        const std::uint64_t taken = (bodies.movesA ? out.bodyColours[bodies.indexA] : 0) |
                                    (bodies.movesB ? out.bodyColours[bodies.indexB] : 0);
        if (taken == ~std::uint64_t{0})
        {
            out.colourOf[i] = -1;
            out.overflow.push_back(static_cast<std::int32_t>(i));
            continue;
        }
        const int colour = std::countr_one(taken);
        const std::uint64_t bit = std::uint64_t{1} << colour;
        if (bodies.movesA)
        {
            out.bodyColours[bodies.indexA] |= bit;
        }
        if (bodies.movesB)
        {
            out.bodyColours[bodies.indexB] |= bit;
        }
        out.colourOf[i] = static_cast<std::int8_t>(colour);
        ++out.colourStarts[colour + 1];
        colourCount = std::max(colourCount, colour + 1);
    }

    // Counting sort by colour, stable: a colour's constraints keep their order.
    out.colourStarts.resize(colourCount + 1);
    for (int c = 0; c < colourCount; ++c)
    {
        out.colourStarts[c + 1] += out.colourStarts[c];
    }
    out.order.resize(count - out.overflow.size());
    out.next.assign(out.colourStarts.begin(), out.colourStarts.end() - 1);
    for (std::size_t i = 0; i < count; ++i)
    {
        if (out.colourOf[i] >= 0)
        {
            out.order[out.next[out.colourOf[i]]++] = static_cast<std::int32_t>(i);
        }
    }
}

} // namespace meff::detail
