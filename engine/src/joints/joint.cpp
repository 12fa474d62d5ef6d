// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// Joint creation (validation, Box2D's constructor clamps, spring constants) and the dispatch
// from the type-erased Joint to the per-type solvers.
#include "joints/joint.h"

#include "core/report_error.h"
#include "meff/error.h"
#include "meff/validity.h"

#include <string>
#include <utility>

namespace meff::detail
{

namespace
{

/// Spring constants from a frequency and damping ratio, as Box2D's b2LinearStiffness: the
/// oscillator mass is the reduced mass mA·mB/(mA + mB) when both bodies are dynamic (seed,
/// "Reduced Effective Mass"), else the one dynamic body's mass. k = m·ω², c = 2·m·ζ·ω with
/// ω = 2πf. Our Box2D mirror calls b2LinearStiffness with the same inputs, so the products
/// are evaluated in its order: (m·ω)·ω and ((2·m)·ζ)·ω.
void LinearStiffness(Real& stiffness, Real& damping, Real hertz, Real dampingRatio, Real massA,
                     Real massB)
{
    Real mass;
    if (massA > 0 && massB > 0)
    {
        mass = massA * massB / (massA + massB);
    }
    else if (massA > 0)
    {
        mass = massA;
    }
    else
    {
        mass = massB;
    }
    const Real omega = Real(2) * kPi * hertz;
    stiffness = mass * omega * omega;
    damping = Real(2) * mass * dampingRatio * omega;
}

/// `lower` (the field named) at most `upper` (its sibling field, named as a member); false once
/// reported.
[[nodiscard]] bool RequireOrdered(const char* lowerField, Real lower, const char* upperMember,
                                  Real upper)
{
    if (lower > upper)
    {
        return ReportRefusal({lowerField, std::string("must not exceed ") + upperMember + " (" +
                                              NumberText(upper) + "), got " + NumberText(lower)});
    }
    return true;
}

/// The unit axis of a prismatic or wheel joint. A zero axis has no direction to slide along.
/// Normalized as b2Vec2::Normalize does (Box2D's prismatic constructor normalizes; its wheel
/// joint does not, so the Box2D mirror normalizes the wheel axis it hands over).
[[nodiscard]] bool RequireUnitAxis(const char* field, Vec2 axis, Vec2& unit)
{
    if (!RequireFinite(axis, field))
    {
        return false;
    }
    unit = axis;
    if (unit.Normalize() == 0)
    {
        return ReportRefusal(
            {field, "must have a direction (a length > 0), got " + NumberText(axis)});
    }
    return true;
}

/// Torsional spring constants from a frequency and damping ratio, as Box2D's
/// b2AngularStiffness: the oscillator inertia is IA·IB/(IA + IB) when both bodies have one,
/// else the one body's. k = I·ω², c = 2·I·ζ·ω with ω = 2πf, in b2AngularStiffness's order.
/// Box2D takes the inertias about the bodies' origins (b2Body::GetInertia), not their
/// centres of mass; the caller passes those.
void AngularStiffness(Real& stiffness, Real& damping, Real hertz, Real dampingRatio, Real inertiaA,
                      Real inertiaB)
{
    Real inertia;
    if (inertiaA > 0 && inertiaB > 0)
    {
        inertia = inertiaA * inertiaB / (inertiaA + inertiaB);
    }
    else if (inertiaA > 0)
    {
        inertia = inertiaA;
    }
    else
    {
        inertia = inertiaB;
    }
    const Real omega = Real(2) * kPi * hertz;
    stiffness = inertia * omega * omega;
    damping = Real(2) * inertia * dampingRatio * omega;
}

Joint MakeTypedJoint(JointType type, std::int32_t bodyA, std::int32_t bodyB, bool collideConnected)
{
    Joint joint;
    joint.type = type;
    joint.bodyA = bodyA;
    joint.bodyB = bodyB;
    joint.collideConnected = collideConnected;
    return joint;
}

} // namespace

Joint MakeJoint(const RevoluteJointDef& def, std::int32_t bodyA, std::int32_t bodyB)
{
    if (!RequireFinite(def.localAnchorA, "RevoluteJointDef::localAnchorA") ||
        !RequireFinite(def.localAnchorB, "RevoluteJointDef::localAnchorB") ||
        !RequireFinite(def.referenceAngle, "RevoluteJointDef::referenceAngle") ||
        !RequireFinite(def.lowerAngle, "RevoluteJointDef::lowerAngle") ||
        !RequireFinite(def.upperAngle, "RevoluteJointDef::upperAngle") ||
        !RequireFinite(def.motorSpeed, "RevoluteJointDef::motorSpeed") ||
        !RequireNonNegative(def.maxMotorTorque, "RevoluteJointDef::maxMotorTorque") ||
        !RequireNonNegative(def.hertz, "RevoluteJointDef::hertz") ||
        !RequireNonNegative(def.dampingRatio, "RevoluteJointDef::dampingRatio") ||
        !RequireFinite(def.targetAngle, "RevoluteJointDef::targetAngle") ||
        !RequireOrdered("RevoluteJointDef::lowerAngle", def.lowerAngle, "upperAngle",
                        def.upperAngle))
    {
        return {};
    }

    RevoluteJoint revolute;
    revolute.localAnchorA = def.localAnchorA;
    revolute.localAnchorB = def.localAnchorB;
    revolute.referenceAngle = def.referenceAngle;
    revolute.enableLimit = def.enableLimit;
    revolute.lowerAngle = def.lowerAngle;
    revolute.upperAngle = def.upperAngle;
    revolute.enableMotor = def.enableMotor;
    revolute.motorSpeed = def.motorSpeed;
    revolute.maxMotorTorque = def.maxMotorTorque;
    revolute.enableSpring = def.enableSpring;
    revolute.hertz = def.hertz;
    revolute.dampingRatio = def.dampingRatio;
    revolute.targetAngle = def.targetAngle;

    Joint joint = MakeTypedJoint(JointType::Revolute, bodyA, bodyB, def.collideConnected);
    joint.data = revolute;
    return joint;
}

Joint MakeJoint(const DistanceJointDef& def, std::int32_t bodyA, std::int32_t bodyB, Real massA,
                Real massB, const Tolerances& tolerances)
{
    if (!RequireFinite(def.localAnchorA, "DistanceJointDef::localAnchorA") ||
        !RequireFinite(def.localAnchorB, "DistanceJointDef::localAnchorB") ||
        !RequireFinite(def.length, "DistanceJointDef::length") ||
        !RequireFinite(def.minLength, "DistanceJointDef::minLength") ||
        !RequireFinite(def.maxLength, "DistanceJointDef::maxLength") ||
        !RequireNonNegative(def.hertz, "DistanceJointDef::hertz") ||
        !RequireNonNegative(def.dampingRatio, "DistanceJointDef::dampingRatio"))
    {
        return {};
    }
    for (const auto& [field, value] : {std::pair{"DistanceJointDef::length", def.length},
                                       {"DistanceJointDef::minLength", def.minLength}})
    {
        if (value > MaxDistanceJointLength())
        {
            ReportRefusal({field, "must be at most " + NumberText(MaxDistanceJointLength()) +
                                      " m (its square must be finite), got " + NumberText(value)});
            return {};
        }
    }
    if (!RequireOrdered("DistanceJointDef::minLength", def.minLength, "maxLength", def.maxLength))
    {
        return {};
    }

    DistanceJoint distance;
    distance.localAnchorA = def.localAnchorA;
    distance.localAnchorB = def.localAnchorB;
    // Box2D's constructor clamps: a length below the slop would make the direction u (and so
    // the row's Jacobian) ill-defined, and maxLength may not fall below the clamped minimum.
    const Real slop = tolerances.linearSlop;
    distance.length = Max(def.length, slop);
    distance.minLength = Max(def.minLength, slop);
    distance.maxLength = Max(def.maxLength, distance.minLength);
    LinearStiffness(distance.stiffness, distance.damping, def.hertz, def.dampingRatio, massA,
                    massB);
    distance.hertz = def.hertz;
    distance.dampingRatio = def.dampingRatio;

    Joint joint = MakeTypedJoint(JointType::Distance, bodyA, bodyB, def.collideConnected);
    joint.data = distance;
    return joint;
}

Joint MakeJoint(const PrismaticJointDef& def, std::int32_t bodyA, std::int32_t bodyB)
{
    Vec2 axis;
    if (!RequireFinite(def.localAnchorA, "PrismaticJointDef::localAnchorA") ||
        !RequireFinite(def.localAnchorB, "PrismaticJointDef::localAnchorB") ||
        !RequireUnitAxis("PrismaticJointDef::localAxisA", def.localAxisA, axis) ||
        !RequireFinite(def.referenceAngle, "PrismaticJointDef::referenceAngle") ||
        !RequireFinite(def.lowerTranslation, "PrismaticJointDef::lowerTranslation") ||
        !RequireFinite(def.upperTranslation, "PrismaticJointDef::upperTranslation") ||
        !RequireFinite(def.motorSpeed, "PrismaticJointDef::motorSpeed") ||
        !RequireNonNegative(def.maxMotorForce, "PrismaticJointDef::maxMotorForce") ||
        !RequireNonNegative(def.hertz, "PrismaticJointDef::hertz") ||
        !RequireNonNegative(def.dampingRatio, "PrismaticJointDef::dampingRatio") ||
        !RequireFinite(def.targetTranslation, "PrismaticJointDef::targetTranslation") ||
        !RequireOrdered("PrismaticJointDef::lowerTranslation", def.lowerTranslation,
                        "upperTranslation", def.upperTranslation))
    {
        return {};
    }

    PrismaticJoint prismatic;
    prismatic.localAnchorA = def.localAnchorA;
    prismatic.localAnchorB = def.localAnchorB;
    prismatic.localXAxisA = axis;
    prismatic.definedAxisA = def.localAxisA;
    prismatic.localYAxisA = Cross(Real(1), axis);
    prismatic.referenceAngle = def.referenceAngle;
    prismatic.enableLimit = def.enableLimit;
    prismatic.lowerTranslation = def.lowerTranslation;
    prismatic.upperTranslation = def.upperTranslation;
    prismatic.enableMotor = def.enableMotor;
    prismatic.motorSpeed = def.motorSpeed;
    prismatic.maxMotorForce = def.maxMotorForce;
    prismatic.enableSpring = def.enableSpring;
    prismatic.hertz = def.hertz;
    prismatic.dampingRatio = def.dampingRatio;
    prismatic.targetTranslation = def.targetTranslation;

    Joint joint = MakeTypedJoint(JointType::Prismatic, bodyA, bodyB, def.collideConnected);
    joint.data = prismatic;
    return joint;
}

Joint MakeJoint(const WheelJointDef& def, std::int32_t bodyA, std::int32_t bodyB, Real massA,
                Real massB)
{
    Vec2 axis;
    if (!RequireFinite(def.localAnchorA, "WheelJointDef::localAnchorA") ||
        !RequireFinite(def.localAnchorB, "WheelJointDef::localAnchorB") ||
        !RequireUnitAxis("WheelJointDef::localAxisA", def.localAxisA, axis) ||
        !RequireFinite(def.lowerTranslation, "WheelJointDef::lowerTranslation") ||
        !RequireFinite(def.upperTranslation, "WheelJointDef::upperTranslation") ||
        !RequireFinite(def.motorSpeed, "WheelJointDef::motorSpeed") ||
        !RequireNonNegative(def.maxMotorTorque, "WheelJointDef::maxMotorTorque") ||
        !RequireNonNegative(def.hertz, "WheelJointDef::hertz") ||
        !RequireNonNegative(def.dampingRatio, "WheelJointDef::dampingRatio") ||
        !RequireOrdered("WheelJointDef::lowerTranslation", def.lowerTranslation, "upperTranslation",
                        def.upperTranslation))
    {
        return {};
    }

    WheelJoint wheel;
    wheel.localAnchorA = def.localAnchorA;
    wheel.localAnchorB = def.localAnchorB;
    wheel.localXAxisA = axis;
    wheel.definedAxisA = def.localAxisA;
    wheel.localYAxisA = Cross(Real(1), axis);
    wheel.enableLimit = def.enableLimit;
    wheel.lowerTranslation = def.lowerTranslation;
    wheel.upperTranslation = def.upperTranslation;
    wheel.enableMotor = def.enableMotor;
    wheel.motorSpeed = def.motorSpeed;
    wheel.maxMotorTorque = def.maxMotorTorque;
    // The suspension's oscillator mass is the reduced mass of chassis and wheel, as the
    // testbed's car passes both bodies to b2LinearStiffness.
    LinearStiffness(wheel.stiffness, wheel.damping, def.hertz, def.dampingRatio, massA, massB);
    wheel.hertz = def.hertz;
    wheel.dampingRatio = def.dampingRatio;

    Joint joint = MakeTypedJoint(JointType::Wheel, bodyA, bodyB, def.collideConnected);
    joint.data = wheel;
    return joint;
}

Joint MakeJoint(const WeldJointDef& def, std::int32_t bodyA, std::int32_t bodyB, Real inertiaA,
                Real inertiaB)
{
    if (!RequireFinite(def.localAnchorA, "WeldJointDef::localAnchorA") ||
        !RequireFinite(def.localAnchorB, "WeldJointDef::localAnchorB") ||
        !RequireFinite(def.referenceAngle, "WeldJointDef::referenceAngle") ||
        !RequireNonNegative(def.hertz, "WeldJointDef::hertz") ||
        !RequireNonNegative(def.dampingRatio, "WeldJointDef::dampingRatio"))
    {
        return {};
    }

    WeldJoint weld;
    weld.localAnchorA = def.localAnchorA;
    weld.localAnchorB = def.localAnchorB;
    weld.referenceAngle = def.referenceAngle;
    // hertz = 0 gives stiffness 0: the rigid weld.
    AngularStiffness(weld.stiffness, weld.damping, def.hertz, def.dampingRatio, inertiaA, inertiaB);
    weld.hertz = def.hertz;
    weld.dampingRatio = def.dampingRatio;

    Joint joint = MakeTypedJoint(JointType::Weld, bodyA, bodyB, def.collideConnected);
    joint.data = weld;
    return joint;
}

Joint MakeJoint(const MotorJointDef& def, std::int32_t bodyA, std::int32_t bodyB)
{
    if (!RequireFinite(def.linearOffset, "MotorJointDef::linearOffset") ||
        !RequireFinite(def.angularOffset, "MotorJointDef::angularOffset") ||
        !RequireNonNegative(def.maxForce, "MotorJointDef::maxForce") ||
        !RequireNonNegative(def.maxTorque, "MotorJointDef::maxTorque") ||
        !RequireNonNegative(def.correctionFactor, "MotorJointDef::correctionFactor"))
    {
        return {};
    }
    if (def.correctionFactor > 1)
    {
        ReportRefusal({"MotorJointDef::correctionFactor",
                       "must be at most 1, got " + NumberText(def.correctionFactor)});
        return {};
    }

    MotorJoint motor;
    motor.linearOffset = def.linearOffset;
    motor.angularOffset = def.angularOffset;
    motor.maxForce = def.maxForce;
    motor.maxTorque = def.maxTorque;
    motor.correctionFactor = def.correctionFactor;

    Joint joint = MakeTypedJoint(JointType::Motor, bodyA, bodyB, def.collideConnected);
    joint.data = motor;
    return joint;
}

Joint MakeJoint(const FrictionJointDef& def, std::int32_t bodyA, std::int32_t bodyB)
{
    if (!RequireFinite(def.localAnchorA, "FrictionJointDef::localAnchorA") ||
        !RequireFinite(def.localAnchorB, "FrictionJointDef::localAnchorB") ||
        !RequireNonNegative(def.maxForce, "FrictionJointDef::maxForce") ||
        !RequireNonNegative(def.maxTorque, "FrictionJointDef::maxTorque"))
    {
        return {};
    }

    FrictionJoint friction;
    friction.localAnchorA = def.localAnchorA;
    friction.localAnchorB = def.localAnchorB;
    friction.maxForce = def.maxForce;
    friction.maxTorque = def.maxTorque;

    Joint joint = MakeTypedJoint(JointType::Friction, bodyA, bodyB, def.collideConnected);
    joint.data = friction;
    return joint;
}

Joint MakeJoint(const PulleyJointDef& def, std::int32_t bodyA, std::int32_t bodyB)
{
    // 0 would cut B's side off the rope; a negative ratio would make it push when pulled.
    if (!RequireFinite(def.groundAnchorA, "PulleyJointDef::groundAnchorA") ||
        !RequireFinite(def.groundAnchorB, "PulleyJointDef::groundAnchorB") ||
        !RequireFinite(def.localAnchorA, "PulleyJointDef::localAnchorA") ||
        !RequireFinite(def.localAnchorB, "PulleyJointDef::localAnchorB") ||
        !RequireNonNegative(def.lengthA, "PulleyJointDef::lengthA") ||
        !RequireNonNegative(def.lengthB, "PulleyJointDef::lengthB") ||
        !RequirePositive(def.ratio, "PulleyJointDef::ratio"))
    {
        return {};
    }

    PulleyJoint pulley;
    pulley.groundAnchorA = def.groundAnchorA;
    pulley.groundAnchorB = def.groundAnchorB;
    pulley.localAnchorA = def.localAnchorA;
    pulley.localAnchorB = def.localAnchorB;
    pulley.lengthA = def.lengthA;
    pulley.lengthB = def.lengthB;
    pulley.ratio = def.ratio;
    pulley.constant = def.lengthA + def.ratio * def.lengthB;

    Joint joint = MakeTypedJoint(JointType::Pulley, bodyA, bodyB, def.collideConnected);
    joint.data = pulley;
    return joint;
}

namespace
{

/// What a gear copies of one of its joints, and the joint's coordinate now.
struct GearSide
{
    bool prismatic = false;
    Vec2 localAnchorBase, localAnchorBody, localAxisBase;
    Real referenceAngle = 0;
    Real coordinate = 0; ///< the joint's angle (rad) or translation (m)
};

/// As Box2D's gear constructor: a prismatic side measures its translation from the
/// transforms, a revolute side its angle from the sweep angles.
GearSide MakeGearSide(const Joint& joint, const GearPose& body, const GearPose& base)
{
    GearSide side;
    if (const auto* revolute = std::get_if<RevoluteJoint>(&joint.data))
    {
        side.localAnchorBase = revolute->localAnchorA;
        side.localAnchorBody = revolute->localAnchorB;
        side.referenceAngle = revolute->referenceAngle;
        side.coordinate = body.angle - base.angle - side.referenceAngle;
        return side;
    }
    const auto& slider = std::get<PrismaticJoint>(joint.data);
    side.prismatic = true;
    side.localAnchorBase = slider.localAnchorA;
    side.localAnchorBody = slider.localAnchorB;
    side.referenceAngle = slider.referenceAngle;
    side.localAxisBase = slider.localXAxisA;
    const Vec2 pBody =
        MulT(base.xf.q, Mul(body.xf.q, side.localAnchorBody) + (body.xf.p - base.xf.p));
    side.coordinate = Dot(pBody - side.localAnchorBase, side.localAxisBase);
    return side;
}

} // namespace

Joint MakeJoint(const GearJointDef& def, const Joint& joint1, const Joint& joint2,
                const GearPose& a, const GearPose& b, const GearPose& c, const GearPose& d)
{
    if (!RequireFinite(def.ratio, "GearJointDef::ratio"))
    {
        return {};
    }
    const GearSide sideA = MakeGearSide(joint1, a, c);
    const GearSide sideB = MakeGearSide(joint2, b, d);

    GearJoint gear;
    gear.joint1 = def.joint1;
    gear.joint2 = def.joint2;
    gear.bodyC = joint1.bodyA;
    gear.bodyD = joint2.bodyA;
    gear.prismaticA = sideA.prismatic;
    gear.prismaticB = sideB.prismatic;
    gear.localAnchorA = sideA.localAnchorBody;
    gear.localAnchorC = sideA.localAnchorBase;
    gear.localAxisC = sideA.localAxisBase;
    gear.referenceAngleA = sideA.referenceAngle;
    gear.localAnchorB = sideB.localAnchorBody;
    gear.localAnchorD = sideB.localAnchorBase;
    gear.localAxisD = sideB.localAxisBase;
    gear.referenceAngleB = sideB.referenceAngle;
    gear.ratio = def.ratio;
    gear.constant = sideA.coordinate + gear.ratio * sideB.coordinate;

    Joint joint = MakeTypedJoint(JointType::Gear, joint1.bodyB, joint2.bodyB, def.collideConnected);
    joint.data = gear;
    return joint;
}

Joint MakeJoint(const MouseJointDef& def, std::int32_t bodyA, std::int32_t bodyB, Real massA,
                Real massB, const Transform& xfB, bool bodyBDynamic)
{
    if (!bodyBDynamic)
    {
        ReportError(
            InvalidArgument("MouseJointDef::bodyB: must be a dynamic body (the joint drags it)"));
        return {};
    }
    if (!RequireFinite(def.target, "MouseJointDef::target") ||
        !RequireNonNegative(def.maxForce, "MouseJointDef::maxForce") ||
        !RequireNonNegative(def.hertz, "MouseJointDef::hertz") ||
        !RequireNonNegative(def.dampingRatio, "MouseJointDef::dampingRatio"))
    {
        return {};
    }

    MouseJoint mouse;
    mouse.target = def.target;
    // The target grabs bodyB where it is now (Box2D's constructor).
    mouse.localAnchorB = MulT(xfB, def.target);
    mouse.maxForce = def.maxForce;
    LinearStiffness(mouse.stiffness, mouse.damping, def.hertz, def.dampingRatio, massA, massB);
    mouse.hertz = def.hertz;
    mouse.dampingRatio = def.dampingRatio;

    Joint joint = MakeTypedJoint(JointType::Mouse, bodyA, bodyB, def.collideConnected);
    joint.data = mouse;
    return joint;
}

Vec2 JointAnchorA(const Joint& joint, const Transform& xfA)
{
    if (const auto* mouse = std::get_if<MouseJoint>(&joint.data))
    {
        return mouse->target;
    }
    return std::visit(
        [&](const auto& j) -> Vec2
        {
            if constexpr (requires { j.localAnchorA; })
            {
                return Mul(xfA, j.localAnchorA);
            }
            else
            {
                return xfA.p; // the motor joint: body A's origin
            }
        },
        joint.data);
}

Vec2 JointAnchorB(const Joint& joint, const Transform& xfB)
{
    return std::visit(
        [&](const auto& j) -> Vec2
        {
            if constexpr (requires { j.localAnchorB; })
            {
                return Mul(xfB, j.localAnchorB);
            }
            else
            {
                return xfB.p; // the motor joint: body B's origin
            }
        },
        joint.data);
}

// The variant's alternative is the joint's type; the JointType tag exists for callers that
// only need to ask. std::visit picks the per-type overload.

void InitJointVelocityConstraints(Joint& joint, const JointBody& a, const JointBody& b,
                                  SolverData& data)
{
    std::visit([&](auto& j) { InitVelocityConstraints(j, a, b, data); }, joint.data);
}

void SolveJointVelocityConstraints(Joint& joint, SolverData& data)
{
    std::visit([&](auto& j) { SolveVelocityConstraints(j, data); }, joint.data);
}

bool SolveJointPositionConstraints(Joint& joint, SolverData& data)
{
    return std::visit([&](auto& j) { return SolvePositionConstraints(j, data); }, joint.data);
}

JointReaction GetJointReaction(const Joint& joint, Real invDt)
{
    return std::visit([&](const auto& j) { return GetReaction(j, invDt); }, joint.data);
}

} // namespace meff::detail
