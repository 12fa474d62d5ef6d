// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Turning a validated Scene into a meff World.
#include "engine_shapes.h"
#include "meff/scene.h"

#include "joint_frame.h"

#include "meff/collision.h"

#include <string>

namespace meff
{

namespace
{

using scene_detail::ToEngine;

/// The engine's error, said about one scene field.
[[noreturn]] void Refused(const Scene& scene, const std::string& fieldPath, const Error& error)
{
    throw SceneError(
        {scene.sourcePath + ": " + fieldPath + ": refused by the engine: " + error.what()});
}

WorldDef MakeWorldDef(const SceneWorldSettings& settings)
{
    WorldDef def;
    def.gravity = ToEngine(settings.gravity);
    def.solver = settings.solver;
    def.allowSleep = settings.allowSleep;
    def.continuous = settings.continuous;
    return def;
}

BodyDef MakeBodyDef(const SceneBody& body)
{
    BodyDef def;
    def.type = body.type;
    def.position = ToEngine(body.position);
    def.angle = Real(body.angle);
    def.linearVelocity = ToEngine(body.linearVelocity);
    def.angularVelocity = Real(body.angularVelocity);
    def.linearDamping = Real(body.linearDamping);
    def.angularDamping = Real(body.angularDamping);
    def.gravityScale = Real(body.gravityScale);
    def.fixedRotation = body.fixedRotation;
    def.bullet = body.bullet;
    def.allowSleep = body.allowSleep;
    def.awake = body.awake;
    return def;
}

/// The chain of a "chain" shape, the file's points and resolved ghosts.
ChainId CreateChain(World& world, BodyId body, const SceneShape& shape)
{
    std::vector<Vec2> points;
    points.reserve(shape.points.size());
    for (const SceneVec2& point : shape.points)
    {
        points.push_back(ToEngine(point));
    }
    Chain chain;
    chain.points = points;
    chain.loop = shape.loop;
    if (shape.prev)
    {
        chain.prev = ToEngine(*shape.prev);
    }
    if (shape.next)
    {
        chain.next = ToEngine(*shape.next);
    }
    return world.CreateChain(body, scene_detail::ToShapeDef(shape), chain);
}

ShapeId CreateShape(World& world, BodyId body, const SceneShape& shape)
{
    if (shape.type == SceneShapeType::Chain)
    {
        return world.GetChainSegments(CreateChain(world, body, shape)).front();
    }
    const ShapeDef def = scene_detail::ToShapeDef(shape);
    return std::visit([&](const auto& geometry) { return world.CreateShape(body, def, geometry); },
                      scene_detail::ToEngineShape(shape));
}

JointId CreateJoint(BuiltScene& built, const SceneJoint& joint)
{
    World& world = built.world;
    if (joint.type == JointType::Gear)
    {
        // The gear's joints come earlier in the list, so they are built already.
        GearJointDef def;
        def.joint1 = built.joints.at(joint.jointIndexA);
        def.joint2 = built.joints.at(joint.jointIndexB);
        def.ratio = Real(joint.ratio);
        def.collideConnected = joint.collideConnected;
        return world.CreateJoint(def);
    }
    const BodyId bodyA = built.bodies.at(joint.bodyIndexA);
    const BodyId bodyB = built.bodies.at(joint.bodyIndexB);
    const scene_detail::JointFrame frame =
        scene_detail::ComputeJointFrame(world, bodyA, bodyB, joint);
    switch (joint.type)
    {
    case JointType::Revolute:
    {
        RevoluteJointDef def;
        def.bodyA = bodyA;
        def.bodyB = bodyB;
        def.localAnchorA = frame.localAnchorA;
        def.localAnchorB = frame.localAnchorB;
        def.referenceAngle = frame.referenceAngle;
        def.enableLimit = joint.enableLimit;
        def.lowerAngle = Real(joint.lowerAngle);
        def.upperAngle = Real(joint.upperAngle);
        def.enableMotor = joint.enableMotor;
        def.motorSpeed = Real(joint.motorSpeed);
        def.maxMotorTorque = Real(joint.maxMotorTorque);
        def.enableSpring = joint.enableSpring;
        def.hertz = Real(joint.stiffnessHz);
        def.dampingRatio = Real(joint.dampingRatio);
        def.targetAngle = Real(joint.targetAngle);
        def.collideConnected = joint.collideConnected;
        return world.CreateJoint(def);
    }
    case JointType::Prismatic:
    {
        PrismaticJointDef def;
        def.bodyA = bodyA;
        def.bodyB = bodyB;
        def.localAnchorA = frame.localAnchorA;
        def.localAnchorB = frame.localAnchorB;
        def.localAxisA = frame.localAxisA;
        def.referenceAngle = frame.referenceAngle;
        def.enableLimit = joint.enableLimit;
        def.lowerTranslation = Real(joint.lowerTranslation);
        def.upperTranslation = Real(joint.upperTranslation);
        def.enableMotor = joint.enableMotor;
        def.motorSpeed = Real(joint.motorSpeed);
        def.maxMotorForce = Real(joint.maxMotorForce);
        def.enableSpring = joint.enableSpring;
        def.hertz = Real(joint.stiffnessHz);
        def.dampingRatio = Real(joint.dampingRatio);
        def.targetTranslation = Real(joint.targetTranslation);
        def.collideConnected = joint.collideConnected;
        return world.CreateJoint(def);
    }
    case JointType::Wheel:
    {
        WheelJointDef def;
        def.bodyA = bodyA;
        def.bodyB = bodyB;
        def.localAnchorA = frame.localAnchorA;
        def.localAnchorB = frame.localAnchorB;
        def.localAxisA = frame.localAxisA;
        def.enableLimit = joint.enableLimit;
        def.lowerTranslation = Real(joint.lowerTranslation);
        def.upperTranslation = Real(joint.upperTranslation);
        def.enableMotor = joint.enableMotor;
        def.motorSpeed = Real(joint.motorSpeed);
        def.maxMotorTorque = Real(joint.maxMotorTorque);
        def.hertz = Real(joint.stiffnessHz);
        def.dampingRatio = Real(joint.dampingRatio);
        def.collideConnected = joint.collideConnected;
        return world.CreateJoint(def);
    }
    case JointType::Distance:
    {
        DistanceJointDef def;
        def.bodyA = bodyA;
        def.bodyB = bodyB;
        def.localAnchorA = frame.localAnchorA;
        def.localAnchorB = frame.localAnchorB;
        def.length = Real(joint.length);
        def.minLength = Real(joint.minLength);
        def.maxLength = Real(joint.maxLength);
        def.hertz = Real(joint.stiffnessHz);
        def.dampingRatio = Real(joint.dampingRatio);
        def.collideConnected = joint.collideConnected;
        return world.CreateJoint(def);
    }
    case JointType::Weld:
    {
        WeldJointDef def;
        def.bodyA = bodyA;
        def.bodyB = bodyB;
        def.localAnchorA = frame.localAnchorA;
        def.localAnchorB = frame.localAnchorB;
        def.referenceAngle = frame.referenceAngle;
        def.hertz = Real(joint.stiffnessHz);
        def.dampingRatio = Real(joint.dampingRatio);
        def.collideConnected = joint.collideConnected;
        return world.CreateJoint(def);
    }
    case JointType::Motor:
    {
        MotorJointDef def = world.MakeMotorJointDef(bodyA, bodyB);
        def.linearOffset = frame.linearOffset;
        def.angularOffset = frame.angularOffset;
        def.maxForce = Real(joint.maxForce);
        def.maxTorque = Real(joint.maxTorque);
        def.correctionFactor = Real(joint.correctionFactor);
        def.collideConnected = joint.collideConnected;
        return world.CreateJoint(def);
    }
    case JointType::Friction:
    {
        FrictionJointDef def;
        def.bodyA = bodyA;
        def.bodyB = bodyB;
        def.localAnchorA = frame.localAnchorA;
        def.localAnchorB = frame.localAnchorB;
        def.maxForce = Real(joint.maxForce);
        def.maxTorque = Real(joint.maxTorque);
        def.collideConnected = joint.collideConnected;
        return world.CreateJoint(def);
    }
    case JointType::Pulley:
    {
        PulleyJointDef def = world.MakePulleyJointDef(
            bodyA, bodyB, ToEngine(joint.groundAnchorA), ToEngine(joint.groundAnchorB),
            ToEngine(joint.anchorA), ToEngine(joint.anchorB), Real(joint.ratio));
        def.collideConnected = joint.collideConnected;
        return world.CreateJoint(def);
    }
    case JointType::Mouse:
    {
        // The anchor grabs body B; then the pointer moves to the target (Box2D's testbed
        // creates the joint at the grab point and calls SetTarget as the mouse moves).
        MouseJointDef def;
        def.bodyA = bodyA;
        def.bodyB = bodyB;
        def.target = ToEngine(joint.anchor);
        def.maxForce = Real(joint.maxForce);
        def.hertz = Real(joint.stiffnessHz);
        def.dampingRatio = Real(joint.dampingRatio);
        def.collideConnected = joint.collideConnected;
        const JointId id = world.CreateJoint(def);
        world.SetMouseTarget(id, ToEngine(joint.target));
        return id;
    }
    case JointType::Gear:
        break; // made above
    }
    throw InvalidArgument("unknown joint type");
}

BuiltCharacter MakeCharacter(const BuiltScene& built, const Scene& scene,
                             const SceneCharacter& character)
{
    // The loader checks these (CheckCharacterBody); a scene built by hand may not have been.
    const std::size_t index = character.bodyIndex;
    if (index >= scene.bodies.size() || scene.bodies[index].shapes.size() != 1 ||
        scene.bodies[index].shapes[0].type != SceneShapeType::Capsule ||
        scene.bodies[index].type != BodyType::Kinematic)
    {
        throw SceneError({scene.sourcePath + ": characters: body index " + std::to_string(index) +
                          ": must be a kinematic body with one capsule"});
    }
    const SceneBody& body = scene.bodies[index];
    const SceneShape& capsule = body.shapes[0];
    BuiltCharacter made;
    made.body = built.bodies[character.bodyIndex];
    made.capsule = {ToEngine(capsule.centerA), ToEngine(capsule.centerB), Real(capsule.radius)};
    made.filter = {capsule.filter.category, capsule.filter.mask};
    made.gravityScale = Real(body.gravityScale);
    made.inputs = character.inputs;
    made.velocity = ToEngine(body.linearVelocity);
    return made;
}

} // namespace

BuiltScene BuildWorld(const Scene& scene)
{
    BuiltScene built{World(MakeWorldDef(scene.world))};
    if (scene.world.lastStepInverseDt != 0)
    {
        built.world.SetLastStepInverseDt(Real(scene.world.lastStepInverseDt));
    }
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    {
        const SceneBody& body = scene.bodies[i];
        const std::string path = "bodies[" + std::to_string(i) + "]";
        BodyId id;
        try
        {
            id = built.world.CreateBody(MakeBodyDef(body));
        }
        catch (const InvalidArgument& error)
        {
            Refused(scene, path, error);
        }
        built.bodies.push_back(id);
        built.bodyByName.emplace(body.name, id);
        if (std::size_t(id.index) >= built.sceneIndexByPoolIndex.size())
        {
            built.sceneIndexByPoolIndex.resize(std::size_t(id.index) + 1, -1);
        }
        built.sceneIndexByPoolIndex[std::size_t(id.index)] = std::ptrdiff_t(i);

        std::vector<ShapeId>& shapes = built.shapes.emplace_back();
        std::vector<ChainId>& chains = built.chains.emplace_back();
        for (std::size_t k = 0; k < body.shapes.size(); ++k)
        {
            try
            {
                shapes.push_back(CreateShape(built.world, id, body.shapes[k]));
                chains.push_back(built.world.GetChain(shapes.back()));
            }
            catch (const InvalidArgument& error)
            {
                Refused(scene, path + ".shapes[" + std::to_string(k) + "]", error);
            }
        }
    }
    for (std::size_t j = 0; j < scene.joints.size(); ++j)
    {
        try
        {
            const JointId id = CreateJoint(built, scene.joints[j]);
            if (!scene.joints[j].impulses.empty())
            {
                const std::vector<Real> impulses(scene.joints[j].impulses.begin(),
                                                 scene.joints[j].impulses.end());
                built.world.SetJointImpulses(id, impulses);
            }
            built.joints.push_back(id);
            built.jointByName.emplace(scene.joints[j].name, id);
        }
        catch (const InvalidArgument& error)
        {
            Refused(scene, "joints[" + std::to_string(j) + "]", error);
        }
    }
    for (const SceneCharacter& character : scene.characters)
    {
        built.characters.push_back(MakeCharacter(built, scene, character));
    }
    return built;
}

std::optional<std::size_t> BuiltScene::SceneIndexOf(BodyId id) const
{
    const std::optional<std::size_t> index = SceneIndexOfPoolIndex(id.index);
    if (index && bodies[*index] == id)
    {
        return index;
    }
    return std::nullopt;
}

std::optional<std::size_t> BuiltScene::SceneIndexOfPoolIndex(std::int32_t poolIndex) const
{
    if (poolIndex < 0 || std::size_t(poolIndex) >= sceneIndexByPoolIndex.size() ||
        sceneIndexByPoolIndex[std::size_t(poolIndex)] < 0)
    {
        return std::nullopt;
    }
    return std::size_t(sceneIndexByPoolIndex[std::size_t(poolIndex)]);
}

} // namespace meff
