// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "solvers/soft_step/soft_joint.h"

#include <variant>

namespace meff::detail
{

void PrepareSoftJoint(Joint& joint, SoftJointFrame& frame, const JointBody& a, const JointBody& b,
                      const Position& poseA, const Position& poseB, Real warmScale,
                      const SoftStepContext& context)
{
    frame = SoftJointFrame{};
    frame.indexA = a.solverIndex;
    frame.indexB = b.solverIndex;
    frame.mA = a.invMass;
    frame.iA = a.invI;
    frame.mB = b.invMass;
    frame.iB = b.invI;
    frame.deltaCenter = poseB.c - poseA.c;
    std::visit(
        [&](auto& data)
        {
            StoreJointBodies(data, a, b); // local centres: the anchors' frames
            PrepareSoft(data, frame, poseA, poseB, context);
            ScaleImpulses(data, warmScale);
        },
        joint.data);
}

namespace
{

/// Runs `update(data, state, bodies)` on the joint's two bodies as they are now.
template <typename Update>
void UpdateSoftJoint(Joint& joint, const SoftJointFrame& frame, const SoftStepContext& context,
                     Update&& update)
{
    SoftBodies& bodies = *context.bodies;
    const SoftDelta& dA = bodies.deltas[frame.indexA];
    const SoftDelta& dB = bodies.deltas[frame.indexB];
    RowBodies b = LoadRowBodies(bodies.velocities.data(), frame.indexA, frame.indexB, frame.mA,
                                frame.iA, frame.mB, frame.iB);
    const SoftJointState state{frame, AnchorsNow(frame, dA, dB), dA, dB, context};
    std::visit([&](auto& data) { update(data, state, b); }, joint.data);
    StoreRowBodies(bodies.velocities.data(), frame.indexA, frame.indexB, b);
}

} // namespace

bool SoftJointSweeps(const Joint& joint, const SoftJointFrame& frame)
{
    const auto* revolute = std::get_if<RevoluteJoint>(&joint.data);
    return revolute == nullptr || !frame.pointInTree || revolute->enableSpring ||
           revolute->enableMotor || revolute->enableLimit;
}

void WarmStartSoftJoint(Joint& joint, const SoftJointFrame& frame, const SoftStepContext& context)
{
    UpdateSoftJoint(joint, frame, context,
                    [](auto& data, const SoftJointState& state, RowBodies& b)
                    { WarmStartSoft(data, state, b); });
}

void SolveSoftJoint(Joint& joint, const SoftJointFrame& frame, const SoftStepContext& context,
                    bool useBias)
{
    UpdateSoftJoint(joint, frame, context,
                    [useBias](auto& data, const SoftJointState& state, RowBodies& b)
                    { SolveSoft(data, state, useBias, b); });
}

void CorrectSoftJoint(const Joint& joint, const SoftJointFrame& frame,
                      const SoftStepContext& context)
{
    if (std::holds_alternative<MotorJoint>(joint.data) ||
        std::holds_alternative<MouseJoint>(joint.data) ||
        std::holds_alternative<FrictionJoint>(joint.data))
    {
        return;
    }
    Joint scratch = joint;
    std::visit(
        [](auto& data)
        {
            ScaleImpulses(data, 0);
            if constexpr (requires { data.enableMotor; })
            {
                data.enableMotor = false;
            }
        },
        scratch.data);
    SolveSoftJoint(scratch, frame, context, true);
}

void ScaleJointImpulses(Joint& joint, Real factor)
{
    std::visit([factor](auto& data) { ScaleImpulses(data, factor); }, joint.data);
}

} // namespace meff::detail
