#include "dynamics/contact_coloring.h"

#include "dynamics/contact_constraint.h"

#include <algorithm>
#include <bit>

namespace meff::detail
{

bool MovesBodyA(const ContactVelocityConstraint& vc)
{
    return vc.invMassA > 0 || vc.invIA > 0;
}

bool MovesBodyB(const ContactVelocityConstraint& vc)
{
    return vc.invMassB > 0 || vc.invIB > 0;
}

void ColorContacts(std::span<const ContactVelocityConstraint> constraints, ContactColoring& out)
{
    std::int32_t bodyCount = 0;
    for (const ContactVelocityConstraint& vc : constraints)
    {
        bodyCount = std::max({bodyCount, vc.indexA + 1, vc.indexB + 1});
    }
    out.bodyColors.assign(static_cast<std::size_t>(bodyCount), 0);
    out.colorOf.resize(constraints.size());
    out.overflow.clear();

    int colorCount = 0;
    // Counts per colour, shifted by one so that a prefix sum turns them into colour starts.
    out.colorStarts.assign(kMaxContactColors + 1, 0);
    for (std::size_t i = 0; i < constraints.size(); ++i)
    {
        const ContactVelocityConstraint& vc = constraints[i];
        const bool movesA = MovesBodyA(vc), movesB = MovesBodyB(vc);
        const std::uint64_t taken =
            (movesA ? out.bodyColors[vc.indexA] : 0) | (movesB ? out.bodyColors[vc.indexB] : 0);
        if (taken == ~std::uint64_t{0})
        {
            out.colorOf[i] = -1;
            out.overflow.push_back(static_cast<std::int32_t>(i));
            continue;
        }
        const int color = std::countr_one(taken);
        const std::uint64_t bit = std::uint64_t{1} << color;
        if (movesA)
        {
            out.bodyColors[vc.indexA] |= bit;
        }
        if (movesB)
        {
            out.bodyColors[vc.indexB] |= bit;
        }
        out.colorOf[i] = static_cast<std::int8_t>(color);
        ++out.colorStarts[color + 1];
        colorCount = std::max(colorCount, color + 1);
    }

    // Counting sort by colour, stable: a colour's contacts keep their island order.
    out.colorStarts.resize(colorCount + 1);
    for (int c = 0; c < colorCount; ++c)
    {
        out.colorStarts[c + 1] += out.colorStarts[c];
    }
    out.order.resize(constraints.size() - out.overflow.size());
    out.next.assign(out.colorStarts.begin(), out.colorStarts.end() - 1);
    for (std::size_t i = 0; i < constraints.size(); ++i)
    {
        if (out.colorOf[i] >= 0)
        {
            out.order[out.next[out.colorOf[i]]++] = static_cast<std::int32_t>(i);
        }
    }
}

} // namespace meff::detail
