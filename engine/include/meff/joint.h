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
    Prismatic = 2,
    Wheel = 3,
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

/// Lets body B slide along an axis fixed in body A, without turning relative to it (Box2D's
/// b2PrismaticJoint): a piston, an elevator, a drawer. Two hard rows (the anchor stays on the
/// axis line, the relative angle stays referenceAngle) are a 2×2 block solved at once (Box2D)
/// or, with SolverSettings::blockJoints off, two scalar rows, each with the scalar effective
/// mass; the motor and the two limits act along the axis.
struct PrismaticJointDef
{
    BodyId bodyA{};
    BodyId bodyB{};
    Vec2 localAnchorA{};           ///< anchor in bodyA's frame (m); default (0, 0)
    Vec2 localAnchorB{};           ///< anchor in bodyB's frame (m); default (0, 0)
    Vec2 localAxisA{1, 0};         ///< slide direction in bodyA's frame, non-zero; normalized at
                                   ///< creation (dimensionless); default (1, 0)
    Real referenceAngle = 0;       ///< angleB − angleA held by the joint (rad); default 0
    bool enableLimit = false;      ///< default false
    Real lowerTranslation = 0;     ///< m along the axis from A's anchor, ≤ upper; default 0
    Real upperTranslation = 0;     ///< m; default 0
    bool enableMotor = false;      ///< default false
    Real motorSpeed = 0;           ///< target speed of B's anchor along the axis (m/s); default 0
    Real maxMotorForce = 0;        ///< N, ≥ 0; default 0
    bool collideConnected = false; ///< may the two bodies' shapes collide; default false
};

/// A wheel on a suspension (Box2D's b2WheelJoint): body B's anchor stays on an axis line fixed
/// in body A (the suspension direction) and B turns freely; an optional spring along the axis,
/// optional limits on the travel, and an optional motor turning B (a car's drive). The rows are
/// scalar in Box2D already, each with the scalar effective mass.
struct WheelJointDef
{
    BodyId bodyA{};
    BodyId bodyB{};
    Vec2 localAnchorA{};       ///< anchor in bodyA's frame (m); default (0, 0)
    Vec2 localAnchorB{};       ///< anchor in bodyB's frame (m); default (0, 0)
    Vec2 localAxisA{1, 0};     ///< suspension direction in bodyA's frame, non-zero; normalized at
                               ///< creation (dimensionless); default (1, 0)
    bool enableLimit = false;  ///< default false
    Real lowerTranslation = 0; ///< m along the axis from A's anchor, ≤ upper; default 0
    Real upperTranslation = 0; ///< m; default 0
    bool enableMotor = false;  ///< default false
    Real motorSpeed = 0;       ///< target angular speed of B relative to A (rad/s); default 0
    Real maxMotorTorque = 0;   ///< N·m, ≥ 0; default 0
    /// Suspension spring frequency (Hz, ≥ 0; default 0 = no spring). Turned into a stiffness
    /// (N/m) and damping (N·s/m) at creation from the two bodies' masses, as Box2D's
    /// b2LinearStiffness, so set up the bodies' shapes before creating the joint.
    Real hertz = 0;
    Real dampingRatio = 0;         ///< dimensionless, ≥ 0; 1 = critical; default 0
    bool collideConnected = false; ///< may the two bodies' shapes collide; default false
};

} // namespace meff
