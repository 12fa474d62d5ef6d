// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// What the engine accepts: the rules World's Create calls (and MakeBox, MakePolygon) apply,
// as functions that say why without throwing, so that a loader can check a whole level before
// creating anything and report each problem at its own field. The scene loader does, so that a
// scene file is refused exactly when, and for the reason, the library would refuse it.
//
// The rules are Box2D 2.4.1's, plus what keeps the step finite: nothing that passes them trips
// an assertion of libbox2d built from the same numbers (its validation mirror), and no mass,
// inertia or area is non-finite, zero or denormal where the solver divides by it.
#pragma once

#include "meff/body.h"
#include "meff/collision.h"
#include "meff/error.h"
#include "meff/joint.h"
#include "meff/shape.h"

#include <optional>
#include <span>
#include <string>
#include <utility>

namespace meff
{

/// Why something would be refused.
struct Refusal
{
    /// What is at fault, as the API names it: "Circle::radius", "Polygon::vertices",
    /// "Segment::point2", "ShapeDef::density", "body" (the body's shapes together),
    /// "JointDef::bodyB".
    std::string field;
    std::string reason; ///< why, with the value: "must be finite and > 0, got -1"
};

/// What World, MakeBox, MakeOffsetBox and MakePolygon throw when one of these rules refuses
/// an argument: an InvalidArgument that also carries the refusal.
class RefusedArgument : public InvalidArgument
{
  public:
    /// The message and the refusal it reports.
    RefusedArgument(const std::string& what, Refusal refusal)
        : InvalidArgument(what), m_refusal(std::move(refusal))
    {
    }
    /// Which field was refused, and why.
    const Refusal& refusal() const { return m_refusal; }

  private:
    Refusal m_refusal;
};

/// The refusal as World throws it: RefusedArgument("FIELD: REASON"). In an engine built
/// without exceptions (MEFF_EXCEPTIONS=OFF), the error handler gets the message, then
/// std::abort() ends the program: World's calls report a refusal and return instead.
[[noreturn]] void ThrowRefusal(const Refusal& refusal);

/// Reports the refusal, if there is one, as RefusedArgument("FIELD: REASON") and returns
/// false; true when there is none: how World, the joints and the queries apply these rules to
/// their arguments, `if (!Require(...)) { return {}; }`. Thrown with exceptions (the default);
/// in an engine built without them (MEFF_EXCEPTIONS=OFF), the error handler gets the message.
[[nodiscard]] bool Require(const std::optional<Refusal>& refusal);

// Numbers: the checks every argument of World goes through, and the one way its messages
// write a number. `field` names the argument as the message should ("BodyDef::position",
// "RevoluteJointDef::hertz", "World::ApplyForce: force"); the reason is formatted only when
// the value is refused.

/// The shortest text that reads back as the same value: "0.1", "-2", "1e+30", "inf", "nan".
std::string NumberText(Real value);
/// "(x, y)", each coordinate as NumberText writes it.
std::string NumberText(Vec2 value);
/// "must be finite, got V".
std::optional<Refusal> CheckFinite(Real value, const char* field);
std::optional<Refusal> CheckFinite(Vec2 value, const char* field);
/// "must be finite and >= 0, got V".
std::optional<Refusal> CheckNonNegative(Real value, const char* field);
/// "must be finite and > 0, got V".
std::optional<Refusal> CheckPositive(Real value, const char* field);
/// The checks as World applies them (Require): RefusedArgument("FIELD: must be finite, got V")
/// and so on; false once reported.
[[nodiscard]] inline bool RequireFinite(Real value, const char* field)
{
    return Require(CheckFinite(value, field));
}
[[nodiscard]] inline bool RequireFinite(Vec2 value, const char* field)
{
    return Require(CheckFinite(value, field));
}
[[nodiscard]] inline bool RequireNonNegative(Real value, const char* field)
{
    return Require(CheckNonNegative(value, field));
}
[[nodiscard]] inline bool RequirePositive(Real value, const char* field)
{
    return Require(CheckPositive(value, field));
}

// Shapes, on their own (any body). Circles: a finite centre, a finite radius > 0, and an area
// πr² that is a normal float (neither overflowing nor rounding to zero or a denormal).
std::optional<Refusal> CheckCircle(const Circle& circle);
/// 3 to 8 finite vertices, counter-clockwise and strictly convex, every edge longer than
/// kEpsilon (m) and not so long that its squared length overflows, each normal the unit
/// outward normal of its edge, a normal, finite area, and a finite centroid inside it. What
/// MakePolygon and MakeBox return always passes.
std::optional<Refusal> CheckPolygon(const Polygon& polygon);
/// A finite radius >= 0 (above Tolerances::polygonSkin it rounds the polygon).
std::optional<Refusal> CheckPolygonRadius(const Polygon& polygon);
/// Finite centres further apart than `linearSlop`, a finite radius > 0, and an area
/// πr² + 2rL that is a normal float.
std::optional<Refusal> CheckCapsule(const Capsule& capsule, Real linearSlop);
/// Finite points further apart than `linearSlop` (Tolerances::linearSlop).
std::optional<Refusal> CheckSegment(const Segment& segment, Real linearSlop);
/// Density and friction finite and >= 0, restitution in [0, 1], restitution threshold finite
/// and >= 0.
std::optional<Refusal> CheckShapeDef(const ShapeDef& def);

/// The longest and shortest step World::Step takes (s), and a scene's world.dt. Above 1 s a
/// step is no simulation (the solvers clamp a body's motion to 2 m and a quarter turn per step:
/// Step(1e30) froze every body); below 1e-9 s the step's 1/dt and dt² leave the float range
/// (a denormal dt passed the old check, then stopped the step with a non-finite state).
inline constexpr double kMaxStepDt = 1.0;
inline constexpr double kMinStepDt = 1e-9;
/// A finite dt in [kMinStepDt, kMaxStepDt] (field "dt").
std::optional<Refusal> CheckStepDt(Real dt);

/// The longest rest length (and minimum length) a distance joint may have (m): the solvers
/// square it, so its square must be a finite Real, about 1.8e19 m in float. A length of 3.4e38
/// was accepted, then stopped step 0 with a non-finite state. The maximum length is not bound:
/// Box2D's default, FLT_MAX, means no upper limit.
Real MaxDistanceJointLength();

// Mass. Only a dynamic body's shapes with density > 0 have mass (segments never do), as in
// Box2D 2.4.1's b2Body::ResetMassData.

/// One shape's mass at `density` (> 0), on a dynamic body: a normal, finite mass, and unless
/// the body has fixed rotation a normal, finite rotational inertia. A polygon's area must also
/// exceed kEpsilon, as Box2D's b2PolygonShape::ComputeMass asserts.
std::optional<Refusal> CheckMass(const Circle& circle, Real density, bool fixedRotation);
std::optional<Refusal> CheckMass(const Polygon& polygon, Real density, bool fixedRotation);
std::optional<Refusal> CheckMass(const Capsule& capsule, Real density, bool fixedRotation);
/// A rounded polygon (radius above the skin): its rounded mass (ComputeRoundedMass).
std::optional<Refusal> CheckRoundedMass(const Polygon& polygon, Real density, bool fixedRotation);

/// A dynamic body's mass properties, from its shapes' MassData (ComputeMass) in the order
/// World keeps its shapes, newest first, as b2Body::ResetMassData sums its fixture list: the
/// mass, the centre of mass in body coordinates and, unless the rotation is fixed, the inertia
/// about the centre of mass (parallel-axis theorem), with their inverses (0 for no mass).
struct BodyMass
{
    Real mass = 0;       ///< kg
    Real invMass = 0;    ///< 1/kg
    Real inertia = 0;    ///< about the centre of mass (kg·m²)
    Real invInertia = 0; ///< 1/(kg·m²)
    Vec2 localCenter{};  ///< centre of mass in body coordinates (m)
};
BodyMass ComputeBodyMass(std::span<const MassData> shapesNewestFirst, bool fixedRotation);
/// Whether a body with these shapes (each already passing CheckMass) can be simulated: a
/// finite total mass and centre of mass, and unless the rotation is fixed a normal, finite
/// inertia about the centre of mass that is more than one rounding unit (kEpsilon) of the
/// inertia about the body origin. (A small shape far from the body origin has a huge inertia
/// about the origin, and moving it to the centre of mass subtracts two huge numbers: what is
/// left is rounding noise, or 0 or below, which Box2D asserts against.)
std::optional<Refusal> CheckBodyMass(std::span<const MassData> shapesNewestFirst,
                                     bool fixedRotation);

// Joints.

/// Which bodies a joint of `type` may connect: two different bodies, and for a mouse joint a
/// dynamic body B. A joint whose bodies are both static or kinematic is accepted, as Box2D
/// accepts it, though it does nothing (JointMovesAnything).
std::optional<Refusal> CheckJointBodies(JointType type, bool sameBody, BodyType typeB);
/// Whether a joint between bodies of these types can move anything: one of them is dynamic.
bool JointMovesAnything(BodyType typeA, BodyType typeB);

} // namespace meff
