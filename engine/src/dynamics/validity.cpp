// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The engine's acceptance rules (meff/validity.h), shared by World, MakeBox/MakePolygon and the
// scene loader.
#include "meff/validity.h"

#include "core/report_error.h"

#include "meff/error.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace meff
{

namespace
{

/// A computed quantity in a message: four significant digits.
std::string Approximately(double value)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4g", value);
    return buffer;
}

/// A value the solver may divide by: finite, and not zero or denormal (whose reciprocal
/// overflows, and which has lost its precision anyway).
bool IsNormalPositive(Real value)
{
    return std::isfinite(value) && value >= std::numeric_limits<Real>::min();
}

/// A limit as people read it: 3.4e+38.
std::string Limit(double value)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.2g", value);
    return buffer;
}

const std::string kLargest = Limit(double(std::numeric_limits<Real>::max()));
const std::string kSmallest = Limit(double(std::numeric_limits<Real>::min()));

/// "is beyond the engine's float" or "rounds to zero", for a quantity that must be normal.
std::string OutOfRange(Real value, double exact, const char* quantity, const char* unit)
{
    if (!std::isfinite(value))
    {
        const std::string amount =
            std::isfinite(exact) ? " " + Approximately(exact) + " " + unit : "";
        return std::string("too large: its ") + quantity + amount +
               " overflows the engine's float (at most " + kLargest + ")";
    }
    return std::string("too small: its ") + quantity + " " + Approximately(exact) + " " + unit +
           " is below the engine's smallest normal float (" + kSmallest +
           "), where it loses its precision and rounds to zero";
}

std::optional<Refusal> Refuse(std::string field, std::string reason)
{
    return Refusal{std::move(field), std::move(reason)};
}

const char* const kBuildPolygons = " (build polygons with MakePolygon or MakeBox)";

/// Twice the signed area of a polygon, in the engine's scalar and in double (for messages), as
/// a fan of triangles from the first vertex (Box2D's ComputeCentroid and ComputeMass).
void PolygonArea(const Polygon& polygon, Real& area, double& exactArea)
{
    area = 0;
    exactArea = 0;
    const Vec2 s = polygon.vertices[0];
    for (int i = 1; i + 1 < polygon.count; ++i)
    {
        const Vec2 e1 = polygon.vertices[i] - s;
        const Vec2 e2 = polygon.vertices[i + 1] - s;
        area += Real(0.5) * Cross(e1, e2);
        const double x1 = double(polygon.vertices[i].x) - s.x;
        const double y1 = double(polygon.vertices[i].y) - s.y;
        const double x2 = double(polygon.vertices[i + 1].x) - s.x;
        const double y2 = double(polygon.vertices[i + 1].y) - s.y;
        exactArea += 0.5 * (x1 * y2 - y1 * x2);
    }
}

std::optional<Refusal> CheckEdges(const Polygon& polygon)
{
    const int n = polygon.count;
    for (int i = 0; i < n; ++i)
    {
        const Vec2 a = polygon.vertices[i];
        const Vec2 b = polygon.vertices[i + 1 < n ? i + 1 : 0];
        const Vec2 edge = b - a;
        const double length = std::hypot(double(edge.x), double(edge.y));
        // The edge's direction gives its normal, and the collision routines square lengths.
        if (!std::isfinite(edge.LengthSquared()))
        {
            return Refuse("Polygon::vertices",
                          "too large: edge " + std::to_string(i) + " is " + Approximately(length) +
                              " m long, and its squared length overflows the engine's float");
        }
        if (!(edge.LengthSquared() > kEpsilon * kEpsilon))
        {
            return Refuse("Polygon::vertices", "edge " + std::to_string(i) + " is " +
                                                   Approximately(length) +
                                                   " m long: edges must be " + "longer than " +
                                                   NumberText(kEpsilon) + " m");
        }
        const Vec2 normal = polygon.normals[i];
        Vec2 expected = Cross(edge, Real(1));
        expected.Normalize();
        if (!normal.IsValid() || !(Dot(normal, expected) > Real(0.999)) ||
            !(std::abs(normal.LengthSquared() - 1) < Real(1e-3)))
        {
            return Refuse("Polygon::normals", "normals[" + std::to_string(i) +
                                                  "] is not the unit outward normal of its " +
                                                  "edge, got " + NumberText(normal) +
                                                  kBuildPolygons);
        }
        for (int j = 0; j < n; ++j)
        {
            if (j != i && j != (i + 1 < n ? i + 1 : 0) &&
                !(Cross(edge, polygon.vertices[j] - a) > 0))
            {
                return Refuse("Polygon::vertices",
                              "not strictly convex and counter-clockwise at vertex " +
                                  std::to_string(j) + kBuildPolygons);
            }
        }
    }
    return std::nullopt;
}

} // namespace

void ThrowRefusal(const Refusal& refusal)
{
    detail::ReportFatalError(RefusedArgument(refusal.field + ": " + refusal.reason, refusal));
}

bool detail::ReportRefusal(const Refusal& refusal)
{
    return Refuse(RefusedArgument(refusal.field + ": " + refusal.reason, refusal));
}

bool Require(const std::optional<Refusal>& refusal)
{
    return !refusal || detail::ReportRefusal(*refusal);
}

std::string NumberText(Real value)
{
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::string NumberText(Vec2 value)
{
    return "(" + NumberText(value.x) + ", " + NumberText(value.y) + ")";
}

std::optional<Refusal> CheckFinite(Real value, const char* field)
{
    if (!IsValid(value))
    {
        return Refuse(field, "must be finite, got " + NumberText(value));
    }
    return std::nullopt;
}

std::optional<Refusal> CheckFinite(Vec2 value, const char* field)
{
    if (!value.IsValid())
    {
        return Refuse(field, "must be finite, got " + NumberText(value));
    }
    return std::nullopt;
}

std::optional<Refusal> CheckNonNegative(Real value, const char* field)
{
    if (!IsValid(value) || !(value >= 0))
    {
        return Refuse(field, "must be finite and >= 0, got " + NumberText(value));
    }
    return std::nullopt;
}

std::optional<Refusal> CheckPositive(Real value, const char* field)
{
    if (!IsValid(value) || !(value > 0))
    {
        return Refuse(field, "must be finite and > 0, got " + NumberText(value));
    }
    return std::nullopt;
}

std::optional<Refusal> CheckCircle(const Circle& circle)
{
    if (auto refusal = CheckFinite(circle.center, "Circle::center"))
    {
        return refusal;
    }
    if (auto refusal = CheckPositive(circle.radius, "Circle::radius"))
    {
        return refusal;
    }
    // As ComputeMass evaluates it.
    const Real area = kPi * circle.radius * circle.radius;
    if (!IsNormalPositive(area))
    {
        const double exact = 3.141592653589793 * double(circle.radius) * double(circle.radius);
        return Refuse("Circle::radius",
                      OutOfRange(area, exact, "area", "m²") + ", got " + NumberText(circle.radius));
    }
    return std::nullopt;
}

std::optional<Refusal> CheckPolygon(const Polygon& polygon)
{
    if (polygon.count < 3 || polygon.count > kMaxPolygonVertices)
    {
        return Refuse("Polygon::count", "must be in [3, " + std::to_string(kMaxPolygonVertices) +
                                            "]" + kBuildPolygons + ", got " +
                                            std::to_string(polygon.count));
    }
    for (int i = 0; i < polygon.count; ++i)
    {
        if (!polygon.vertices[i].IsValid())
        {
            return Refuse("Polygon::vertices", "vertex " + std::to_string(i) +
                                                   " must be finite, got " +
                                                   NumberText(polygon.vertices[i]));
        }
    }
    if (std::optional<Refusal> edges = CheckEdges(polygon))
    {
        return edges;
    }
    Real area = 0;
    double exactArea = 0;
    PolygonArea(polygon, area, exactArea);
    if (!IsNormalPositive(area))
    {
        return Refuse("Polygon::vertices", OutOfRange(area, exactArea, "area", "m²"));
    }
    if (std::optional<Refusal> refusal = CheckFinite(polygon.centroid, "Polygon::centroid"))
    {
        return refusal;
    }
    // The manifolds of one-sided segments and of rounded polygons tell which side the polygon
    // is on by its centroid: one outside it turned their contacts off, or round, unsaid. Inside
    // up to a few roundings of the coordinates (a sliver's own centroid rounds to its edge):
    // of the largest, since the centroid is summed from the first vertex across the polygon.
    const Vec2 c = polygon.centroid;
    Real reach = std::abs(c.x) + std::abs(c.y);
    for (int i = 0; i < polygon.count; ++i)
    {
        reach = Max(reach, std::abs(polygon.vertices[i].x) + std::abs(polygon.vertices[i].y));
    }
    const Real tolerance = 16 * kEpsilon * reach;
    for (int i = 0; i < polygon.count; ++i)
    {
        if (!(Dot(polygon.normals[i], c - polygon.vertices[i]) <= tolerance))
        {
            return Refuse("Polygon::centroid", "must be inside the polygon (its area centroid" +
                                                   std::string(kBuildPolygons) + "), got " +
                                                   NumberText(c) + ", outside edge " +
                                                   std::to_string(i));
        }
    }
    return std::nullopt;
}

std::optional<Refusal> CheckPolygonRadius(const Polygon& polygon)
{
    return CheckNonNegative(polygon.radius, "Polygon::radius");
}

std::optional<Refusal> CheckCapsule(const Capsule& capsule, Real linearSlop)
{
    if (auto refusal = CheckFinite(capsule.center1, "Capsule::center1"))
    {
        return refusal;
    }
    if (auto refusal = CheckFinite(capsule.center2, "Capsule::center2"))
    {
        return refusal;
    }
    if (!(DistanceSquared(capsule.center1, capsule.center2) > linearSlop * linearSlop))
    {
        return Refuse("Capsule::center2",
                      "must be more than the linear slop (" + NumberText(linearSlop) +
                          " m) from center1 (a capsule with one centre is a circle), got " +
                          NumberText(capsule.center1) + " and " + NumberText(capsule.center2));
    }
    if (auto refusal = CheckPositive(capsule.radius, "Capsule::radius"))
    {
        return refusal;
    }
    // As ComputeMass adds it up: the caps and the two bands along the core.
    const Real length = Distance(capsule.center1, capsule.center2);
    const Real area = kPi * capsule.radius * capsule.radius + Real(2) * capsule.radius * length;
    if (!IsNormalPositive(area))
    {
        const double r = double(capsule.radius);
        const double exact = 3.141592653589793 * r * r + 2 * r * double(length);
        return Refuse("Capsule::radius", OutOfRange(area, exact, "area", "m²") + ", got " +
                                             NumberText(capsule.radius));
    }
    return std::nullopt;
}

std::optional<Refusal> CheckSegment(const Segment& segment, Real linearSlop)
{
    if (auto refusal = CheckFinite(segment.point1, "Segment::point1"))
    {
        return refusal;
    }
    if (auto refusal = CheckFinite(segment.point2, "Segment::point2"))
    {
        return refusal;
    }
    if (!(DistanceSquared(segment.point1, segment.point2) > linearSlop * linearSlop))
    {
        return Refuse("Segment::point2", "must be more than the linear slop (" +
                                             NumberText(linearSlop) + " m) from point1, got " +
                                             NumberText(segment.point1) + " and " +
                                             NumberText(segment.point2));
    }
    return std::nullopt;
}

std::optional<Refusal> CheckStepDt(Real dt)
{
    if (!(dt >= Real(kMinStepDt) && dt <= Real(kMaxStepDt)))
    {
        return Refuse("dt", "must be finite, from " + NumberText(Real(kMinStepDt)) + " to " +
                                NumberText(Real(kMaxStepDt)) + " s, got " + NumberText(dt));
    }
    return std::nullopt;
}

Real MaxDistanceJointLength()
{
    return std::sqrt(std::numeric_limits<Real>::max());
}

std::optional<Refusal> CheckShapeDef(const ShapeDef& def)
{
    const std::pair<const char*, Real> nonNegative[] = {
        {"ShapeDef::density", def.density},
        {"ShapeDef::friction", def.friction},
        {"ShapeDef::restitutionThreshold", def.restitutionThreshold},
        {"ShapeDef::rollingResistance", def.rollingResistance}};
    for (const auto& [field, value] : nonNegative)
    {
        if (auto refusal = CheckNonNegative(value, field))
        {
            return refusal;
        }
    }
    if (!IsValid(def.restitution) || !(def.restitution >= 0 && def.restitution <= 1))
    {
        return Refuse("ShapeDef::restitution",
                      "must be in [0, 1], got " + NumberText(def.restitution));
    }
    return CheckFinite(def.tangentSpeed, "ShapeDef::tangentSpeed");
}

namespace
{

/// The rules every shape's mass data obeys; `size` names the geometry field that sets the
/// inertia.
std::optional<Refusal> CheckMassData(const MassData& md, Real density, bool fixedRotation,
                                     const char* size)
{
    if (!IsNormalPositive(md.mass))
    {
        return Refuse("ShapeDef::density", OutOfRange(md.mass, double(md.mass), "mass", "kg") +
                                               " at density " + NumberText(density) + " kg/m²");
    }
    if (!md.center.IsValid() || !(md.mass * md.center).IsValid())
    {
        return Refuse(size, "too large: its centre of mass " + NumberText(md.center) +
                                " times its mass overflows the engine's float");
    }
    if (!fixedRotation && !IsNormalPositive(md.rotationalInertia))
    {
        return Refuse(size, OutOfRange(md.rotationalInertia, double(md.rotationalInertia),
                                       "rotational inertia about the body origin", "kg·m²") +
                                " at density " + NumberText(density) + " kg/m²");
    }
    return std::nullopt;
}

} // namespace

std::optional<Refusal> CheckMass(const Circle& circle, Real density, bool fixedRotation)
{
    return CheckMassData(ComputeMass(circle, density), density, fixedRotation, "Circle::radius");
}

std::optional<Refusal> CheckMass(const Polygon& polygon, Real density, bool fixedRotation)
{
    Real area = 0;
    double exactArea = 0;
    PolygonArea(polygon, area, exactArea);
    if (!(area > kEpsilon))
    {
        return Refuse("Polygon::vertices",
                      "too small to have a mass: its area " + Approximately(exactArea) +
                          " m² is not above " + NumberText(kEpsilon) +
                          " m² (Box2D 2.4.1 asserts as much; give it density 0 or make it larger)");
    }
    return CheckMassData(ComputeMass(polygon, density), density, fixedRotation,
                         "Polygon::vertices");
}

std::optional<Refusal> CheckMass(const Capsule& capsule, Real density, bool fixedRotation)
{
    return CheckMassData(ComputeMass(capsule, density), density, fixedRotation, "Capsule::radius");
}

std::optional<Refusal> CheckRoundedMass(const Polygon& polygon, Real density, bool fixedRotation)
{
    return CheckMassData(ComputeRoundedMass(polygon, density), density, fixedRotation,
                         "Polygon::radius");
}

BodyMass ComputeBodyMass(std::span<const MassData> shapesNewestFirst, bool fixedRotation)
{
    // b2Body::ResetMassData, operation for operation: meff and Box2D must agree bit for bit.
    BodyMass body;
    Vec2 localCenter{0, 0};
    Real inertia = 0;
    for (const MassData& md : shapesNewestFirst)
    {
        body.mass += md.mass;
        localCenter += md.mass * md.center;
        inertia += md.rotationalInertia;
    }
    if (body.mass > 0)
    {
        body.invMass = Real(1) / body.mass;
        localCenter *= body.invMass;
    }
    if (inertia > 0 && !fixedRotation)
    {
        inertia -= body.mass * Dot(localCenter, localCenter); // parallel-axis theorem
        // Only a body CheckBodyMass refuses gets here without a normal inertia (a shape
        // destroyed from a body that passed): it then turns as if its rotation were fixed.
        if (IsNormalPositive(inertia))
        {
            body.inertia = inertia;
            body.invInertia = Real(1) / inertia;
        }
    }
    body.localCenter = localCenter;
    return body;
}

std::optional<Refusal> CheckBodyMass(std::span<const MassData> shapesNewestFirst,
                                     bool fixedRotation)
{
    if (shapesNewestFirst.empty())
    {
        return std::nullopt; // no mass at all: allowed, as in Box2D (the body is not pushed)
    }
    Real mass = 0;
    Vec2 weighted{0, 0};
    Real inertia = 0;
    for (const MassData& md : shapesNewestFirst)
    {
        mass += md.mass;
        weighted += md.mass * md.center;
        inertia += md.rotationalInertia;
    }
    if (!std::isfinite(mass))
    {
        return Refuse("body", "too heavy: the mass of its shapes together overflows the engine's "
                              "float (at most " +
                                  kLargest + " kg)");
    }
    if (!weighted.IsValid() || !((Real(1) / mass) * weighted).IsValid())
    {
        return Refuse("body", "its centre of mass overflows the engine's float");
    }
    if (fixedRotation)
    {
        return std::nullopt;
    }
    if (!std::isfinite(inertia))
    {
        return Refuse("body", "its rotational inertia about the body origin overflows the engine's "
                              "float (at most " +
                                  kLargest + " kg·m²)");
    }
    // Moving the inertia to the centre of mass subtracts m·|c|² from it: when what is left is
    // within one rounding unit of the inertia about the origin, it is noise (or 0, or below).
    const BodyMass body = ComputeBodyMass(shapesNewestFirst, fixedRotation);
    if (!IsNormalPositive(body.inertia) || !(body.inertia > kEpsilon * inertia))
    {
        const Vec2 center = (Real(1) / mass) * weighted;
        return Refuse("body", "its rotational inertia about its centre of mass is lost to "
                              "rounding: its inertia about the body origin, " +
                                  Approximately(inertia) +
                                  " kg·m², is almost all the parallel-axis term of its centre of "
                                  "mass at " +
                                  NumberText(center) +
                                  " m, and subtracting that leaves "
                                  "nothing the engine's float can tell from 0; put the body origin "
                                  "near its shapes");
    }
    return std::nullopt;
}

std::optional<Refusal> CheckJointBodies(JointType type, bool sameBody, BodyType typeB)
{
    if (sameBody)
    {
        return Refuse("JointDef::bodyB", "must be a different body from bodyA");
    }
    if (type == JointType::Mouse && typeB != BodyType::Dynamic)
    {
        return Refuse("JointDef::bodyB", "must be dynamic for a mouse joint (it drags body B)");
    }
    return std::nullopt;
}

bool JointMovesAnything(BodyType typeA, BodyType typeB)
{
    return typeA == BodyType::Dynamic || typeB == BodyType::Dynamic;
}

} // namespace meff
