// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Scene → meff scene file (WriteScene): the loader's fields, in the order docs/scene-format.md
// lists them. A field is left out only when its value is the loader's default bit for bit, so
// that the file reads back as the same scene (a -0 stays -0: a state hash sees the sign).
#include "json_document.h"
#include "scene_sections.h"

#include "meff/scene.h"

#include <bit>
#include <cstdint>

namespace meff
{

using scene_detail::JointTypeName;
using scene_detail::PairJson;
using Json = scene_detail::SectionJson;

namespace
{

bool Same(double a, double b)
{
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

bool Same(SceneVec2 a, SceneVec2 b)
{
    return Same(a.x, b.x) && Same(a.y, b.y);
}

/// Puts `value` under `key` unless it is `fallback`, the loader's default.
template <typename T>
void PutUnlessDefault(Json& out, const char* key, const T& value, const T& fallback)
{
    if constexpr (std::is_same_v<T, double>)
    {
        if (!Same(value, fallback))
        {
            out[key] = value;
        }
    }
    else if constexpr (std::is_same_v<T, SceneVec2>)
    {
        if (!Same(value, fallback))
        {
            out[key] = PairJson(value);
        }
    }
    else if (value != fallback)
    {
        out[key] = value;
    }
}

Json Points(const std::vector<SceneVec2>& points)
{
    Json out = Json::array();
    for (const SceneVec2& point : points)
    {
        out.push_back(PairJson(point));
    }
    return out;
}

Json WorldSection(const SceneWorldSettings& world)
{
    const SolverSettings& solver = world.solver;
    Json out = Json::object();
    out["gravity"] = PairJson(world.gravity);
    out["dt"] = world.dt;
    out["frames"] = world.frames;
    out["solver"] = SolverKindName(solver.kind);
    if (const std::optional<Json> soft = scene_detail::SoftStepJson(solver.softStep))
    {
        out["soft_step"] = *soft;
    }
    out["velocity_iterations"] = solver.velocityIterations;
    out["position_iterations"] = solver.positionIterations;
    out["warm_starting"] = solver.warmStarting;
    out["block_solver"] = solver.blockSolver;
    out["block_joints"] = solver.blockJoints;
    out["restitution_from_step_start"] = solver.restitutionFromStepStart;
    out["allow_sleep"] = world.allowSleep;
    out["continuous"] = world.continuous;
    PutUnlessDefault(out, "last_step_inv_dt", world.lastStepInverseDt, 0.0);
    return out;
}

const char* ShapeTypeName(SceneShapeType type)
{
    static const char* const kNames[] = {"circle", "box", "polygon", "segment", "chain", "capsule"};
    return kNames[int(type)];
}

Json Shape(const SceneShape& shape)
{
    const SceneShape defaults;
    Json out = {{"type", ShapeTypeName(shape.type)}};
    switch (shape.type)
    {
    case SceneShapeType::Circle:
        out["radius"] = shape.radius;
        PutUnlessDefault(out, "center", shape.center, defaults.center);
        break;
    case SceneShapeType::Box:
        out["half_width"] = shape.halfWidth;
        out["half_height"] = shape.halfHeight;
        PutUnlessDefault(out, "center", shape.center, defaults.center);
        PutUnlessDefault(out, "angle", shape.angle, defaults.angle);
        PutUnlessDefault(out, "radius", shape.rounding, defaults.rounding);
        break;
    case SceneShapeType::Polygon:
        out["vertices"] = Points(shape.vertices);
        PutUnlessDefault(out, "radius", shape.rounding, defaults.rounding);
        break;
    case SceneShapeType::Capsule:
        out["center_a"] = PairJson(shape.centerA);
        out["center_b"] = PairJson(shape.centerB);
        out["radius"] = shape.radius;
        break;
    case SceneShapeType::Segment:
        out["points"] = Points({shape.point1, shape.point2});
        PutUnlessDefault(out, "one_sided", shape.oneSided, defaults.oneSided);
        break;
    case SceneShapeType::Chain:
        out["points"] = Points(shape.points);
        PutUnlessDefault(out, "loop", shape.loop, defaults.loop);
        break;
    }
    // Ghosts: a one-sided segment's and an open chain's, as the loader resolved them.
    if (shape.prev && (shape.type == SceneShapeType::Chain || shape.oneSided))
    {
        out["prev"] = PairJson(*shape.prev);
    }
    if (shape.next && (shape.type == SceneShapeType::Chain || shape.oneSided))
    {
        out["next"] = PairJson(*shape.next);
    }
    PutUnlessDefault(out, "density", shape.density, defaults.density);
    PutUnlessDefault(out, "friction", shape.friction, defaults.friction);
    PutUnlessDefault(out, "restitution", shape.restitution, defaults.restitution);
    PutUnlessDefault(out, "restitution_threshold", shape.restitutionThreshold,
                     defaults.restitutionThreshold);
    PutUnlessDefault(out, "tangent_speed", shape.tangentSpeed, defaults.tangentSpeed);
    PutUnlessDefault(out, "rolling_resistance", shape.rollingResistance,
                     defaults.rollingResistance);
    if (shape.filter != defaults.filter)
    {
        out["filter"] = {{"category", shape.filter.category},
                         {"mask", shape.filter.mask},
                         {"group", shape.filter.group}};
    }
    PutUnlessDefault(out, "sensor", shape.sensor, defaults.sensor);
    return out;
}

Json Body(const SceneBody& body)
{
    static const char* const kTypes[] = {"static", "kinematic", "dynamic"};
    const SceneBody defaults;
    Json out = {{"name", body.name},
                {"type", kTypes[int(body.type)]},
                {"position", PairJson(body.position)},
                {"angle", body.angle}};
    PutUnlessDefault(out, "linear_velocity", body.linearVelocity, defaults.linearVelocity);
    PutUnlessDefault(out, "angular_velocity", body.angularVelocity, defaults.angularVelocity);
    PutUnlessDefault(out, "linear_damping", body.linearDamping, defaults.linearDamping);
    PutUnlessDefault(out, "angular_damping", body.angularDamping, defaults.angularDamping);
    PutUnlessDefault(out, "gravity_scale", body.gravityScale, defaults.gravityScale);
    PutUnlessDefault(out, "fixed_rotation", body.fixedRotation, defaults.fixedRotation);
    PutUnlessDefault(out, "bullet", body.bullet, defaults.bullet);
    PutUnlessDefault(out, "allow_sleep", body.allowSleep, defaults.allowSleep);
    PutUnlessDefault(out, "awake", body.awake, defaults.awake);
    out["shapes"] = Json::array();
    for (const SceneShape& shape : body.shapes)
    {
        out["shapes"].push_back(Shape(shape));
    }
    return out;
}

/// The anchor (or, for a distance joint, the two anchors) in the form the joint holds it.
void Anchors(Json& out, const SceneJoint& joint)
{
    if (joint.localAnchors)
    {
        out["local_anchor_a"] = PairJson(joint.localAnchorA);
        out["local_anchor_b"] = PairJson(joint.localAnchorB);
    }
    else if (joint.type == JointType::Distance)
    {
        out["anchor_a"] = PairJson(joint.anchorA);
        out["anchor_b"] = PairJson(joint.anchorB);
    }
    else
    {
        out["anchor"] = PairJson(joint.anchor);
    }
}

void ReferenceAngle(Json& out, const SceneJoint& joint)
{
    if (joint.referenceAngle)
    {
        out["reference_angle"] = *joint.referenceAngle;
    }
}

void Axis(Json& out, const SceneJoint& joint)
{
    if (joint.localAxisA)
    {
        out["local_axis_a"] = PairJson(*joint.localAxisA);
    }
    else
    {
        out["axis"] = PairJson(joint.axis);
    }
}

/// Limits and motor speed, as revolute (angles) or prismatic and wheel (translations) have them.
void LimitAndMotor(Json& out, const SceneJoint& joint, bool angular)
{
    const SceneJoint defaults;
    PutUnlessDefault(out, "enable_limit", joint.enableLimit, defaults.enableLimit);
    if (angular)
    {
        PutUnlessDefault(out, "lower_angle", joint.lowerAngle, defaults.lowerAngle);
        PutUnlessDefault(out, "upper_angle", joint.upperAngle, defaults.upperAngle);
    }
    else
    {
        PutUnlessDefault(out, "lower_translation", joint.lowerTranslation,
                         defaults.lowerTranslation);
        PutUnlessDefault(out, "upper_translation", joint.upperTranslation,
                         defaults.upperTranslation);
    }
    PutUnlessDefault(out, "enable_motor", joint.enableMotor, defaults.enableMotor);
    PutUnlessDefault(out, "motor_speed", joint.motorSpeed, defaults.motorSpeed);
}

void Spring(Json& out, const SceneJoint& joint)
{
    const SceneJoint defaults;
    PutUnlessDefault(out, "stiffness_hz", joint.stiffnessHz, defaults.stiffnessHz);
    PutUnlessDefault(out, "damping_ratio", joint.dampingRatio, defaults.dampingRatio);
}

/// The joint's saved impulses (warm start), when it has any.
void Impulses(Json& out, const SceneJoint& joint)
{
    if (!joint.impulses.empty())
    {
        out["impulses"] = joint.impulses;
    }
}

Json Joint(const SceneJoint& joint)
{
    const SceneJoint defaults;
    Json out = {{"type", JointTypeName(joint.type)}, {"name", joint.name}};
    if (joint.type == JointType::Gear)
    {
        out["joint_a"] = joint.jointA;
        out["joint_b"] = joint.jointB;
        PutUnlessDefault(out, "ratio", joint.ratio, defaults.ratio);
        PutUnlessDefault(out, "collide_connected", joint.collideConnected,
                         defaults.collideConnected);
        Impulses(out, joint);
        return out;
    }
    out["body_a"] = joint.bodyA;
    out["body_b"] = joint.bodyB;
    PutUnlessDefault(out, "collide_connected", joint.collideConnected, defaults.collideConnected);
    switch (joint.type)
    {
    case JointType::Revolute:
        Anchors(out, joint);
        ReferenceAngle(out, joint);
        LimitAndMotor(out, joint, true);
        PutUnlessDefault(out, "max_motor_torque", joint.maxMotorTorque, defaults.maxMotorTorque);
        PutUnlessDefault(out, "enable_spring", joint.enableSpring, defaults.enableSpring);
        Spring(out, joint);
        PutUnlessDefault(out, "target_angle", joint.targetAngle, defaults.targetAngle);
        break;
    case JointType::Prismatic:
        Anchors(out, joint);
        Axis(out, joint);
        ReferenceAngle(out, joint);
        LimitAndMotor(out, joint, false);
        PutUnlessDefault(out, "max_motor_force", joint.maxMotorForce, defaults.maxMotorForce);
        PutUnlessDefault(out, "enable_spring", joint.enableSpring, defaults.enableSpring);
        Spring(out, joint);
        PutUnlessDefault(out, "target_translation", joint.targetTranslation,
                         defaults.targetTranslation);
        break;
    case JointType::Wheel:
        Anchors(out, joint);
        Axis(out, joint);
        LimitAndMotor(out, joint, false);
        PutUnlessDefault(out, "max_motor_torque", joint.maxMotorTorque, defaults.maxMotorTorque);
        Spring(out, joint);
        break;
    case JointType::Weld:
        Anchors(out, joint);
        ReferenceAngle(out, joint);
        Spring(out, joint);
        break;
    case JointType::Distance:
        Anchors(out, joint);
        out["length"] = joint.length;
        out["min_length"] = joint.minLength;
        out["max_length"] = joint.maxLength;
        Spring(out, joint);
        break;
    case JointType::Friction:
        Anchors(out, joint);
        out["max_force"] = joint.maxForce;
        out["max_torque"] = joint.maxTorque;
        break;
    case JointType::Motor:
        if (joint.linearOffset)
        {
            out["linear_offset"] = PairJson(*joint.linearOffset);
        }
        if (joint.angularOffset)
        {
            out["angular_offset"] = *joint.angularOffset;
        }
        out["max_force"] = joint.maxForce;
        out["max_torque"] = joint.maxTorque;
        out["correction_factor"] = joint.correctionFactor;
        break;
    case JointType::Mouse:
        out["anchor"] = PairJson(joint.anchor);
        out["target"] = PairJson(joint.target);
        out["max_force"] = joint.maxForce;
        out["stiffness_hz"] = joint.stiffnessHz;
        out["damping_ratio"] = joint.dampingRatio;
        break;
    case JointType::Pulley:
        out["ground_anchor_a"] = PairJson(joint.groundAnchorA);
        out["ground_anchor_b"] = PairJson(joint.groundAnchorB);
        out["anchor_a"] = PairJson(joint.anchorA);
        out["anchor_b"] = PairJson(joint.anchorB);
        PutUnlessDefault(out, "ratio", joint.ratio, defaults.ratio);
        break;
    case JointType::Gear:
        break; // written above
    }
    Impulses(out, joint);
    return out;
}

Json Character(const SceneCharacter& character)
{
    Json out = {{"name", character.name}, {"body", character.body}};
    Json inputs = Json::array();
    for (const SceneCharacterInput& input : character.inputs)
    {
        Json entry = {{"time", input.time}};
        if (input.walk)
        {
            entry["walk"] = *input.walk;
        }
        if (input.jump)
        {
            entry["jump"] = *input.jump;
        }
        inputs.push_back(entry);
    }
    out["inputs"] = inputs;
    return out;
}

} // namespace

std::string WriteScene(const Scene& scene)
{
    Json out = {{"meff_scene", kSceneFormatVersion}, {"name", scene.name}};
    if (!scene.description.empty())
    {
        out["description"] = scene.description;
    }
    out["world"] = WorldSection(scene.world);
    out["bodies"] = Json::array();
    for (const SceneBody& body : scene.bodies)
    {
        out["bodies"].push_back(Body(body));
    }
    out["joints"] = Json::array();
    for (const SceneJoint& joint : scene.joints)
    {
        out["joints"].push_back(Joint(joint));
    }
    if (!scene.characters.empty())
    {
        out["characters"] = Json::array();
        for (const SceneCharacter& character : scene.characters)
        {
            out["characters"].push_back(Character(character));
        }
    }
    if (const std::optional<Json> validate =
            scene_detail::ValidateJson(scene.tolerances, scene.validation))
    {
        out["validate"] = *validate;
    }
    if (const std::optional<Json> plausibility = scene_detail::PlausibilityJson(scene.plausibility))
    {
        out["plausibility"] = *plausibility;
    }
    if (scene.camera)
    {
        out["render"] = scene_detail::RenderJson(*scene.camera);
    }
    if (scene.analytic)
    {
        out["analytic"] = scene_detail::AnalyticJson(scene);
    }
    return b2djson_detail::FormatJson(out);
}

} // namespace meff
