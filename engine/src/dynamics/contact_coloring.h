// Graph colouring of an island's contacts (Box2D v3's constraint graph, built per island and
// step): contacts of one colour share no body that the solver moves, so a colour's contacts
// can be solved at the same time — four to a SIMD group, later on several threads — without
// two of them writing the same body. Static and kinematic bodies (zero inverse mass and
// inertia) are only read, so any number of a colour's contacts may touch one.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace meff::detail
{

struct ContactVelocityConstraint;

/// At most this many colours (one bit each per body); contacts that find every colour taken
/// at one of their bodies go to the overflow and are solved one by one.
inline constexpr int kMaxContactColors = 64;

struct ContactColoring
{
    std::vector<std::int32_t> order;       ///< constraint indices, colour after colour
    std::vector<std::int32_t> colorStarts; ///< colour c is order[colorStarts[c], colorStarts[c+1])
    std::vector<std::int32_t> overflow;    ///< constraint indices no colour had room for
    std::vector<std::uint64_t> bodyColors; ///< scratch: colours taken at each solver body
    std::vector<std::int8_t> colorOf;      ///< scratch: each constraint's colour, −1 overflow
    std::vector<std::int32_t> next;        ///< scratch: next free slot of each colour in order

    int ColorCount() const { return static_cast<int>(colorStarts.size()) - 1; }
};

/// True when the solver may change the body's velocity through this contact.
bool MovesBodyA(const ContactVelocityConstraint& vc);
bool MovesBodyB(const ContactVelocityConstraint& vc);

/// Greedy colouring in island order: each contact takes the lowest colour free at both of its
/// moving bodies. Within a colour, contacts keep their island order.
void ColorContacts(std::span<const ContactVelocityConstraint> constraints, ContactColoring& out);

} // namespace meff::detail
