// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
#include "engine_shapes.h"

#include "meff/validity.h"

#include <cmath>
#include <vector>

namespace meff::scene_detail
{

EngineShape ToEngineShape(const SceneShape& shape)
{
    switch (shape.type)
    {
    case SceneShapeType::Circle:
        return Circle{ToEngine(shape.center), Real(shape.radius)};
    case SceneShapeType::Box:
    {
        Polygon box = MakeOffsetBox(Real(shape.halfWidth), Real(shape.halfHeight),
                                    ToEngine(shape.center), Real(shape.angle));
        box.radius = Real(shape.rounding); // rounded above the skin, else sharp
        return box;
    }
    case SceneShapeType::Polygon:
    {
        std::vector<Vec2> points;
        points.reserve(shape.vertices.size());
        for (const SceneVec2& vertex : shape.vertices)
        {
            points.push_back(ToEngine(vertex));
        }
        Polygon polygon = MakePolygon(points);
        polygon.radius = Real(shape.rounding);
        return polygon;
    }
    case SceneShapeType::Capsule:
        return Capsule{ToEngine(shape.centerA), ToEngine(shape.centerB), Real(shape.radius)};
    case SceneShapeType::Segment:
    {
        Segment segment;
        segment.point1 = ToEngine(shape.point1);
        segment.point2 = ToEngine(shape.point2);
        if (shape.oneSided)
        {
            return ChainSegment{ToEngine(shape.prev.value_or(shape.point1)), segment,
                                ToEngine(shape.next.value_or(shape.point2))};
        }
        return segment;
    }
    case SceneShapeType::Chain:
        break;
    }
    throw InvalidArgument("ToEngineShape: chains are made by World::CreateChain");
}

ShapeDef ToShapeDef(const SceneShape& shape)
{
    ShapeDef def;
    def.density = Real(shape.density);
    def.friction = Real(shape.friction);
    def.restitution = Real(shape.restitution);
    def.restitutionThreshold = Real(shape.restitutionThreshold);
    def.tangentSpeed = Real(shape.tangentSpeed);
    def.rollingResistance = Real(shape.rollingResistance);
    def.filter.categoryBits = shape.filter.category;
    def.filter.maskBits = shape.filter.mask;
    def.filter.groupIndex = shape.filter.group;
    def.isSensor = shape.sensor;
    return def;
}

bool HasMass(const SceneShape& shape)
{
    return shape.density > 0 && shape.type != SceneShapeType::Segment &&
           shape.type != SceneShapeType::Chain;
}

std::string SceneField(const SceneShape& shape, const std::string& engineField)
{
    if (engineField == "body")
    {
        return "";
    }
    if (engineField == "Polygon::radius")
    {
        return "radius";
    }
    if (engineField.rfind("Polygon::", 0) == 0)
    {
        if (shape.type != SceneShapeType::Box)
        {
            return "vertices";
        }
        // The half extent furthest from 1 m (by ratio) is what made the box too large or too
        // thin.
        return std::abs(std::log(shape.halfWidth)) >= std::abs(std::log(shape.halfHeight))
                   ? "half_width"
                   : "half_height";
    }
    if (engineField.rfind("Segment::", 0) == 0)
    {
        return "points";
    }
    if (engineField == "Capsule::center1")
    {
        return "center_a";
    }
    if (engineField == "Capsule::center2")
    {
        return "center_b";
    }
    const std::size_t colon = engineField.rfind("::");
    const std::string member =
        colon == std::string::npos ? engineField : engineField.substr(colon + 2);
    if (member == "restitutionThreshold")
    {
        return "restitution_threshold";
    }
    if (member == "tangentSpeed")
    {
        return "tangent_speed";
    }
    if (member == "rollingResistance")
    {
        return "rolling_resistance";
    }
    return member; // radius, center, density, friction, restitution
}

namespace
{

std::optional<Refusal> CheckGeometry(const EngineShape& geometry)
{
    if (const Circle* circle = std::get_if<Circle>(&geometry))
    {
        return CheckCircle(*circle);
    }
    if (const Segment* segment = std::get_if<Segment>(&geometry))
    {
        return CheckSegment(*segment, Tolerances{}.linearSlop);
    }
    if (const ChainSegment* segment = std::get_if<ChainSegment>(&geometry))
    {
        return CheckSegment(segment->segment, Tolerances{}.linearSlop);
    }
    if (const Capsule* capsule = std::get_if<Capsule>(&geometry))
    {
        return CheckCapsule(*capsule, Tolerances{}.linearSlop);
    }
    return std::nullopt; // MakePolygon and MakeOffsetBox checked it already
}

/// Rounded as the world decides (World::CreateShape): a radius above the skin.
bool IsRounded(const Polygon& polygon)
{
    return polygon.radius > Tolerances{}.polygonSkin;
}

std::optional<Refusal> CheckShapeMass(const EngineShape& geometry, Real density, bool fixed)
{
    if (const Circle* circle = std::get_if<Circle>(&geometry))
    {
        return CheckMass(*circle, density, fixed);
    }
    if (const Capsule* capsule = std::get_if<Capsule>(&geometry))
    {
        return CheckMass(*capsule, density, fixed);
    }
    const Polygon& polygon = std::get<Polygon>(geometry);
    return IsRounded(polygon) ? CheckRoundedMass(polygon, density, fixed)
                              : CheckMass(polygon, density, fixed);
}

MassData ShapeMass(const EngineShape& geometry, Real density)
{
    if (const Circle* circle = std::get_if<Circle>(&geometry))
    {
        return ComputeMass(*circle, density);
    }
    if (const Capsule* capsule = std::get_if<Capsule>(&geometry))
    {
        return ComputeMass(*capsule, density);
    }
    const Polygon& polygon = std::get<Polygon>(geometry);
    return IsRounded(polygon) ? ComputeRoundedMass(polygon, density)
                              : ComputeMass(polygon, density);
}

} // namespace

void CheckShapesAsTheEngine(Diagnostics& diagnostics, const std::string& shapesPath,
                            const SceneBody& body, const std::vector<bool>& checked)
{
    const auto report = [&](std::size_t k, const Refusal& refusal)
    {
        const std::string field = SceneField(body.shapes[k], refusal.field);
        const std::string path = IndexPath(shapesPath, k);
        diagnostics.Report(field.empty() ? path : JoinPath(path, field), refusal.reason);
    };
    std::vector<MassData> masses; // newest first, as World keeps a body's shapes
    bool bodyRefused = false;
    for (std::size_t k = 0; k < body.shapes.size(); ++k)
    {
        if (!checked[k])
        {
            continue;
        }
        const SceneShape& shape = body.shapes[k];
        if (shape.type == SceneShapeType::Chain)
        {
            continue; // its rules are World::CreateChain's, checked where it is read
        }
        EngineShape geometry;
        try
        {
            geometry = ToEngineShape(shape);
        }
        catch (const RefusedArgument& error)
        {
            report(k, error.refusal());
            continue;
        }
        if (std::optional<Refusal> refusal = CheckGeometry(geometry))
        {
            report(k, *refusal);
            continue;
        }
        if (body.type != BodyType::Dynamic || !HasMass(shape) || bodyRefused)
        {
            continue;
        }
        const Real density = Real(shape.density);
        if (std::optional<Refusal> refusal = CheckShapeMass(geometry, density, body.fixedRotation))
        {
            report(k, *refusal);
            continue;
        }
        masses.insert(masses.begin(), ShapeMass(geometry, density));
        if (std::optional<Refusal> refusal = CheckBodyMass(masses, body.fixedRotation))
        {
            refusal->reason = "the body with this shape: " + refusal->reason;
            report(k, *refusal);
            bodyRefused = true; // one report: later shapes would only repeat it
        }
    }
}

} // namespace meff::scene_detail
