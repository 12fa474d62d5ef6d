// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Building and stepping the Box2D 2.4.1 world of a scene. Numbers are converted from the
// scene's doubles exactly as meff::BuildWorld converts them (static_cast<float>), and every
// object is created in BuildWorld's order: each body followed by its shapes in file order,
// then the joints in file order.
#include "meff/box2d_mirror.h"

#include "meff/box2d_v3_features.h"

#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <utility>

// Box2D 2.4.1 exports its block-solver switch but declares it in no header.
extern B2_API bool g_blockSolve;

namespace meff::validation
{

namespace
{

b2Vec2 ToB2(SceneVec2 v)
{
    return {static_cast<float>(v.x), static_cast<float>(v.y)};
}

std::vector<b2Vec2> ToB2(const std::vector<SceneVec2>& points)
{
    std::vector<b2Vec2> converted;
    converted.reserve(points.size());
    for (const SceneVec2& point : points)
    {
        converted.push_back(ToB2(point));
    }
    return converted;
}

b2BodyType ToB2(BodyType type)
{
    switch (type)
    {
    case BodyType::Static:
        return b2_staticBody;
    case BodyType::Kinematic:
        return b2_kinematicBody;
    case BodyType::Dynamic:
        return b2_dynamicBody;
    }
    throw std::invalid_argument("unknown body type");
}

b2BodyDef MakeBodyDef(const SceneBody& body)
{
    b2BodyDef def;
    def.type = ToB2(body.type);
    def.position = ToB2(body.position);
    def.angle = static_cast<float>(body.angle);
    def.linearVelocity = ToB2(body.linearVelocity);
    def.angularVelocity = static_cast<float>(body.angularVelocity);
    def.linearDamping = static_cast<float>(body.linearDamping);
    def.angularDamping = static_cast<float>(body.angularDamping);
    def.allowSleep = body.allowSleep;
    def.awake = body.awake;
    def.fixedRotation = body.fixedRotation;
    def.bullet = body.bullet;
    def.enabled = true;
    def.gravityScale = static_cast<float>(body.gravityScale);
    return def;
}

b2FixtureDef MakeFixtureDef(const SceneShape& shape, const b2Shape* geometry)
{
    b2FixtureDef def;
    def.shape = geometry;
    def.friction = static_cast<float>(shape.friction);
    def.restitution = static_cast<float>(shape.restitution);
    def.restitutionThreshold = static_cast<float>(shape.restitutionThreshold);
    def.density = static_cast<float>(shape.density);
    def.isSensor = shape.sensor;
    def.filter.categoryBits = shape.filter.category;
    def.filter.maskBits = shape.filter.mask;
    def.filter.groupIndex = shape.filter.group;
    return def;
}

b2Fixture* CreateFixture(b2Body* body, const SceneShape& shape)
{
    switch (shape.type)
    {
    case SceneShapeType::Circle:
    {
        b2CircleShape circle;
        circle.m_p = ToB2(shape.center);
        circle.m_radius = static_cast<float>(shape.radius);
        const b2FixtureDef def = MakeFixtureDef(shape, &circle);
        return body->CreateFixture(&def);
    }
    case SceneShapeType::Box:
    {
        // BuildWorld uses MakeOffsetBox, which is this overload's arithmetic.
        b2PolygonShape box;
        box.SetAsBox(static_cast<float>(shape.halfWidth), static_cast<float>(shape.halfHeight),
                     ToB2(shape.center), static_cast<float>(shape.angle));
        const b2FixtureDef def = MakeFixtureDef(shape, &box);
        return body->CreateFixture(&def);
    }
    case SceneShapeType::Polygon:
    {
        const std::vector<b2Vec2> points = ToB2(shape.vertices);
        b2PolygonShape polygon;
        polygon.Set(points.data(), static_cast<int32>(points.size()));
        const b2FixtureDef def = MakeFixtureDef(shape, &polygon);
        return body->CreateFixture(&def);
    }
    case SceneShapeType::Segment:
    {
        b2EdgeShape edge;
        if (shape.oneSided)
        {
            edge.SetOneSided(ToB2(shape.prev.value()), ToB2(shape.point1), ToB2(shape.point2),
                             ToB2(shape.next.value()));
        }
        else
        {
            edge.SetTwoSided(ToB2(shape.point1), ToB2(shape.point2));
        }
        const b2FixtureDef def = MakeFixtureDef(shape, &edge);
        return body->CreateFixture(&def);
    }
    case SceneShapeType::Chain:
    {
        const std::vector<b2Vec2> points = ToB2(shape.points);
        b2ChainShape chain;
        if (shape.loop)
        {
            chain.CreateLoop(points.data(), static_cast<int32>(points.size()));
        }
        else
        {
            chain.CreateChain(points.data(), static_cast<int32>(points.size()),
                              ToB2(shape.prev.value()), ToB2(shape.next.value()));
        }
        const b2FixtureDef def = MakeFixtureDef(shape, &chain);
        return body->CreateFixture(&def);
    }
    case SceneShapeType::Capsule:
        break; // Box2D v3's: refused by Validate (FieldsBox2D241Lacks)
    }
    throw std::invalid_argument("Box2D 2.4.1 has no such shape (a capsule)");
}

/// A joint given in the bodies' frames (the scene's local form, b2dJson's) replaces what
/// Initialize computed from world points.
template <typename Def>
void ApplyLocalForm(const SceneJoint& joint, Def& def)
{
    if (joint.localAnchors)
    {
        def.localAnchorA = ToB2(joint.localAnchorA);
        def.localAnchorB = ToB2(joint.localAnchorB);
    }
    if constexpr (requires { def.referenceAngle; })
    {
        if (joint.referenceAngle)
        {
            def.referenceAngle = static_cast<float>(*joint.referenceAngle);
        }
    }
    if constexpr (requires { def.localAxisA; })
    {
        if (joint.localAxisA)
        {
            def.localAxisA = ToB2(*joint.localAxisA);
        }
    }
}

/// `made`: the joints made so far, in scene order (a gear's joints come before it).
b2Joint* CreateJoint(b2World& world, const SceneJoint& joint, b2Body* bodyA, b2Body* bodyB,
                     const std::vector<b2Joint*>& made)
{
    switch (joint.type)
    {
    case JointType::Gear:
    {
        b2GearJointDef def;
        def.bodyA = bodyA;
        def.bodyB = bodyB;
        def.joint1 = made.at(joint.jointIndexA);
        def.joint2 = made.at(joint.jointIndexB);
        def.ratio = static_cast<float>(joint.ratio);
        def.collideConnected = joint.collideConnected;
        return world.CreateJoint(&def);
    }
    case JointType::Revolute:
    {
        b2RevoluteJointDef def;
        def.Initialize(bodyA, bodyB, ToB2(joint.anchor));
        ApplyLocalForm(joint, def);
        def.enableLimit = joint.enableLimit;
        def.lowerAngle = static_cast<float>(joint.lowerAngle);
        def.upperAngle = static_cast<float>(joint.upperAngle);
        def.enableMotor = joint.enableMotor;
        def.motorSpeed = static_cast<float>(joint.motorSpeed);
        def.maxMotorTorque = static_cast<float>(joint.maxMotorTorque);
        def.collideConnected = joint.collideConnected;
        return world.CreateJoint(&def);
    }
    case JointType::Prismatic:
    {
        b2PrismaticJointDef def;
        def.Initialize(bodyA, bodyB, ToB2(joint.anchor), ToB2(joint.axis));
        ApplyLocalForm(joint, def);
        def.enableLimit = joint.enableLimit;
        def.lowerTranslation = static_cast<float>(joint.lowerTranslation);
        def.upperTranslation = static_cast<float>(joint.upperTranslation);
        def.enableMotor = joint.enableMotor;
        def.motorSpeed = static_cast<float>(joint.motorSpeed);
        def.maxMotorForce = static_cast<float>(joint.maxMotorForce);
        def.collideConnected = joint.collideConnected;
        return world.CreateJoint(&def);
    }
    case JointType::Wheel:
    {
        b2WheelJointDef def;
        def.Initialize(bodyA, bodyB, ToB2(joint.anchor), ToB2(joint.axis));
        ApplyLocalForm(joint, def);
        // meff normalizes the axis at creation, Box2D's wheel joint does not: hand it the
        // same unit vector (b2Vec2::Normalize is meff's Vec2::Normalize, operation for
        // operation).
        def.localAxisA.Normalize();
        def.enableLimit = joint.enableLimit;
        def.lowerTranslation = static_cast<float>(joint.lowerTranslation);
        def.upperTranslation = static_cast<float>(joint.upperTranslation);
        def.enableMotor = joint.enableMotor;
        def.motorSpeed = static_cast<float>(joint.motorSpeed);
        def.maxMotorTorque = static_cast<float>(joint.maxMotorTorque);
        def.stiffness = 0.0f;
        def.damping = 0.0f;
        if (joint.stiffnessHz > 0)
        {
            b2LinearStiffness(def.stiffness, def.damping, static_cast<float>(joint.stiffnessHz),
                              static_cast<float>(joint.dampingRatio), bodyA, bodyB);
        }
        def.collideConnected = joint.collideConnected;
        return world.CreateJoint(&def);
    }
    case JointType::Distance:
    {
        b2DistanceJointDef def;
        def.Initialize(bodyA, bodyB, ToB2(joint.anchorA), ToB2(joint.anchorB));
        ApplyLocalForm(joint, def);
        def.length = static_cast<float>(joint.length);
        def.minLength = static_cast<float>(joint.minLength);
        def.maxLength = static_cast<float>(joint.maxLength);
        def.stiffness = 0.0f;
        def.damping = 0.0f;
        if (joint.stiffnessHz > 0)
        {
            b2LinearStiffness(def.stiffness, def.damping, static_cast<float>(joint.stiffnessHz),
                              static_cast<float>(joint.dampingRatio), bodyA, bodyB);
        }
        def.collideConnected = joint.collideConnected;
        return world.CreateJoint(&def);
    }
    case JointType::Weld:
    {
        b2WeldJointDef def;
        def.Initialize(bodyA, bodyB, ToB2(joint.anchor));
        ApplyLocalForm(joint, def);
        def.stiffness = 0.0f;
        def.damping = 0.0f;
        if (joint.stiffnessHz > 0)
        {
            b2AngularStiffness(def.stiffness, def.damping, static_cast<float>(joint.stiffnessHz),
                               static_cast<float>(joint.dampingRatio), bodyA, bodyB);
        }
        def.collideConnected = joint.collideConnected;
        return world.CreateJoint(&def);
    }
    case JointType::Motor:
    {
        b2MotorJointDef def;
        def.Initialize(bodyA, bodyB);
        if (joint.linearOffset)
        {
            def.linearOffset = ToB2(*joint.linearOffset);
        }
        if (joint.angularOffset)
        {
            def.angularOffset = static_cast<float>(*joint.angularOffset);
        }
        def.maxForce = static_cast<float>(joint.maxForce);
        def.maxTorque = static_cast<float>(joint.maxTorque);
        def.correctionFactor = static_cast<float>(joint.correctionFactor);
        def.collideConnected = joint.collideConnected;
        return world.CreateJoint(&def);
    }
    case JointType::Friction:
    {
        b2FrictionJointDef def;
        def.Initialize(bodyA, bodyB, ToB2(joint.anchor));
        ApplyLocalForm(joint, def);
        def.maxForce = static_cast<float>(joint.maxForce);
        def.maxTorque = static_cast<float>(joint.maxTorque);
        def.collideConnected = joint.collideConnected;
        return world.CreateJoint(&def);
    }
    case JointType::Pulley:
    {
        b2PulleyJointDef def;
        def.Initialize(bodyA, bodyB, ToB2(joint.groundAnchorA), ToB2(joint.groundAnchorB),
                       ToB2(joint.anchorA), ToB2(joint.anchorB), static_cast<float>(joint.ratio));
        def.collideConnected = joint.collideConnected;
        return world.CreateJoint(&def);
    }
    case JointType::Mouse:
    {
        // Grab body B at the anchor, then move the pointer to the target (see build_world).
        b2MouseJointDef def;
        def.bodyA = bodyA;
        def.bodyB = bodyB;
        def.target = ToB2(joint.anchor);
        def.maxForce = static_cast<float>(joint.maxForce);
        b2LinearStiffness(def.stiffness, def.damping, static_cast<float>(joint.stiffnessHz),
                          static_cast<float>(joint.dampingRatio), bodyA, bodyB);
        def.collideConnected = joint.collideConnected;
        auto* mouse = static_cast<b2MouseJoint*>(world.CreateJoint(&def));
        mouse->SetTarget(ToB2(joint.target));
        return mouse;
    }
    }
    throw std::invalid_argument("unknown joint type");
}

/// Box2D's block-solver switch is one global for the whole process, so mirrors stepping on
/// several threads (`meff validate --jobs N`) may step together only while they want the same
/// value. A step waits until no step with the other value runs; when both values wait, the
/// one that came second goes next (a step entering with the running value does not jump a
/// waiting one), so neither starves. The value found before the first step is put back when
/// the last one ends, as the single-threaded scope did.
class BlockSolveGate
{
  public:
    void Enter(bool value)
    {
        std::unique_lock lock(m_mutex);
        ++m_waiting[value];
        m_changed.wait(lock, [&]
                       { return m_active == 0 || (m_current == value && m_waiting[!value] == 0); });
        --m_waiting[value];
        if (m_active == 0)
        {
            m_saved = g_blockSolve;
        }
        m_current = value;
        g_blockSolve = value;
        ++m_active;
    }

    void Leave()
    {
        {
            const std::lock_guard lock(m_mutex);
            if (--m_active == 0)
            {
                g_blockSolve = m_saved;
            }
        }
        m_changed.notify_all();
    }

  private:
    std::mutex m_mutex;
    std::condition_variable m_changed;
    int m_active = 0;      ///< steps running with m_current
    int m_waiting[2] = {}; ///< steps waiting, by value
    bool m_current = true;
    bool m_saved = true;
};

BlockSolveGate& TheBlockSolveGate()
{
    static BlockSolveGate gate;
    return gate;
}

/// Holds g_blockSolve at `value` for one step, however the step ends.
class BlockSolveScope
{
  public:
    explicit BlockSolveScope(bool value) { TheBlockSolveGate().Enter(value); }
    ~BlockSolveScope() { TheBlockSolveGate().Leave(); }
    BlockSolveScope(const BlockSolveScope&) = delete;
    BlockSolveScope& operator=(const BlockSolveScope&) = delete;
};

} // namespace

/// Keeps the PostSolve data of the current step, every call in order. With continuous physics
/// Box2D calls PostSolve again for the contacts of each time-of-impact sub-step, and meff
/// appends those reports the same way, so a contact may appear more than once.
class Box2DMirror::Listener : public b2ContactListener
{
  public:
    struct Point
    {
        const b2Fixture* fixtureA = nullptr;
        const b2Fixture* fixtureB = nullptr;
        int32 childA = 0; ///< a chain's segment (child index); 0 for other shapes
        int32 childB = 0;
        std::uint32_t featureKey = 0;
        float normalImpulse = 0;
        float tangentImpulse = 0;
    };

    void Clear() { m_points.clear(); }

    /// A conveyor fixture's tangent speed (m/s, as meff's Real: the float of the scene's value).
    void SetTangentSpeed(const b2Fixture* fixture, float speed)
    {
        m_tangentSpeeds[fixture] = speed;
    }

    /// meff gives a contact its shapes' tangent speeds summed (ShapeDef::tangentSpeed); 2.4.1
    /// keeps one per contact (0 when made), which PreSolve may set in each touching update,
    /// before the solver reads it: the same float sum here makes the rows alike.
    void PreSolve(b2Contact* contact, const b2Manifold* /*oldManifold*/) override
    {
        if (m_tangentSpeeds.empty())
        {
            return;
        }
        contact->SetTangentSpeed(TangentSpeed(contact->GetFixtureA()) +
                                 TangentSpeed(contact->GetFixtureB()));
    }

    void PostSolve(b2Contact* contact, const b2ContactImpulse* impulse) override
    {
        const b2Manifold* manifold = contact->GetManifold();
        for (int32 i = 0; i < impulse->count; ++i)
        {
            Point point;
            point.fixtureA = contact->GetFixtureA();
            point.fixtureB = contact->GetFixtureB();
            point.childA = contact->GetChildIndexA();
            point.childB = contact->GetChildIndexB();
            point.featureKey = manifold->points[i].id.key;
            point.normalImpulse = impulse->normalImpulses[i];
            point.tangentImpulse = impulse->tangentImpulses[i];
            m_points.push_back(point);
        }
    }

    const std::vector<Point>& Points() const { return m_points; }

  private:
    float TangentSpeed(const b2Fixture* fixture) const
    {
        const auto found = m_tangentSpeeds.find(fixture);
        return found == m_tangentSpeeds.end() ? 0.0f : found->second;
    }

    std::vector<Point> m_points;
    std::unordered_map<const b2Fixture*, float> m_tangentSpeeds;
};

Box2DMirror::Box2DMirror(const Scene& scene, std::optional<bool> blockSolver)
    : m_scene(scene), m_dt(static_cast<float>(scene.world.dt)),
      m_blockSolve(blockSolver.value_or(scene.world.solver.blockSolver)),
      m_world(std::make_unique<b2World>(ToB2(scene.world.gravity))),
      m_listener(std::make_unique<Listener>())
{
    // A capsule, a rounding, a joint spring or a character has no 2.4.1 counterpart: built
    // without it, the mirror would be another scene, compared as if it were this one.
    const std::vector<std::string> lacking =
        FieldsBox2D241Lacks(scene, "Box2D 2.4.1 cannot run this scene beside meff");
    if (!lacking.empty())
    {
        throw SceneError(lacking);
    }
    const SceneWorldSettings& settings = scene.world;
    m_world->SetAllowSleeping(settings.allowSleep);
    m_world->SetWarmStarting(settings.solver.warmStarting);
    m_world->SetContinuousPhysics(settings.continuous);
    m_world->SetSubStepping(false);
    m_world->SetAutoClearForces(true);
    m_world->SetContactListener(m_listener.get());

    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    {
        const SceneBody& body = scene.bodies[i];
        const b2BodyDef def = MakeBodyDef(body);
        b2Body* created = m_world->CreateBody(&def);
        m_bodies.push_back(created);
        for (std::size_t k = 0; k < body.shapes.size(); ++k)
        {
            b2Fixture* fixture = CreateFixture(created, body.shapes[k]);
            m_shapeOf.emplace(fixture, std::make_pair(i, k));
            if (body.shapes[k].tangentSpeed != 0)
            {
                m_listener->SetTangentSpeed(fixture,
                                            static_cast<float>(body.shapes[k].tangentSpeed));
            }
        }
    }
    for (const SceneJoint& joint : scene.joints)
    {
        b2Body* bodyA = m_bodies.at(joint.bodyIndexA);
        b2Body* bodyB = m_bodies.at(joint.bodyIndexB);
        m_joints.push_back(CreateJoint(*m_world, joint, bodyA, bodyB, m_joints));
        // meff wakes a joint's bodies when it is created (a joint change wakes, a documented
        // departure from 2.4.1, whose CreateJoint does not): do the same, so that a scene with
        // a body starting asleep on a joint compares like with like.
        bodyA->SetAwake(true);
        bodyB->SetAwake(true);
    }
}

Box2DMirror::~Box2DMirror()
{
    if (m_world)
    {
        m_world->SetContactListener(nullptr);
    }
}

void Box2DMirror::Step()
{
    m_listener->Clear();
    ++m_steps;
    const BlockSolveScope scope(m_blockSolve);
    m_world->Step(m_dt, m_scene.world.solver.velocityIterations,
                  m_scene.world.solver.positionIterations);
}

FrameSample Box2DMirror::Sample() const
{
    FrameSample sample;
    sample.bodies.reserve(m_bodies.size());
    for (const b2Body* body : m_bodies)
    {
        const b2Vec2 p = body->GetPosition();
        const b2Vec2 v = body->GetLinearVelocity();
        sample.bodies.push_back(
            {p.x, p.y, body->GetAngle(), v.x, v.y, body->GetAngularVelocity(), body->IsAwake()});
    }
    for (const Listener::Point& point : m_listener->Points())
    {
        const auto& [bodyA, shapeA] = m_shapeOf.at(point.fixtureA);
        const auto& [bodyB, shapeB] = m_shapeOf.at(point.fixtureB);
        ContactSample contact;
        contact.key = {bodyA,
                       shapeA,
                       bodyB,
                       shapeB,
                       point.featureKey,
                       static_cast<std::size_t>(point.childA),
                       static_cast<std::size_t>(point.childB)};
        contact.normalImpulse = point.normalImpulse;
        contact.tangentImpulse = point.tangentImpulse;
        sample.contacts.push_back(contact);
    }
    // As meff's reports and Box2D's testbed compute it: the reciprocal in float.
    const float invDt = 1.0f / m_dt;
    sample.joints.reserve(m_joints.size());
    for (const b2Joint* joint : m_joints)
    {
        if (m_steps == 0)
        {
            // No step, no impulse. Box2D's reaction would read directions its first step has
            // not computed yet (a distance joint's m_u is uninitialized memory until then:
            // 0 × garbage made frame 0 fail at random with a NaN reaction).
            sample.joints.push_back({0, 0, 0});
            continue;
        }
        const b2Vec2 force = joint->GetReactionForce(invDt);
        sample.joints.push_back({force.x, force.y, joint->GetReactionTorque(invDt)});
    }
    return sample;
}

void Box2DMirror::Draw(DebugDraw& draw, const DrawColor& color) const
{
    for (std::size_t i = 0; i < m_scene.bodies.size(); ++i)
    {
        const b2Body* body = Body(i);
        const b2Transform& xf = body->GetTransform();
        const auto toMeff = [&](const b2Vec2& local)
        {
            const b2Vec2 p = b2Mul(xf, local);
            return Vec2{Real(p.x), Real(p.y)};
        };
        for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr;
             fixture = fixture->GetNext())
        {
            const b2Shape* shape = fixture->GetShape();
            switch (shape->GetType())
            {
            case b2Shape::e_circle:
            {
                const auto* circle = static_cast<const b2CircleShape*>(shape);
                const Vec2 center = toMeff(circle->m_p);
                draw.DrawCircle(center, Real(circle->m_radius), color);
                const b2Vec2 axis = xf.q.GetXAxis();
                draw.DrawSegment(center, center + Real(circle->m_radius) * Vec2{axis.x, axis.y},
                                 color);
                break;
            }
            case b2Shape::e_polygon:
            {
                const auto* polygon = static_cast<const b2PolygonShape*>(shape);
                Vec2 vertices[b2_maxPolygonVertices];
                for (int k = 0; k < polygon->m_count; ++k)
                {
                    vertices[k] = toMeff(polygon->m_vertices[k]);
                }
                draw.DrawPolygon(std::span<const Vec2>(vertices, std::size_t(polygon->m_count)),
                                 color);
                break;
            }
            case b2Shape::e_edge:
            {
                const auto* edge = static_cast<const b2EdgeShape*>(shape);
                draw.DrawSegment(toMeff(edge->m_vertex1), toMeff(edge->m_vertex2), color);
                break;
            }
            default:
                break;
            }
        }
    }
}

} // namespace meff::validation
