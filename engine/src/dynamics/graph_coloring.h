// Graph colouring of an island's constraints (Box2D v3's constraint graph, built per island and
// step): constraints of one colour share no body that the solver moves, so a colour's
// constraints can be solved at the same time — four to a SIMD group, later on several threads —
// without two of them writing the same body. Static and kinematic bodies (zero inverse mass and
// inertia) are only read, so any number of a colour's constraints may touch one. Contacts
// (contact_coloring.h) and joints (joint_solver.h) are coloured apart, because they are solved
// in separate passes.
#pragma once

#include "meff/math.h"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace meff::detail
{

/// At most this many colours (one bit each per body); constraints that find every colour taken
/// at one of their bodies go to the overflow and are solved one by one.
inline constexpr int kMaxColors = 64;

struct ConstraintColoring
{
    std::vector<std::int32_t> order;       ///< constraint indices, colour after colour
    std::vector<std::int32_t> colorStarts; ///< colour c is order[colorStarts[c], colorStarts[c+1])
    std::vector<std::int32_t> overflow;    ///< constraint indices no colour had room for
    std::vector<std::uint64_t> bodyColors; ///< scratch: colours taken at each solver body
    std::vector<std::int8_t> colorOf;      ///< scratch: each constraint's colour, −1 overflow
    std::vector<std::int32_t> next;        ///< scratch: next free slot of each colour in order

    int ColorCount() const { return static_cast<int>(colorStarts.size()) - 1; }
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
};

/// Greedy colouring in the given order: constraint i (of `count`, described by
/// `bodiesOf(i)`) takes the lowest colour free at both of its moving bodies. Within a colour,
/// constraints keep their order. `bodyCount` bounds the solver body indices.
template <typename BodiesOf>
void ColorConstraints(std::size_t count, std::size_t bodyCount, BodiesOf&& bodiesOf,
                      ConstraintColoring& out)
{
    out.bodyColors.assign(bodyCount, 0);
    out.colorOf.resize(count);
    out.overflow.clear();

    int colorCount = 0;
    // Counts per colour, shifted by one so that a prefix sum turns them into colour starts.
    out.colorStarts.assign(kMaxColors + 1, 0);
    for (std::size_t i = 0; i < count; ++i)
    {
        const ConstraintBodies bodies = bodiesOf(i);
        const std::uint64_t taken = (bodies.movesA ? out.bodyColors[bodies.indexA] : 0) |
                                    (bodies.movesB ? out.bodyColors[bodies.indexB] : 0);
        if (taken == ~std::uint64_t{0})
        {
            out.colorOf[i] = -1;
            out.overflow.push_back(static_cast<std::int32_t>(i));
            continue;
        }
        const int color = std::countr_one(taken);
        const std::uint64_t bit = std::uint64_t{1} << color;
        if (bodies.movesA)
        {
            out.bodyColors[bodies.indexA] |= bit;
        }
        if (bodies.movesB)
        {
            out.bodyColors[bodies.indexB] |= bit;
        }
        out.colorOf[i] = static_cast<std::int8_t>(color);
        ++out.colorStarts[color + 1];
        colorCount = std::max(colorCount, color + 1);
    }

    // Counting sort by colour, stable: a colour's constraints keep their order.
    out.colorStarts.resize(colorCount + 1);
    for (int c = 0; c < colorCount; ++c)
    {
        out.colorStarts[c + 1] += out.colorStarts[c];
    }
    out.order.resize(count - out.overflow.size());
    out.next.assign(out.colorStarts.begin(), out.colorStarts.end() - 1);
    for (std::size_t i = 0; i < count; ++i)
    {
        if (out.colorOf[i] >= 0)
        {
            out.order[out.next[out.colorOf[i]]++] = static_cast<std::int32_t>(i);
        }
    }
}

} // namespace meff::detail
