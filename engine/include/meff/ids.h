// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Handles to world objects. An id is an index plus a generation: using an id after its object
// was destroyed is detected (the generation no longer matches) and refused with InvalidArgument.
#pragma once

#include <cstdint>

namespace meff
{

/// The id of a body, shape, joint or chain (BodyId, ShapeId, JointId, ChainId): an index and a
/// generation, so an id whose object was destroyed is detected (World::IsValid).
template <typename Tag>
struct Id
{
    std::int32_t index = -1;      ///< slot in the world's pool
    std::uint32_t generation = 0; ///< 0 never names a live object

    /// The null id, which names nothing (a default-constructed id).
    bool IsNull() const { return generation == 0; }
    /// Same index and generation.
    friend bool operator==(Id a, Id b) = default;
};

struct BodyTag;
struct ShapeTag;
struct JointTag;
struct ChainTag;
using BodyId = Id<BodyTag>;
using ShapeId = Id<ShapeTag>;
using JointId = Id<JointTag>;
using ChainId = Id<ChainTag>; ///< a chain of segment shapes (World::CreateChain)

} // namespace meff
