// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// meff scene → b2dJson. Geometry and joint frames are written as the engine builds them (a
// box's corners from MakeOffsetBox, local anchors from the joint-frame arithmetic BuildWorld
// uses), so the level loads in Box2D as the scene runs in meff; numbers the scene holds are
// written exactly. What b2dJson has no field for travels in "meff.*" custom properties
// (docs/b2djson.md).
#include "b2djson_values.h"
#include "joint_frame.h"
#include "scene_sections.h"

#include "meff/b2djson.h"
#include "meff/box2d_v3_features.h"
#include "meff/collision.h"

#include <cmath>
#include <string>
#include <tuple>

namespace meff
{

using b2djson_detail::FormatJson;
using Json = b2djson_detail::OrderedJson;
using b2djson_detail::WriteNumber;
using b2djson_detail::WriteVector;

namespace
{

SceneVec2 FromEngine(Vec2 v)
{
    return {double(v.x), double(v.y)};
}

class Exporter
{
  public:
    Exporter(const Scene& scene, const B2dJsonExportOptions& options)
        : m_scene(scene), m_hex(options.hexFloats), m_built(BuildWorld(scene))
    {
    }

    Json Level()
    {
        Json level = Json::object();
        const SceneWorldSettings& world = m_scene.world;
        const SceneWorldSettings defaults;
        level["gravity"] = Vector(world.gravity);
        level["allowSleep"] = world.allowSleep;
        level["autoClearForces"] = true;
        level["warmStarting"] = world.solver.warmStarting;
        level["continuousPhysics"] = world.continuous;
        level["subStepping"] = false;
        level["stepsPerSecond"] = Number(1.0 / world.dt);
        level["velocityIterations"] = world.solver.velocityIterations;
        level["positionIterations"] = world.solver.positionIterations;

        Json custom = Json::array();
        Property(custom, "meff.name", "string", m_scene.name);
        if (!m_scene.description.empty())
        {
            Property(custom, "meff.description", "string", m_scene.description);
        }
        // The step rate is the inverse of dt; when it does not give dt back exactly, the
        // exact dt goes along.
        if (1.0 / (1.0 / world.dt) != world.dt)
        {
            Property(custom, "meff.dt", "float", world.dt);
        }
        if (world.frames != defaults.frames)
        {
            Property(custom, "meff.frames", "int", world.frames);
        }
        const SolverSettings& solver = world.solver;
        if (solver.kind != defaults.solver.kind)
        {
            Property(custom, "meff.solver", "string", SolverKindName(solver.kind));
        }
        const std::tuple<const char*, bool, bool> flags[] = {
            {"meff.block_solver", solver.blockSolver, defaults.solver.blockSolver},
            {"meff.block_joints", solver.blockJoints, defaults.solver.blockJoints},
            {"meff.restitution_from_step_start", solver.restitutionFromStepStart,
             defaults.solver.restitutionFromStepStart}};
        for (const auto& [name, value, fallback] : flags)
        {
            if (value != fallback)
            {
                Property(custom, name, "bool", value);
            }
        }
        if (const std::optional<Json> soft = scene_detail::SoftStepJson(solver.softStep))
        {
            Property(custom, "meff.soft_step", "string", soft->dump());
        }
        if (const std::optional<Json> validate =
                scene_detail::ValidateJson(m_scene.tolerances, m_scene.validation))
        {
            Property(custom, "meff.validate", "string", validate->dump());
        }
        if (const std::optional<Json> plausibility =
                scene_detail::PlausibilityJson(m_scene.plausibility))
        {
            Property(custom, "meff.plausibility", "string", plausibility->dump());
        }
        if (m_scene.camera)
        {
            Property(custom, "meff.render", "string",
                     scene_detail::RenderJson(*m_scene.camera).dump());
        }
        if (m_scene.analytic)
        {
            Property(custom, "meff.analytic", "string", scene_detail::AnalyticJson(m_scene).dump());
        }
        level["customProperties"] = custom;

        level["body"] = Json::array();
        for (std::size_t i = 0; i < m_scene.bodies.size(); ++i)
        {
            level["body"].push_back(Body(i));
        }
        level["joint"] = Json::array();
        for (std::size_t j = 0; j < m_scene.joints.size(); ++j)
        {
            level["joint"].push_back(Joint(j));
        }
        return level;
    }

  private:
    Json Number(double value) const { return WriteNumber(value, m_hex); }
    Json Vector(SceneVec2 value) const { return WriteVector(value, m_hex); }
    Json Vector(Vec2 value) const { return Vector(FromEngine(value)); }

    void Property(Json& list, const char* name, const char* type, const Json& value) const
    {
        list.push_back({{"name", name},
                        {type, value.is_number_float() ? Number(value.get<double>()) : value}});
    }

    Json Body(std::size_t index) const
    {
        const SceneBody& body = m_scene.bodies[index];
        const BodyId id = m_built.bodies[index];
        const World& world = m_built.world;
        Json out = Json::object();
        out["name"] = body.name;
        out["type"] = body.type == BodyType::Static ? 0 : body.type == BodyType::Kinematic ? 1 : 2;
        out["position"] = Vector(body.position);
        out["angle"] = Number(body.angle);
        out["linearVelocity"] = Vector(body.linearVelocity);
        out["angularVelocity"] = Number(body.angularVelocity);
        if (body.linearDamping != 0)
        {
            out["linearDamping"] = Number(body.linearDamping);
        }
        if (body.angularDamping != 0)
        {
            out["angularDamping"] = Number(body.angularDamping);
        }
        if (body.gravityScale != 1)
        {
            out["gravityScale"] = Number(body.gravityScale);
        }
        if (body.bullet)
        {
            out["bullet"] = true;
        }
        if (!body.allowSleep)
        {
            out["allowSleep"] = false;
        }
        // b2dJson's loader reads a missing "awake" as asleep.
        out["awake"] = body.awake;
        if (body.fixedRotation)
        {
            out["fixedRotation"] = true;
        }
        // b2dJson's loader sets every body's mass from these (Box2D makes a dynamic body
        // without them 1 kg): the engine's values, with the inertia about the body origin as
        // b2Body::GetMassData gives it.
        if (body.type == BodyType::Dynamic)
        {
            const Real mass = world.GetMass(id);
            const Vec2 center = world.GetLocalCenter(id);
            const Real inertia = world.GetRotationalInertia(id) + mass * Dot(center, center);
            out["massData-mass"] = Number(double(mass));
            if (center.x != 0 || center.y != 0)
            {
                out["massData-center"] = Vector(center);
            }
            if (inertia != 0)
            {
                out["massData-I"] = Number(double(inertia));
            }
        }
        out["fixture"] = Json::array();
        for (const SceneShape& shape : body.shapes)
        {
            out["fixture"].push_back(Fixture(shape));
        }
        return out;
    }

    Json Fixture(const SceneShape& shape) const
    {
        Json out = Json::object();
        if (shape.density != 0)
        {
            out["density"] = Number(shape.density);
        }
        if (shape.friction != 0)
        {
            out["friction"] = Number(shape.friction);
        }
        if (shape.restitution != 0)
        {
            out["restitution"] = Number(shape.restitution);
        }
        if (shape.restitutionThreshold != 1)
        {
            out["restitutionThreshold"] = Number(shape.restitutionThreshold);
        }
        if (shape.sensor)
        {
            out["sensor"] = true;
        }
        if (shape.filter.category != 0x0001)
        {
            out["filter-categoryBits"] = shape.filter.category;
        }
        if (shape.filter.mask != 0xFFFF)
        {
            out["filter-maskBits"] = shape.filter.mask;
        }
        if (shape.filter.group != 0)
        {
            out["filter-groupIndex"] = shape.filter.group;
        }
        // meff's surface fields, which R.U.B.E. has no place for, go as meff.* properties.
        Json custom = Json::array();
        if (shape.tangentSpeed != 0)
        {
            Property(custom, "meff.tangent_speed", "float", shape.tangentSpeed);
        }
        if (shape.rollingResistance != 0)
        {
            Property(custom, "meff.rolling_resistance", "float", shape.rollingResistance);
        }
        switch (shape.type)
        {
        case SceneShapeType::Circle:
            out["circle"] = {{"center", Vector(shape.center)}, {"radius", Number(shape.radius)}};
            break;
        case SceneShapeType::Box:
        {
            const Polygon box =
                MakeOffsetBox(Real(shape.halfWidth), Real(shape.halfHeight),
                              scene_detail::ToEngine(shape.center), Real(shape.angle));
            std::vector<SceneVec2> corners;
            for (int k = 0; k < box.count; ++k)
            {
                corners.push_back(FromEngine(box.vertices[std::size_t(k)]));
            }
            out["polygon"] = {{"vertices", Points(corners)}};
            const Json authored = {{"half_width", shape.halfWidth},
                                   {"half_height", shape.halfHeight},
                                   {"center", scene_detail::PairJson(shape.center)},
                                   {"angle", shape.angle}};
            Property(custom, "meff.box", "string", authored.dump());
            break;
        }
        case SceneShapeType::Polygon:
            out["polygon"] = {{"vertices", Points(shape.vertices)}};
            break;
        case SceneShapeType::Segment:
            out["edge"] = {{"vertex1", Vector(shape.point1)}, {"vertex2", Vector(shape.point2)}};
            // A one-sided segment is Box2D 2.4's edge with ghost vertices.
            if (shape.oneSided && shape.prev && shape.next)
            {
                out["edge"]["hasVertex0"] = true;
                out["edge"]["hasVertex3"] = true;
                out["edge"]["vertex0"] = Vector(*shape.prev);
                out["edge"]["vertex3"] = Vector(*shape.next);
            }
            break;
        case SceneShapeType::Chain:
            out["chain"] = Chain(shape);
            break;
        case SceneShapeType::Capsule:
            break; // refused by ExportB2dJson before anything is written
        }
        if (!custom.empty())
        {
            out["customProperties"] = custom;
        }
        return out;
    }

    /// As b2dJson writes a b2ChainShape: a loop with its first point repeated at the end and
    /// its neighbours as ghosts (Box2D 2.3's CreateLoop), an open chain with its ghosts.
    Json Chain(const SceneShape& shape) const
    {
        std::vector<SceneVec2> points = shape.points;
        std::optional<SceneVec2> prev = shape.prev;
        std::optional<SceneVec2> next = shape.next;
        if (shape.loop)
        {
            prev = points[points.size() - 1];
            next = points[1];
            points.push_back(points.front());
        }
        Json chain = {{"vertices", Points(points)}};
        if (prev)
        {
            chain["hasPrevVertex"] = true;
            chain["prevVertex"] = Vector(*prev);
        }
        if (next)
        {
            chain["hasNextVertex"] = true;
            chain["nextVertex"] = Vector(*next);
        }
        return chain;
    }

    Json Points(const std::vector<SceneVec2>& points) const
    {
        Json xs = Json::array();
        Json ys = Json::array();
        for (const SceneVec2& point : points)
        {
            xs.push_back(Number(point.x));
            ys.push_back(Number(point.y));
        }
        return {{"x", xs}, {"y", ys}};
    }

    Json Joint(std::size_t index) const
    {
        const SceneJoint& joint = m_scene.joints[index];
        const scene_detail::JointFrame frame =
            scene_detail::ComputeJointFrame(m_built.world, m_built.bodies[joint.bodyIndexA],
                                            m_built.bodies[joint.bodyIndexB], joint);
        Json out = Json::object();
        out["name"] = joint.name;
        out["bodyA"] = joint.bodyIndexA;
        out["bodyB"] = joint.bodyIndexB;
        if (joint.collideConnected)
        {
            out["collideConnected"] = true;
        }
        const auto anchors = [&]
        {
            out["anchorA"] = Vector(frame.localAnchorA);
            out["anchorB"] = Vector(frame.localAnchorB);
        };
        const auto motor = [&](double speed)
        {
            out["enableMotor"] = joint.enableMotor;
            out["motorSpeed"] = Number(speed);
        };
        const auto limit = [&](double lower, double upper)
        {
            out["enableLimit"] = joint.enableLimit;
            out["lowerLimit"] = Number(lower);
            out["upperLimit"] = Number(upper);
        };
        switch (joint.type)
        {
        case JointType::Revolute:
            out["type"] = "revolute";
            anchors();
            out["refAngle"] = Number(double(frame.referenceAngle));
            limit(joint.lowerAngle, joint.upperAngle);
            motor(joint.motorSpeed);
            out["maxMotorTorque"] = Number(joint.maxMotorTorque);
            break;
        case JointType::Prismatic:
            out["type"] = "prismatic";
            anchors();
            out["localAxisA"] = Vector(frame.localAxisA);
            out["refAngle"] = Number(double(frame.referenceAngle));
            limit(joint.lowerTranslation, joint.upperTranslation);
            motor(joint.motorSpeed);
            out["maxMotorForce"] = Number(joint.maxMotorForce);
            break;
        case JointType::Wheel:
            out["type"] = "wheel";
            anchors();
            out["localAxisA"] = Vector(frame.localAxisA);
            motor(joint.motorSpeed);
            out["maxMotorTorque"] = Number(joint.maxMotorTorque);
            out["springFrequency"] = Number(joint.stiffnessHz);
            out["springDampingRatio"] = Number(joint.dampingRatio);
            limit(joint.lowerTranslation, joint.upperTranslation); // Box2D 2.4's wheel limits
            break;
        case JointType::Weld:
            out["type"] = "weld";
            anchors();
            out["refAngle"] = Number(double(frame.referenceAngle));
            out["frequency"] = Number(joint.stiffnessHz);
            out["dampingRatio"] = Number(joint.dampingRatio);
            break;
        case JointType::Distance:
            Distance(joint, out);
            anchors();
            break;
        case JointType::Motor:
            out["type"] = "motor";
            out["linearOffset"] = Vector(frame.linearOffset);
            out["refAngle"] = Number(double(frame.angularOffset));
            out["maxForce"] = Number(joint.maxForce);
            out["maxTorque"] = Number(joint.maxTorque);
            out["correctionFactor"] = Number(joint.correctionFactor);
            break;
        case JointType::Friction:
            out["type"] = "friction";
            anchors();
            out["maxForce"] = Number(joint.maxForce);
            out["maxTorque"] = Number(joint.maxTorque);
            break;
        case JointType::Pulley:
            Refuse(joint, index, "pulley");
        case JointType::Gear:
            Refuse(joint, index, "gear");
        case JointType::Mouse:
            out["type"] = "mouse";
            out["anchorB"] = Vector(joint.anchor); // b2dJson's mouse anchor is a world point
            out["target"] = Vector(joint.target);
            out["maxForce"] = Number(joint.maxForce);
            out["frequency"] = Number(joint.stiffnessHz);
            out["dampingRatio"] = Number(joint.dampingRatio);
            break;
        default:
            break;
        }
        if (const std::optional<Json> form = AuthoringForm(joint))
        {
            out["customProperties"] =
                Json::array({{{"name", "meff.joint"}, {"string", form->dump()}}});
        }
        return out;
    }

    /// Throws for a joint b2dJson has no form for, naming it.
    [[noreturn]] void Refuse(const SceneJoint& joint, std::size_t index, const char* type) const
    {
        throw SceneError({m_scene.sourcePath + ": joints[" + std::to_string(index) + "] (\"" +
                          joint.name + "\"): a " + type +
                          " joint cannot be exported: b2dJson (R.U.B.E.) has no " + type +
                          " joint that Box2D 2.4.1 builds from it"});
    }

    /// A rod or spring is a "distance" joint as Box2D 2.3 (R.U.B.E.) has it; a slack link
    /// without a spring is a "rope" (2.3's name for a maximum distance). Box2D 2.4's minimum
    /// and maximum go along in keys 2.3 readers ignore.
    void Distance(const SceneJoint& joint, Json& out) const
    {
        const bool rope = joint.stiffnessHz == 0 && joint.minLength < joint.maxLength;
        out["type"] = rope ? "rope" : "distance";
        out["length"] = Number(joint.length);
        if (!rope)
        {
            out["frequency"] = Number(joint.stiffnessHz);
            out["dampingRatio"] = Number(joint.dampingRatio);
        }
        out["minLength"] = Number(joint.minLength);
        out["maxLength"] = Number(joint.maxLength);
    }

    /// How the scene wrote the joint's frame, when not in b2dJson's own local form: the
    /// importer restores it while it still gives the same frame ("meff.joint").
    static std::optional<Json> AuthoringForm(const SceneJoint& joint)
    {
        Json form = Json::object();
        switch (joint.type)
        {
        case JointType::Revolute:
        case JointType::Prismatic:
        case JointType::Wheel:
        case JointType::Weld:
        case JointType::Distance:
        case JointType::Friction:
            if (!joint.localAnchors)
            {
                if (joint.type == JointType::Distance)
                {
                    form["anchor_a"] = scene_detail::PairJson(joint.anchorA);
                    form["anchor_b"] = scene_detail::PairJson(joint.anchorB);
                }
                else
                {
                    form["anchor"] = scene_detail::PairJson(joint.anchor);
                }
            }
            if ((joint.type == JointType::Prismatic || joint.type == JointType::Wheel) &&
                !joint.localAxisA)
            {
                form["axis"] = scene_detail::PairJson(joint.axis);
            }
            if (joint.type != JointType::Wheel && joint.type != JointType::Distance &&
                joint.type != JointType::Friction && !joint.referenceAngle)
            {
                form["reference_angle"] = nullptr; // as created
            }
            break;
        case JointType::Motor:
            if (!joint.linearOffset)
            {
                form["linear_offset"] = nullptr;
            }
            if (!joint.angularOffset)
            {
                form["angular_offset"] = nullptr;
            }
            break;
        default:
            break;
        }
        if (form.empty())
        {
            return std::nullopt;
        }
        return form;
    }

    const Scene& m_scene;
    bool m_hex;
    BuiltScene m_built;
};

} // namespace

std::string ExportB2dJson(const Scene& scene, const B2dJsonExportOptions& options)
{
    const std::vector<std::string> lacking =
        FieldsBox2D241Lacks(scene, "b2dJson cannot hold it, so the scene is not exported");
    if (!lacking.empty())
    {
        throw SceneError(lacking);
    }
    return FormatJson(Exporter(scene, options).Level());
}

} // namespace meff
