// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The joints of the soft step. Every joint type keeps its definition, and its accumulated
// impulses between steps, in its joint (joints/joint.h: the same members the Box2D back end
// uses, stored per step); what the soft rows add is each joint's frame at the step's start —
// anchors from the centres of mass, the gap between the centres, angles and axes — from which
// every sub-step measures the joint's error through the bodies' motion since (soft_bodies.h).
//
// Rigid rows (points, rigid lengths, perpendicular and angular locks, limits) are solved soft
// with SoftStepContext::joint while solving and rigidly while relaxing; a joint's own spring
// (distance, wheel, weld, mouse; revolute and prismatic when enabled) is a real spring and
// acts once per kick, while solving
// (softness.h: SpringSoftness); motors are velocity rows bounded by their force or torque × h.
#pragma once

#include "joints/joint.h"
#include "solvers/soft_step/soft_row.h"
#include "solvers/soft_step/soft_step_context.h"

#include <cstdint>

namespace meff::detail
{

/// A joint's frame at the step's start.
struct SoftJointFrame
{
    std::int32_t indexA = 0, indexB = 0; ///< solver indices
    Real mA = 0, iA = 0, mB = 0, iB = 0; ///< 1/kg, 1/(kg·m²)
    Vec2 rA0, rB0;                       ///< anchors from the centres of mass, world axes (m)
    Vec2 deltaCenter;                    ///< cB − cA (m); the mouse: cB − target
    Real angle0 = 0;                     ///< aB − aA − reference angle (rad)
    Vec2 axis0;                          ///< prismatic and wheel: the slide axis in world axes
    Vec2 ropeA0, ropeB0;                 ///< pulley: each anchor from its ground anchor (m)
    Softness spring;     ///< the joint's own spring over a sub-step, where it has one
    Softness halfSpring; ///< the same over half a sub-step (velocity Verlet's half kicks)
    /// A revolute joint's point rows are solved with the others of its tree (SoftJointTree),
    /// not by its own update.
    bool pointInTree = false;
};

/// Sets the frame's spring (SpringSoftness) of stiffness and damping on a row of inverse
/// effective mass k.
inline void SetSpring(SoftJointFrame& frame, Real stiffness, Real damping, Real k,
                      const SoftStepContext& context)
{
    frame.spring = SpringSoftness(stiffness, damping, k, context.h);
    frame.halfSpring = SpringSoftness(stiffness, damping, k, Real(0.5) * context.h);
}

/// Sets the frame's spring from a natural frequency (Hz) and damping ratio on the row's own
/// effective mass (the revolute and prismatic springs: FrequencySpringSoftness).
inline void SetFrequencySpring(SoftJointFrame& frame, Real hertz, Real dampingRatio,
                               const SoftStepContext& context)
{
    frame.spring = FrequencySpringSoftness(hertz, dampingRatio, context.h);
    frame.halfSpring = FrequencySpringSoftness(hertz, dampingRatio, Real(0.5) * context.h);
}

/// The joint's anchors now and the vector between them (anchor B − anchor A, m).
struct SoftAnchors
{
    Vec2 rA, rB, d;
};

inline SoftAnchors AnchorsNow(const SoftJointFrame& f, const SoftDelta& dA, const SoftDelta& dB)
{
    const Vec2 rA = Mul(dA.dq, f.rA0);
    const Vec2 rB = Mul(dB.dq, f.rB0);
    return {rA, rB, (dB.dp - dA.dp) + f.deltaCenter + (rB - rA)};
}

/// What one update of a joint's rows sees of it now.
struct SoftJointState
{
    const SoftJointFrame& frame;
    SoftAnchors at; ///< anchors now
    SoftDelta dA;   ///< body A's motion since the step began
    SoftDelta dB;   ///< body B's
    const SoftStepContext& context;

    /// B's rotation relative to A since the step began (rad).
    Real Rotation() const { return RelativeRotation(dA.dq, dB.dq); }

    /// The joint's spring for this sweep (it acts once per kick: while solving, and in the
    /// closing half kick), or null.
    const Softness* Spring(bool useBias) const
    {
        if ((!useBias && !context.closing) || context.correcting)
        {
            return nullptr;
        }
        return context.halfKick ? &frame.halfSpring : &frame.spring;
    }
};

/// A line joint's (prismatic, wheel) slide axis and its perpendicular now: the axis fixed in A
/// (frame.axis0 at the step's start) turned with A since.
struct SlideAxes
{
    Vec2 axis, perp;
};

inline SlideAxes SlideAxesNow(const SoftJointState& state)
{
    const Vec2 axis = Mul(state.dA.dq, state.frame.axis0);
    return {axis, Cross(Real(1), axis)};
}

// Per joint type (soft_<type>_joint.cpp): the type's part of the frame (anchors, centres and
// masses are set already), its warm start, one update of its rows on its bodies `b`, and the
// scaling of its accumulated impulses.
void PrepareSoft(RevoluteJoint& joint, SoftJointFrame& frame, const Position& poseA,
                 const Position& poseB, const SoftStepContext& context);
void WarmStartSoft(const RevoluteJoint& joint, const SoftJointState& state, RowBodies& b);
void SolveSoft(RevoluteJoint& joint, const SoftJointState& state, bool useBias, RowBodies& b);
void ScaleImpulses(RevoluteJoint& joint, Real factor);
void PrepareSoft(PrismaticJoint& joint, SoftJointFrame& frame, const Position& poseA,
                 const Position& poseB, const SoftStepContext& context);
void WarmStartSoft(const PrismaticJoint& joint, const SoftJointState& state, RowBodies& b);
void SolveSoft(PrismaticJoint& joint, const SoftJointState& state, bool useBias, RowBodies& b);
void ScaleImpulses(PrismaticJoint& joint, Real factor);
void PrepareSoft(WheelJoint& joint, SoftJointFrame& frame, const Position& poseA,
                 const Position& poseB, const SoftStepContext& context);
void WarmStartSoft(const WheelJoint& joint, const SoftJointState& state, RowBodies& b);
void SolveSoft(WheelJoint& joint, const SoftJointState& state, bool useBias, RowBodies& b);
void ScaleImpulses(WheelJoint& joint, Real factor);
void PrepareSoft(DistanceJoint& joint, SoftJointFrame& frame, const Position& poseA,
                 const Position& poseB, const SoftStepContext& context);
void WarmStartSoft(const DistanceJoint& joint, const SoftJointState& state, RowBodies& b);
void SolveSoft(DistanceJoint& joint, const SoftJointState& state, bool useBias, RowBodies& b);
void ScaleImpulses(DistanceJoint& joint, Real factor);
void PrepareSoft(WeldJoint& joint, SoftJointFrame& frame, const Position& poseA,
                 const Position& poseB, const SoftStepContext& context);
void WarmStartSoft(const WeldJoint& joint, const SoftJointState& state, RowBodies& b);
void SolveSoft(WeldJoint& joint, const SoftJointState& state, bool useBias, RowBodies& b);
void ScaleImpulses(WeldJoint& joint, Real factor);
void PrepareSoft(MotorJoint& joint, SoftJointFrame& frame, const Position& poseA,
                 const Position& poseB, const SoftStepContext& context);
void WarmStartSoft(const MotorJoint& joint, const SoftJointState& state, RowBodies& b);
void SolveSoft(MotorJoint& joint, const SoftJointState& state, bool useBias, RowBodies& b);
void ScaleImpulses(MotorJoint& joint, Real factor);
void PrepareSoft(MouseJoint& joint, SoftJointFrame& frame, const Position& poseA,
                 const Position& poseB, const SoftStepContext& context);
void WarmStartSoft(const MouseJoint& joint, const SoftJointState& state, RowBodies& b);
void SolveSoft(MouseJoint& joint, const SoftJointState& state, bool useBias, RowBodies& b);
void ScaleImpulses(MouseJoint& joint, Real factor);
void PrepareSoft(FrictionJoint& joint, SoftJointFrame& frame, const Position& poseA,
                 const Position& poseB, const SoftStepContext& context);
void WarmStartSoft(const FrictionJoint& joint, const SoftJointState& state, RowBodies& b);
void SolveSoft(FrictionJoint& joint, const SoftJointState& state, bool useBias, RowBodies& b);
void ScaleImpulses(FrictionJoint& joint, Real factor);
void PrepareSoft(PulleyJoint& joint, SoftJointFrame& frame, const Position& poseA,
                 const Position& poseB, const SoftStepContext& context);
void WarmStartSoft(const PulleyJoint& joint, const SoftJointState& state, RowBodies& b);
void SolveSoft(PulleyJoint& joint, const SoftJointState& state, bool useBias, RowBodies& b);
void ScaleImpulses(PulleyJoint& joint, Real factor);

// The gear acts on four bodies: its functions take A and B in `b` as every joint, and reach
// its bodies C and D (the bodies its two joints are anchored on) through the context.
void PrepareSoft(GearJoint& joint, SoftJointFrame& frame, const Position& poseA,
                 const Position& poseB, const SoftStepContext& context);
void WarmStartSoft(const GearJoint& joint, const SoftJointState& state, RowBodies& b);
void SolveSoft(GearJoint& joint, const SoftJointState& state, bool useBias, RowBodies& b);
void ScaleImpulses(GearJoint& joint, Real factor);

/// Prepares the frame of a joint whose bodies are `a`, `b` (their poses at the step's start),
/// and scales its stored per-step impulses to this sub-step (`warmScale`; 0 without warm
/// starting).
void PrepareSoftJoint(Joint& joint, SoftJointFrame& frame, const JointBody& a, const JointBody& b,
                      const Position& poseA, const Position& poseB, Real warmScale,
                      const SoftStepContext& context);
/// The joint's part of the joints' position pass (context.correcting, context.joint the
/// correction): its rigid rows solved once on the pseudo-velocities in context.bodies, from
/// impulses of zero that are then dropped (the joint's own accumulated impulses do not change).
/// Joints without rigid rows (motor, mouse, friction) do nothing.
void CorrectSoftJoint(const Joint& joint, const SoftJointFrame& frame,
                      const SoftStepContext& context);
/// Whether SolveSoftJoint and CorrectSoftJoint have rows of the joint to update: false for a
/// revolute joint whose point rows its tree solves and that has no spring, motor or limit.
bool SoftJointSweeps(const Joint& joint, const SoftJointFrame& frame);
/// Applies the joint's accumulated sub-step impulses.
void WarmStartSoftJoint(Joint& joint, const SoftJointFrame& frame, const SoftStepContext& context);
/// One update of every row of the joint.
void SolveSoftJoint(Joint& joint, const SoftJointFrame& frame, const SoftStepContext& context,
                    bool useBias);
/// Scales the joint's accumulated impulses by `factor` (sub-step ↔ step).
void ScaleJointImpulses(Joint& joint, Real factor);

} // namespace meff::detail
