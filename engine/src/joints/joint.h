// Joints inside the solver. Each joint type lives in its own file (revolute_joint.cpp,
// distance_joint.cpp, prismatic_joint.cpp, wheel_joint.cpp) and is reached through the functions at
// the bottom, which switch on the type. Every constraint row is solved with the scalar effective
// mass
//   k = 1/mA + 1/mB + (rA×n)²/IA + (rB×n)²/IB   (seed: effective-mass.md)
// and λ = −(Jv + bias)/k, following Box2D 2.4.1's sequential-impulse formulation.
#pragma once

#include "dynamics/solver_types.h"
#include "meff/joint.h"
#include "meff/world.h"

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
    // Accumulated impulses, carried from step to step for warm starting
    Vec2 impulse;
    Real motorImpulse = 0, lowerImpulse = 0, upperImpulse = 0;
    // Solver temporaries, set by InitJointVelocityConstraints
    std::int32_t indexA = 0, indexB = 0;
    Vec2 rA, rB, localCenterA, localCenterB;
    Real invMassA = 0, invMassB = 0, invIA = 0, invIB = 0;
    Mat22 K;
    Real angle = 0, axialMass = 0;
};

struct DistanceJoint
{
    // Definition
    Vec2 localAnchorA, localAnchorB;
    Real length = 1, minLength = 0, maxLength = kMaxReal;
    Real stiffness = 0; ///< N/m, from hertz and the bodies' masses at creation
    Real damping = 0;   ///< N·s/m
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
    Vec2 localXAxisA{1, 0}; ///< unit slide axis in A's frame
    Vec2 localYAxisA{0, 1}; ///< its perpendicular, 1 × localXAxisA
    Real referenceAngle = 0;
    bool enableLimit = false;
    Real lowerTranslation = 0, upperTranslation = 0;
    bool enableMotor = false;
    Real motorSpeed = 0, maxMotorForce = 0;
    // Accumulated impulses: (perpendicular, angular) block, then the axial rows
    Vec2 impulse;
    Real motorImpulse = 0, lowerImpulse = 0, upperImpulse = 0;
    // Solver temporaries
    std::int32_t indexA = 0, indexB = 0;
    Vec2 localCenterA, localCenterB;
    Real invMassA = 0, invMassB = 0, invIA = 0, invIB = 0;
    Vec2 axis, perp;     ///< world axis and perpendicular at the step's start
    Real s1 = 0, s2 = 0; ///< perpendicular row's angular Jacobian terms (A, B)
    Real a1 = 0, a2 = 0; ///< axial rows' angular Jacobian terms (A, B)
    Mat22 K;             ///< block of the perpendicular and angular rows
    Real translation = 0, axialMass = 0;
};

struct WheelJoint
{
    // Definition
    Vec2 localAnchorA, localAnchorB;
    Vec2 localXAxisA{1, 0}; ///< unit suspension axis in A's frame
    Vec2 localYAxisA{0, 1}; ///< its perpendicular, 1 × localXAxisA
    bool enableLimit = false;
    Real lowerTranslation = 0, upperTranslation = 0;
    bool enableMotor = false;
    Real motorSpeed = 0, maxMotorTorque = 0;
    Real stiffness = 0; ///< N/m, from hertz and the bodies' masses at creation
    Real damping = 0;   ///< N·s/m
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

struct Joint
{
    JointType type = JointType::Revolute;
    std::int32_t bodyA = -1; ///< world body index
    std::int32_t bodyB = -1;
    bool collideConnected = false;
    std::variant<RevoluteJoint, DistanceJoint, PrismaticJoint, WheelJoint> data;
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

/// The joint's anchors in its bodies' frames (m); side 0 is body A, 1 is body B.
Vec2 GetLocalAnchor(const Joint& joint, int side);

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

} // namespace meff::detail
