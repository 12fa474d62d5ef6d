// Joint creation (validation, Box2D's constructor clamps, spring constants) and the dispatch
// from the type-erased Joint to the per-type solvers.
#include "joints/joint.h"

#include "meff/error.h"

#include <sstream>

namespace meff::detail
{

namespace
{

[[noreturn]] void Reject(const char* def, const char* field, Real value, const char* rule)
{
    std::ostringstream message;
    message.precision(9); // enough digits to print any float exactly
    message << def << '.' << field << " = " << value << ' ' << rule;
    throw InvalidArgument(message.str());
}

void RequireFinite(const char* def, const char* field, Real value)
{
    if (!IsValid(value))
    {
        Reject(def, field, value, "is not finite");
    }
}

void RequireFinite(const char* def, const char* field, Vec2 value)
{
    if (!value.IsValid())
    {
        std::ostringstream message;
        message.precision(9);
        message << def << '.' << field << " = (" << value.x << ", " << value.y << ") is not finite";
        throw InvalidArgument(message.str());
    }
}

void RequireNonNegative(const char* def, const char* field, Real value)
{
    RequireFinite(def, field, value);
    if (value < 0)
    {
        Reject(def, field, value, "must be >= 0");
    }
}

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

void RequireOrdered(const char* def, const char* lowerField, Real lower, const char* upperField,
                    Real upper)
{
    if (lower > upper)
    {
        std::ostringstream message;
        message.precision(9);
        message << def << '.' << lowerField << " = " << lower << " exceeds " << upperField << " = "
                << upper;
        throw InvalidArgument(message.str());
    }
}

/// The unit axis of a prismatic or wheel joint. A zero axis has no direction to slide along.
/// Normalized as b2Vec2::Normalize does (Box2D's prismatic constructor normalizes; its wheel
/// joint does not, so the Box2D mirror normalizes the wheel axis it hands over).
Vec2 RequireUnitAxis(const char* def, Vec2 axis)
{
    RequireFinite(def, "localAxisA", axis);
    Vec2 unit = axis;
    if (unit.Normalize() == 0)
    {
        std::ostringstream message;
        message.precision(9);
        message << def << ".localAxisA = (" << axis.x << ", " << axis.y
                << ") has no direction (length 0)";
        throw InvalidArgument(message.str());
    }
    return unit;
}

} // namespace

Joint MakeJoint(const RevoluteJointDef& def, std::int32_t bodyA, std::int32_t bodyB)
{
    constexpr const char* kDef = "RevoluteJointDef";
    RequireFinite(kDef, "localAnchorA", def.localAnchorA);
    RequireFinite(kDef, "localAnchorB", def.localAnchorB);
    RequireFinite(kDef, "referenceAngle", def.referenceAngle);
    RequireFinite(kDef, "lowerAngle", def.lowerAngle);
    RequireFinite(kDef, "upperAngle", def.upperAngle);
    RequireFinite(kDef, "motorSpeed", def.motorSpeed);
    RequireNonNegative(kDef, "maxMotorTorque", def.maxMotorTorque);
    if (def.lowerAngle > def.upperAngle)
    {
        std::ostringstream message;
        message.precision(9);
        message << kDef << ".lowerAngle = " << def.lowerAngle
                << " exceeds upperAngle = " << def.upperAngle;
        throw InvalidArgument(message.str());
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

    Joint joint;
    joint.type = JointType::Revolute;
    joint.bodyA = bodyA;
    joint.bodyB = bodyB;
    joint.collideConnected = def.collideConnected;
    joint.data = revolute;
    return joint;
}

Joint MakeJoint(const DistanceJointDef& def, std::int32_t bodyA, std::int32_t bodyB, Real massA,
                Real massB, const Tolerances& tolerances)
{
    constexpr const char* kDef = "DistanceJointDef";
    RequireFinite(kDef, "localAnchorA", def.localAnchorA);
    RequireFinite(kDef, "localAnchorB", def.localAnchorB);
    RequireFinite(kDef, "length", def.length);
    RequireFinite(kDef, "minLength", def.minLength);
    RequireFinite(kDef, "maxLength", def.maxLength);
    RequireNonNegative(kDef, "hertz", def.hertz);
    RequireNonNegative(kDef, "dampingRatio", def.dampingRatio);
    if (def.minLength > def.maxLength)
    {
        std::ostringstream message;
        message.precision(9);
        message << kDef << ".minLength = " << def.minLength
                << " exceeds maxLength = " << def.maxLength;
        throw InvalidArgument(message.str());
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

    Joint joint;
    joint.type = JointType::Distance;
    joint.bodyA = bodyA;
    joint.bodyB = bodyB;
    joint.collideConnected = def.collideConnected;
    joint.data = distance;
    return joint;
}

Joint MakeJoint(const PrismaticJointDef& def, std::int32_t bodyA, std::int32_t bodyB)
{
    constexpr const char* kDef = "PrismaticJointDef";
    RequireFinite(kDef, "localAnchorA", def.localAnchorA);
    RequireFinite(kDef, "localAnchorB", def.localAnchorB);
    const Vec2 axis = RequireUnitAxis(kDef, def.localAxisA);
    RequireFinite(kDef, "referenceAngle", def.referenceAngle);
    RequireFinite(kDef, "lowerTranslation", def.lowerTranslation);
    RequireFinite(kDef, "upperTranslation", def.upperTranslation);
    RequireFinite(kDef, "motorSpeed", def.motorSpeed);
    RequireNonNegative(kDef, "maxMotorForce", def.maxMotorForce);
    RequireOrdered(kDef, "lowerTranslation", def.lowerTranslation, "upperTranslation",
                   def.upperTranslation);

    PrismaticJoint prismatic;
    prismatic.localAnchorA = def.localAnchorA;
    prismatic.localAnchorB = def.localAnchorB;
    prismatic.localXAxisA = axis;
    prismatic.localYAxisA = Cross(Real(1), axis);
    prismatic.referenceAngle = def.referenceAngle;
    prismatic.enableLimit = def.enableLimit;
    prismatic.lowerTranslation = def.lowerTranslation;
    prismatic.upperTranslation = def.upperTranslation;
    prismatic.enableMotor = def.enableMotor;
    prismatic.motorSpeed = def.motorSpeed;
    prismatic.maxMotorForce = def.maxMotorForce;

    Joint joint;
    joint.type = JointType::Prismatic;
    joint.bodyA = bodyA;
    joint.bodyB = bodyB;
    joint.collideConnected = def.collideConnected;
    joint.data = prismatic;
    return joint;
}

Joint MakeJoint(const WheelJointDef& def, std::int32_t bodyA, std::int32_t bodyB, Real massA,
                Real massB)
{
    constexpr const char* kDef = "WheelJointDef";
    RequireFinite(kDef, "localAnchorA", def.localAnchorA);
    RequireFinite(kDef, "localAnchorB", def.localAnchorB);
    const Vec2 axis = RequireUnitAxis(kDef, def.localAxisA);
    RequireFinite(kDef, "lowerTranslation", def.lowerTranslation);
    RequireFinite(kDef, "upperTranslation", def.upperTranslation);
    RequireFinite(kDef, "motorSpeed", def.motorSpeed);
    RequireNonNegative(kDef, "maxMotorTorque", def.maxMotorTorque);
    RequireNonNegative(kDef, "hertz", def.hertz);
    RequireNonNegative(kDef, "dampingRatio", def.dampingRatio);
    RequireOrdered(kDef, "lowerTranslation", def.lowerTranslation, "upperTranslation",
                   def.upperTranslation);

    WheelJoint wheel;
    wheel.localAnchorA = def.localAnchorA;
    wheel.localAnchorB = def.localAnchorB;
    wheel.localXAxisA = axis;
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

    Joint joint;
    joint.type = JointType::Wheel;
    joint.bodyA = bodyA;
    joint.bodyB = bodyB;
    joint.collideConnected = def.collideConnected;
    joint.data = wheel;
    return joint;
}

Vec2 GetLocalAnchor(const Joint& joint, int side)
{
    return std::visit([side](const auto& j) { return side == 0 ? j.localAnchorA : j.localAnchorB; },
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
