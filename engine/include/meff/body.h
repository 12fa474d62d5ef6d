// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Body definitions.
#pragma once

#include "meff/math.h"

#include <cstdint>

namespace meff
{

enum class BodyType : std::uint8_t
{
    Static = 0,    ///< zero velocity, infinite mass; moved only by the user
    Kinematic = 1, ///< moves with the velocity the user sets, infinite mass
    Dynamic = 2,   ///< moved by forces and contacts; mass from its shapes
};

/// Everything needed to create a body. Defaults make a static body at the origin.
struct BodyDef
{
    BodyType type = BodyType::Static; ///< static, kinematic or dynamic
    Vec2 position{};                  ///< world position of the body origin (m)
    Real angle = 0;                   ///< world angle (rad, counter-clockwise)
    Vec2 linearVelocity{};            ///< velocity of the centre of mass (m/s)
    Real angularVelocity = 0;         ///< rad/s
    Real linearDamping = 0;           ///< 1/s; v *= 1/(1 + h·linearDamping) each step
    Real angularDamping = 0;          ///< 1/s; ω *= 1/(1 + h·angularDamping) each step
    Real gravityScale = 1;            ///< dimensionless multiplier of the world's gravity
    bool fixedRotation = false;       ///< infinite rotational inertia
    bool bullet = false;              ///< continuous collision against dynamic bodies too
    bool allowSleep = true;           ///< may fall asleep (when the world allows sleeping)
    bool awake = true;                ///< starts awake; false: asleep until woken (not static)
    std::uint64_t userData = 0;       ///< yours; meff never reads it
};

} // namespace meff
