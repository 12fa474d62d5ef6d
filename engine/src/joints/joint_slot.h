// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// A joint in the world's pool: the joint itself, its id's generation, and its place in the
// world's joint list and on its two bodies' joint edge lists (newest first, as Box2D 2.4.1).
#pragma once

#include "joints/joint.h"
#include "model/body.h"
#include "model/contact.h"

#include <cstdint>

namespace meff::detail
{

struct JointSlot
{
    std::uint32_t generation = 0;
    bool alive = false;
    Joint joint;
    std::int32_t prev = kNullIndex, next = kNullIndex; ///< world joint list, newest first
    Edge edges[2];                                     ///< [0] on bodyA's list, [1] on bodyB's
    bool islandFlag = false;
};

} // namespace meff::detail
