// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// A live World → Scene (SceneFromWorld): every body, shape and joint as the world holds it,
// in creation order, in the forms the loader reads back to the same engine objects (joints in
// their bodies' frames, numbers as the engine's floats widened to double).
#include "engine_shapes.h"
#include "json_document.h"

#include "meff/scene.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <unordered_map>

namespace meff
{

namespace
{

SceneVec2 FromEngine(Vec2 v)
{
    return {double(v.x), double(v.y)};
}

/// Bit for bit (a zero's sign included).
bool Same(Vec2 a, Vec2 b)
{
    return std::memcmp(&a, &b, sizeof(Vec2)) == 0;
}

bool SamePolygon(const Polygon& a, const Polygon& b)
{
    if (a.count != b.count || !Same(a.centroid, b.centroid))
    {
        return false;
    }
    for (int i = 0; i < a.count; ++i)
    {
        if (!Same(a.vertices[i], b.vertices[i]) || !Same(a.normals[i], b.normals[i]))
        {
            return false;
        }
    }
    return true;
}

/// Floats near `estimate` to try as a box's half extent: the short decimals a file would give
/// (1 to 8 significant digits) first, then the nearest float and a few steps either side.
std::vector<Real> Candidates(double estimate)
{
    std::vector<Real> out;
    const auto add = [&](Real value)
    {
        if (value > 0 && std::find(out.begin(), out.end(), value) == out.end())
        {
            out.push_back(value);
        }
    };
    if (!(estimate > 0) || !std::isfinite(estimate))
    {
        return out;
    }
    for (int digits = 1; digits <= 8; ++digits)
    {
        const double scale = std::pow(10.0, digits - 1 - int(std::floor(std::log10(estimate))));
        add(Real(std::round(estimate * scale) / scale));
    }
    Real up = Real(estimate);
    Real down = up;
    add(up);
    for (int step = 0; step < 4; ++step)
    {
        up = std::nextafter(up, kMaxReal);
        down = std::nextafter(down, Real(0));
        add(up);
        add(down);
    }
    return out;
}

/// The box (half extents, centre, angle) MakeOffsetBox makes `polygon` from, bit for bit, or
/// nothing: the centre is the centroid, the angle the one whose rotation gives the second
/// face's normal, the half extents those that give the corners (Candidates around the corner
/// taken back into the box's frame).
std::optional<SceneShape> AsBox(const Polygon& polygon)
{
    if (polygon.count != 4)
    {
        return std::nullopt;
    }
    const Vec2 normal = polygon.normals[1]; // the rotation's (cos, sin)
    std::optional<Real> angle;
    Real guess = std::atan2(normal.y, normal.x);
    for (int k = 0; k < 3 && !angle; ++k)
    {
        for (const Real candidate :
             {guess, std::nextafter(guess, Real(10)), std::nextafter(guess, Real(-10))})
        {
            const Rot q(candidate);
            if (q.c == normal.x && q.s == normal.y)
            {
                angle = candidate;
                break;
            }
        }
        guess = std::nextafter(guess, k % 2 == 0 ? Real(10) : Real(-10));
    }
    if (!angle)
    {
        return std::nullopt;
    }
    // The corner (hw, hh) taken back into the box's frame, in double; the corners were rounded
    // to floats at the box's size, so a thin box's half height may be many float steps off.
    const Rot q(*angle);
    const double dx = double(polygon.vertices[2].x) - double(polygon.centroid.x);
    const double dy = double(polygon.vertices[2].y) - double(polygon.centroid.y);
    const double c = q.c;
    const double sn = q.s;
    const std::vector<Real> widths = Candidates(c * dx + sn * dy);
    const std::vector<Real> heights = Candidates(-sn * dx + c * dy);
    for (const Real halfWidth : widths)
    {
        for (const Real halfHeight : heights)
        {
            if (!(halfWidth > 0) || !(halfHeight > 0))
            {
                continue;
            }
            try
            {
                if (SamePolygon(MakeOffsetBox(halfWidth, halfHeight, polygon.centroid, *angle),
                                polygon))
                {
                    SceneShape box;
                    box.type = SceneShapeType::Box;
                    box.halfWidth = halfWidth;
                    box.halfHeight = halfHeight;
                    box.center = FromEngine(polygon.centroid);
                    box.angle = *angle;
                    return box;
                }
            }
            catch (const InvalidArgument&)
            {
                // not this candidate
            }
        }
    }
    return std::nullopt;
}

SceneShape Geometry(const World& world, ShapeId id)
{
    SceneShape shape;
    switch (world.GetShapeType(id))
    {
    case ShapeType::Circle:
    {
        const Circle& circle = world.GetCircle(id);
        shape.type = SceneShapeType::Circle;
        shape.center = FromEngine(circle.center);
        shape.radius = circle.radius;
        break;
    }
    case ShapeType::Polygon:
    {
        const Polygon& polygon = world.GetPolygon(id);
        if (const std::optional<SceneShape> box = AsBox(polygon))
        {
            shape = *box;
        }
        else
        {
            shape.type = SceneShapeType::Polygon;
            for (int i = 0; i < polygon.count; ++i)
            {
                shape.vertices.push_back(FromEngine(polygon.vertices[i]));
            }
        }
        // Sharp polygons carry the world's skin; a rounded one its own radius.
        if (polygon.radius > world.GetTolerances().polygonSkin)
        {
            shape.rounding = polygon.radius;
        }
        break;
    }
    case ShapeType::Capsule:
    {
        const Capsule& capsule = world.GetCapsule(id);
        shape.type = SceneShapeType::Capsule;
        shape.centerA = FromEngine(capsule.center1);
        shape.centerB = FromEngine(capsule.center2);
        shape.radius = capsule.radius;
        break;
    }
    case ShapeType::Segment:
    {
        const Segment& segment = world.GetSegment(id);
        shape.type = SceneShapeType::Segment;
        shape.point1 = FromEngine(segment.point1);
        shape.point2 = FromEngine(segment.point2);
        break;
    }
    case ShapeType::ChainSegment:
    {
        // A one-sided segment made alone (chains are read whole by Chain()).
        const ChainSegment& segment = world.GetChainSegment(id);
        shape.type = SceneShapeType::Segment;
        shape.oneSided = true;
        shape.point1 = FromEngine(segment.segment.point1);
        shape.point2 = FromEngine(segment.segment.point2);
        shape.prev = FromEngine(segment.ghost1);
        shape.next = FromEngine(segment.ghost2);
        break;
    }
    }
    return shape;
}

/// A chain's points from its segments: each segment's first point, and an open chain's last
/// point and ghosts from its end segments.
SceneShape Chain(const World& world, ChainId chain)
{
    SceneShape shape;
    shape.type = SceneShapeType::Chain;
    shape.loop = world.IsChainLoop(chain);
    const std::span<const ShapeId> segments = world.GetChainSegments(chain);
    for (const ShapeId segment : segments)
    {
        shape.points.push_back(FromEngine(world.GetChainSegment(segment).segment.point1));
    }
    if (!shape.loop)
    {
        const ChainSegment& first = world.GetChainSegment(segments.front());
        const ChainSegment& last = world.GetChainSegment(segments.back());
        shape.points.push_back(FromEngine(last.segment.point2));
        shape.prev = FromEngine(first.ghost1);
        shape.next = FromEngine(last.ghost2);
    }
    return shape;
}

void Material(SceneShape& shape, const ShapeDef& def)
{
    shape.density = def.density;
    shape.friction = def.friction;
    shape.restitution = def.restitution;
    shape.restitutionThreshold = def.restitutionThreshold;
    shape.tangentSpeed = def.tangentSpeed;
    shape.rollingResistance = def.rollingResistance;
    shape.filter = {def.filter.categoryBits, def.filter.maskBits, def.filter.groupIndex};
    shape.sensor = def.isSensor;
}

/// The body's shapes in creation order: World::GetShapes lists them newest first, a chain's
/// segments together in order along it, so the list is walked backwards and each chain is
/// taken whole where it is first met.
std::vector<SceneShape> Shapes(const World& world, BodyId body)
{
    std::vector<SceneShape> shapes;
    const std::vector<ShapeId> ids = world.GetShapes(body);
    std::set<std::int32_t> chainsDone;
    for (auto it = ids.rbegin(); it != ids.rend(); ++it)
    {
        const ChainId chain = world.GetChain(*it);
        SceneShape shape;
        if (!chain.IsNull())
        {
            if (!chainsDone.insert(chain.index).second)
            {
                continue;
            }
            shape = Chain(world, chain);
        }
        else
        {
            shape = Geometry(world, *it);
        }
        Material(shape, world.GetShapeDef(*it));
        shapes.push_back(std::move(shape));
    }
    return shapes;
}

/// The linear velocity to create `body` with so that it has `target` once BuildWorld has given
/// it its shapes: each shape moves the centre of mass, and a spinning body's centre velocity
/// changes with it (Box2D's ResetMassData). A few corrections on a scratch world of the body
/// alone find it; where none does, `target` (off in the last bits).
SceneVec2 CreationVelocity(SceneBody body, Vec2 target)
{
    Scene scratch;
    body.linearVelocity = FromEngine(target);
    for (int attempt = 0; attempt < 8; ++attempt)
    {
        scratch.bodies = {body};
        const BuiltScene built = BuildWorld(scratch);
        const Vec2 got = built.world.GetLinearVelocity(built.bodies[0]);
        if (Same(got, target))
        {
            return body.linearVelocity;
        }
        const Vec2 tried = scene_detail::ToEngine(body.linearVelocity);
        Vec2 next = tried + (target - got);
        // A correction below the velocity's float step: one step towards the target.
        const auto nudge = [](Real& value, Real from, Real gotValue, Real want)
        {
            if (value == from && gotValue != want)
            {
                value = std::nextafter(from, want > gotValue ? kMaxReal : -kMaxReal);
            }
        };
        nudge(next.x, tried.x, got.x, target.x);
        nudge(next.y, tried.y, got.y, target.y);
        body.linearVelocity = FromEngine(next);
    }
    return FromEngine(target);
}

SceneBody Body(const World& world, BodyId id, std::string name)
{
    const BodyDef def = world.GetBodyDef(id);
    SceneBody body;
    body.name = std::move(name);
    body.type = def.type;
    body.position = FromEngine(def.position);
    body.angle = def.angle;
    body.linearVelocity = FromEngine(def.linearVelocity);
    body.angularVelocity = def.angularVelocity;
    body.linearDamping = def.linearDamping;
    body.angularDamping = def.angularDamping;
    body.gravityScale = def.gravityScale;
    body.fixedRotation = def.fixedRotation;
    body.bullet = def.bullet;
    body.allowSleep = def.allowSleep;
    body.awake = def.awake;
    body.shapes = Shapes(world, id);
    if (body.type == BodyType::Dynamic && def.angularVelocity != 0 && !body.shapes.empty())
    {
        body.linearVelocity = CreationVelocity(body, def.linearVelocity);
    }
    return body;
}

/// The joint's settings from its definition (World::GetJointDef), in the local form.
class JointReader
{
  public:
    JointReader(const World& world, SceneJoint& joint) : m_world(world), m_joint(joint) {}

    void operator()(const RevoluteJointDef& def)
    {
        Local(def);
        m_joint.referenceAngle = def.referenceAngle;
        Limit(def.enableLimit, def.lowerAngle, def.upperAngle);
        Motor(def.enableMotor, def.motorSpeed);
        m_joint.maxMotorTorque = def.maxMotorTorque;
        Spring(def.hertz, def.dampingRatio);
        m_joint.enableSpring = def.enableSpring;
        m_joint.targetAngle = def.targetAngle;
    }
    void operator()(const PrismaticJointDef& def)
    {
        Local(def);
        m_joint.localAxisA = FromEngine(def.localAxisA);
        m_joint.referenceAngle = def.referenceAngle;
        Translations(def.enableLimit, def.lowerTranslation, def.upperTranslation);
        Motor(def.enableMotor, def.motorSpeed);
        m_joint.maxMotorForce = def.maxMotorForce;
        Spring(def.hertz, def.dampingRatio);
        m_joint.enableSpring = def.enableSpring;
        m_joint.targetTranslation = def.targetTranslation;
    }
    void operator()(const WheelJointDef& def)
    {
        Local(def);
        m_joint.localAxisA = FromEngine(def.localAxisA);
        Translations(def.enableLimit, def.lowerTranslation, def.upperTranslation);
        Motor(def.enableMotor, def.motorSpeed);
        m_joint.maxMotorTorque = def.maxMotorTorque;
        Spring(def.hertz, def.dampingRatio);
    }
    void operator()(const WeldJointDef& def)
    {
        Local(def);
        m_joint.referenceAngle = def.referenceAngle;
        Spring(def.hertz, def.dampingRatio);
    }
    void operator()(const DistanceJointDef& def)
    {
        Local(def);
        m_joint.length = def.length;
        m_joint.minLength = def.minLength;
        m_joint.maxLength = def.maxLength;
        Spring(def.hertz, def.dampingRatio);
    }
    void operator()(const FrictionJointDef& def)
    {
        Local(def);
        m_joint.maxForce = def.maxForce;
        m_joint.maxTorque = def.maxTorque;
    }
    void operator()(const MotorJointDef& def)
    {
        m_joint.linearOffset = FromEngine(def.linearOffset);
        m_joint.angularOffset = def.angularOffset;
        m_joint.maxForce = def.maxForce;
        m_joint.maxTorque = def.maxTorque;
        m_joint.correctionFactor = def.correctionFactor;
    }
    void operator()(const MouseJointDef& def)
    {
        m_joint.anchor = FromEngine(def.target); // the grabbed point, where it is now
        m_joint.maxForce = def.maxForce;
        Spring(def.hertz, def.dampingRatio);
    }
    void operator()(const PulleyJointDef& def)
    {
        m_joint.groundAnchorA = FromEngine(def.groundAnchorA);
        m_joint.groundAnchorB = FromEngine(def.groundAnchorB);
        m_joint.anchorA = FromEngine(m_world.GetWorldPoint(def.bodyA, def.localAnchorA));
        m_joint.anchorB = FromEngine(m_world.GetWorldPoint(def.bodyB, def.localAnchorB));
        m_joint.ratio = def.ratio;
    }
    void operator()(const GearJointDef& def) { m_joint.ratio = def.ratio; }

  private:
    template <typename Def>
    void Local(const Def& def)
    {
        m_joint.localAnchors = true;
        m_joint.localAnchorA = FromEngine(def.localAnchorA);
        m_joint.localAnchorB = FromEngine(def.localAnchorB);
    }
    void Limit(bool enable, Real lower, Real upper)
    {
        m_joint.enableLimit = enable;
        m_joint.lowerAngle = lower;
        m_joint.upperAngle = upper;
    }
    void Translations(bool enable, Real lower, Real upper)
    {
        m_joint.enableLimit = enable;
        m_joint.lowerTranslation = lower;
        m_joint.upperTranslation = upper;
    }
    void Motor(bool enable, Real speed)
    {
        m_joint.enableMotor = enable;
        m_joint.motorSpeed = speed;
    }
    void Spring(Real hertz, Real dampingRatio)
    {
        m_joint.stiffnessHz = hertz;
        m_joint.dampingRatio = dampingRatio;
    }

    const World& m_world;
    SceneJoint& m_joint;
};

/// Unique plain names from `named` (or "PREFIX<i>"), refused with SceneError otherwise.
template <typename Id>
std::vector<std::string> Names(const std::vector<Id>& ids,
                               const std::function<std::string(Id)>& named, const char* prefix,
                               const char* list, const std::string& sceneName)
{
    std::vector<std::string> names;
    std::set<std::string> used;
    std::vector<std::string> problems;
    for (std::size_t i = 0; i < ids.size(); ++i)
    {
        std::string name = named ? named(ids[i]) : std::string();
        if (name.empty())
        {
            name = prefix + std::to_string(i);
        }
        if (!scene_detail::IsPlainName(name))
        {
            problems.push_back(sceneName + ": " + list + "[" + std::to_string(i) +
                               "].name: must be 1 to 64 characters from A-Z a-z 0-9 _ - ., got \"" +
                               name + "\"");
        }
        else if (!used.insert(name).second)
        {
            problems.push_back(sceneName + ": " + list + "[" + std::to_string(i) +
                               "].name: given twice, got \"" + name + "\"");
        }
        names.push_back(std::move(name));
    }
    if (!problems.empty())
    {
        throw SceneError(problems);
    }
    return names;
}

} // namespace

Scene SceneFromWorld(const World& world, const SceneFromWorldOptions& options)
{
    Scene scene;
    scene.name = options.name;
    if (!(world.GetTolerances() == Tolerances{}))
    {
        throw SceneError({options.name + ": world.tolerances: a scene file has no tolerances: "
                                         "only a world with the default Tolerances can be saved"});
    }
    scene.world.gravity = FromEngine(world.GetGravity());
    scene.world.dt = options.dt;
    scene.world.frames = options.frames;
    scene.world.solver = world.GetSolverSettings();
    scene.world.allowSleep = world.GetAllowSleeping();
    scene.world.continuous = world.GetContinuous();
    scene.world.lastStepInverseDt = world.GetLastStepInverseDt();

    const std::vector<BodyId> bodies = world.GetBodies();
    const std::vector<std::string> bodyNames =
        Names(bodies, options.bodyName, "body", "bodies", options.name);
    std::unordered_map<std::int32_t, std::size_t> bodyIndex;
    for (std::size_t i = 0; i < bodies.size(); ++i)
    {
        bodyIndex[bodies[i].index] = i;
        scene.bodies.push_back(Body(world, bodies[i], bodyNames[i]));
    }

    const std::vector<JointId> joints = world.GetJoints();
    const std::vector<std::string> jointNames =
        Names(joints, options.jointName, "joint", "joints", options.name);
    std::unordered_map<std::int32_t, std::size_t> jointIndex;
    for (std::size_t j = 0; j < joints.size(); ++j)
    {
        jointIndex[joints[j].index] = j;
        SceneJoint joint;
        joint.type = world.GetJointType(joints[j]);
        joint.name = jointNames[j];
        const AnyJointDef def = world.GetJointDef(joints[j]);
        std::visit([&](const auto& d) { joint.collideConnected = d.collideConnected; }, def);
        if (const auto* gear = std::get_if<GearJointDef>(&def))
        {
            // Gears come after their joints (each is created after the two it couples).
            joint.jointIndexA = jointIndex.at(gear->joint1.index);
            joint.jointIndexB = jointIndex.at(gear->joint2.index);
            joint.jointA = scene.joints[joint.jointIndexA].name;
            joint.jointB = scene.joints[joint.jointIndexB].name;
        }
        joint.bodyIndexA = bodyIndex.at(world.GetBodyA(joints[j]).index);
        joint.bodyIndexB = bodyIndex.at(world.GetBodyB(joints[j]).index);
        joint.bodyA = scene.bodies[joint.bodyIndexA].name;
        joint.bodyB = scene.bodies[joint.bodyIndexB].name;
        std::visit(JointReader(world, joint), def);
        if (joint.type == JointType::Mouse)
        {
            joint.target = FromEngine(world.GetMouseTarget(joints[j]));
        }
        // The warm start, when there is one (a joint that has not acted holds only zeros).
        const std::vector<Real> impulses = world.GetJointImpulses(joints[j]);
        if (std::any_of(impulses.begin(), impulses.end(),
                        [](Real impulse) { return impulse != 0 || std::signbit(impulse); }))
        {
            joint.impulses.assign(impulses.begin(), impulses.end());
        }
        scene.joints.push_back(std::move(joint));
    }
    return scene;
}

Scene SceneFromBuilt(const BuiltScene& built, const Scene& scene)
{
    if (!scene.characters.empty())
    {
        throw SceneError({scene.sourcePath +
                          ": characters: a scene with characters cannot be saved from its world "
                          "(the character mover's state is not in the world)"});
    }
    std::unordered_map<std::int32_t, std::string> bodies;
    std::unordered_map<std::int32_t, std::string> joints;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    {
        bodies[built.bodies[i].index] = scene.bodies[i].name;
    }
    for (std::size_t j = 0; j < scene.joints.size(); ++j)
    {
        joints[built.joints[j].index] = scene.joints[j].name;
    }
    SceneFromWorldOptions options;
    options.name = scene.name;
    options.dt = scene.world.dt;
    options.frames = scene.world.frames;
    // Bodies and joints the game made after the scene was built get the default names.
    options.bodyName = [&bodies](BodyId id)
    {
        const auto found = bodies.find(id.index);
        return found == bodies.end() ? std::string() : found->second;
    };
    options.jointName = [&joints](JointId id)
    {
        const auto found = joints.find(id.index);
        return found == joints.end() ? std::string() : found->second;
    };
    Scene saved = SceneFromWorld(built.world, options);
    saved.sourcePath = scene.sourcePath;
    saved.description = scene.description;
    saved.tolerances = scene.tolerances;
    saved.validation = scene.validation;
    saved.plausibility = scene.plausibility;
    saved.camera = scene.camera;
    return saved;
}

Scene SceneFromSnapshot(const WorldSnapshot& snapshot, const SceneFromWorldOptions& options)
{
    World world;
    world.RestoreSnapshot(snapshot);
    return SceneFromWorld(world, options);
}

} // namespace meff
