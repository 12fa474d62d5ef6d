// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Reading and validating scene files. The rule throughout: report every problem that can be
// found without guessing, each once, and never let a bad value reach the engine.
#include "engine_shapes.h"
#include "json_document.h"
#include "plausibility_fields.h"

#include "meff/collision.h"
#include "meff/scene.h"
#include "meff/validity.h"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>

namespace meff
{

using scene_detail::CheckInRange;
using scene_detail::CheckNonNegative;
using scene_detail::CheckPositive;
using scene_detail::Diagnostics;
using scene_detail::IndexPath;
using scene_detail::IsPlainName;
using scene_detail::Json;
using scene_detail::ObjectReader;
using scene_detail::ToEngine;

namespace
{

template <typename T, typename U>
void Assign(T& target, const std::optional<U>& value)
{
    if (value)
    {
        target = static_cast<T>(*value);
    }
}

std::optional<std::string> ReadName(ObjectReader& reader)
{
    std::optional<std::string> name = reader.String("name", std::nullopt);
    if (name && !IsPlainName(*name))
    {
        reader.Fail("name", "must be 1 to 64 letters, digits, '_', '-' or '.'");
        return std::nullopt;
    }
    return name;
}

/// Reads a number that must be > 0 (or >= 0); returns it only when it passed.
std::optional<double> ReadPositive(ObjectReader& reader, std::string_view key,
                                   std::optional<double> fallback)
{
    std::optional<double> value = reader.Number(key, fallback);
    if (value && !CheckPositive(reader, key, *value))
    {
        return std::nullopt;
    }
    return value;
}

std::optional<double> ReadNonNegative(ObjectReader& reader, std::string_view key,
                                      std::optional<double> fallback)
{
    std::optional<double> value = reader.Number(key, fallback);
    if (value && !CheckNonNegative(reader, key, *value))
    {
        return std::nullopt;
    }
    return value;
}

/// A string field that must be one of a few words; returns the index of the word.
std::optional<std::size_t> ReadChoice(ObjectReader& reader, std::string_view key,
                                      std::initializer_list<const char*> choices)
{
    const std::optional<std::string> word = reader.String(key, std::nullopt);
    if (!word)
    {
        return std::nullopt;
    }
    std::string listed;
    std::size_t index = 0;
    for (const char* choice : choices)
    {
        if (*word == choice)
        {
            return index;
        }
        listed += (index == 0 ? "\"" : ", \"") + std::string(choice) + "\"";
        ++index;
    }
    reader.Fail(key, "must be one of " + listed);
    return std::nullopt;
}

/// "soft_step": the sub-stepped solver's settings (SoftStepSettings), each optional.
void ReadSoftStep(ObjectReader& reader, SoftStepSettings& soft)
{
    const SoftStepSettings defaults;
    Assign(soft.substeps, reader.Integer("substeps", defaults.substeps, 1, 1000));
    Assign(soft.relaxIterations,
           reader.Integer("relax_iterations", defaults.relaxIterations, 0, 1000));
    if (reader.Find("contacts") != nullptr)
    {
        const std::optional<std::size_t> model = ReadChoice(reader, "contacts", {"rigid", "soft"});
        if (model)
        {
            soft.contacts = *model == 0 ? SoftContactModel::Rigid : SoftContactModel::Soft;
        }
    }
    if (const std::optional<double> correction =
            ReadPositive(reader, "contact_correction", defaults.contactCorrection))
    {
        if (*correction > 1)
        {
            reader.Fail("contact_correction", "must be in (0, 1]");
        }
        else
        {
            soft.contactCorrection = Real(*correction);
        }
    }
    Assign(soft.contactHertz, ReadPositive(reader, "contact_hertz", defaults.contactHertz));
    Assign(soft.contactDampingRatio,
           ReadNonNegative(reader, "contact_damping_ratio", defaults.contactDampingRatio));
    Assign(soft.jointHertz, ReadPositive(reader, "joint_hertz", defaults.jointHertz));
    Assign(soft.jointDampingRatio,
           ReadNonNegative(reader, "joint_damping_ratio", defaults.jointDampingRatio));
    Assign(soft.maxPushOutSpeed,
           ReadPositive(reader, "max_push_out_speed", defaults.maxPushOutSpeed));
    Assign(soft.jointTrees, reader.Boolean("joint_trees", defaults.jointTrees));
    reader.Finish();
}

/// "solver": "box2d" (default), "colour" or "soft_step"; "graph_coloring": true is the older
/// spelling of "colour" and may stand alone or beside "solver": "colour".
void ReadSolverKind(ObjectReader& reader, SolverSettings& solver)
{
    constexpr SolverKind kinds[] = {SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep};
    std::optional<std::size_t> chosen;
    if (reader.Find("solver") != nullptr)
    {
        chosen = ReadChoice(
            reader, "solver",
            {SolverKindName(kinds[0]), SolverKindName(kinds[1]), SolverKindName(kinds[2])});
    }
    if (chosen)
    {
        solver.kind = kinds[*chosen];
    }
    const std::optional<bool> coloured = reader.Boolean("graph_coloring", false);
    if (coloured && *coloured)
    {
        if (chosen && solver.kind != SolverKind::Colour)
        {
            reader.Fail("graph_coloring",
                        std::string("true means \"solver\": \"colour\", but \"solver\" is \"") +
                            SolverKindName(solver.kind) + "\"");
            return;
        }
        solver.kind = SolverKind::Colour;
    }
}

void ReadWorld(ObjectReader& reader, SceneWorldSettings& world)
{
    const SceneWorldSettings defaults;
    Assign(world.gravity, reader.Vector("gravity", defaults.gravity));
    std::optional<double> dt = ReadPositive(reader, "dt", defaults.dt);
    // World::Step's range (meff/validity.h): at most 1 s, at least 1e-9 s.
    if (dt && !CheckInRange(reader, "dt", *dt, kMinStepDt, kMaxStepDt))
    {
        dt.reset();
    }
    Assign(world.dt, dt);
    Assign(world.frames, reader.Integer("frames", defaults.frames, 0, INT_MAX));
    ReadSolverKind(reader, world.solver);
    SolverSettings& solver = world.solver;
    Assign(solver.velocityIterations,
           reader.Integer("velocity_iterations", defaults.solver.velocityIterations, 1, 1000));
    // Zero position iterations is legitimate: it shows what the velocity solver alone does.
    Assign(solver.positionIterations,
           reader.Integer("position_iterations", defaults.solver.positionIterations, 0, 1000));
    Assign(solver.warmStarting, reader.Boolean("warm_starting", defaults.solver.warmStarting));
    Assign(solver.blockSolver, reader.Boolean("block_solver", defaults.solver.blockSolver));
    Assign(solver.blockJoints, reader.Boolean("block_joints", defaults.solver.blockJoints));
    Assign(solver.restitutionFromStepStart,
           reader.Boolean("restitution_from_step_start", defaults.solver.restitutionFromStepStart));
    if (const Json* soft = reader.Object("soft_step", false))
    {
        ObjectReader softReader(reader.Diag(), *soft, reader.PathOf("soft_step"));
        ReadSoftStep(softReader, solver.softStep);
    }
    Assign(world.allowSleep, reader.Boolean("allow_sleep", defaults.allowSleep));
    Assign(world.continuous, reader.Boolean("continuous", defaults.continuous));
    Assign(world.lastStepInverseDt,
           ReadNonNegative(reader, "last_step_inv_dt", defaults.lastStepInverseDt));
    reader.Finish();
}

void ReadFilter(ObjectReader& reader, SceneFilter& filter)
{
    const SceneFilter defaults;
    Assign(filter.category, reader.Integer("category", defaults.category, 0, 0xFFFF));
    Assign(filter.mask, reader.Integer("mask", defaults.mask, 0, 0xFFFF));
    Assign(filter.group, reader.Integer("group", defaults.group, INT16_MIN, INT16_MAX));
    reader.Finish();
}

void ReadPolygonVertices(ObjectReader& reader, SceneShape& shape)
{
    const std::optional<std::vector<SceneVec2>> vertices = reader.VectorList("vertices");
    if (!vertices)
    {
        return;
    }
    if (vertices->size() < 3 || vertices->size() > std::size_t(kMaxPolygonVertices))
    {
        reader.Fail("vertices",
                    "must list 3 to " + std::to_string(kMaxPolygonVertices) + " points");
        return;
    }
    std::vector<Vec2> points;
    for (const SceneVec2& vertex : *vertices)
    {
        points.push_back(ToEngine(vertex));
    }
    // The engine takes the convex hull of whatever it is given; a point the hull drops would
    // silently change the shape the user drew, so that is refused too.
    try
    {
        const Polygon polygon = MakePolygon(points);
        if (std::size_t(polygon.count) != points.size())
        {
            reader.Fail("vertices", "must be the corners of a convex polygon (a point lies "
                                    "inside the hull, or two points are closer than " +
                                        scene_detail::FormatReal(kPolygonWeldTolerance) + " m)");
            return;
        }
    }
    catch (const RefusedArgument&)
    {
        // A hull the engine's rules refuse (too large, say): said, with the reason, where the
        // shapes are checked as the engine will create them (CheckShapesAsTheEngine).
    }
    catch (const InvalidArgument&)
    {
        reader.Fail("vertices", "must enclose a non-zero area (the points are collinear or "
                                "coincide)");
        return;
    }
    shape.vertices = *vertices;
}

/// The ghost vertex `key` ("prev" or "next") of a one-sided segment or open chain, next to
/// the end point `end` whose segment runs from `inner`: the file's, or the segment continued
/// in a straight line beyond `end` (computed here in double, so both engines get one number).
std::optional<SceneVec2> ReadGhost(ObjectReader& reader, std::string_view key, SceneVec2 end,
                                   SceneVec2 inner)
{
    if (reader.Find(key) == nullptr)
    {
        return SceneVec2{end.x + (end.x - inner.x), end.y + (end.y - inner.y)};
    }
    const std::optional<SceneVec2> ghost = reader.Vector(key, std::nullopt);
    if (ghost && !(Distance(ToEngine(*ghost), ToEngine(end)) > Tolerances{}.linearSlop))
    {
        reader.Fail(key, "must be more than " + scene_detail::FormatReal(Tolerances{}.linearSlop) +
                             " m from the end point it precedes or follows");
        return std::nullopt;
    }
    return ghost;
}

/// Two points, as far apart as the engine requires (CheckSegment). A segment may be on any
/// body, as in Box2D: it has no mass, and collides with circles and polygons (not with other
/// segments). Returns whether the two points are usable (the ghosts are measured from them).
bool ReadSegmentPoints(ObjectReader& reader, SceneShape& shape)
{
    const std::optional<std::vector<SceneVec2>> points = reader.VectorList("points");
    if (!points)
    {
        return false;
    }
    if (points->size() != 2)
    {
        reader.Fail("points", "must be two points [[x1, y1], [x2, y2]]");
        return false;
    }
    Segment segment;
    segment.point1 = ToEngine((*points)[0]);
    segment.point2 = ToEngine((*points)[1]);
    if (const std::optional<Refusal> refusal = CheckSegment(segment, Tolerances{}.linearSlop))
    {
        reader.Fail("points", refusal->reason);
        return false;
    }
    shape.point1 = (*points)[0];
    shape.point2 = (*points)[1];
    return true;
}

/// A segment's optional "one_sided" with its ghosts "prev" and "next" (only when one-sided;
/// checked only against usable points).
void ReadSegmentSides(ObjectReader& reader, bool pointsRead, SceneShape& shape)
{
    Assign(shape.oneSided, reader.Boolean("one_sided", false));
    if (!shape.oneSided)
    {
        for (const char* key : {"prev", "next"})
        {
            if (reader.Find(key) != nullptr)
            {
                reader.Fail(key, "is only for a one-sided segment (\"one_sided\": true)");
            }
        }
    }
    else if (pointsRead)
    {
        shape.prev = ReadGhost(reader, "prev", shape.point1, shape.point2);
        shape.next = ReadGhost(reader, "next", shape.point2, shape.point1);
    }
    else
    {
        reader.Find("prev");
        reader.Find("next");
    }
}

/// A chain's points: at least 2 (3 for a loop), consecutive ones (a loop's last and first
/// too) more than the linear slop apart. Returns whether they are usable.
bool ReadChainPoints(ObjectReader& reader, SceneShape& shape)
{
    const std::optional<std::vector<SceneVec2>> points = reader.VectorList("points");
    if (!points)
    {
        return false;
    }
    const std::size_t minimum = shape.loop ? 3 : 2;
    if (points->size() < minimum)
    {
        reader.Fail("points", std::string("must list at least ") + std::to_string(minimum) +
                                  " points for " + (shape.loop ? "a loop" : "an open chain"));
        return false;
    }
    const Real minimumLength = Tolerances{}.linearSlop;
    const std::size_t n = points->size();
    for (std::size_t i = shape.loop ? 0 : 1; i < n; ++i)
    {
        const std::size_t before = (i + n - 1) % n;
        if (!(Distance(ToEngine((*points)[before]), ToEngine((*points)[i])) > minimumLength))
        {
            reader.Fail("points", "consecutive points " + std::to_string(before) + " and " +
                                      std::to_string(i) + " must be more than " +
                                      scene_detail::FormatReal(minimumLength) + " m apart");
            return false;
        }
    }
    shape.points = *points;
    return true;
}

/// A chain, on any body: as in Box2D, it has no mass.
void ReadChain(ObjectReader& reader, SceneShape& shape)
{
    Assign(shape.loop, reader.Boolean("loop", false));
    const bool pointsRead = ReadChainPoints(reader, shape);
    if (shape.loop)
    {
        for (const char* key : {"prev", "next"})
        {
            if (reader.Find(key) != nullptr)
            {
                reader.Fail(key, "must be left out for a loop (its ghosts are its own points)");
            }
        }
    }
    else if (pointsRead)
    {
        const std::vector<SceneVec2>& points = shape.points;
        shape.prev = ReadGhost(reader, "prev", points.front(), points[1]);
        shape.next = ReadGhost(reader, "next", points.back(), points[points.size() - 2]);
    }
    else
    {
        reader.Find("prev");
        reader.Find("next");
    }
}

/// A box's or polygon's optional "radius": the rounding of a Box2D v3 rounded polygon, above
/// the skin every sharp polygon has (a smaller one would change nothing).
void ReadRounding(ObjectReader& reader, SceneShape& shape)
{
    if (reader.Find("radius") == nullptr)
    {
        return; // sharp
    }
    const std::optional<double> radius = ReadPositive(reader, "radius", std::nullopt);
    // Compared as the engine compares it (World::CreateShape), in its float.
    const Real skin = Tolerances{}.polygonSkin;
    if (radius && !(Real(*radius) > skin))
    {
        reader.Fail("radius", "must be above the polygon skin (" + scene_detail::FormatReal(skin) +
                                  " m; every sharp polygon is rounded that much), or left out");
        return;
    }
    Assign(shape.rounding, radius);
}

/// A capsule: two distinct centres and a radius > 0 (World::CreateShape's CheckCapsule).
void ReadCapsule(ObjectReader& reader, SceneShape& shape)
{
    const std::optional<SceneVec2> a = reader.Vector("center_a", std::nullopt);
    const std::optional<SceneVec2> b = reader.Vector("center_b", std::nullopt);
    Assign(shape.radius, ReadPositive(reader, "radius", std::nullopt));
    if (a && b && !(Distance(ToEngine(*a), ToEngine(*b)) > Tolerances{}.linearSlop))
    {
        reader.Fail("center_b", "must be more than " +
                                    scene_detail::FormatReal(Tolerances{}.linearSlop) +
                                    " m from center_a (a capsule with one centre is a circle)");
        return;
    }
    Assign(shape.centerA, a);
    Assign(shape.centerB, b);
}

void ReadShape(ObjectReader& reader, SceneShape& shape)
{
    const std::optional<std::size_t> type =
        ReadChoice(reader, "type", {"circle", "box", "polygon", "segment", "chain", "capsule"});
    if (!type)
    {
        // Which other fields belong here depends on the type: say nothing more.
        return;
    }
    shape.type = SceneShapeType(*type);
    switch (shape.type)
    {
    case SceneShapeType::Circle:
        Assign(shape.radius, ReadPositive(reader, "radius", std::nullopt));
        Assign(shape.center, reader.Vector("center", SceneVec2{}));
        break;
    case SceneShapeType::Box:
    {
        const std::optional<double> halfWidth = ReadPositive(reader, "half_width", std::nullopt);
        const std::optional<double> halfHeight = ReadPositive(reader, "half_height", std::nullopt);
        Assign(shape.halfWidth, halfWidth);
        Assign(shape.halfHeight, halfHeight);
        Assign(shape.center, reader.Vector("center", SceneVec2{}));
        Assign(shape.angle, reader.Number("angle", 0.0));
        ReadRounding(reader, shape);
        break;
    }
    case SceneShapeType::Polygon:
        ReadPolygonVertices(reader, shape);
        ReadRounding(reader, shape);
        break;
    case SceneShapeType::Capsule:
        ReadCapsule(reader, shape);
        break;
    case SceneShapeType::Segment:
        ReadSegmentSides(reader, ReadSegmentPoints(reader, shape), shape);
        break;
    case SceneShapeType::Chain:
        ReadChain(reader, shape);
        break;
    }
    const SceneShape defaults;
    Assign(shape.density, ReadNonNegative(reader, "density", defaults.density));
    Assign(shape.friction, ReadNonNegative(reader, "friction", defaults.friction));
    if (const std::optional<double> restitution =
            reader.Number("restitution", defaults.restitution))
    {
        if (CheckInRange(reader, "restitution", *restitution, 0, 1))
        {
            shape.restitution = *restitution;
        }
    }
    Assign(shape.restitutionThreshold,
           ReadNonNegative(reader, "restitution_threshold", defaults.restitutionThreshold));
    Assign(shape.tangentSpeed, reader.Number("tangent_speed", defaults.tangentSpeed));
    Assign(shape.rollingResistance,
           ReadNonNegative(reader, "rolling_resistance", defaults.rollingResistance));
    if (const Json* filter = reader.Object("filter", false))
    {
        ObjectReader filterReader(reader.Diag(), *filter, reader.PathOf("filter"));
        ReadFilter(filterReader, shape.filter);
    }
    Assign(shape.sensor, reader.Boolean("sensor", defaults.sensor));
    reader.Finish();
}

void ReadBody(ObjectReader& reader, SceneBody& body)
{
    Assign(body.name, ReadName(reader));
    const std::optional<std::size_t> type =
        ReadChoice(reader, "type", {"static", "kinematic", "dynamic"});
    constexpr BodyType kTypes[] = {BodyType::Static, BodyType::Kinematic, BodyType::Dynamic};
    if (type)
    {
        body.type = kTypes[*type];
    }
    const SceneBody defaults;
    Assign(body.position, reader.Vector("position", defaults.position));
    Assign(body.angle, reader.Number("angle", defaults.angle));
    Assign(body.linearVelocity, reader.Vector("linear_velocity", defaults.linearVelocity));
    Assign(body.angularVelocity, reader.Number("angular_velocity", defaults.angularVelocity));
    // A static body never moves; a velocity on one is a mistake, not something to ignore.
    if (type && body.type == BodyType::Static)
    {
        if (body.linearVelocity.x != 0 || body.linearVelocity.y != 0)
        {
            reader.Fail("linear_velocity", "must be [0, 0] for a static body");
        }
        if (body.angularVelocity != 0)
        {
            reader.Fail("angular_velocity", "must be 0 for a static body");
        }
    }
    Assign(body.linearDamping, ReadNonNegative(reader, "linear_damping", defaults.linearDamping));
    Assign(body.angularDamping,
           ReadNonNegative(reader, "angular_damping", defaults.angularDamping));
    Assign(body.gravityScale, reader.Number("gravity_scale", defaults.gravityScale));
    Assign(body.fixedRotation, reader.Boolean("fixed_rotation", defaults.fixedRotation));
    Assign(body.bullet, reader.Boolean("bullet", defaults.bullet));
    Assign(body.allowSleep, reader.Boolean("allow_sleep", defaults.allowSleep));
    Assign(body.awake, reader.Boolean("awake", defaults.awake));
    std::vector<bool> readWell; // per shape: read without errors, so the engine may check it
    if (const Json* shapes = reader.Array("shapes", false))
    {
        for (std::size_t i = 0; i < shapes->size(); ++i)
        {
            const std::string path = IndexPath(reader.PathOf("shapes"), i);
            const Json& entry = (*shapes)[i];
            if (!entry.is_object())
            {
                reader.Diag().Report(path, "must be an object", entry);
                continue;
            }
            ObjectReader shapeReader(reader.Diag(), entry, path);
            SceneShape& shape = body.shapes.emplace_back();
            const std::size_t errorsBefore = reader.Diag().Count();
            ReadShape(shapeReader, shape);
            readWell.push_back(reader.Diag().Count() == errorsBefore);
        }
    }
    if (type)
    {
        scene_detail::CheckShapesAsTheEngine(reader.Diag(), reader.PathOf("shapes"), body,
                                             readWell);
    }
    // Without mass a dynamic body would be pushed by nothing (Box2D 2.4.1 gives it mass 0),
    // which is never what a scene means.
    if (type && body.type == BodyType::Dynamic &&
        std::none_of(body.shapes.begin(), body.shapes.end(), scene_detail::HasMass))
    {
        reader.Fail("shapes", "a dynamic body needs mass: give one of its circles, boxes or "
                              "polygons a density > 0 (segments and chains have none)");
    }
    if (type)
    {
        reader.Finish();
    }
}

/// True when the joint gives its anchors in the bodies' frames (`local_anchor_a` and
/// `local_anchor_b`, b2dJson's form); then reads them and refuses the world-point keys.
bool ReadLocalAnchors(ObjectReader& reader, SceneJoint& joint,
                      std::initializer_list<const char*> worldKeys)
{
    if (reader.Find("local_anchor_a") == nullptr && reader.Find("local_anchor_b") == nullptr)
    {
        return false;
    }
    joint.localAnchors = true;
    Assign(joint.localAnchorA, reader.Vector("local_anchor_a", std::nullopt));
    Assign(joint.localAnchorB, reader.Vector("local_anchor_b", std::nullopt));
    for (const char* key : worldKeys)
    {
        if (reader.Find(key) != nullptr)
        {
            reader.Fail(key, "give the anchors either as world points or as local_anchor_a and "
                             "local_anchor_b, not both");
        }
    }
    return true;
}

/// `anchor` (a world point) or the two local anchors.
void ReadAnchor(ObjectReader& reader, SceneJoint& joint)
{
    if (!ReadLocalAnchors(reader, joint, {"anchor"}))
    {
        Assign(joint.anchor, reader.Vector("anchor", std::nullopt));
    }
}

void ReadReferenceAngle(ObjectReader& reader, SceneJoint& joint)
{
    if (reader.Find("reference_angle") != nullptr)
    {
        joint.referenceAngle = reader.Number("reference_angle", std::nullopt);
    }
}

/// A world point of a body given in its own frame, in double from the file's numbers.
SceneVec2 WorldPoint(const SceneBody& body, SceneVec2 local)
{
    const double c = std::cos(body.angle);
    const double s = std::sin(body.angle);
    return {body.position.x + c * local.x - s * local.y,
            body.position.y + s * local.x + c * local.y};
}

/// Box2D v3's spring of a revolute or prismatic joint: enable_spring, stiffness_hz and
/// damping_ratio (each ≥ 0) and the target (`targetKey`: target_angle or target_translation).
void ReadJointSpring(ObjectReader& reader, SceneJoint& joint, const char* targetKey, double& target)
{
    const SceneJoint defaults;
    Assign(joint.enableSpring, reader.Boolean("enable_spring", defaults.enableSpring));
    Assign(joint.stiffnessHz, ReadNonNegative(reader, "stiffness_hz", defaults.stiffnessHz));
    Assign(joint.dampingRatio, ReadNonNegative(reader, "damping_ratio", defaults.dampingRatio));
    Assign(target, reader.Number(targetKey, 0.0));
}

void ReadRevoluteFields(ObjectReader& reader, SceneJoint& joint)
{
    ReadAnchor(reader, joint);
    ReadReferenceAngle(reader, joint);
    const SceneJoint defaults;
    Assign(joint.enableLimit, reader.Boolean("enable_limit", defaults.enableLimit));
    const std::optional<double> lower = reader.Number("lower_angle", defaults.lowerAngle);
    const std::optional<double> upper = reader.Number("upper_angle", defaults.upperAngle);
    if (lower && upper && *lower > *upper)
    {
        reader.Fail("upper_angle",
                    "must be >= lower_angle (" + scene_detail::FormatNumber(*lower) + ")");
    }
    Assign(joint.lowerAngle, lower);
    Assign(joint.upperAngle, upper);
    Assign(joint.enableMotor, reader.Boolean("enable_motor", defaults.enableMotor));
    Assign(joint.motorSpeed, reader.Number("motor_speed", defaults.motorSpeed));
    Assign(joint.maxMotorTorque,
           ReadNonNegative(reader, "max_motor_torque", defaults.maxMotorTorque));
    ReadJointSpring(reader, joint, "target_angle", joint.targetAngle);
}

void ReadDistanceFields(ObjectReader& reader, const Scene& scene, SceneJoint& joint)
{
    std::optional<SceneVec2> anchorA;
    std::optional<SceneVec2> anchorB;
    if (ReadLocalAnchors(reader, joint, {"anchor_a", "anchor_b"}))
    {
        // The world points where the bodies are placed, for the default length.
        if (joint.bodyIndexA < scene.bodies.size() && joint.bodyIndexB < scene.bodies.size() &&
            reader.Find("local_anchor_a") != nullptr && reader.Find("local_anchor_b") != nullptr)
        {
            anchorA = WorldPoint(scene.bodies[joint.bodyIndexA], joint.localAnchorA);
            anchorB = WorldPoint(scene.bodies[joint.bodyIndexB], joint.localAnchorB);
        }
    }
    else
    {
        anchorA = reader.Vector("anchor_a", std::nullopt);
        anchorB = reader.Vector("anchor_b", std::nullopt);
        Assign(joint.anchorA, anchorA);
        Assign(joint.anchorB, anchorB);
    }
    // Computed in double from the file's numbers, so meff and the Box2D mirror both start
    // from this one value instead of each measuring in its own precision.
    std::optional<double> length;
    if (reader.Find("length") != nullptr)
    {
        length = ReadPositive(reader, "length", std::nullopt);
    }
    else if (anchorA && anchorB)
    {
        length = std::hypot(anchorB->x - anchorA->x, anchorB->y - anchorA->y);
        if (!(*length > 0))
        {
            reader.Fail("length", "is missing and anchor_a and anchor_b coincide; give a "
                                  "length > 0");
            length.reset();
        }
    }
    // The engine's bound (meff/validity.h): the solvers square these lengths.
    const double longest = double(MaxDistanceJointLength());
    if (length && *length > longest)
    {
        reader.Fail("length", "must be at most " +
                                  scene_detail::FormatReal(MaxDistanceJointLength()) +
                                  " m (the solvers square it)");
        length.reset();
    }
    Assign(joint.length, length);
    // Both limits default to the length: a rigid rod. (Box2D's defaults, 0 and FLT_MAX, would
    // make a joint without a spring do nothing at all.)
    const std::optional<double> minLength =
        ReadNonNegative(reader, "min_length", length ? length : std::optional<double>(0.0));
    const std::optional<double> maxLength =
        reader.Number("max_length", length ? length : std::optional<double>(0.0));
    if (minLength && *minLength > longest)
    {
        reader.Fail("min_length", "must be at most " +
                                      scene_detail::FormatReal(MaxDistanceJointLength()) +
                                      " m (the solvers square it)");
    }
    else if (minLength && maxLength && *maxLength < *minLength)
    {
        reader.Fail("max_length",
                    "must be >= min_length (" + scene_detail::FormatNumber(*minLength) + ")");
    }
    Assign(joint.minLength, minLength);
    Assign(joint.maxLength, maxLength);
    Assign(joint.stiffnessHz, ReadNonNegative(reader, "stiffness_hz", 0.0));
    Assign(joint.dampingRatio, ReadNonNegative(reader, "damping_ratio", 0.0));
}

/// Fields shared by the prismatic and wheel joints: the anchor, the axis (non-zero) and the
/// translation limits.
void ReadSlideFields(ObjectReader& reader, SceneJoint& joint)
{
    ReadAnchor(reader, joint);
    // The axis as a world direction, or in body A's frame (b2dJson's form).
    const bool local = reader.Find("local_axis_a") != nullptr;
    const char* axisKey = local ? "local_axis_a" : "axis";
    if (local && reader.Find("axis") != nullptr)
    {
        reader.Fail("axis", "give either axis or local_axis_a, not both");
    }
    const std::optional<SceneVec2> axis = reader.Vector(axisKey, std::nullopt);
    if (axis && axis->x == 0 && axis->y == 0)
    {
        reader.Fail(axisKey, "must not be [0, 0] (it is the direction the joint slides along)");
    }
    else if (local)
    {
        joint.localAxisA = axis;
    }
    else
    {
        Assign(joint.axis, axis);
    }
    const SceneJoint defaults;
    Assign(joint.enableLimit, reader.Boolean("enable_limit", defaults.enableLimit));
    const std::optional<double> lower =
        reader.Number("lower_translation", defaults.lowerTranslation);
    const std::optional<double> upper =
        reader.Number("upper_translation", defaults.upperTranslation);
    if (lower && upper && *lower > *upper)
    {
        reader.Fail("lower_translation",
                    "must be <= upper_translation (" + scene_detail::FormatNumber(*upper) + ")");
    }
    Assign(joint.lowerTranslation, lower);
    Assign(joint.upperTranslation, upper);
    Assign(joint.enableMotor, reader.Boolean("enable_motor", defaults.enableMotor));
    Assign(joint.motorSpeed, reader.Number("motor_speed", defaults.motorSpeed));
}

void ReadPrismaticFields(ObjectReader& reader, SceneJoint& joint)
{
    ReadSlideFields(reader, joint);
    ReadReferenceAngle(reader, joint);
    Assign(joint.maxMotorForce, ReadNonNegative(reader, "max_motor_force", 0.0));
    ReadJointSpring(reader, joint, "target_translation", joint.targetTranslation);
}

void ReadWheelFields(ObjectReader& reader, SceneJoint& joint)
{
    ReadSlideFields(reader, joint);
    Assign(joint.maxMotorTorque, ReadNonNegative(reader, "max_motor_torque", 0.0));
    Assign(joint.stiffnessHz, ReadNonNegative(reader, "stiffness_hz", 0.0));
    Assign(joint.dampingRatio, ReadNonNegative(reader, "damping_ratio", 0.0));
}

void ReadWeldFields(ObjectReader& reader, SceneJoint& joint)
{
    ReadAnchor(reader, joint);
    ReadReferenceAngle(reader, joint);
    Assign(joint.stiffnessHz, ReadNonNegative(reader, "stiffness_hz", 0.0));
    Assign(joint.dampingRatio, ReadNonNegative(reader, "damping_ratio", 0.0));
}

/// "impulses": a saved joint's warm start (World::GetJointImpulses), as many as its type has.
void ReadJointImpulses(ObjectReader& reader, SceneJoint& joint)
{
    if (!reader.Has("impulses"))
    {
        return;
    }
    const std::optional<std::vector<double>> impulses = reader.NumberList("impulses");
    if (!impulses)
    {
        return;
    }
    const std::size_t count = std::size_t(JointImpulseCount(joint.type));
    if (impulses->size() != count)
    {
        reader.Fail("impulses", "a " + std::string(scene_detail::JointTypeName(joint.type)) +
                                    " joint has " + std::to_string(count) + " impulses");
        return;
    }
    joint.impulses = *impulses;
}

void ReadMotorFields(ObjectReader& reader, SceneJoint& joint)
{
    const SceneJoint defaults;
    if (reader.Find("linear_offset") != nullptr)
    {
        joint.linearOffset = reader.Vector("linear_offset", std::nullopt);
    }
    if (reader.Find("angular_offset") != nullptr)
    {
        joint.angularOffset = reader.Number("angular_offset", std::nullopt);
    }
    Assign(joint.maxForce, ReadNonNegative(reader, "max_force", defaults.maxForce));
    Assign(joint.maxTorque, ReadNonNegative(reader, "max_torque", defaults.maxTorque));
    std::optional<double> factor =
        ReadNonNegative(reader, "correction_factor", defaults.correctionFactor);
    if (factor && *factor > 1)
    {
        reader.Fail("correction_factor", "must be in [0, 1]");
        factor.reset();
    }
    Assign(joint.correctionFactor, factor);
}

/// Friction: the anchor and the two bounds, whose defaults are FrictionJointDef's (0: a
/// joint that holds nothing until given a force or torque).
void ReadFrictionFields(ObjectReader& reader, SceneJoint& joint)
{
    ReadAnchor(reader, joint);
    const FrictionJointDef defaults;
    Assign(joint.maxForce, ReadNonNegative(reader, "max_force", double(defaults.maxForce)));
    Assign(joint.maxTorque, ReadNonNegative(reader, "max_torque", double(defaults.maxTorque)));
}

/// Pulley: the two ground anchors, the rope's ends on the bodies (world points) and the ratio.
void ReadPulleyFields(ObjectReader& reader, SceneJoint& joint)
{
    Assign(joint.groundAnchorA, reader.Vector("ground_anchor_a", std::nullopt));
    Assign(joint.groundAnchorB, reader.Vector("ground_anchor_b", std::nullopt));
    Assign(joint.anchorA, reader.Vector("anchor_a", std::nullopt));
    Assign(joint.anchorB, reader.Vector("anchor_b", std::nullopt));
    Assign(joint.ratio, ReadPositive(reader, "ratio", 1.0));
}

/// Gear: joint_a and joint_b name two revolute or prismatic joints earlier in the list, whose
/// bodies B become the gear's bodies (they must be dynamic: the gear turns them).
void ReadGearFields(ObjectReader& reader, const Scene& scene, std::size_t self, SceneJoint& joint)
{
    const auto reference = [&](std::string_view key, std::string& name, std::size_t& index) -> bool
    {
        const std::optional<std::string> wanted = reader.String(key, std::nullopt);
        if (!wanted)
        {
            return false;
        }
        name = *wanted;
        for (std::size_t j = 0; j < self; ++j)
        {
            const SceneJoint& other = scene.joints[j];
            if (other.name != name || name.empty())
            {
                continue;
            }
            if (other.type != JointType::Revolute && other.type != JointType::Prismatic)
            {
                reader.Fail(key, "must name a revolute or prismatic joint");
                return false;
            }
            if (other.bodyIndexB >= scene.bodies.size())
            {
                // The joint failed its own checks (body_b missing or naming no body), which
                // are reported already; its index is not a body's (found by the scene fuzzer).
                return false;
            }
            if (scene.bodies[other.bodyIndexB].type != BodyType::Dynamic)
            {
                reader.Fail(key, "must name a joint whose body_b is dynamic (the gear turns it)");
                return false;
            }
            index = j;
            return true;
        }
        reader.Fail(key, "no joint earlier in the list has this name");
        return false;
    };
    const bool haveA = reference("joint_a", joint.jointA, joint.jointIndexA);
    const bool haveB = reference("joint_b", joint.jointB, joint.jointIndexB);
    if (haveA && haveB && joint.jointIndexA == joint.jointIndexB)
    {
        reader.Fail("joint_b", "must differ from joint_a");
    }
    if (haveA)
    {
        joint.bodyIndexA = scene.joints[joint.jointIndexA].bodyIndexB;
        joint.bodyA = scene.joints[joint.jointIndexA].bodyB;
    }
    if (haveB)
    {
        joint.bodyIndexB = scene.joints[joint.jointIndexB].bodyIndexB;
        joint.bodyB = scene.joints[joint.jointIndexB].bodyB;
    }
    Assign(joint.ratio, reader.Number("ratio", 1.0));
}

void ReadMouseFields(ObjectReader& reader, SceneJoint& joint)
{
    const std::optional<SceneVec2> anchor = reader.Vector("anchor", std::nullopt);
    Assign(joint.anchor, anchor);
    Assign(joint.target, reader.Vector("target", anchor));
    Assign(joint.maxForce, ReadNonNegative(reader, "max_force", std::nullopt));
    // MouseJointDef's defaults (Box2D testbed's values).
    const MouseJointDef defaults;
    Assign(joint.stiffnessHz, ReadNonNegative(reader, "stiffness_hz", double(defaults.hertz)));
    Assign(joint.dampingRatio,
           ReadNonNegative(reader, "damping_ratio", double(defaults.dampingRatio)));
}

/// Looks up body_a or body_b; returns the body index when the name is defined.
std::optional<std::size_t> ReadBodyReference(ObjectReader& reader, std::string_view key,
                                             const std::map<std::string, std::size_t>& bodies,
                                             std::string& name)
{
    const std::optional<std::string> reference = reader.String(key, std::nullopt);
    if (!reference)
    {
        return std::nullopt;
    }
    name = *reference;
    const auto found = bodies.find(*reference);
    if (found == bodies.end())
    {
        reader.Fail(key, "no body has this name");
        return std::nullopt;
    }
    return found->second;
}

void ReadJoint(ObjectReader& reader, const Scene& scene,
               const std::map<std::string, std::size_t>& bodyIndexByName, std::size_t self,
               SceneJoint& joint)
{
    // In JointType's order.
    const std::optional<std::size_t> type =
        ReadChoice(reader, "type",
                   {"revolute", "distance", "prismatic", "wheel", "weld", "motor", "mouse",
                    "friction", "pulley", "gear"});
    constexpr JointType kTypes[] = {JointType::Revolute, JointType::Distance, JointType::Prismatic,
                                    JointType::Wheel,    JointType::Weld,     JointType::Motor,
                                    JointType::Mouse,    JointType::Friction, JointType::Pulley,
                                    JointType::Gear};
    Assign(joint.name, ReadName(reader));
    if (type && kTypes[*type] == JointType::Gear)
    {
        // A gear names joints, not bodies.
        joint.type = JointType::Gear;
        ReadGearFields(reader, scene, self, joint);
        Assign(joint.collideConnected, reader.Boolean("collide_connected", false));
        ReadJointImpulses(reader, joint);
        reader.Finish();
        return;
    }
    const std::optional<std::size_t> bodyA =
        ReadBodyReference(reader, "body_a", bodyIndexByName, joint.bodyA);
    const std::optional<std::size_t> bodyB =
        ReadBodyReference(reader, "body_b", bodyIndexByName, joint.bodyB);
    if (bodyA && bodyB)
    {
        joint.bodyIndexA = *bodyA;
        joint.bodyIndexB = *bodyB;
        // The engine's rule (meff/validity.h): World::CreateJoint refuses exactly these.
        const BodyType typeA = scene.bodies[*bodyA].type;
        const BodyType typeB = scene.bodies[*bodyB].type;
        if (*bodyA == *bodyB)
        {
            reader.Fail("body_b", "must differ from body_a");
        }
        else if (const std::optional<Refusal> refusal =
                     type ? CheckJointBodies(kTypes[*type], false, typeB) : std::nullopt)
        {
            reader.Fail("body_b", refusal->reason);
        }
        else if (!JointMovesAnything(typeA, typeB))
        {
            // Box2D accepts it, so scenes written for Box2D may have one: load them.
            reader.Diag().Warn(reader.Path(), "neither body_a nor body_b is dynamic, so this "
                                              "joint does nothing (accepted, as Box2D accepts it)");
        }
    }
    Assign(joint.collideConnected, reader.Boolean("collide_connected", false));
    if (!type)
    {
        return;
    }
    joint.type = kTypes[*type];
    switch (joint.type)
    {
    case JointType::Revolute:
        ReadRevoluteFields(reader, joint);
        break;
    case JointType::Distance:
        ReadDistanceFields(reader, scene, joint);
        break;
    case JointType::Prismatic:
        ReadPrismaticFields(reader, joint);
        break;
    case JointType::Wheel:
        ReadWheelFields(reader, joint);
        break;
    case JointType::Weld:
        ReadWeldFields(reader, joint);
        break;
    case JointType::Motor:
        ReadMotorFields(reader, joint);
        break;
    case JointType::Mouse:
        ReadMouseFields(reader, joint);
        break;
    case JointType::Friction:
        ReadFrictionFields(reader, joint);
        break;
    case JointType::Pulley:
        ReadPulleyFields(reader, joint);
        break;
    case JointType::Gear:
        break; // read above
    }
    ReadJointImpulses(reader, joint);
    reader.Finish();
}

void ReadTolerances(ObjectReader& reader, SceneTolerances& tolerances)
{
    const SceneTolerances defaults;
    Assign(tolerances.position, ReadNonNegative(reader, "position", defaults.position));
    Assign(tolerances.angle, ReadNonNegative(reader, "angle", defaults.angle));
    Assign(tolerances.velocity, ReadNonNegative(reader, "velocity", defaults.velocity));
    Assign(tolerances.impulse, ReadNonNegative(reader, "impulse", defaults.impulse));
    Assign(tolerances.impulseRelative,
           ReadNonNegative(reader, "impulse_relative", defaults.impulseRelative));
    reader.Finish();
}

void ReadSettle(ObjectReader& reader, SceneSettleCheck& settle)
{
    const SceneSettleCheck defaults;
    Assign(settle.position, ReadNonNegative(reader, "position", defaults.position));
    if (reader.Find("angle") != nullptr)
    {
        settle.angle = ReadNonNegative(reader, "angle", std::nullopt);
    }
    if (reader.Find("min_height") != nullptr)
    {
        settle.minimumHeight = reader.Number("min_height", std::nullopt);
    }
    reader.Finish();
}

void ReadValidation(ObjectReader& reader, SceneValidation& validation)
{
    Assign(validation.chaotic, reader.Boolean("chaotic", false));
    Assign(validation.horizonFrames, reader.Integer("horizon_frames", 0, 0, INT_MAX));
    if (validation.horizonFrames > 0 && !validation.chaotic)
    {
        reader.Fail("horizon_frames", "is only meaningful with \"chaotic\": true");
    }
    if (validation.chaotic && reader.Find("horizon_frames") == nullptr)
    {
        reader.Fail("horizon_frames", "is required with \"chaotic\": true (how many frames "
                                      "must agree before round-off may part the engines)");
    }
}

void ReadCamera(ObjectReader& reader, SceneCamera& camera)
{
    const SceneCamera defaults;
    Assign(camera.center, reader.Vector("center", defaults.center));
    Assign(camera.height, ReadPositive(reader, "height", defaults.height));
    reader.Finish();
}

/// Looks up a joint name in "analytic"; returns its index when it names a joint whose body A
/// is static (the pivot the exact solutions assume fixed).
std::optional<std::size_t> ReadAnalyticJoint(ObjectReader& reader, const std::string& key,
                                             const Json& value, const Scene& scene,
                                             const std::map<std::string, std::size_t>& joints)
{
    if (!value.is_string())
    {
        reader.Diag().Report(reader.PathOf(key), "must be a joint name", value);
        return std::nullopt;
    }
    const auto found = joints.find(value.get<std::string>());
    if (found == joints.end())
    {
        reader.Diag().Report(reader.PathOf(key), "no joint has this name", value);
        return std::nullopt;
    }
    const SceneJoint& joint = scene.joints[found->second];
    if (joint.bodyIndexA >= scene.bodies.size())
    {
        // The joint failed its own checks (body_a missing or naming no body), which are
        // reported already; its index is not a body's (found by the scene fuzzer).
        return std::nullopt;
    }
    if (joint.type != JointType::Revolute && joint.type != JointType::Distance)
    {
        reader.Diag().Report(reader.PathOf(key),
                             "must name a revolute or distance joint (a pendulum's rod)", value);
        return std::nullopt;
    }
    if (scene.bodies[joint.bodyIndexA].type != BodyType::Static)
    {
        reader.Diag().Report(reader.PathOf(key),
                             "must name a joint whose body_a is static (the fixed pivot)", value);
        return std::nullopt;
    }
    if (joint.type != JointType::Revolute && joint.type != JointType::Distance)
    {
        // The exact solutions are pendulums: a pin or a rod.
        reader.Diag().Report(reader.PathOf(key), "must name a revolute or distance joint", value);
        return std::nullopt;
    }
    return found->second;
}

void ReadAnalytic(ObjectReader& reader, const Scene& scene,
                  const std::map<std::string, std::size_t>& bodyIndexByName,
                  const std::map<std::string, std::size_t>& jointIndexByName,
                  SceneAnalytic& analytic)
{
    const std::optional<std::size_t> kind =
        ReadChoice(reader, "kind", {"pendulum", "cradle", "bounce"});
    if (!kind)
    {
        return; // the other fields depend on the kind
    }
    analytic.kind = static_cast<SceneAnalyticKind>(*kind);
    // Each kind has its own fields; another kind's field is refused rather than ignored.
    const auto refuse = [&](std::string_view key, const char* kinds)
    {
        if (reader.Find(key) != nullptr)
        {
            reader.Fail(key, std::string("is only meaningful with \"kind\": ") + kinds);
        }
    };
    if (analytic.kind == SceneAnalyticKind::Pendulum)
    {
        refuse("joints", "\"cradle\"");
        if (const Json* joint = reader.Find("joint"))
        {
            if (const std::optional<std::size_t> index =
                    ReadAnalyticJoint(reader, "joint", *joint, scene, jointIndexByName))
            {
                analytic.joints = {*index};
            }
        }
        else
        {
            reader.Fail("joint", "is required with \"kind\": \"pendulum\"");
        }
    }
    else
    {
        refuse("joint", "\"pendulum\"");
    }
    if (analytic.kind == SceneAnalyticKind::Cradle)
    {
        if (const Json* joints = reader.Array("joints", true))
        {
            if (joints->size() < 2)
            {
                reader.Fail("joints", "must name at least two joints");
            }
            for (std::size_t i = 0; i < joints->size(); ++i)
            {
                if (const std::optional<std::size_t> index = ReadAnalyticJoint(
                        reader, IndexPath("joints", i), (*joints)[i], scene, jointIndexByName))
                {
                    analytic.joints.push_back(*index);
                }
            }
        }
    }
    if (analytic.kind == SceneAnalyticKind::Bounce)
    {
        std::string name;
        if (const std::optional<std::size_t> body =
                ReadBodyReference(reader, "body", bodyIndexByName, name))
        {
            analytic.body = *body;
            if (scene.bodies[*body].type != BodyType::Dynamic)
            {
                reader.Fail("body", "must be a dynamic body");
            }
        }
        Assign(analytic.contactHeight, reader.Number("contact_height", std::nullopt));
    }
    else
    {
        refuse("body", "\"bounce\"");
        refuse("contact_height", "\"bounce\"");
    }
    reader.Finish();
}

/// Reads an optional nested object with `read` and reports its unknown fields.
template <typename ReadFunction>
void ReadSection(ObjectReader& parent, std::string_view key, ReadFunction read)
{
    if (const Json* section = parent.Object(key, false))
    {
        ObjectReader reader(parent.Diag(), *section, parent.PathOf(key));
        read(reader);
    }
}

/// Every key of an array of objects, with the path of each object, skipping (after reporting)
/// entries that are not objects.
template <typename ReadFunction>
void ReadObjectArray(ObjectReader& parent, std::string_view key, bool required, ReadFunction read)
{
    const Json* entries = parent.Array(key, required);
    if (entries == nullptr)
    {
        return;
    }
    for (std::size_t i = 0; i < entries->size(); ++i)
    {
        const std::string path = IndexPath(parent.PathOf(key), i);
        const Json& entry = (*entries)[i];
        if (!entry.is_object())
        {
            parent.Diag().Report(path, "must be an object", entry);
            continue;
        }
        ObjectReader reader(parent.Diag(), entry, path);
        read(reader, i);
    }
}

void ReadCharacterInput(ObjectReader& reader, double previousTime, SceneCharacterInput& input)
{
    if (const std::optional<double> time = ReadNonNegative(reader, "time", std::nullopt))
    {
        input.time = *time;
        if (*time < previousTime)
        {
            reader.Fail("time", "must not be before the previous input's (" +
                                    scene_detail::FormatNumber(previousTime) + " s)");
        }
    }
    const bool walks = reader.Find("walk") != nullptr;
    const bool jumps = reader.Find("jump") != nullptr;
    if (walks)
    {
        input.walk = reader.Number("walk", std::nullopt);
    }
    if (jumps)
    {
        input.jump = reader.Number("jump", std::nullopt);
    }
    if (!walks && !jumps)
    {
        reader.Fail("walk", "is required unless \"jump\" is given (an input must do something)");
    }
    reader.Finish();
}

/// The body a character moves must be what World::MoveCharacter can move: kinematic, one
/// capsule, and a filter that does not find its own capsule.
void CheckCharacterBody(ObjectReader& reader, const SceneBody& body)
{
    if (body.type != BodyType::Kinematic)
    {
        reader.Fail("body", "must name a kinematic body (the character mover moves it)");
    }
    else if (body.shapes.size() != 1 || body.shapes[0].type != SceneShapeType::Capsule)
    {
        reader.Fail("body", "must name a body with exactly one shape, a capsule (the mover)");
    }
    else if ((body.shapes[0].filter.category & body.shapes[0].filter.mask) != 0)
    {
        reader.Fail("body", "must name a body whose capsule's filter.category is not in its own "
                            "filter.mask (category " +
                                std::to_string(body.shapes[0].filter.category) + ", mask " +
                                std::to_string(body.shapes[0].filter.mask) +
                                "): the mover would find its own capsule");
    }
}

void ReadCharacter(ObjectReader& reader, const Scene& scene,
                   const std::map<std::string, std::size_t>& bodyIndexByName,
                   SceneCharacter& character)
{
    if (reader.Find("name") != nullptr)
    {
        Assign(character.name, ReadName(reader));
    }
    if (const std::optional<std::size_t> body =
            ReadBodyReference(reader, "body", bodyIndexByName, character.body))
    {
        character.bodyIndex = *body;
        CheckCharacterBody(reader, scene.bodies[*body]);
        for (const SceneCharacter& other : scene.characters)
        {
            if (&other != &character && other.body == character.body)
            {
                reader.Fail("body", "is already moved by another character");
                break;
            }
        }
    }
    ReadObjectArray(reader, "inputs", false,
                    [&](ObjectReader& entry, std::size_t)
                    {
                        const double previous =
                            character.inputs.empty() ? 0.0 : character.inputs.back().time;
                        ReadCharacterInput(entry, previous, character.inputs.emplace_back());
                    });
    reader.Finish();
}

/// Reports names used twice; returns the index of the first holder of each name (names[i] and
/// paths[i] belong to scene.bodies[i] or scene.joints[i]).
std::map<std::string, std::size_t> IndexNames(Diagnostics& diagnostics,
                                              const std::vector<std::string>& names,
                                              const std::vector<std::string>& paths)
{
    std::map<std::string, std::size_t> indexByName;
    for (std::size_t i = 0; i < names.size(); ++i)
    {
        if (names[i].empty())
        {
            continue; // no valid name: already reported
        }
        const auto [existing, inserted] = indexByName.emplace(names[i], i);
        if (!inserted)
        {
            diagnostics.Report(paths[i] + ".name",
                               "duplicate name (also used by " + paths[existing->second] + ")",
                               Json(names[i]));
        }
    }
    return indexByName;
}

Scene ReadScene(const Json& document, const std::string& sourcePath, Diagnostics& diagnostics)
{
    Scene scene;
    scene.sourcePath = sourcePath;
    if (!document.is_object())
    {
        diagnostics.Report("", "the scene must be a JSON object", document);
        return scene;
    }
    ObjectReader top(diagnostics, document, "");

    // An unknown version may mean anything at all: refuse it before reading further.
    const Json* version = top.Find("meff_scene");
    if (version == nullptr)
    {
        top.Fail("meff_scene", "required field is missing (the format version: write "
                               "\"meff_scene\": 1)");
    }
    else if (!version->is_number_integer() || version->get<long long>() != kSceneFormatVersion)
    {
        top.Fail("meff_scene", "must be 1 (the only version of the format)");
        return scene;
    }

    scene.name = std::filesystem::path(sourcePath).stem().string();
    if (const std::optional<std::string> name = top.String("name", scene.name))
    {
        if (name->empty())
        {
            top.Fail("name", "must not be empty");
        }
        else
        {
            scene.name = *name;
        }
    }
    Assign(scene.description, top.String("description", std::string()));
    ReadSection(top, "world", [&](ObjectReader& reader) { ReadWorld(reader, scene.world); });

    std::vector<std::string> bodyNames;
    std::vector<std::string> bodyPaths;
    ReadObjectArray(top, "bodies", true,
                    [&](ObjectReader& reader, std::size_t)
                    {
                        SceneBody& body = scene.bodies.emplace_back();
                        ReadBody(reader, body);
                        bodyNames.push_back(body.name);
                        bodyPaths.push_back(reader.Path());
                    });
    const std::map<std::string, std::size_t> bodyIndexByName =
        IndexNames(diagnostics, bodyNames, bodyPaths);

    std::vector<std::string> jointNames;
    std::vector<std::string> jointPaths;
    ReadObjectArray(top, "joints", false,
                    [&](ObjectReader& reader, std::size_t)
                    {
                        const std::size_t self = scene.joints.size();
                        SceneJoint& joint = scene.joints.emplace_back();
                        ReadJoint(reader, scene, bodyIndexByName, self, joint);
                        jointNames.push_back(joint.name);
                        jointPaths.push_back(reader.Path());
                    });
    const std::map<std::string, std::size_t> jointIndexByName =
        IndexNames(diagnostics, jointNames, jointPaths);

    ReadObjectArray(
        top, "characters", false,
        [&](ObjectReader& reader, std::size_t)
        { ReadCharacter(reader, scene, bodyIndexByName, scene.characters.emplace_back()); });

    ReadSection(top, "validate",
                [&](ObjectReader& validate)
                {
                    ReadSection(validate, "tolerances",
                                [&](ObjectReader& reader)
                                { ReadTolerances(reader, scene.tolerances); });
                    ReadValidation(validate, scene.validation);
                    ReadSection(validate, "settle",
                                [&](ObjectReader& reader)
                                { ReadSettle(reader, scene.validation.settle.emplace()); });
                    validate.Finish();
                });
    ReadSection(top, "plausibility",
                [&](ObjectReader& reader) { ReadPlausibility(reader, scene.plausibility); });
    ReadSection(top, "render",
                [&](ObjectReader& render)
                {
                    ReadSection(render, "camera",
                                [&](ObjectReader& reader)
                                { ReadCamera(reader, scene.camera.emplace()); });
                    render.Finish();
                });
    ReadSection(top, "analytic",
                [&](ObjectReader& reader) {
                    ReadAnalytic(reader, scene, bodyIndexByName, jointIndexByName,
                                 scene.analytic.emplace());
                });
    top.Finish();
    return scene;
}

} // namespace

SceneError::SceneError(std::vector<std::string> messages)
    : Error(
          [&]
          {
              std::string joined;
              for (const std::string& message : messages)
              {
                  joined += joined.empty() ? message : "\n" + message;
              }
              return joined;
          }()),
      m_messages(std::move(messages))
{
}

std::optional<std::size_t> Scene::FindBody(std::string_view bodyName) const
{
    for (std::size_t i = 0; i < bodies.size(); ++i)
    {
        if (bodies[i].name == bodyName)
        {
            return i;
        }
    }
    return std::nullopt;
}

std::optional<std::size_t> Scene::FindJoint(std::string_view jointName) const
{
    for (std::size_t i = 0; i < joints.size(); ++i)
    {
        if (joints[i].name == jointName)
        {
            return i;
        }
    }
    return std::nullopt;
}

namespace scene_detail
{

Scene ReadSceneDocument(const Json& document, const std::string& sourcePath)
{
    Diagnostics diagnostics(sourcePath);
    Scene scene = ReadScene(document, sourcePath, diagnostics);
    if (diagnostics.HasErrors())
    {
        diagnostics.Throw();
    }
    return scene;
}

} // namespace scene_detail

Scene ParseScene(std::string_view text, const std::string& sourcePath, const SceneLimits& limits)
{
    Diagnostics diagnostics(sourcePath);
    const std::optional<Json> document = scene_detail::ParseDocument(text, diagnostics);
    if (!document ||
        !scene_detail::CheckCounts(*document, "bodies", "shapes", "joints", limits, diagnostics))
    {
        diagnostics.Throw();
    }
    Scene scene = ReadScene(*document, sourcePath, diagnostics);
    if (diagnostics.HasErrors())
    {
        diagnostics.Throw();
    }
    scene_detail::CheckPairs(BuildWorld(scene), limits, sourcePath);
    scene.warnings = diagnostics.Warnings();
    return scene;
}

namespace scene_detail
{

std::string ReadTextFile(const std::string& path, std::size_t maxBytes)
{
    std::error_code error;
    if (std::filesystem::is_directory(path, error))
    {
        throw SceneError({path + ": is a directory, not a scene file"});
    }
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (file == nullptr)
    {
        throw SceneError({path + ": cannot open: " + std::strerror(errno)});
    }
    // Read at most one byte more than a scene may have: /dev/zero, or a huge file given by
    // mistake, is refused instead of filling the memory.
    std::string text;
    char buffer[1 << 16];
    std::size_t count = 0;
    while (text.size() <= maxBytes && (count = std::fread(buffer, 1, sizeof buffer, file)) > 0)
    {
        text.append(buffer, count);
    }
    const bool failed = std::ferror(file) != 0;
    const int readError = errno;
    std::fclose(file);
    if (failed)
    {
        throw SceneError({path + ": cannot read: " + std::strerror(readError)});
    }
    if (text.size() > maxBytes)
    {
        throw SceneError({path + ": larger than " + std::to_string(maxBytes >> 20) +
                          " MiB: not a scene file (raise the limit with --max-file-size MiB)"});
    }
    return text;
}

} // namespace scene_detail

Scene LoadScene(const std::string& path, const SceneLimits& limits)
{
    return ParseScene(scene_detail::ReadTextFile(path, limits.fileBytes), path, limits);
}

} // namespace meff
