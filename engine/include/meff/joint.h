// Joint definitions. Anchors are in each body's local frame; the World offers helpers that
// make a definition from world points, as Box2D's Initialize() functions do.
#pragma once

#include "meff/ids.h"
#include "meff/math.h"

#include <cstdint>

namespace meff
{

enum class JointType : std::uint8_t
{
    Revolute = 0,
    Distance = 1,
};

/// Pins two bodies together at one point (an anchored body when bodyA is static). Its point
/// constraint is a 2×2 block solved at once (Box2D) or, with SolverSettings::blockJoints off,
/// as two scalar rows, each with the scalar effective mass.
struct RevoluteJointDef
{
    BodyId bodyA{};
    BodyId bodyB{};
    Vec2 localAnchorA{};     ///< anchor in bodyA's frame (m)
    Vec2 localAnchorB{};     ///< anchor in bodyB's frame (m)
    Real referenceAngle = 0; ///< angleB − angleA at which the joint angle is zero (rad)
    bool enableLimit = false;
    Real lowerAngle = 0; ///< rad, ≤ upperAngle
    Real upperAngle = 0; ///< rad
    bool enableMotor = false;
    Real motorSpeed = 0;           ///< target relative angular speed (rad/s)
    Real maxMotorTorque = 0;       ///< N·m, ≥ 0
    bool collideConnected = false; ///< may the two bodies' shapes collide
};

/// Keeps two anchor points at a distance: a rigid rod when minLength = maxLength = length and
/// hertz = 0, a spring when hertz > 0 (then min/max act as limits).
struct DistanceJointDef
{
    BodyId bodyA{};
    BodyId bodyB{};
    Vec2 localAnchorA{};           ///< anchor in bodyA's frame (m)
    Vec2 localAnchorB{};           ///< anchor in bodyB's frame (m)
    Real length = 1;               ///< rest length (m), clamped to ≥ linear slop
    Real minLength = 0;            ///< m
    Real maxLength = kMaxReal;     ///< m
    Real hertz = 0;                ///< spring frequency (Hz); 0 = no spring
    Real dampingRatio = 0;         ///< dimensionless; 1 = critical
    bool collideConnected = false; ///< may the two bodies' shapes collide
};

} // namespace meff
