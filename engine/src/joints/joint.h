// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Joints inside the solver. Each joint type lives in its own file (revolute_joint.cpp,
// distance_joint.cpp, prismatic_joint.cpp, wheel_joint.cpp, weld_joint.cpp, motor_joint.cpp,
// mouse_joint.cpp, friction_joint.cpp, pulley_joint.cpp) and is reached through the functions at
// the bottom, which switch on the type. Every constraint row is solved with the scalar effective
// mass
//   k = 1/mA + 1/mB + (rA×n)²/IA + (rB×n)²/IB   (seed: effective-mass.md)
// and λ = −(Jv + bias)/k, following Box2D 2.4.1's sequential-impulse formulation.
// Each solver function copies its bodies' state out of SolverData at the start
// (`auto [vA, wA] = data.velocities[joint.indexA];`), works on the copies as Box2D does, and
// writes them back at the end (`data.velocities[joint.indexA] = {vA, wA};`).
#pragma once

#include "joints/mat33.h"
#include "joints/softness.h" // the soft row shared by every back end's springs
#include "model/solver_types.h"
#include "meff/joint.h"
#include "meff/settings.h"

#include <cstdint>
#include <variant>

namespace meff::detail
{

/// What a joint needs of each of its bodies when a step begins.
struct JointBody
{
    std::int32_t solverIndex = -1; ///< index into SolverData::positions/velocities
    Vec2 localCenter;              ///< centre of mass in body coordinates (m)
    Real invMass = 0;              ///< 1/kg, 0 for static/kinematic
    Real invI = 0;                 ///< 1/(kg·m²), 0 for static/kinematic/fixed rotation
};

struct RevoluteJoint
{
    // Definition
    Vec2 localAnchorA, localAnchorB;
    Real referenceAngle = 0;
    bool enableLimit = false;
    Real lowerAngle = 0, upperAngle = 0;
    bool enableMotor = false;
    Real motorSpeed = 0, maxMotorTorque = 0;
    bool enableSpring = false;
    Real hertz = 0, dampingRatio = 0; ///< Hz on the angular row's mass; dimensionless
    Real targetAngle = 0;             ///< rad
    // Accumulated impulses, carried from step to step for warm starting
    Vec2 impulse;
    Real motorImpulse = 0, lowerImpulse = 0, upperImpulse = 0, springImpulse = 0;
    // Solver temporaries, set by InitJointVelocityConstraints
    std::int32_t indexA = 0, indexB = 0;
    Vec2 rA, rB, localCenterA, localCenterB;
    Real invMassA = 0, invMassB = 0, invIA = 0, invIB = 0;
    Mat22 K;
    Real angle = 0, axialMass = 0;
    Softness spring; ///< the spring row over this step (FrequencySpringSoftness)
};

struct DistanceJoint
{
    // Definition
    Vec2 localAnchorA, localAnchorB;
    Real length = 1, minLength = 0, maxLength = kMaxReal;
    Real stiffness = 0;               ///< N/m, from hertz and the bodies' masses at creation
    Real damping = 0;                 ///< N·s/m
    Real hertz = 0, dampingRatio = 0; ///< as defined (World::GetJointDef)
    // Accumulated impulses
    Real impulse = 0, lowerImpulse = 0, upperImpulse = 0;
    // Solver temporaries
    std::int32_t indexA = 0, indexB = 0;
    Vec2 u, rA, rB, localCenterA, localCenterB;
    Real currentLength = 0;
    Real invMassA = 0, invMassB = 0, invIA = 0, invIB = 0;
    Real softMass = 0, mass = 0, gamma = 0, bias = 0;
};

struct PrismaticJoint
{
    // Definition
    Vec2 localAnchorA, localAnchorB;
    Vec2 localXAxisA{1, 0};  ///< unit slide axis in A's frame
    Vec2 localYAxisA{0, 1};  ///< its perpendicular, 1 × localXAxisA
    Vec2 definedAxisA{1, 0}; ///< the axis as defined, before normalizing (World::GetJointDef)
    Real referenceAngle = 0;
    bool enableLimit = false;
    Real lowerTranslation = 0, upperTranslation = 0;
    bool enableMotor = false;
    Real motorSpeed = 0, maxMotorForce = 0;
    bool enableSpring = false;
    Real hertz = 0, dampingRatio = 0; ///< Hz on the axial row's mass; dimensionless
    Real targetTranslation = 0;       ///< m
    // Accumulated impulses: (perpendicular, angular) block, then the axial rows
    Vec2 impulse;
    Real motorImpulse = 0, lowerImpulse = 0, upperImpulse = 0, springImpulse = 0;
    // Solver temporaries
    std::int32_t indexA = 0, indexB = 0;
    Vec2 localCenterA, localCenterB;
    Real invMassA = 0, invMassB = 0, invIA = 0, invIB = 0;
    Vec2 axis, perp;     ///< world axis and perpendicular at the step's start
    Real s1 = 0, s2 = 0; ///< perpendicular row's angular Jacobian terms (A, B)
    Real a1 = 0, a2 = 0; ///< axial rows' angular Jacobian terms (A, B)
    Mat22 K;             ///< block of the perpendicular and angular rows
    Real translation = 0, axialMass = 0;
    Softness spring; ///< the spring row over this step (FrequencySpringSoftness)
};

struct WheelJoint
{
    // Definition
    Vec2 localAnchorA, localAnchorB;
    Vec2 localXAxisA{1, 0};  ///< unit suspension axis in A's frame
    Vec2 localYAxisA{0, 1};  ///< its perpendicular, 1 × localXAxisA
    Vec2 definedAxisA{1, 0}; ///< the axis as defined, before normalizing (World::GetJointDef)
    bool enableLimit = false;
    Real lowerTranslation = 0, upperTranslation = 0;
    bool enableMotor = false;
    Real motorSpeed = 0, maxMotorTorque = 0;
    Real stiffness = 0;               ///< N/m, from hertz and the bodies' masses at creation
    Real damping = 0;                 ///< N·s/m
    Real hertz = 0, dampingRatio = 0; ///< as defined (World::GetJointDef)
    // Accumulated impulses
    Real impulse = 0, motorImpulse = 0, springImpulse = 0, lowerImpulse = 0, upperImpulse = 0;
    // Solver temporaries
    std::int32_t indexA = 0, indexB = 0;
    Vec2 localCenterA, localCenterB;
    Real invMassA = 0, invMassB = 0, invIA = 0, invIB = 0;
    Vec2 ax, ay;           ///< world axis and perpendicular at the step's start
    Real sAx = 0, sBx = 0; ///< axial rows' angular Jacobian terms
    Real sAy = 0, sBy = 0; ///< perpendicular row's angular Jacobian terms
    Real mass = 0, motorMass = 0, axialMass = 0, springMass = 0;
    Real bias = 0, gamma = 0, translation = 0;
};

struct WeldJoint
{
    // Definition
    Vec2 localAnchorA, localAnchorB;
    Real referenceAngle = 0;
    Real stiffness = 0; ///< N·m/rad, from hertz and the bodies' inertias at creation; 0 = rigid
    Real damping = 0;   ///< N·m·s/rad
    Real hertz = 0, dampingRatio = 0; ///< as defined (World::GetJointDef)
    // Accumulated impulses (point x, point y, angle)
    Vec3 impulse;
    // Solver temporaries
    std::int32_t indexA = 0, indexB = 0;
    Vec2 rA, rB, localCenterA, localCenterB;
    Real invMassA = 0, invMassB = 0, invIA = 0, invIB = 0;
    Mat33 K;    ///< J·M⁻¹·Jᵀ of the three rows; its diagonal holds each row's scalar k
    Mat33 mass; ///< inverse of K (or of its point block, plus the soft angular mass)
    Real gamma = 0, bias = 0;
};

struct MotorJoint
{
    // Definition (the offsets may change between steps)
    Vec2 linearOffset;
    Real angularOffset = 0;
    Real maxForce = 1, maxTorque = 1, correctionFactor = Real(0.3);
    // Accumulated impulses
    Vec2 linearImpulse;
    Real angularImpulse = 0;
    // Solver temporaries
    std::int32_t indexA = 0, indexB = 0;
    Vec2 rA, rB, localCenterA, localCenterB;
    Vec2 linearError;
    Real angularError = 0;
    Real invMassA = 0, invMassB = 0, invIA = 0, invIB = 0;
    Mat22 K;          ///< point block J·M⁻¹·Jᵀ; its diagonal holds each row's scalar k
    Mat22 linearMass; ///< K⁻¹
    Real angularMass = 0;
};

struct MouseJoint
{
    // Definition (the target may change between steps)
    Vec2 target;       ///< world point (m)
    Vec2 localAnchorB; ///< the grabbed point in bodyB's frame
    Real maxForce = 0;
    Real stiffness = 0;               ///< N/m, from hertz and the bodies' masses at creation
    Real damping = 0;                 ///< N·s/m
    Real hertz = 0, dampingRatio = 0; ///< as defined (World::GetJointDef)
    // Accumulated impulse
    Vec2 impulse;
    // Solver temporaries (the A members are stored but unused: body A takes no part)
    std::int32_t indexA = 0, indexB = 0;
    Vec2 rB, localCenterA, localCenterB;
    Real invMassA = 0, invMassB = 0, invIA = 0, invIB = 0;
    Mat22 K;    ///< soft point block, γ on the diagonal
    Mat22 mass; ///< K⁻¹
    Vec2 C;     ///< position error × β, the rows' bias
    Real beta = 0, gamma = 0;
};

struct FrictionJoint
{
    // Definition
    Vec2 localAnchorA, localAnchorB;
    Real maxForce = 0, maxTorque = 0;
    // Accumulated impulses
    Vec2 linearImpulse;
    Real angularImpulse = 0;
    // Solver temporaries
    std::int32_t indexA = 0, indexB = 0;
    Vec2 rA, rB, localCenterA, localCenterB;
    Real invMassA = 0, invMassB = 0, invIA = 0, invIB = 0;
    Mat22 K;          ///< point block J·M⁻¹·Jᵀ; its diagonal holds each row's scalar k
    Mat22 linearMass; ///< K⁻¹
    Real angularMass = 0;
};

struct PulleyJoint
{
    // Definition
    Vec2 groundAnchorA, groundAnchorB; ///< world points (m)
    Vec2 localAnchorA, localAnchorB;
    Real lengthA = 0, lengthB = 0, ratio = 1;
    Real constant = 0; ///< lengthA + ratio·lengthB, the rope's length
    // Accumulated impulse
    Real impulse = 0;
    // Solver temporaries
    std::int32_t indexA = 0, indexB = 0;
    Vec2 uA, uB; ///< unit rope directions from the ground anchors (0 when too short)
    Vec2 rA, rB, localCenterA, localCenterB;
    Real invMassA = 0, invMassB = 0, invIA = 0, invIB = 0;
    Real mass = 0; ///< 1/k
};

/// Pose of a body when a gear is made: its transform and its angle (Box2D's m_sweep.a).
struct GearPose
{
    Transform xf;
    Real angle = 0;
};

struct GearJoint
{
    // Definition. Body A and B are joint1's and joint2's bodies B, C and D their bodies A.
    JointId joint1, joint2;                      ///< the coupled joints
    bool prismaticA = false, prismaticB = false; ///< joint1's, joint2's type (else revolute)
    std::int32_t bodyC = -1, bodyD = -1;         ///< world body indices
    Vec2 localAnchorA, localAnchorB, localAnchorC, localAnchorD;
    Vec2 localAxisC, localAxisD; ///< a prismatic side's slide axis in C's (D's) frame
    Real referenceAngleA = 0, referenceAngleB = 0;
    Real ratio = 1;
    Real constant = 0; ///< coordinateA + ratio·coordinateB at creation
    // Accumulated impulse
    Real impulse = 0;
    // Solver temporaries. C and D are stored by StoreGearBodies before the step's preparation.
    std::int32_t indexA = 0, indexB = 0, indexC = 0, indexD = 0;
    Vec2 localCenterA, localCenterB, localCenterC, localCenterD;
    Real invMassA = 0, invMassB = 0, invMassC = 0, invMassD = 0;
    Real invIA = 0, invIB = 0, invIC = 0, invID = 0;
    Vec2 JvAC, JvBD;                         ///< linear Jacobian of each side (0 when revolute)
    Real JwA = 0, JwB = 0, JwC = 0, JwD = 0; ///< angular Jacobian terms
    Real mass = 0;                           ///< 1/k
};

struct Joint
{
    JointType type = JointType::Revolute;
    std::int32_t bodyA = -1; ///< world body index
    std::int32_t bodyB = -1;
    bool collideConnected = false;
    std::variant<RevoluteJoint, DistanceJoint, PrismaticJoint, WheelJoint, WeldJoint, MotorJoint,
                 MouseJoint, FrictionJoint, PulleyJoint, GearJoint>
        data;
};

/// Stores what a joint's rows need of its two bodies for this step (every joint type has these
/// members).
template <typename JointData>
void StoreJointBodies(JointData& joint, const JointBody& a, const JointBody& b)
{
    joint.indexA = a.solverIndex;
    joint.indexB = b.solverIndex;
    joint.localCenterA = a.localCenter;
    joint.localCenterB = b.localCenter;
    joint.invMassA = a.invMass;
    joint.invMassB = b.invMass;
    joint.invIA = a.invI;
    joint.invIB = b.invI;
}

/// Builds the solver joint from a definition whose ids the world has already checked.
/// massA/massB (kg, 0 for static) set a distance spring's stiffness as Box2D's
/// b2LinearStiffness does. Throws InvalidArgument for non-finite or out-of-range values.
Joint MakeJoint(const RevoluteJointDef& def, std::int32_t bodyA, std::int32_t bodyB);
Joint MakeJoint(const DistanceJointDef& def, std::int32_t bodyA, std::int32_t bodyB, Real massA,
                Real massB, const Tolerances& tolerances);
Joint MakeJoint(const PrismaticJointDef& def, std::int32_t bodyA, std::int32_t bodyB);
/// massA/massB (kg, 0 for static) set the suspension spring as for the distance joint.
Joint MakeJoint(const WheelJointDef& def, std::int32_t bodyA, std::int32_t bodyB, Real massA,
                Real massB);

/// inertiaA/inertiaB: each body's rotational inertia about its origin (kg·m², Box2D's
/// b2Body::GetInertia), which set the angular spring as b2AngularStiffness does.
Joint MakeJoint(const WeldJointDef& def, std::int32_t bodyA, std::int32_t bodyB, Real inertiaA,
                Real inertiaB);
Joint MakeJoint(const MotorJointDef& def, std::int32_t bodyA, std::int32_t bodyB);
Joint MakeJoint(const FrictionJointDef& def, std::int32_t bodyA, std::int32_t bodyB);
Joint MakeJoint(const PulleyJointDef& def, std::int32_t bodyA, std::int32_t bodyB);
/// joint1/joint2: the coupled joints (revolute or prismatic, checked by the world); poses of
/// the gear's bodies A, B (joint1's, joint2's body B) and C, D (their bodies A) now.
Joint MakeJoint(const GearJointDef& def, const Joint& joint1, const Joint& joint2,
                const GearPose& a, const GearPose& b, const GearPose& c, const GearPose& d);
/// Stores what the gear's rows need of its bodies C and D for this step (bodies A and B come
/// through InitJointVelocityConstraints, as for every joint).
void StoreGearBodies(GearJoint& gear, const JointBody& c, const JointBody& d);
/// xfB: bodyB's transform now, which turns the target into the grabbed local point.
/// bodyBDynamic: the world's answer to "is bodyB dynamic" (a mouse joint must move it).
Joint MakeJoint(const MouseJointDef& def, std::int32_t bodyA, std::int32_t bodyB, Real massA,
                Real massB, const Transform& xfB, bool bodyBDynamic);

/// World anchors (m) as Box2D's GetAnchorA/GetAnchorB, from the bodies' transforms.
Vec2 JointAnchorA(const Joint& joint, const Transform& xfA);
Vec2 JointAnchorB(const Joint& joint, const Transform& xfB);

/// Prepares the rows for this step and applies the warm-start impulse (or zeroes the
/// accumulated impulses when warm starting is off): Box2D's InitVelocityConstraints.
void InitJointVelocityConstraints(Joint& joint, const JointBody& a, const JointBody& b,
                                  SolverData& data);
void SolveJointVelocityConstraints(Joint& joint, SolverData& data);
/// One non-linear Gauss-Seidel correction; returns true when the joint is within tolerance.
bool SolveJointPositionConstraints(Joint& joint, SolverData& data);
/// Reaction on body B: accumulated impulse × invDt (force, N) and torque (N·m).
JointReaction GetJointReaction(const Joint& joint, Real invDt);

// Per-type implementations behind the dispatchers above (revolute_joint.cpp,
// distance_joint.cpp). Same contracts as the dispatchers.
void InitVelocityConstraints(RevoluteJoint& joint, const JointBody& a, const JointBody& b,
                             SolverData& data);
void SolveVelocityConstraints(RevoluteJoint& joint, SolverData& data);
bool SolvePositionConstraints(RevoluteJoint& joint, SolverData& data);
JointReaction GetReaction(const RevoluteJoint& joint, Real invDt);

void InitVelocityConstraints(DistanceJoint& joint, const JointBody& a, const JointBody& b,
                             SolverData& data);
void SolveVelocityConstraints(DistanceJoint& joint, SolverData& data);
bool SolvePositionConstraints(DistanceJoint& joint, SolverData& data);
JointReaction GetReaction(const DistanceJoint& joint, Real invDt);

void InitVelocityConstraints(PrismaticJoint& joint, const JointBody& a, const JointBody& b,
                             SolverData& data);
void SolveVelocityConstraints(PrismaticJoint& joint, SolverData& data);
bool SolvePositionConstraints(PrismaticJoint& joint, SolverData& data);
JointReaction GetReaction(const PrismaticJoint& joint, Real invDt);

void InitVelocityConstraints(WheelJoint& joint, const JointBody& a, const JointBody& b,
                             SolverData& data);
void SolveVelocityConstraints(WheelJoint& joint, SolverData& data);
bool SolvePositionConstraints(WheelJoint& joint, SolverData& data);
JointReaction GetReaction(const WheelJoint& joint, Real invDt);
void InitVelocityConstraints(WeldJoint& joint, const JointBody& a, const JointBody& b,
                             SolverData& data);
void SolveVelocityConstraints(WeldJoint& joint, SolverData& data);
bool SolvePositionConstraints(WeldJoint& joint, SolverData& data);
JointReaction GetReaction(const WeldJoint& joint, Real invDt);

void InitVelocityConstraints(MotorJoint& joint, const JointBody& a, const JointBody& b,
                             SolverData& data);
void SolveVelocityConstraints(MotorJoint& joint, SolverData& data);
bool SolvePositionConstraints(MotorJoint& joint, SolverData& data);
JointReaction GetReaction(const MotorJoint& joint, Real invDt);

void InitVelocityConstraints(MouseJoint& joint, const JointBody& a, const JointBody& b,
                             SolverData& data);
void SolveVelocityConstraints(MouseJoint& joint, SolverData& data);
bool SolvePositionConstraints(MouseJoint& joint, SolverData& data);
JointReaction GetReaction(const MouseJoint& joint, Real invDt);

void InitVelocityConstraints(FrictionJoint& joint, const JointBody& a, const JointBody& b,
                             SolverData& data);
void SolveVelocityConstraints(FrictionJoint& joint, SolverData& data);
bool SolvePositionConstraints(FrictionJoint& joint, SolverData& data);
JointReaction GetReaction(const FrictionJoint& joint, Real invDt);

void InitVelocityConstraints(PulleyJoint& joint, const JointBody& a, const JointBody& b,
                             SolverData& data);
void SolveVelocityConstraints(PulleyJoint& joint, SolverData& data);
bool SolvePositionConstraints(PulleyJoint& joint, SolverData& data);
JointReaction GetReaction(const PulleyJoint& joint, Real invDt);
void InitVelocityConstraints(GearJoint& joint, const JointBody& a, const JointBody& b,
                             SolverData& data);
void SolveVelocityConstraints(GearJoint& joint, SolverData& data);
bool SolvePositionConstraints(GearJoint& joint, SolverData& data);
JointReaction GetReaction(const GearJoint& joint, Real invDt);

/// The rope's unit direction from a ground anchor to a body's anchor (offset d), or 0 when
/// the side is within 10 linear slops of its ground anchor (Box2D's cut-off); `length`
/// receives |d|.
Vec2 PulleyDirection(Vec2 d, Real linearSlop, Real& length);

} // namespace meff::detail
