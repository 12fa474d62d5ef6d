// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Joint definitions. Anchors are in each body's local frame; the World offers helpers that
// make a definition from world points, as Box2D's Initialize() functions do.
#pragma once

#include "meff/ids.h"
#include "meff/math.h"

#include <cstdint>
#include <variant>

namespace meff
{

enum class JointType : std::uint8_t
{
    Revolute = 0,
    Distance = 1,
    Prismatic = 2,
    Wheel = 3,
    Weld = 4,
    Motor = 5,
    Mouse = 6,
    Friction = 7,
    Pulley = 8,
    Gear = 9,
};

/// A joint's reaction on body B, as Box2D's GetReactionForce/GetReactionTorque.
struct JointReaction
{
    Vec2 force{};    ///< N
    Real torque = 0; ///< N·m
};

/// Pins two bodies together at one point (an anchored body when bodyA is static). Its point
/// constraint is a 2×2 block solved at once (Box2D) or, with SolverSettings::blockJoints off,
/// as two scalar rows, each with the scalar effective mass.
struct RevoluteJointDef
{
    BodyId bodyA{};           ///< the first body (A)
    BodyId bodyB{};           ///< the second body (B)
    Vec2 localAnchorA{};      ///< anchor in bodyA's frame (m)
    Vec2 localAnchorB{};      ///< anchor in bodyB's frame (m)
    Real referenceAngle = 0;  ///< angleB − angleA at which the joint angle is zero (rad)
    bool enableLimit = false; ///< keep the joint angle in [lowerAngle, upperAngle]
    Real lowerAngle = 0;      ///< rad, ≤ upperAngle
    Real upperAngle = 0;      ///< rad
    bool enableMotor = false; ///< drive the joint at motorSpeed with at most maxMotorTorque
    Real motorSpeed = 0;      ///< target relative angular speed (rad/s)
    Real maxMotorTorque = 0;  ///< N·m, ≥ 0
    /// A torsional spring on the joint angle (Box2D v3's): it pulls angleB − angleA −
    /// referenceAngle towards targetAngle. Off by default; with it off the joint is Box2D
    /// 2.4.1's exactly. Solved before the motor and the limits, which bound it.
    bool enableSpring = false;
    /// Natural frequency of the spring (Hz, ≥ 0; default 0) on the angular row's effective
    /// mass 1/(1/IA + 1/IB): its stiffness is that mass × (2π·hertz)². 0 = no spring (and,
    /// the damping being a ratio of it, no damping either).
    Real hertz = 0;
    Real dampingRatio = 0;         ///< dimensionless, ≥ 0; 1 = critical; default 0
    Real targetAngle = 0;          ///< joint angle the spring pulls towards (rad); default 0
    bool collideConnected = false; ///< may the two bodies' shapes collide
};

/// Keeps two anchor points at a distance: a rigid rod when minLength = maxLength = length and
/// hertz = 0, a spring when hertz > 0 (then min/max act as limits).
struct DistanceJointDef
{
    BodyId bodyA{};                ///< the first body (A)
    BodyId bodyB{};                ///< the second body (B)
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
    BodyId bodyA{};            ///< the first body (A)
    BodyId bodyB{};            ///< the second body (B)
    Vec2 localAnchorA{};       ///< anchor in bodyA's frame (m); default (0, 0)
    Vec2 localAnchorB{};       ///< anchor in bodyB's frame (m); default (0, 0)
    Vec2 localAxisA{1, 0};     ///< slide direction in bodyA's frame, non-zero; normalized at
                               ///< creation (dimensionless); default (1, 0)
    Real referenceAngle = 0;   ///< angleB − angleA held by the joint (rad); default 0
    bool enableLimit = false;  ///< default false
    Real lowerTranslation = 0; ///< m along the axis from A's anchor, ≤ upper; default 0
    Real upperTranslation = 0; ///< m; default 0
    bool enableMotor = false;  ///< default false
    Real motorSpeed = 0;       ///< target speed of B's anchor along the axis (m/s); default 0
    Real maxMotorForce = 0;    ///< N, ≥ 0; default 0
    /// A spring along the axis (Box2D v3's): it pulls the translation (B's anchor along the
    /// axis from A's) towards targetTranslation. Off by default; with it off the joint is Box2D
    /// 2.4.1's exactly. Solved before the motor and the limits, which bound it.
    bool enableSpring = false;
    /// Natural frequency of the spring (Hz, ≥ 0; default 0) on the axial row's effective mass
    /// 1/(1/mA + 1/mB + a1²/IA + a2²/IB): its stiffness is that mass × (2π·hertz)². 0 = no
    /// spring (and, the damping being a ratio of it, no damping either).
    Real hertz = 0;
    Real dampingRatio = 0;         ///< dimensionless, ≥ 0; 1 = critical; default 0
    Real targetTranslation = 0;    ///< translation the spring pulls towards (m); default 0
    bool collideConnected = false; ///< may the two bodies' shapes collide; default false
};

/// A revolute or prismatic joint's spring, as World::SetJointSpring and GetJointSpring hand it
/// over (the same fields as in RevoluteJointDef and PrismaticJointDef).
struct JointSpring
{
    bool enable = false;   ///< default false
    Real hertz = 0;        ///< natural frequency on the row's effective mass (Hz, ≥ 0)
    Real dampingRatio = 0; ///< dimensionless, ≥ 0; 1 = critical
    /// The spring's rest position: targetAngle (rad) for a revolute joint, targetTranslation
    /// (m) for a prismatic joint.
    Real target = 0;
};

/// A wheel on a suspension (Box2D's b2WheelJoint): body B's anchor stays on an axis line fixed
/// in body A (the suspension direction) and B turns freely; an optional spring along the axis,
/// optional limits on the travel, and an optional motor turning B (a car's drive). The rows are
/// scalar in Box2D already, each with the scalar effective mass.
struct WheelJointDef
{
    BodyId bodyA{};            ///< the first body (A)
    BodyId bodyB{};            ///< the second body (B)
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

/// Glues two bodies together at one point: their relative position and angle are held
/// (Box2D's b2WeldJoint). Rigid when hertz = 0: point and angle form one 3×3 block (Box2D) or,
/// with SolverSettings::blockJoints off, three scalar rows, each with the scalar effective
/// mass. With hertz > 0 the angle is a torsional spring (the point stays rigid).
struct WeldJointDef
{
    BodyId bodyA{};          ///< the first body (A)
    BodyId bodyB{};          ///< the second body (B)
    Vec2 localAnchorA{};     ///< anchor in bodyA's frame (m)
    Vec2 localAnchorB{};     ///< anchor in bodyB's frame (m)
    Real referenceAngle = 0; ///< angleB − angleA that the joint holds (rad)
    /// Angular spring frequency (Hz), ≥ 0; 0 = rigid. Turned into Box2D's stiffness
    /// (N·m/rad) and damping (N·m·s/rad) at creation as b2AngularStiffness does, from the
    /// bodies' rotational inertias about their origins.
    Real hertz = 0;
    Real dampingRatio = 0;         ///< dimensionless, ≥ 0; 1 = critical
    bool collideConnected = false; ///< may the two bodies' shapes collide
};

/// Drives bodyB towards a pose relative to bodyA with a bounded force and torque (Box2D's
/// b2MotorJoint): bodyB's origin towards linearOffset in A's frame, angleB − angleA towards
/// angularOffset. The linear part is a 2×2 block (Box2D) or, with blockJoints off, two
/// scalar rows; the angular part is one scalar row. No position correction: the
/// correctionFactor feeds the pose error into the velocity rows instead.
struct MotorJointDef
{
    BodyId bodyA{};                    ///< the first body (A)
    BodyId bodyB{};                    ///< the second body (B)
    Vec2 linearOffset{};               ///< target position of bodyB's origin in bodyA's frame (m)
    Real angularOffset = 0;            ///< target angleB − angleA (rad)
    Real maxForce = 1;                 ///< N, ≥ 0 (Box2D's default)
    Real maxTorque = 1;                ///< N·m, ≥ 0 (Box2D's default)
    Real correctionFactor = Real(0.3); ///< fraction of the pose error removed per step, in [0, 1]
    bool collideConnected = false;     ///< may the two bodies' shapes collide
};

/// Pulls a point of bodyB towards a world target with a soft, force-limited spring (Box2D's
/// b2MouseJoint, for dragging with a pointer). bodyA takes no part in the solve; as in Box2D
/// it is normally a static ground body. The point rows are a 2×2 block (Box2D) or, with
/// blockJoints off, two scalar rows. Box2D's solver also scales bodyB's angular velocity by
/// 0.98 each step, so the dragged body's spin decays; mirrored.
struct MouseJointDef
{
    BodyId bodyA{}; ///< normally a static ground body (takes no part in the solve)
    BodyId bodyB{}; ///< dynamic
    /// World point (m) that grabs bodyB at creation and is its first target; move the target
    /// with World::SetMouseTarget.
    Vec2 target{};
    Real maxForce = 0;             ///< N, ≥ 0; 0 = the joint applies nothing
    Real hertz = 5;                ///< spring frequency (Hz), ≥ 0 (Box2D testbed's value)
    Real dampingRatio = Real(0.7); ///< dimensionless, ≥ 0; 1 = critical (testbed's value)
    bool collideConnected = false; ///< may the two bodies' shapes collide
};

/// Top-down friction (Box2D's b2FrictionJoint): resists the relative motion of body B's anchor
/// against body A's with at most maxForce, and their relative turning with at most maxTorque,
/// as dry friction against a floor seen from above (body A is usually the static ground). It
/// only removes relative velocity, never restores a pose. The linear rows are a 2×2 block
/// (Box2D) or, with SolverSettings::blockJoints off, two scalar rows, each with the scalar
/// effective mass; the angular row is scalar.
struct FrictionJointDef
{
    BodyId bodyA{};                ///< the first body (A)
    BodyId bodyB{};                ///< the second body (B)
    Vec2 localAnchorA{};           ///< anchor in bodyA's frame (m); default (0, 0)
    Vec2 localAnchorB{};           ///< anchor in bodyB's frame (m); default (0, 0)
    Real maxForce = 0;             ///< N, ≥ 0; default 0 (Box2D's: no friction)
    Real maxTorque = 0;            ///< N·m, ≥ 0; default 0
    bool collideConnected = false; ///< may the two bodies' shapes collide; default false
};

/// Two bodies hung from two fixed ground points by one rope over a pulley (Box2D's
/// b2PulleyJoint): lengthA + ratio·lengthB stays what it was at creation, where lengthA is
/// the distance from groundAnchorA to body A's anchor and lengthB from groundAnchorB to body
/// B's. With ratio > 1 body B's side moves 1/ratio as far (a block and tackle). One scalar
/// row with the scalar effective mass k = mA⁻¹ + IA⁻¹·(rA×uA)² + ratio²·(mB⁻¹ + IB⁻¹·(rB×uB)²).
/// The rope is rigid both ways, as Box2D's: it pushes as well as pulls, so keep both sides
/// taut (the lengths well above 10 linear slops, where the rope's direction is defined).
struct PulleyJointDef
{
    BodyId bodyA{};               ///< the first body (A)
    BodyId bodyB{};               ///< the second body (B)
    Vec2 groundAnchorA{-1, 1};    ///< fixed world point body A hangs from (m); Box2D's default
    Vec2 groundAnchorB{1, 1};     ///< fixed world point body B hangs from (m)
    Vec2 localAnchorA{-1, 0};     ///< rope end in bodyA's frame (m)
    Vec2 localAnchorB{1, 0};      ///< rope end in bodyB's frame (m)
    Real lengthA = 0;             ///< reference length of A's side (m), ≥ 0
    Real lengthB = 0;             ///< reference length of B's side (m), ≥ 0
    Real ratio = 1;               ///< dimensionless, > 0 and finite
    bool collideConnected = true; ///< Box2D's default for pulleys: the two loads may collide
};

/// Couples two revolute or prismatic joints (Box2D's b2GearJoint): with coordinate1 joint1's
/// angle (rad) or translation (m) and coordinate2 joint2's,
///   coordinate1 + ratio·coordinate2 = its value at creation.
/// The gear acts on four bodies: joint1's and joint2's bodies B (its own bodies A and B, which
/// must be dynamic) and their bodies A (often the ground). Its one row has the scalar effective
/// mass of the seed summed over both sides, the second side's scaled by ratio²:
///   k = [IA⁻¹ + IC⁻¹ | mA⁻¹ + mC⁻¹ + IA⁻¹(rA×u)² + IC⁻¹(rC×u)²] + ratio²·[same for B, D].
/// Destroying either joint destroys the gear first (Box2D 2.4.1 leaves that to the caller).
struct GearJointDef
{
    JointId joint1{};              ///< a revolute or prismatic joint
    JointId joint2{};              ///< another revolute or prismatic joint
    Real ratio = 1;                ///< dimensionless (rad/rad, m/rad or m/m), finite; default 1
    bool collideConnected = false; ///< may the gear's bodies A and B collide; default false
};

/// How many accumulated impulses a joint of this type has (World::GetJointImpulses lists
/// them): revolute and prismatic 6, wheel 5, distance, weld, motor and friction 3, mouse 2,
/// pulley and gear 1.
constexpr int JointImpulseCount(JointType type)
{
    constexpr int kCounts[] = {6, 3, 6, 5, 3, 3, 2, 3, 1, 1};
    return kCounts[int(type)];
}

/// Any joint's definition, the alternative of its JointType (in the enumeration's order), as
/// World::GetJointDef gives it.
using AnyJointDef =
    std::variant<RevoluteJointDef, DistanceJointDef, PrismaticJointDef, WheelJointDef, WeldJointDef,
                 MotorJointDef, MouseJointDef, FrictionJointDef, PulleyJointDef, GearJointDef>;

} // namespace meff
