// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The World's public API: creation and destruction, accessors, and argument checking. The step
// itself is in step.cpp.
#include "meff/world.h"

#include "core/report_error.h"
#include "dynamics/step_stages.h"
#include "dynamics/world_state.h"
#include "meff/validity.h"

#include <algorithm>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

namespace meff
{

using namespace detail;

namespace
{

/// Reports InvalidArgument and returns false when `condition` is false. The message is built
/// only then (`message()` returns it): formatting it on every call cost more than the checks
/// themselves when a scene creates ten thousand bodies.
template <typename MakeMessage>
[[nodiscard]] bool Require(bool condition, MakeMessage&& message)
{
    return condition || Refuse(InvalidArgument(message()));
}

[[nodiscard]] bool RequireSoftStepSettings(const SoftStepSettings& soft)
{
    return Require(soft.substeps >= 1,
                   [&]
                   {
                       return "SolverSettings::softStep.substeps: must be >= 1, got " +
                              std::to_string(soft.substeps);
                   }) &&
           Require(soft.relaxIterations >= 0,
                   [&]
                   {
                       return "SolverSettings::softStep.relaxIterations: must be >= 0, got " +
                              std::to_string(soft.relaxIterations);
                   }) &&
           Require(soft.contacts == SoftContactModel::Rigid ||
                       soft.contacts == SoftContactModel::Soft,
                   [&]
                   {
                       return "SolverSettings::softStep.contacts: not a SoftContactModel (" +
                              std::to_string(static_cast<int>(soft.contacts)) + ")";
                   }) &&
           Require(
               meff::IsValid(soft.contactCorrection) && soft.contactCorrection > 0 &&
                   soft.contactCorrection <= 1,
               [&]
               {
                   return "SolverSettings::softStep.contactCorrection: must be in (0, 1], got " +
                          NumberText(soft.contactCorrection);
               }) &&
           RequirePositive(soft.contactHertz, "SolverSettings::softStep.contactHertz") &&
           RequireNonNegative(soft.contactDampingRatio,
                              "SolverSettings::softStep.contactDampingRatio") &&
           RequirePositive(soft.jointHertz, "SolverSettings::softStep.jointHertz") &&
           RequireNonNegative(soft.jointDampingRatio,
                              "SolverSettings::softStep.jointDampingRatio") &&
           RequirePositive(soft.maxPushOutSpeed, "SolverSettings::softStep.maxPushOutSpeed");
}

/// Looks an id up in a pool (a Pool or a const Pool), refusing null, out-of-range and stale
/// ids: Pool::Resolve, as World's calls write it (reported, then nullptr).
template <typename Pool, typename IdType>
[[nodiscard]] auto* Resolve(Pool& pool, IdType id, const char* kind)
{
    return pool.Resolve(id, kind);
}

/// What a refused call that returns a reference returns: a value-initialized T.
template <typename T>
const T& Nothing()
{
    static const T none{};
    return none;
}

/// A shape's mass data (ComputeMass at its density).
MassData ShapeMass(const Shape& shape)
{
    if (shape.type == ShapeType::Circle)
    {
        return ComputeMass(shape.circle, shape.def.density);
    }
    return shape.IsRounded() ? ComputeRoundedMass(shape.polygon, shape.def.density)
                             : ComputeMass(shape.polygon, shape.def.density);
}

/// Whether a shape gives its body mass: Box2D skips zero densities, and segments and chain
/// segments have none.
bool HasMass(const Shape& shape)
{
    return shape.def.density != 0 &&
           (shape.type == ShapeType::Circle || shape.type == ShapeType::Polygon ||
            shape.type == ShapeType::Capsule);
}

/// The mass data of a body's shapes that have mass, newest first (b2Body's fixture order).
std::vector<MassData> ShapeMasses(const WorldState& world, const Body& body)
{
    std::vector<MassData> masses;
    for (const std::int32_t s : body.shapes)
    {
        if (HasMass(world.shapes[s]))
        {
            masses.push_back(ShapeMass(world.shapes[s]));
        }
    }
    return masses;
}

/// Box2D 2.4.1's b2Body::ResetMassData: mass, centre and inertia from the shapes
/// (ComputeBodyMass), and the centre's velocity updated for the moved centre.
void ResetMassData(WorldState& world, Body& body)
{
    body.mass = 0;
    body.invMass = 0;
    body.I = 0;
    body.invI = 0;
    body.sweep.localCenter = {0, 0};
    if (body.type != BodyType::Dynamic)
    {
        body.sweep.c0 = body.xf.p;
        body.sweep.c = body.xf.p;
        body.sweep.a0 = body.sweep.a;
        return;
    }
    // A dynamic body without mass keeps mass 0 and inverse mass 0, as in Box2D 2.4.1: it then
    // moves with its velocity and nothing can push it (the scene loader refuses such bodies).
    const BodyMass mass = ComputeBodyMass(ShapeMasses(world, body), body.fixedRotation);
    body.mass = mass.mass;
    body.invMass = mass.invMass;
    body.I = mass.inertia;
    body.invI = mass.invInertia;
    const Vec2 oldCenter = body.sweep.c;
    body.sweep.localCenter = mass.localCenter;
    body.sweep.c = Mul(body.xf, body.sweep.localCenter);
    body.sweep.c0 = body.sweep.c;
    body.linearVelocity += Cross(body.angularVelocity, body.sweep.c - oldCenter);
}

void LinkJointEdge(WorldState& world, std::int32_t jointIndex, int side, std::int32_t bodyIndex,
                   std::int32_t other)
{
    Body& body = world.bodies[bodyIndex];
    Edge& edge = world.joints[jointIndex].edges[side];
    edge.other = other;
    edge.prev = kNullIndex;
    edge.next = body.jointList;
    if (body.jointList != kNullIndex)
    {
        world.joints[EdgeOwner(body.jointList)].edges[EdgeSide(body.jointList)].prev =
            EdgeKey(jointIndex, side);
    }
    body.jointList = EdgeKey(jointIndex, side);
}

void UnlinkJointEdge(WorldState& world, std::int32_t jointIndex, int side, std::int32_t bodyIndex)
{
    Body& body = world.bodies[bodyIndex];
    const Edge& edge = world.joints[jointIndex].edges[side];
    if (edge.prev != kNullIndex)
    {
        world.joints[EdgeOwner(edge.prev)].edges[EdgeSide(edge.prev)].next = edge.next;
    }
    if (edge.next != kNullIndex)
    {
        world.joints[EdgeOwner(edge.next)].edges[EdgeSide(edge.next)].prev = edge.prev;
    }
    if (body.jointList == EdgeKey(jointIndex, side))
    {
        body.jointList = edge.next;
    }
}

} // namespace

const char* SolverKindName(SolverKind kind)
{
    switch (kind)
    {
    case SolverKind::Box2D:
        return "box2d";
    case SolverKind::Colour:
        return "colour";
    case SolverKind::SoftStep:
        return "soft_step";
    }
    return "unknown";
}

Tolerances TolerancesForLengthUnits(Real lengthUnitsPerMeter)
{
    if (!RequirePositive(lengthUnitsPerMeter, "TolerancesForLengthUnits"))
    {
        return {};
    }
    Tolerances t;
    t.linearSlop *= lengthUnitsPerMeter;
    t.polygonSkin *= lengthUnitsPerMeter;
    t.aabbMargin *= lengthUnitsPerMeter;
    t.maxLinearCorrection *= lengthUnitsPerMeter;
    t.maxTranslation *= lengthUnitsPerMeter;
    t.linearSleepTolerance *= lengthUnitsPerMeter;
    t.hitEventThreshold *= lengthUnitsPerMeter; // a speed, in length units per second
    return t;
}

namespace
{

/// The rules of SetSolverSettings.
[[nodiscard]] bool RequireSolverSettings(const SolverSettings& settings)
{
    return Require(settings.velocityIterations >= 1,
                   [&]
                   {
                       return std::string("SolverSettings::velocityIterations: must be >= 1, got " +
                                          std::to_string(settings.velocityIterations));
                   }) &&
           Require(settings.positionIterations >= 0,
                   [&]
                   {
                       return std::string("SolverSettings::positionIterations: must be >= 0, got " +
                                          std::to_string(settings.positionIterations));
                   }) &&
           Require(settings.kind == SolverKind::Box2D || settings.kind == SolverKind::Colour ||
                       settings.kind == SolverKind::SoftStep,
                   [&]
                   {
                       return "SolverSettings::kind: not a SolverKind (" +
                              std::to_string(static_cast<int>(settings.kind)) + ")";
                   }) &&
           RequireSoftStepSettings(settings.softStep);
}

/// The rules of World's constructor.
[[nodiscard]] bool RequireWorldDef(const WorldDef& def)
{
    if (!RequireFinite(def.gravity, "WorldDef::gravity"))
    {
        return false;
    }
    const Tolerances& t = def.tolerances;
    const std::pair<const char*, Real> tolerances[] = {
        {"linearSlop", t.linearSlop},
        {"polygonSkin", t.polygonSkin},
        {"aabbMargin", t.aabbMargin},
        {"maxLinearCorrection", t.maxLinearCorrection},
        {"maxAngularCorrection", t.maxAngularCorrection},
        {"angularSlop", t.angularSlop},
        {"maxTranslation", t.maxTranslation},
        {"maxRotation", t.maxRotation},
        {"baumgarte", t.baumgarte},
        {"toiBaumgarte", t.toiBaumgarte},
        {"timeToSleep", t.timeToSleep},
        {"linearSleepTolerance", t.linearSleepTolerance},
        {"angularSleepTolerance", t.angularSleepTolerance},
        {"hitEventThreshold", t.hitEventThreshold}};
    for (const auto& [name, value] : tolerances)
    {
        if (!RequireNonNegative(value, (std::string("WorldDef::tolerances.") + name).c_str()))
        {
            return false;
        }
    }
    return RequireSolverSettings(def.solver);
}

} // namespace

World::World(const WorldDef& def)
{
    // A refused definition throws; without exceptions it is reported and the World is built
    // from the default WorldDef, so that it stays usable.
    m_state = std::make_unique<WorldState>(RequireWorldDef(def) ? def : WorldDef{});
    SetSolverSettings(m_state->solver);
}

namespace
{

/// A World cannot be destroyed or assigned while a step, a callback or a walk of this thread is
/// inside it (they would go on reading freed memory), and neither can refuse: the message, then
/// std::abort() (core/report_error.h).
void RequireNotInUse(const std::unique_ptr<detail::WorldState>& state, const char* call) noexcept
{
    if (state != nullptr && (detail::InStep(*state) || detail::InWalk::Walking(*state)))
    {
        detail::CallErrorHandler((std::string(call) +
                                  ": called while World::Step, a callback, a query or World::Draw "
                                  "runs inside this world; the world it reads cannot go away")
                                     .c_str());
        detail::AbortAfterError();
    }
}

} // namespace

World::~World()
{
    RequireNotInUse(m_state, "World::~World");
}
World::World(World&&) noexcept = default;
World& World::operator=(World&& other) noexcept
{
    RequireNotInUse(m_state, "World::operator=");
    RequireNotInUse(other.m_state, "World::operator=");
    m_state = std::move(other.m_state);
    return *this;
}

namespace
{

/// A moved-from World has no state to work on: without exceptions the handler is called, then
/// std::abort (docs/api-guide.md, "Errors").
[[noreturn]] void ThrowMovedFrom()
{
    ReportFatalError(InvalidArgument("World: this World was moved from and has no state; use the "
                                     "World it was moved to, or assign a new one to it"));
}

} // namespace

namespace
{
/// This thread's innermost walk (InWalk), or null.
thread_local const detail::InWalk* t_innermostWalk = nullptr;
} // namespace

detail::InWalk::InWalk(const WorldState& world) : m_world(world), m_outer(t_innermostWalk)
{
    t_innermostWalk = this;
}

detail::InWalk::~InWalk()
{
    t_innermostWalk = m_outer;
}

bool detail::InWalk::Walking(const WorldState& world)
{
    for (const InWalk* walk = t_innermostWalk; walk != nullptr; walk = walk->m_outer)
    {
        if (&walk->m_world == &world)
        {
            return true;
        }
    }
    return false;
}

bool detail::RequireNotStepping(const WorldState& world, const char* call, const char* why)
{
    if (InStep(world))
    {
        return Refuse(InvalidArgument(std::string(call) + ": called during World::Step (from " +
                                      (world.callback != nullptr ? world.callback : "a callback") +
                                      "); " + why));
    }
    return true;
}

bool detail::RequireNotWalked(const WorldState& world, const char* call)
{
    if (!RequireNotStepping(world, call))
    {
        return false;
    }
    if (InWalk::Walking(world))
    {
        return Refuse(InvalidArgument(std::string(call) +
                                      ": called while a query or World::Draw walks the world "
                                      "(from its callback); the callback must not add, remove or "
                                      "move what the walk reads"));
    }
    return true;
}

WorldState& World::State()
{
    if (!m_state)
    {
        ThrowMovedFrom();
    }
    return *m_state;
}

const WorldState& World::State() const
{
    if (!m_state)
    {
        ThrowMovedFrom();
    }
    return *m_state;
}

// ---------------------------------------------------------------------------------------------
// Bodies

BodyId World::CreateBody(const BodyDef& def)
{
    WorldState& world = State();
    if (!RequireNotWalked(world, "World::CreateBody") ||
        !RequireFinite(def.position, "BodyDef::position") ||
        !RequireFinite(def.angle, "BodyDef::angle") ||
        !RequireFinite(def.linearVelocity, "BodyDef::linearVelocity") ||
        !RequireFinite(def.angularVelocity, "BodyDef::angularVelocity") ||
        !RequireNonNegative(def.linearDamping, "BodyDef::linearDamping") ||
        !RequireNonNegative(def.angularDamping, "BodyDef::angularDamping") ||
        !RequireFinite(def.gravityScale, "BodyDef::gravityScale"))
    {
        return {};
    }

    const BodyId id = world.bodies.Allocate();
    const std::int32_t index = id.index;
    Body& body = world.bodies[index];
    body.type = def.type;
    body.xf.Set(def.position, def.angle);
    body.sweep.localCenter = {0, 0};
    body.sweep.c0 = body.sweep.c = def.position;
    body.sweep.a0 = body.sweep.a = def.angle;
    body.linearVelocity = def.type == BodyType::Static ? Vec2{} : def.linearVelocity;
    body.angularVelocity = def.type == BodyType::Static ? Real(0) : def.angularVelocity;
    body.linearDamping = def.linearDamping;
    body.angularDamping = def.angularDamping;
    body.gravityScale = def.gravityScale;
    body.fixedRotation = def.fixedRotation;
    body.bullet = def.bullet;
    body.allowSleep = def.allowSleep;
    body.awake = def.awake && def.type != BodyType::Static; // static bodies never wake
    body.sleepTime = 0;
    body.userData = def.userData;

    body.prev = kNullIndex;
    body.next = world.bodyList;
    if (world.bodyList != kNullIndex)
    {
        world.bodies[world.bodyList].prev = index;
    }
    world.bodyList = index;

    world.bodyIds.push_back(id);
    return id;
}

void World::DestroyBody(BodyId id)
{
    WorldState& world = State();
    if (!RequireNotWalked(world, "World::DestroyBody"))
    {
        return;
    }
    auto* const found = Resolve(world.bodies, id, "body");
    if (found == nullptr)
    {
        return;
    }
    Body& body = *found;
    BuildContactReports(world); // the last step's reports still name this body
    // Bodies resting on this one must not sleep on in mid-air. Box2D 2.4.1 wakes only the
    // jointed bodies (through DestroyJoint); meff also wakes the touching ones.
    WakeTouchingBodies(world, id.index);
    while (body.jointList != kNullIndex)
    {
        const std::int32_t j = EdgeOwner(body.jointList);
        DestroyJoint({j, world.joints[j].generation});
    }
    while (body.contactList != kNullIndex)
    {
        DestroyContact(world, EdgeOwner(body.contactList));
    }
    while (!body.shapeIds.empty())
    {
        const ShapeId shapeId = body.shapeIds.back();
        Shape& shape = world.shapes[shapeId.index];
        if (shape.chain >= 0 && world.chains[shape.chain].alive)
        {
            world.chains.Free(shape.chain);
        }
        world.broadPhase.DestroyProxy(shape.proxyId);
        world.shapes.Free(shapeId.index);
        body.shapeIds.pop_back();
    }
    body.shapes.clear();

    if (body.prev != kNullIndex)
    {
        world.bodies[body.prev].next = body.next;
    }
    if (body.next != kNullIndex)
    {
        world.bodies[body.next].prev = body.prev;
    }
    if (world.bodyList == id.index)
    {
        world.bodyList = body.next;
    }
    world.bodies.Free(id.index);
    world.bodyIds.erase(std::find(world.bodyIds.begin(), world.bodyIds.end(), id));
}

bool World::IsValid(BodyId id) const
{
    return State().bodies.IsValid(id);
}

BodyType World::GetType(BodyId id) const
{
    const auto* const found = Resolve(State().bodies, id, "body");
    return found != nullptr ? found->type : BodyType{};
}
Vec2 World::GetPosition(BodyId id) const
{
    const auto* const found = Resolve(State().bodies, id, "body");
    return found != nullptr ? found->xf.p : Vec2{};
}
Real World::GetAngle(BodyId id) const
{
    const auto* const found = Resolve(State().bodies, id, "body");
    return found != nullptr ? found->sweep.a : Real{};
}
Transform World::GetTransform(BodyId id) const
{
    const auto* const found = Resolve(State().bodies, id, "body");
    return found != nullptr ? found->xf : Transform{};
}
Vec2 World::GetWorldCenter(BodyId id) const
{
    const auto* const found = Resolve(State().bodies, id, "body");
    return found != nullptr ? found->sweep.c : Vec2{};
}
Vec2 World::GetLocalCenter(BodyId id) const
{
    const auto* const found = Resolve(State().bodies, id, "body");
    return found != nullptr ? found->sweep.localCenter : Vec2{};
}
Vec2 World::GetLinearVelocity(BodyId id) const
{
    const auto* const found = Resolve(State().bodies, id, "body");
    return found != nullptr ? found->linearVelocity : Vec2{};
}
Real World::GetAngularVelocity(BodyId id) const
{
    const auto* const found = Resolve(State().bodies, id, "body");
    return found != nullptr ? found->angularVelocity : Real{};
}
Real World::GetMass(BodyId id) const
{
    const auto* const found = Resolve(State().bodies, id, "body");
    return found != nullptr ? found->mass : Real{};
}
Real World::GetRotationalInertia(BodyId id) const
{
    const auto* const found = Resolve(State().bodies, id, "body");
    return found != nullptr ? found->I : Real{};
}
std::uint64_t World::GetUserData(BodyId id) const
{
    const auto* const found = Resolve(State().bodies, id, "body");
    return found != nullptr ? found->userData : std::uint64_t{};
}
Vec2 World::GetWorldPoint(BodyId id, Vec2 localPoint) const
{
    const auto* const found = Resolve(State().bodies, id, "body");
    return found != nullptr ? Mul(found->xf, localPoint) : Vec2{};
}
Vec2 World::GetLocalPoint(BodyId id, Vec2 worldPoint) const
{
    const auto* const found = Resolve(State().bodies, id, "body");
    return found != nullptr ? MulT(found->xf, worldPoint) : Vec2{};
}

void World::SetTransform(BodyId id, Vec2 position, Real angle)
{
    WorldState& world = State();
    if (!RequireNotWalked(world, "World::SetTransform"))
    {
        return;
    }
    auto* const found = Resolve(world.bodies, id, "body");
    if (found == nullptr)
    {
        return;
    }
    Body& body = *found;
    if (!RequireFinite(position, "World::SetTransform: position") ||
        !RequireFinite(angle, "World::SetTransform: angle"))
    {
        return;
    }
    BuildContactReports(world); // the last step's reports are where the step left the body
    body.xf.Set(position, angle);
    body.sweep.c = Mul(body.xf, body.sweep.localCenter);
    body.sweep.a = angle;
    body.sweep.c0 = body.sweep.c;
    body.sweep.a0 = angle;
    for (const std::int32_t s : body.shapes)
    {
        Shape& shape = world.shapes[s];
        shape.aabb = shape.ComputeAABB(body.xf);
        world.broadPhase.MoveProxy(shape.proxyId, shape.aabb, {0, 0});
    }
    world.newShapes = true;
    // Box2D 2.4.1 does not wake here. meff wakes the moved body and what it was touching, so
    // that a body the user moves never stays asleep where it was put, nor leaves its old
    // neighbours asleep in mid-air.
    WakeTouchingBodies(world, id.index);
    WakeBody(body);
}

void World::SetLinearVelocity(BodyId id, Vec2 v)
{
    if (!RequireNotStepping(State(), "World::SetLinearVelocity"))
    {
        return;
    }
    auto* const found = Resolve(State().bodies, id, "body");
    if (found == nullptr)
    {
        return;
    }
    Body& body = *found;
    if (!RequireFinite(v, "World::SetLinearVelocity: v"))
    {
        return;
    }
    if (body.type == BodyType::Static)
    {
        return;
    }
    if (Dot(v, v) > 0)
    {
        WakeBody(body);
    }
    body.linearVelocity = v;
}

void World::SetAngularVelocity(BodyId id, Real w)
{
    if (!RequireNotStepping(State(), "World::SetAngularVelocity"))
    {
        return;
    }
    auto* const found = Resolve(State().bodies, id, "body");
    if (found == nullptr)
    {
        return;
    }
    Body& body = *found;
    if (!RequireFinite(w, "World::SetAngularVelocity: w"))
    {
        return;
    }
    if (body.type == BodyType::Static)
    {
        return;
    }
    if (w * w > 0)
    {
        WakeBody(body);
    }
    body.angularVelocity = w;
}

namespace
{

/// Box2D 2.4.1's rule for forces and impulses: only dynamic bodies take them; `wake` wakes a
/// sleeping body first (an awake one keeps its rest time); a body still asleep ignores them.
bool TakesLoad(Body& body, bool wake)
{
    if (body.type != BodyType::Dynamic)
    {
        return false;
    }
    if (wake && !body.awake)
    {
        WakeBody(body);
    }
    return body.awake;
}

} // namespace

void World::ApplyForce(BodyId id, Vec2 force, Vec2 worldPoint, bool wake)
{
    if (!RequireNotStepping(State(), "World::ApplyForce"))
    {
        return;
    }
    auto* const found = Resolve(State().bodies, id, "body");
    if (found == nullptr)
    {
        return;
    }
    Body& body = *found;
    if (!RequireFinite(force, "World::ApplyForce: force") ||
        !RequireFinite(worldPoint, "World::ApplyForce: point"))
    {
        return;
    }
    if (TakesLoad(body, wake))
    {
        body.force += force;
        body.torque += Cross(worldPoint - body.sweep.c, force);
    }
}

void World::ApplyForceToCenter(BodyId id, Vec2 force, bool wake)
{
    if (!RequireNotStepping(State(), "World::ApplyForceToCenter"))
    {
        return;
    }
    auto* const found = Resolve(State().bodies, id, "body");
    if (found == nullptr)
    {
        return;
    }
    Body& body = *found;
    if (!RequireFinite(force, "World::ApplyForceToCenter: force"))
    {
        return;
    }
    if (TakesLoad(body, wake))
    {
        body.force += force;
    }
}

void World::ApplyTorque(BodyId id, Real torque, bool wake)
{
    if (!RequireNotStepping(State(), "World::ApplyTorque"))
    {
        return;
    }
    auto* const found = Resolve(State().bodies, id, "body");
    if (found == nullptr)
    {
        return;
    }
    Body& body = *found;
    if (!RequireFinite(torque, "World::ApplyTorque: torque"))
    {
        return;
    }
    if (TakesLoad(body, wake))
    {
        body.torque += torque;
    }
}

void World::ApplyLinearImpulse(BodyId id, Vec2 impulse, Vec2 worldPoint, bool wake)
{
    if (!RequireNotStepping(State(), "World::ApplyLinearImpulse"))
    {
        return;
    }
    auto* const found = Resolve(State().bodies, id, "body");
    if (found == nullptr)
    {
        return;
    }
    Body& body = *found;
    if (!RequireFinite(impulse, "World::ApplyLinearImpulse: impulse") ||
        !RequireFinite(worldPoint, "World::ApplyLinearImpulse: point"))
    {
        return;
    }
    if (TakesLoad(body, wake))
    {
        body.linearVelocity += body.invMass * impulse;
        body.angularVelocity += body.invI * Cross(worldPoint - body.sweep.c, impulse);
    }
}

void World::ApplyAngularImpulse(BodyId id, Real impulse, bool wake)
{
    if (!RequireNotStepping(State(), "World::ApplyAngularImpulse"))
    {
        return;
    }
    auto* const found = Resolve(State().bodies, id, "body");
    if (found == nullptr)
    {
        return;
    }
    Body& body = *found;
    if (!RequireFinite(impulse, "World::ApplyAngularImpulse: impulse"))
    {
        return;
    }
    if (TakesLoad(body, wake))
    {
        body.angularVelocity += body.invI * impulse;
    }
}

bool World::IsAwake(BodyId id) const
{
    const auto* const found = Resolve(State().bodies, id, "body");
    return found != nullptr ? found->awake : bool{};
}

void World::SetAwake(BodyId id, bool awake)
{
    if (!RequireNotStepping(State(), "World::SetAwake"))
    {
        return;
    }
    auto* const found = Resolve(State().bodies, id, "body");
    if (found == nullptr)
    {
        return;
    }
    Body& body = *found;
    if (awake)
    {
        WakeBody(body);
    }
    else
    {
        PutBodyToSleep(body);
    }
}

bool World::IsSleepingAllowed(BodyId id) const
{
    const auto* const found = Resolve(State().bodies, id, "body");
    return found != nullptr ? found->allowSleep : bool{};
}

void World::SetSleepingAllowed(BodyId id, bool allowed)
{
    if (!RequireNotStepping(State(), "World::SetSleepingAllowed"))
    {
        return;
    }
    auto* const found = Resolve(State().bodies, id, "body");
    if (found == nullptr)
    {
        return;
    }
    Body& body = *found;
    body.allowSleep = allowed;
    if (!allowed)
    {
        WakeBody(body);
    }
}

std::vector<BodyId> World::GetBodies() const
{
    return State().bodyIds;
}

// ---------------------------------------------------------------------------------------------
// Shapes

namespace
{

/// A dynamic body must be able to take the new shape's mass: the shape's own mass and
/// inertia, and the body's with it (meff/validity.h), checked before anything changes.
[[nodiscard]] bool RequireMassAccepted(const WorldState& world, const Body& body,
                                       const Shape& shape)
{
    if (body.type != BodyType::Dynamic || !HasMass(shape))
    {
        return true;
    }
    const Real density = shape.def.density;
    if (!Require(shape.type == ShapeType::Circle
                     ? CheckMass(shape.circle, density, body.fixedRotation)
                 : shape.type == ShapeType::Capsule
                     ? CheckMass(shape.capsule, density, body.fixedRotation)
                 : shape.rounded ? CheckRoundedMass(shape.polygon, density, body.fixedRotation)
                                 : CheckMass(shape.polygon, density, body.fixedRotation)))
    {
        return false;
    }
    std::vector<MassData> masses = ShapeMasses(world, body);
    masses.insert(masses.begin(), ShapeMass(shape)); // the new shape will be the newest
    if (!Require(CheckBodyMass(masses, body.fixedRotation)))
    {
        return false;
    }
    return true;
}

ShapeId AddShape(WorldState& world, BodyId bodyId, const ShapeDef& def, Shape prototype)
{
    if (!RequireNotWalked(world, "World::CreateShape"))
    {
        return {};
    }
    auto* const found = Resolve(world.bodies, bodyId, "body");
    if (found == nullptr)
    {
        return {};
    }
    Body& body = *found;
    if (!Require(CheckShapeDef(def)))
    {
        return {};
    }
    prototype.def = def;
    if (!RequireMassAccepted(world, body, prototype))
    {
        return {};
    }
    const ShapeId id = world.shapes.Allocate(std::move(prototype));
    const std::int32_t index = id.index;
    Shape& shape = world.shapes[index];
    shape.body = bodyId.index;
    shape.def = def;
    shape.aabb = shape.ComputeAABB(body.xf);
    shape.reach = shape.ComputeReach();
    // A shape in a positive group pairs with its group whatever the bits (FiltersAllow).
    const Filter& filter = def.filter;
    shape.proxyId = world.broadPhase.CreateProxy(
        shape.aabb, index, {filter.categoryBits, filter.maskBits, filter.groupIndex <= 0});

    body.shapes.insert(body.shapes.begin(), index); // newest first, as Box2D's fixture list
    body.shapeIds.insert(body.shapeIds.begin(), id);
    if (def.density > 0)
    {
        ResetMassData(world, body);
    }
    world.newShapes = true;
    return id;
}

} // namespace

ShapeId World::CreateShape(BodyId body, const ShapeDef& def, const Circle& circle)
{
    if (!Require(CheckCircle(circle)))
    {
        return {};
    }
    Shape shape;
    shape.type = ShapeType::Circle;
    shape.circle = circle;
    return AddShape(State(), body, def, shape);
}

ShapeId World::CreateShape(BodyId body, const ShapeDef& def, const Polygon& polygon)
{
    // Polygon is a public struct, so one built by hand reaches CreateShape without
    // MakePolygon's checks: the same rule is applied here (found by the hostile-input tests).
    if (!Require(CheckPolygon(polygon)) || !Require(CheckPolygonRadius(polygon)))
    {
        return {};
    }
    Shape shape;
    shape.type = ShapeType::Polygon;
    shape.polygon = polygon;
    // A radius within the skin leaves a sharp polygon, Box2D 2.4.1's, bit for bit.
    const Real skin = State().tolerances.polygonSkin;
    shape.rounded = polygon.radius > skin;
    shape.polygon.radius = shape.rounded ? polygon.radius : skin;
    return AddShape(State(), body, def, shape);
}

ShapeId World::CreateShape(BodyId body, const ShapeDef& def, const Capsule& capsule)
{
    if (!Require(CheckCapsule(capsule, State().tolerances.linearSlop)))
    {
        return {};
    }
    Shape shape;
    shape.type = ShapeType::Capsule;
    shape.capsule = capsule;
    shape.polygon = MakeCapsulePolygon(capsule);
    return AddShape(State(), body, def, shape);
}

namespace
{

/// Box2D asserts this of edges and of every link of a chain.
[[nodiscard]] bool RequireValidSegment(const Segment& segment, const Tolerances& tolerances,
                                       const char* where)
{
    return RequireFinite(segment.point1, (std::string(where) + "::point1").c_str()) &&
           RequireFinite(segment.point2, (std::string(where) + "::point2").c_str()) &&
           Require(!CheckSegment(segment, tolerances.linearSlop), // the rule of meff/validity.h
                   [&]
                   {
                       return std::string(where) +
                              ": points must be further apart than the linear slop, got " +
                              NumberText(segment.point1) + " and " + NumberText(segment.point2);
                   });
}

} // namespace

ShapeId World::CreateShape(BodyId body, const ShapeDef& def, const Segment& segment)
{
    if (!RequireValidSegment(segment, State().tolerances, "Segment"))
    {
        return {};
    }
    Shape shape;
    shape.type = ShapeType::Segment;
    shape.segment = segment;
    shape.segment.radius = State().tolerances.polygonSkin;
    return AddShape(State(), body, def, shape);
}

ShapeId World::CreateShape(BodyId body, const ShapeDef& def, const ChainSegment& segment)
{
    if (!RequireValidSegment(segment.segment, State().tolerances, "ChainSegment::segment"))
    {
        return {};
    }
    // A ghost on its end point would give the end no direction to meet: the same rule as
    // for the segment's length.
    if (!RequireValidSegment({segment.ghost1, segment.segment.point1}, State().tolerances,
                             "ChainSegment (ghost1 to point1)") ||
        !RequireValidSegment({segment.segment.point2, segment.ghost2}, State().tolerances,
                             "ChainSegment (point2 to ghost2)"))
    {
        return {};
    }
    Shape shape;
    shape.type = ShapeType::ChainSegment;
    shape.chainSegment = segment;
    shape.chainSegment.segment.radius = State().tolerances.polygonSkin;
    return AddShape(State(), body, def, shape);
}

void World::DestroyShape(ShapeId id)
{
    WorldState& world = State();
    if (!RequireNotWalked(world, "World::DestroyShape"))
    {
        return;
    }
    auto* const found = Resolve(world.shapes, id, "shape");
    if (found == nullptr)
    {
        return;
    }
    Shape& shape = *found;
    if (!Require(shape.chain < 0,
                 [&]
                 {
                     return std::string("World::DestroyShape: the shape is a segment of a chain; "
                                        "destroy the whole chain with DestroyChain");
                 }))
    {
        return;
    }
    BuildContactReports(world); // the last step's reports still name this shape
    Body& body = world.bodies[shape.body];
    WakeTouchingBodies(world, shape.body, id.index); // departs from Box2D 2.4.1, see world.h
    for (std::int32_t key = body.contactList; key != kNullIndex;)
    {
        const std::int32_t c = EdgeOwner(key);
        key = world.contacts[c].edges[EdgeSide(key)].next;
        if (world.contacts[c].shapeA == id.index || world.contacts[c].shapeB == id.index)
        {
            DestroyContact(world, c);
        }
    }
    world.broadPhase.DestroyProxy(shape.proxyId);
    body.shapes.erase(std::find(body.shapes.begin(), body.shapes.end(), id.index));
    body.shapeIds.erase(std::find(body.shapeIds.begin(), body.shapeIds.end(), id));
    world.shapes.Free(id.index);
    ResetMassData(world, body);
}

bool World::IsValid(ShapeId id) const
{
    return State().shapes.IsValid(id);
}

BodyId World::GetBody(ShapeId id) const
{
    const auto* const found = Resolve(State().shapes, id, "shape");
    if (found == nullptr)
    {
        return {};
    }
    const Shape& shape = *found;
    return {shape.body, State().bodies[shape.body].generation};
}
ShapeType World::GetShapeType(ShapeId id) const
{
    const auto* const found = Resolve(State().shapes, id, "shape");
    return found != nullptr ? found->type : ShapeType{};
}
const Circle& World::GetCircle(ShapeId id) const
{
    const auto* const found = Resolve(State().shapes, id, "shape");
    if (found == nullptr)
    {
        return Nothing<Circle>();
    }
    const Shape& shape = *found;
    if (!Require(shape.type == ShapeType::Circle,
                 [&] { return std::string("World::GetCircle: the shape is not a circle"); }))
    {
        return Nothing<Circle>();
    }
    return shape.circle;
}
const Polygon& World::GetPolygon(ShapeId id) const
{
    const auto* const found = Resolve(State().shapes, id, "shape");
    if (found == nullptr)
    {
        return Nothing<Polygon>();
    }
    const Shape& shape = *found;
    if (!Require(shape.type == ShapeType::Polygon,
                 [&] { return std::string("World::GetPolygon: the shape is not a polygon"); }))
    {
        return Nothing<Polygon>();
    }
    return shape.polygon;
}
const Capsule& World::GetCapsule(ShapeId id) const
{
    const auto* const found = Resolve(State().shapes, id, "shape");
    if (found == nullptr)
    {
        return Nothing<Capsule>();
    }
    const Shape& shape = *found;
    if (!Require(shape.type == ShapeType::Capsule,
                 [&] { return std::string("World::GetCapsule: the shape is not a capsule"); }))
    {
        return Nothing<Capsule>();
    }
    return shape.capsule;
}
const Segment& World::GetSegment(ShapeId id) const
{
    const auto* const found = Resolve(State().shapes, id, "shape");
    if (found == nullptr)
    {
        return Nothing<Segment>();
    }
    const Shape& shape = *found;
    if (!Require(shape.type == ShapeType::Segment,
                 [&] { return std::string("World::GetSegment: the shape is not a segment"); }))
    {
        return Nothing<Segment>();
    }
    return shape.segment;
}
const ChainSegment& World::GetChainSegment(ShapeId id) const
{
    const auto* const found = Resolve(State().shapes, id, "shape");
    if (found == nullptr)
    {
        return Nothing<ChainSegment>();
    }
    const Shape& shape = *found;
    if (!Require(shape.type == ShapeType::ChainSegment,
                 [&] {
                     return std::string("World::GetChainSegment: the shape is not a chain segment");
                 }))
    {
        return Nothing<ChainSegment>();
    }
    return shape.chainSegment;
}
const ShapeDef& World::GetShapeDef(ShapeId id) const
{
    const auto* const found = Resolve(State().shapes, id, "shape");
    return found != nullptr ? found->def : Nothing<ShapeDef>();
}
std::vector<ShapeId> World::GetShapes(BodyId body) const
{
    const auto* const found = Resolve(State().bodies, body, "body");
    return found != nullptr ? found->shapeIds : std::vector<ShapeId>{};
}

// ---------------------------------------------------------------------------------------------
// Joints

namespace
{

/// Adds a joint MakeJoint made; a joint it refused (reported, no bodies) adds nothing.
JointId AddJoint(WorldState& world, Joint joint)
{
    if (joint.bodyA == kNullIndex)
    {
        return {};
    }
    const JointId id = world.joints.Allocate();
    const std::int32_t index = id.index;
    JointSlot& slot = world.joints[index];
    slot.joint = joint;

    slot.prev = kNullIndex;
    slot.next = world.jointList;
    if (world.jointList != kNullIndex)
    {
        world.joints[world.jointList].prev = index;
    }
    world.jointList = index;
    LinkJointEdge(world, index, 0, joint.bodyA, joint.bodyB);
    LinkJointEdge(world, index, 1, joint.bodyB, joint.bodyA);
    // Box2D 2.4.1 leaves the bodies as they are; meff wakes them so the new joint acts at once.
    WakeBody(world, joint.bodyA);
    WakeBody(world, joint.bodyB);
    if (!joint.collideConnected)
    {
        FlagContactsForFiltering(world, joint.bodyA, joint.bodyB);
    }
    world.jointIds.push_back(id);
    return id;
}

/// Both ids live, and the pair allowed for this joint type (meff/validity.h).
[[nodiscard]] bool RequireTwoBodies(WorldState& world, JointType type, BodyId a, BodyId b)
{
    if (!RequireNotWalked(world, "World::CreateJoint"))
    {
        return false;
    }
    if (Resolve(world.bodies, a, "body") == nullptr)
    {
        return false;
    }
    const auto* const found = Resolve(world.bodies, b, "body");
    if (found == nullptr)
    {
        return false;
    }
    const Body& bodyB = *found;
    if (!Require(CheckJointBodies(type, a == b, bodyB.type)))
    {
        return false;
    }
    return true;
}

} // namespace

JointId World::CreateJoint(const RevoluteJointDef& def)
{
    if (!RequireTwoBodies(State(), JointType::Revolute, def.bodyA, def.bodyB))
    {
        return {};
    }
    return AddJoint(State(), MakeJoint(def, def.bodyA.index, def.bodyB.index));
}

JointId World::CreateJoint(const DistanceJointDef& def)
{
    if (!RequireTwoBodies(State(), JointType::Distance, def.bodyA, def.bodyB))
    {
        return {};
    }
    const Body& a = State().bodies[def.bodyA.index];
    const Body& b = State().bodies[def.bodyB.index];
    return AddJoint(State(), MakeJoint(def, def.bodyA.index, def.bodyB.index, a.mass, b.mass,
                                       State().tolerances));
}

JointId World::CreateJoint(const PrismaticJointDef& def)
{
    if (!RequireTwoBodies(State(), JointType::Prismatic, def.bodyA, def.bodyB))
    {
        return {};
    }
    return AddJoint(State(), MakeJoint(def, def.bodyA.index, def.bodyB.index));
}

namespace
{

/// Rotational inertia about the body's origin, as Box2D's b2Body::GetInertia (which
/// b2AngularStiffness reads): I_centre + m·|localCenter|².
Real InertiaAboutOrigin(const Body& body)
{
    return body.I + body.mass * Dot(body.sweep.localCenter, body.sweep.localCenter);
}

} // namespace

JointId World::CreateJoint(const WeldJointDef& def)
{
    if (!RequireTwoBodies(State(), JointType::Weld, def.bodyA, def.bodyB))
    {
        return {};
    }
    const Body& a = State().bodies[def.bodyA.index];
    const Body& b = State().bodies[def.bodyB.index];
    return AddJoint(State(), MakeJoint(def, def.bodyA.index, def.bodyB.index, InertiaAboutOrigin(a),
                                       InertiaAboutOrigin(b)));
}

JointId World::CreateJoint(const MotorJointDef& def)
{
    if (!RequireTwoBodies(State(), JointType::Motor, def.bodyA, def.bodyB))
    {
        return {};
    }
    return AddJoint(State(), MakeJoint(def, def.bodyA.index, def.bodyB.index));
}

JointId World::CreateJoint(const WheelJointDef& def)
{
    if (!RequireTwoBodies(State(), JointType::Wheel, def.bodyA, def.bodyB))
    {
        return {};
    }
    const Body& a = State().bodies[def.bodyA.index];
    const Body& b = State().bodies[def.bodyB.index];
    return AddJoint(State(), MakeJoint(def, def.bodyA.index, def.bodyB.index, a.mass, b.mass));
}

JointId World::CreateJoint(const FrictionJointDef& def)
{
    if (!RequireTwoBodies(State(), JointType::Friction, def.bodyA, def.bodyB))
    {
        return {};
    }
    return AddJoint(State(), MakeJoint(def, def.bodyA.index, def.bodyB.index));
}

JointId World::CreateJoint(const PulleyJointDef& def)
{
    if (!RequireTwoBodies(State(), JointType::Pulley, def.bodyA, def.bodyB))
    {
        return {};
    }
    return AddJoint(State(), MakeJoint(def, def.bodyA.index, def.bodyB.index));
}

JointId World::CreateJoint(const GearJointDef& def)
{
    WorldState& world = State();
    if (!RequireNotWalked(world, "World::CreateJoint"))
    {
        return {};
    }
    const auto* const slot1 = Resolve(world.joints, def.joint1, "joint");
    if (slot1 == nullptr)
    {
        return {};
    }
    const auto* const slot2 = Resolve(world.joints, def.joint2, "joint");
    if (slot2 == nullptr)
    {
        return {};
    }
    const Joint& joint1 = slot1->joint;
    const Joint& joint2 = slot2->joint;
    const auto requireGearable = [&](const Joint& joint, const char* field)
    {
        if (joint.type != JointType::Revolute && joint.type != JointType::Prismatic)
        {
            return Refuse(InvalidArgument(std::string("GearJointDef::") + field +
                                          ": must be a revolute or prismatic joint"));
        }
        // The gear moves the joint's body B; Box2D 2.4.1 asserts the same.
        return Require(world.bodies[joint.bodyB].type == BodyType::Dynamic,
                       [&]
                       {
                           return std::string("GearJointDef::") + field +
                                  ": its body B must be dynamic (the gear turns it)";
                       });
    };
    if (!requireGearable(joint1, "joint1") || !requireGearable(joint2, "joint2"))
    {
        return {};
    }
    if (def.joint1 == def.joint2)
    {
        ReportError(InvalidArgument("GearJointDef::joint2: must be a different joint from joint1"));
        return {};
    }
    const auto pose = [&](std::int32_t body) {
        return GearPose{world.bodies[body].xf, world.bodies[body].sweep.a};
    };
    return AddJoint(world, MakeJoint(def, joint1, joint2, pose(joint1.bodyB), pose(joint2.bodyB),
                                     pose(joint1.bodyA), pose(joint2.bodyA)));
}

JointId World::CreateJoint(const MouseJointDef& def)
{
    if (!RequireTwoBodies(State(), JointType::Mouse, def.bodyA, def.bodyB))
    {
        return {};
    }
    const Body& a = State().bodies[def.bodyA.index];
    const Body& b = State().bodies[def.bodyB.index];
    return AddJoint(State(), MakeJoint(def, def.bodyA.index, def.bodyB.index, a.mass, b.mass, b.xf,
                                       b.type == BodyType::Dynamic));
}

void World::SetMouseTarget(JointId id, Vec2 target)
{
    if (!RequireNotStepping(State(), "World::SetMouseTarget"))
    {
        return;
    }
    auto* const found = Resolve(State().joints, id, "joint");
    if (found == nullptr)
    {
        return;
    }
    Joint& joint = found->joint;
    auto* mouse = std::get_if<MouseJoint>(&joint.data);
    if (!Require(mouse != nullptr, [&]
                 { return std::string("World::SetMouseTarget: the joint is not a mouse joint"); }))
    {
        return;
    }
    if (!RequireFinite(target, "World::SetMouseTarget: target"))
    {
        return;
    }
    if (target != mouse->target)
    {
        // The pointer moved: the dragged body must follow (Box2D's SetTarget wakes it then;
        // an unchanged target wakes nothing, so a game may set it every frame).
        WakeBody(State(), joint.bodyB);
        mouse->target = target;
    }
}

Vec2 World::GetMouseTarget(JointId id) const
{
    const auto* const found = Resolve(State().joints, id, "joint");
    if (found == nullptr)
    {
        return {};
    }
    const Joint& joint = found->joint;
    const auto* mouse = std::get_if<MouseJoint>(&joint.data);
    if (!Require(mouse != nullptr, [&]
                 { return std::string("World::GetMouseTarget: the joint is not a mouse joint"); }))
    {
        return {};
    }
    return mouse->target;
}

void World::SetMotorJointOffsets(JointId id, Vec2 linearOffset, Real angularOffset)
{
    if (!RequireNotStepping(State(), "World::SetMotorJointOffsets"))
    {
        return;
    }
    auto* const found = Resolve(State().joints, id, "joint");
    if (found == nullptr)
    {
        return;
    }
    Joint& joint = found->joint;
    auto* motor = std::get_if<MotorJoint>(&joint.data);
    if (!Require(
            motor != nullptr, [&]
            { return std::string("World::SetMotorJointOffsets: the joint is not a motor joint"); }))
    {
        return;
    }
    if (!RequireFinite(linearOffset, "World::SetMotorJointOffsets: linearOffset") ||
        !RequireFinite(angularOffset, "World::SetMotorJointOffsets: angularOffset"))
    {
        return;
    }
    if (linearOffset != motor->linearOffset || angularOffset != motor->angularOffset)
    {
        // A new target pose moves the bodies: wake them, as Box2D's SetLinearOffset and
        // SetAngularOffset do when the value changes.
        WakeBody(State(), joint.bodyA);
        WakeBody(State(), joint.bodyB);
        motor->linearOffset = linearOffset;
        motor->angularOffset = angularOffset;
    }
}

namespace
{

/// The gear joints that couple joint `id` (a gear cannot outlive its joints).
std::vector<JointId> GearsOf(const WorldState& world, JointId id)
{
    std::vector<JointId> gears;
    for (std::int32_t j = world.jointList; j != kNullIndex; j = world.joints[j].next)
    {
        const JointSlot& slot = world.joints[j];
        const auto* gear = std::get_if<GearJoint>(&slot.joint.data);
        if (gear != nullptr && (gear->joint1 == id || gear->joint2 == id))
        {
            gears.push_back({j, slot.generation});
        }
    }
    return gears;
}

} // namespace

void World::DestroyJoint(JointId id)
{
    WorldState& world = State();
    if (!RequireNotWalked(world, "World::DestroyJoint"))
    {
        return;
    }
    if (Resolve(world.joints, id, "joint") == nullptr)
    {
        return;
    }
    for (const JointId gear : GearsOf(world, id))
    {
        DestroyJoint(gear);
    }
    JointSlot& slot = world.joints[id.index];
    if (slot.prev != kNullIndex)
    {
        world.joints[slot.prev].next = slot.next;
    }
    if (slot.next != kNullIndex)
    {
        world.joints[slot.next].prev = slot.prev;
    }
    if (world.jointList == id.index)
    {
        world.jointList = slot.next;
    }
    WakeBody(world, slot.joint.bodyA); // as b2World::DestroyJoint
    WakeBody(world, slot.joint.bodyB);
    UnlinkJointEdge(world, id.index, 0, slot.joint.bodyA);
    UnlinkJointEdge(world, id.index, 1, slot.joint.bodyB);
    if (!slot.joint.collideConnected)
    {
        FlagContactsForFiltering(world, slot.joint.bodyA, slot.joint.bodyB);
    }
    world.joints.Free(id.index);
    world.jointIds.erase(std::find(world.jointIds.begin(), world.jointIds.end(), id));
}

bool World::IsValid(JointId id) const
{
    return State().joints.IsValid(id);
}

JointType World::GetJointType(JointId id) const
{
    const auto* const found = Resolve(State().joints, id, "joint");
    return found != nullptr ? found->joint.type : JointType{};
}
BodyId World::GetBodyA(JointId id) const
{
    const auto* const found = Resolve(State().joints, id, "joint");
    if (found == nullptr)
    {
        return {};
    }
    const Joint& joint = found->joint;
    return {joint.bodyA, State().bodies[joint.bodyA].generation};
}
BodyId World::GetBodyB(JointId id) const
{
    const auto* const found = Resolve(State().joints, id, "joint");
    if (found == nullptr)
    {
        return {};
    }
    const Joint& joint = found->joint;
    return {joint.bodyB, State().bodies[joint.bodyB].generation};
}

Vec2 World::GetAnchorA(JointId id) const
{
    const auto* const found = Resolve(State().joints, id, "joint");
    if (found == nullptr)
    {
        return {};
    }
    const Joint& joint = found->joint;
    return JointAnchorA(joint, State().bodies[joint.bodyA].xf);
}
Vec2 World::GetAnchorB(JointId id) const
{
    const auto* const found = Resolve(State().joints, id, "joint");
    if (found == nullptr)
    {
        return {};
    }
    const Joint& joint = found->joint;
    return JointAnchorB(joint, State().bodies[joint.bodyB].xf);
}
JointReaction World::GetReaction(JointId id, Real invDt) const
{
    const auto* const found = Resolve(State().joints, id, "joint");
    return found != nullptr ? GetJointReaction(found->joint, invDt) : JointReaction{};
}
std::vector<JointId> World::GetJoints() const
{
    return State().jointIds;
}

void World::SetJointMotorSpeed(JointId id, Real speed)
{
    if (!RequireNotStepping(State(), "World::SetJointMotorSpeed"))
    {
        return;
    }
    auto* const found = Resolve(State().joints, id, "joint");
    if (found == nullptr)
    {
        return;
    }
    Joint& joint = found->joint;
    if (!RequireFinite(speed, "World::SetJointMotorSpeed: speed"))
    {
        return;
    }
    Real* motorSpeed = nullptr;
    if (auto* r = std::get_if<RevoluteJoint>(&joint.data))
    {
        motorSpeed = &r->motorSpeed;
    }
    else if (auto* p = std::get_if<PrismaticJoint>(&joint.data))
    {
        motorSpeed = &p->motorSpeed;
    }
    else if (auto* w = std::get_if<WheelJoint>(&joint.data))
    {
        motorSpeed = &w->motorSpeed;
    }
    else
    {
        ReportError(InvalidArgument("World::SetJointMotorSpeed: the joint has no motor (only "
                                    "revolute, prismatic and wheel joints do)"));
        return;
    }
    if (speed != *motorSpeed)
    {
        // A changed motor moves its bodies: wake them, as Box2D's SetMotorSpeed does. An
        // unchanged speed wakes nothing, so a game may set it every frame and still sleep.
        WakeBody(State(), joint.bodyA);
        WakeBody(State(), joint.bodyB);
        *motorSpeed = speed;
    }
}

namespace
{

/// References to a revolute or prismatic joint's spring members (enable, hertz, damping ratio,
/// target: targetAngle or targetTranslation), const for a const joint; for other types, none
/// (reported).
template <typename JointT>
auto SpringOf(JointT& joint, const char* caller)
{
    using Members = decltype(std::tie(std::get<RevoluteJoint>(joint.data).enableSpring,
                                      std::get<RevoluteJoint>(joint.data).hertz,
                                      std::get<RevoluteJoint>(joint.data).dampingRatio,
                                      std::get<RevoluteJoint>(joint.data).targetAngle));
    if (auto* r = std::get_if<RevoluteJoint>(&joint.data))
    {
        return std::optional<Members>(
            std::tie(r->enableSpring, r->hertz, r->dampingRatio, r->targetAngle));
    }
    if (auto* p = std::get_if<PrismaticJoint>(&joint.data))
    {
        return std::optional<Members>(
            std::tie(p->enableSpring, p->hertz, p->dampingRatio, p->targetTranslation));
    }
    ReportError(
        InvalidArgument(std::string("World::") + caller +
                        ": the joint has no spring (only revolute and prismatic joints do)"));
    return std::optional<Members>();
}

} // namespace

void World::SetJointSpring(JointId id, const JointSpring& spring)
{
    if (!RequireNotStepping(State(), "World::SetJointSpring"))
    {
        return;
    }
    auto* const found = Resolve(State().joints, id, "joint");
    if (found == nullptr)
    {
        return;
    }
    Joint& joint = found->joint;
    auto members = SpringOf(joint, "SetJointSpring");
    if (!members)
    {
        return;
    }
    auto [enable, hertz, dampingRatio, target] = *members;
    if (!RequireNonNegative(spring.hertz, "World::SetJointSpring: hertz") ||
        !RequireNonNegative(spring.dampingRatio, "World::SetJointSpring: dampingRatio") ||
        !RequireFinite(spring.target, "World::SetJointSpring: target"))
    {
        return;
    }
    if (spring.enable != enable || spring.hertz != hertz || spring.dampingRatio != dampingRatio ||
        spring.target != target)
    {
        // A changed spring moves its bodies: wake them, as SetJointMotorSpeed does. An
        // unchanged one wakes nothing, so a game may set it every frame and still sleep.
        WakeBody(State(), joint.bodyA);
        WakeBody(State(), joint.bodyB);
        enable = spring.enable;
        hertz = spring.hertz;
        dampingRatio = spring.dampingRatio;
        target = spring.target;
    }
}

JointSpring World::GetJointSpring(JointId id) const
{
    const auto* const found = Resolve(State().joints, id, "joint");
    if (found == nullptr)
    {
        return {};
    }
    const Joint& joint = found->joint;
    const auto members = SpringOf(joint, "GetJointSpring");
    if (!members)
    {
        return {};
    }
    const auto [enable, hertz, dampingRatio, target] = *members;
    return {enable, hertz, dampingRatio, target};
}

namespace
{

/// A prismatic or wheel joint's anchors and slide axis, in its bodies' frames.
struct SlideFrame
{
    Vec2 localAnchorA, localAnchorB, localAxisA;
};

/// The slide frame of a prismatic or wheel joint; for other types, none (reported).
std::optional<SlideFrame> GetSlideFrame(const Joint& joint, const char* caller)
{
    if (const auto* p = std::get_if<PrismaticJoint>(&joint.data))
    {
        return SlideFrame{p->localAnchorA, p->localAnchorB, p->localXAxisA};
    }
    if (const auto* w = std::get_if<WheelJoint>(&joint.data))
    {
        return SlideFrame{w->localAnchorA, w->localAnchorB, w->localXAxisA};
    }
    ReportError(InvalidArgument(std::string("World::") + caller +
                                ": only prismatic and wheel joints have an axis"));
    return std::nullopt;
}

} // namespace

Real World::GetJointTranslation(JointId id) const
{
    const auto* const found = Resolve(State().joints, id, "joint");
    if (found == nullptr)
    {
        return {};
    }
    const Joint& joint = found->joint;
    const auto frameOrNone = GetSlideFrame(joint, "GetJointTranslation");
    if (!frameOrNone)
    {
        return {};
    }
    const SlideFrame frame = *frameOrNone;
    const Body& a = State().bodies[joint.bodyA];
    const Body& b = State().bodies[joint.bodyB];
    const Vec2 pA = Mul(a.xf, frame.localAnchorA);
    const Vec2 pB = Mul(b.xf, frame.localAnchorB);
    const Vec2 d = pB - pA;
    const Vec2 axis = Mul(a.xf.q, frame.localAxisA);
    return Dot(d, axis);
}

Real World::GetJointSpeed(JointId id) const
{
    const auto* const found = Resolve(State().joints, id, "joint");
    if (found == nullptr)
    {
        return {};
    }
    const Joint& joint = found->joint;
    const Body& a = State().bodies[joint.bodyA];
    const Body& b = State().bodies[joint.bodyB];
    if (joint.type == JointType::Revolute)
    {
        return b.angularVelocity - a.angularVelocity;
    }
    const auto frameOrNone = GetSlideFrame(joint, "GetJointSpeed");
    if (!frameOrNone)
    {
        return {};
    }
    const SlideFrame frame = *frameOrNone;
    // Cdot of the axial row: the axis turns with A, hence the d·(wA × axis) term.
    const Vec2 rA = Mul(a.xf.q, frame.localAnchorA - a.sweep.localCenter);
    const Vec2 rB = Mul(b.xf.q, frame.localAnchorB - b.sweep.localCenter);
    const Vec2 p1 = a.sweep.c + rA;
    const Vec2 p2 = b.sweep.c + rB;
    const Vec2 d = p2 - p1;
    const Vec2 axis = Mul(a.xf.q, frame.localAxisA);
    const Vec2 vA = a.linearVelocity, vB = b.linearVelocity;
    const Real wA = a.angularVelocity, wB = b.angularVelocity;
    return Dot(d, Cross(wA, axis)) + Dot(axis, vB + Cross(wB, rB) - vA - Cross(wA, rA));
}

namespace
{

/// Both bodies live, checked in the order given (the order the definition reads them), so
/// that a Make...JointDef reports a stale id once.
[[nodiscard]] bool RequireBodies(const WorldState& world, BodyId first, BodyId second)
{
    return Resolve(world.bodies, first, "body") != nullptr &&
           Resolve(world.bodies, second, "body") != nullptr;
}

} // namespace

RevoluteJointDef World::MakeRevoluteJointDef(BodyId a, BodyId b, Vec2 worldAnchor) const
{
    if (!RequireFinite(worldAnchor, "MakeRevoluteJointDef: anchor"))
    {
        return {};
    }
    if (!RequireBodies(State(), a, b))
    {
        return {};
    }
    RevoluteJointDef def;
    def.bodyA = a;
    def.bodyB = b;
    def.localAnchorA = GetLocalPoint(a, worldAnchor);
    def.localAnchorB = GetLocalPoint(b, worldAnchor);
    def.referenceAngle = GetAngle(b) - GetAngle(a);
    return def;
}

DistanceJointDef World::MakeDistanceJointDef(BodyId a, BodyId b, Vec2 worldAnchorA,
                                             Vec2 worldAnchorB) const
{
    if (!RequireFinite(worldAnchorA, "MakeDistanceJointDef: anchorA") ||
        !RequireFinite(worldAnchorB, "MakeDistanceJointDef: anchorB"))
    {
        return {};
    }
    if (!RequireBodies(State(), a, b))
    {
        return {};
    }
    DistanceJointDef def;
    def.bodyA = a;
    def.bodyB = b;
    def.localAnchorA = GetLocalPoint(a, worldAnchorA);
    def.localAnchorB = GetLocalPoint(b, worldAnchorB);
    const Vec2 d = worldAnchorB - worldAnchorA;
    def.length = Max(d.Length(), State().tolerances.linearSlop);
    def.minLength = def.length;
    def.maxLength = def.length;
    return def;
}

PrismaticJointDef World::MakePrismaticJointDef(BodyId a, BodyId b, Vec2 worldAnchor,
                                               Vec2 worldAxis) const
{
    if (!RequireFinite(worldAnchor, "MakePrismaticJointDef: anchor") ||
        !RequireFinite(worldAxis, "MakePrismaticJointDef: axis"))
    {
        return {};
    }
    if (!RequireBodies(State(), a, b))
    {
        return {};
    }
    PrismaticJointDef def;
    def.bodyA = a;
    def.bodyB = b;
    def.localAnchorA = GetLocalPoint(a, worldAnchor);
    def.localAnchorB = GetLocalPoint(b, worldAnchor);
    def.localAxisA = MulT(GetTransform(a).q, worldAxis);
    def.referenceAngle = GetAngle(b) - GetAngle(a);
    return def;
}

WheelJointDef World::MakeWheelJointDef(BodyId a, BodyId b, Vec2 worldAnchor, Vec2 worldAxis) const
{
    if (!RequireFinite(worldAnchor, "MakeWheelJointDef: anchor") ||
        !RequireFinite(worldAxis, "MakeWheelJointDef: axis"))
    {
        return {};
    }
    if (!RequireBodies(State(), a, b))
    {
        return {};
    }
    WheelJointDef def;
    def.bodyA = a;
    def.bodyB = b;
    def.localAnchorA = GetLocalPoint(a, worldAnchor);
    def.localAnchorB = GetLocalPoint(b, worldAnchor);
    def.localAxisA = MulT(GetTransform(a).q, worldAxis);
    return def;
}

WeldJointDef World::MakeWeldJointDef(BodyId a, BodyId b, Vec2 worldAnchor) const
{
    if (!RequireFinite(worldAnchor, "MakeWeldJointDef: anchor"))
    {
        return {};
    }
    if (!RequireBodies(State(), a, b))
    {
        return {};
    }
    WeldJointDef def;
    def.bodyA = a;
    def.bodyB = b;
    def.localAnchorA = GetLocalPoint(a, worldAnchor);
    def.localAnchorB = GetLocalPoint(b, worldAnchor);
    def.referenceAngle = GetAngle(b) - GetAngle(a);
    return def;
}

MotorJointDef World::MakeMotorJointDef(BodyId a, BodyId b) const
{
    if (!RequireBodies(State(), b, a))
    {
        return {};
    }
    MotorJointDef def;
    def.bodyA = a;
    def.bodyB = b;
    def.linearOffset = GetLocalPoint(a, GetPosition(b));
    def.angularOffset = GetAngle(b) - GetAngle(a);
    return def;
}

FrictionJointDef World::MakeFrictionJointDef(BodyId a, BodyId b, Vec2 worldAnchor) const
{
    if (!RequireFinite(worldAnchor, "MakeFrictionJointDef: anchor"))
    {
        return {};
    }
    if (!RequireBodies(State(), a, b))
    {
        return {};
    }
    FrictionJointDef def;
    def.bodyA = a;
    def.bodyB = b;
    def.localAnchorA = GetLocalPoint(a, worldAnchor);
    def.localAnchorB = GetLocalPoint(b, worldAnchor);
    return def;
}

PulleyJointDef World::MakePulleyJointDef(BodyId a, BodyId b, Vec2 groundAnchorA, Vec2 groundAnchorB,
                                         Vec2 anchorA, Vec2 anchorB, Real ratio) const
{
    if (!RequireFinite(groundAnchorA, "MakePulleyJointDef: groundAnchorA") ||
        !RequireFinite(groundAnchorB, "MakePulleyJointDef: groundAnchorB") ||
        !RequireFinite(anchorA, "MakePulleyJointDef: anchorA") ||
        !RequireFinite(anchorB, "MakePulleyJointDef: anchorB"))
    {
        return {};
    }
    if (!RequireBodies(State(), a, b))
    {
        return {};
    }
    PulleyJointDef def;
    def.bodyA = a;
    def.bodyB = b;
    def.groundAnchorA = groundAnchorA;
    def.groundAnchorB = groundAnchorB;
    def.localAnchorA = GetLocalPoint(a, anchorA);
    def.localAnchorB = GetLocalPoint(b, anchorB);
    def.lengthA = (anchorA - groundAnchorA).Length();
    def.lengthB = (anchorB - groundAnchorB).Length();
    def.ratio = ratio; // checked by CreateJoint
    return def;
}

// ---------------------------------------------------------------------------------------------
// Settings and reports

std::uint64_t World::GetStepCount() const
{
    return State().stepCount;
}
const StepProfile& World::GetProfile() const
{
    return State().profile;
}
const SolverSettings& World::GetSolverSettings() const
{
    return State().solver;
}
void World::SetSolverSettings(const SolverSettings& settings)
{
    if (!RequireNotWalked(State(), "World::SetSolverSettings") || !RequireSolverSettings(settings))
    {
        return;
    }
    WorldState& world = State();
    world.solver = settings;
    // The back end chooses how the broad phase fattens boxes and whether the narrow phase may
    // keep manifolds (collision/collision_policy.h).
    world.collision = world.solvers.For(settings.kind).Collision(world.tolerances);
    world.broadPhase.SetFatBoxRule(world.collision.fatBoxes);
    world.broadPhase.SetTreeUpdate(world.collision.treeUpdate);
}
Vec2 World::GetGravity() const
{
    return State().gravity;
}
void World::SetGravity(Vec2 gravity)
{
    if (!RequireNotStepping(State(), "World::SetGravity") ||
        !RequireFinite(gravity, "World::SetGravity: gravity"))
    {
        return;
    }
    State().gravity = gravity;
}
const Tolerances& World::GetTolerances() const
{
    return State().tolerances;
}
bool World::GetContinuous() const
{
    return State().continuous;
}
void World::SetContinuous(bool continuous)
{
    if (!RequireNotWalked(State(), "World::SetContinuous"))
    {
        return;
    }
    State().continuous = continuous;
}
Real World::GetLastStepInverseDt() const
{
    return State().invDt0;
}
void World::SetLastStepInverseDt(Real invDt)
{
    if (!RequireNotStepping(State(), "World::SetLastStepInverseDt") ||
        !RequireNonNegative(invDt, "World::SetLastStepInverseDt: invDt"))
    {
        return;
    }
    State().invDt0 = invDt;
}
bool World::GetAllowSleeping() const
{
    return State().allowSleep;
}
void World::SetAllowSleeping(bool allow)
{
    if (!RequireNotStepping(State(), "World::SetAllowSleeping"))
    {
        return;
    }
    WorldState& world = State();
    if (allow == world.allowSleep)
    {
        return;
    }
    world.allowSleep = allow;
    if (!allow)
    {
        for (std::int32_t b = world.bodyList; b != kNullIndex; b = world.bodies[b].next)
        {
            WakeBody(world, b);
        }
    }
}

void World::SetPreSolveCallback(PreSolveCallback callback)
{
    if (!RequireNotStepping(State(), "World::SetPreSolveCallback"))
    {
        return;
    }
    State().preSolve = std::move(callback);
}

void World::SetCustomFilterCallback(CustomFilterCallback callback)
{
    if (!RequireNotStepping(State(), "World::SetCustomFilterCallback"))
    {
        return;
    }
    State().customFilter = std::move(callback);
}

void World::SetTaskSystem(TaskSystem* tasks)
{
    WorldState& world = State();
    if (!RequireNotStepping(world, "World::SetTaskSystem"))
    {
        return;
    }
    if (tasks == nullptr)
    {
        world.checkedTasks = nullptr;
        return;
    }
    // The engine sizes per-worker scratch by it: a count of 2^31 - 1 asked for 16 GB.
    if (const int threads = tasks->ThreadCount(); threads < 1 || threads > kMaxTaskThreads)
    {
        ReportError(InvalidArgument("World::SetTaskSystem: ThreadCount() is " +
                                    std::to_string(threads) + ", must be from 1 to " +
                                    std::to_string(kMaxTaskThreads)));
        return;
    }
    world.checkedTasks = std::make_shared<CheckedTasks>(*tasks);
}

TaskSystem* World::GetTaskSystem() const
{
    const WorldState& world = State();
    return world.checkedTasks == nullptr ? nullptr : &world.checkedTasks->User();
}

bool World::UsesThreads() const
{
    return State().StageTasks() != nullptr;
}

std::span<const ContactPointReport> World::GetContactReports() const
{
    // Built on the first read after a step (contact_reports.h): the world's visible state does
    // not change, so this stays a const call, but like every World call it is not thread-safe.
    // The state itself is not const (only this view of it): building the reports is allowed.
    BuildContactReports(const_cast<WorldState&>(State()));
    return State().contactReports;
}
std::span<const ContactEvent> World::GetContactBeginEvents() const
{
    return State().beginEvents;
}
std::span<const ContactEvent> World::GetContactEndEvents() const
{
    return State().endEvents;
}
std::span<const SensorEvent> World::GetSensorBeginEvents() const
{
    return State().sensorBeginEvents;
}
std::span<const SensorEvent> World::GetSensorEndEvents() const
{
    return State().sensorEndEvents;
}
std::span<const ContactHitEvent> World::GetContactHitEvents() const
{
    return State().hitEvents;
}
int World::GetContactCount() const
{
    return State().contactCount;
}
int World::GetTouchingContactCount() const
{
    int count = 0;
    for (std::int32_t c = State().contactList; c != kNullIndex; c = State().contacts[c].next)
    {
        count += State().contacts[c].IsTouching() ? 1 : 0;
    }
    return count;
}

BodyDef World::GetBodyDef(BodyId id) const
{
    const auto* const found = Resolve(State().bodies, id, "body");
    if (found == nullptr)
    {
        return {};
    }
    const Body& body = *found;
    BodyDef def;
    def.type = body.type;
    def.position = body.xf.p;
    def.angle = body.sweep.a;
    def.linearVelocity = body.linearVelocity;
    def.angularVelocity = body.angularVelocity;
    def.linearDamping = body.linearDamping;
    def.angularDamping = body.angularDamping;
    def.gravityScale = body.gravityScale;
    def.fixedRotation = body.fixedRotation;
    def.bullet = body.bullet;
    def.allowSleep = body.allowSleep;
    def.awake = body.type == BodyType::Static || body.awake; // a static body is never awake
    def.userData = body.userData;
    return def;
}

namespace
{

/// The definition's bodies, anchors and collide flag, which most joint types share.
template <typename Def, typename Data>
Def AnchoredDef(const WorldState& world, const Joint& joint, const Data& data)
{
    Def def;
    def.bodyA = {joint.bodyA, world.bodies[joint.bodyA].generation};
    def.bodyB = {joint.bodyB, world.bodies[joint.bodyB].generation};
    if constexpr (requires { def.localAnchorA; })
    {
        def.localAnchorA = data.localAnchorA;
    }
    if constexpr (requires { def.localAnchorB; })
    {
        def.localAnchorB = data.localAnchorB;
    }
    def.collideConnected = joint.collideConnected;
    return def;
}

AnyJointDef JointDefOf(const WorldState& world, const Joint& joint, const RevoluteJoint& r)
{
    auto def = AnchoredDef<RevoluteJointDef>(world, joint, r);
    def.referenceAngle = r.referenceAngle;
    def.enableLimit = r.enableLimit;
    def.lowerAngle = r.lowerAngle;
    def.upperAngle = r.upperAngle;
    def.enableMotor = r.enableMotor;
    def.motorSpeed = r.motorSpeed;
    def.maxMotorTorque = r.maxMotorTorque;
    def.enableSpring = r.enableSpring;
    def.hertz = r.hertz;
    def.dampingRatio = r.dampingRatio;
    def.targetAngle = r.targetAngle;
    return def;
}

AnyJointDef JointDefOf(const WorldState& world, const Joint& joint, const DistanceJoint& d)
{
    auto def = AnchoredDef<DistanceJointDef>(world, joint, d);
    def.length = d.length;
    def.minLength = d.minLength;
    def.maxLength = d.maxLength;
    def.hertz = d.hertz;
    def.dampingRatio = d.dampingRatio;
    return def;
}

AnyJointDef JointDefOf(const WorldState& world, const Joint& joint, const PrismaticJoint& p)
{
    auto def = AnchoredDef<PrismaticJointDef>(world, joint, p);
    def.localAxisA = p.definedAxisA;
    def.referenceAngle = p.referenceAngle;
    def.enableLimit = p.enableLimit;
    def.lowerTranslation = p.lowerTranslation;
    def.upperTranslation = p.upperTranslation;
    def.enableMotor = p.enableMotor;
    def.motorSpeed = p.motorSpeed;
    def.maxMotorForce = p.maxMotorForce;
    def.enableSpring = p.enableSpring;
    def.hertz = p.hertz;
    def.dampingRatio = p.dampingRatio;
    def.targetTranslation = p.targetTranslation;
    return def;
}

AnyJointDef JointDefOf(const WorldState& world, const Joint& joint, const WheelJoint& w)
{
    auto def = AnchoredDef<WheelJointDef>(world, joint, w);
    def.localAxisA = w.definedAxisA;
    def.enableLimit = w.enableLimit;
    def.lowerTranslation = w.lowerTranslation;
    def.upperTranslation = w.upperTranslation;
    def.enableMotor = w.enableMotor;
    def.motorSpeed = w.motorSpeed;
    def.maxMotorTorque = w.maxMotorTorque;
    def.hertz = w.hertz;
    def.dampingRatio = w.dampingRatio;
    return def;
}

AnyJointDef JointDefOf(const WorldState& world, const Joint& joint, const WeldJoint& w)
{
    auto def = AnchoredDef<WeldJointDef>(world, joint, w);
    def.referenceAngle = w.referenceAngle;
    def.hertz = w.hertz;
    def.dampingRatio = w.dampingRatio;
    return def;
}

AnyJointDef JointDefOf(const WorldState& world, const Joint& joint, const MotorJoint& m)
{
    auto def = AnchoredDef<MotorJointDef>(world, joint, m);
    def.linearOffset = m.linearOffset;
    def.angularOffset = m.angularOffset;
    def.maxForce = m.maxForce;
    def.maxTorque = m.maxTorque;
    def.correctionFactor = m.correctionFactor;
    return def;
}

AnyJointDef JointDefOf(const WorldState& world, const Joint& joint, const MouseJoint& m)
{
    auto def = AnchoredDef<MouseJointDef>(world, joint, m);
    def.target = Mul(world.bodies[joint.bodyB].xf, m.localAnchorB); // the grabbed point now
    def.maxForce = m.maxForce;
    def.hertz = m.hertz;
    def.dampingRatio = m.dampingRatio;
    return def;
}

AnyJointDef JointDefOf(const WorldState& world, const Joint& joint, const FrictionJoint& f)
{
    auto def = AnchoredDef<FrictionJointDef>(world, joint, f);
    def.maxForce = f.maxForce;
    def.maxTorque = f.maxTorque;
    return def;
}

AnyJointDef JointDefOf(const WorldState& world, const Joint& joint, const PulleyJoint& p)
{
    auto def = AnchoredDef<PulleyJointDef>(world, joint, p);
    def.groundAnchorA = p.groundAnchorA;
    def.groundAnchorB = p.groundAnchorB;
    def.lengthA = p.lengthA;
    def.lengthB = p.lengthB;
    def.ratio = p.ratio;
    return def;
}

AnyJointDef JointDefOf(const WorldState&, const Joint& joint, const GearJoint& g)
{
    GearJointDef def;
    def.joint1 = g.joint1;
    def.joint2 = g.joint2;
    def.ratio = g.ratio;
    def.collideConnected = joint.collideConnected;
    return def;
}

} // namespace

AnyJointDef World::GetJointDef(JointId id) const
{
    const auto* const found = Resolve(State().joints, id, "joint");
    if (found == nullptr)
    {
        return {};
    }
    const Joint& joint = found->joint;
    return std::visit([&](const auto& data) { return JointDefOf(State(), joint, data); },
                      joint.data);
}

namespace
{

/// The joint's accumulated impulses, as World::GetJointImpulses orders them (Real* or, for a
/// const joint, const Real*).
template <typename JointT>
auto ImpulsesOf(JointT& joint)
{
    using Pointer = std::conditional_t<std::is_const_v<JointT>, const Real*, Real*>;
    return std::visit(
        [](auto& j) -> std::vector<Pointer>
        {
            using Data = std::decay_t<decltype(j)>;
            if constexpr (std::is_same_v<Data, RevoluteJoint> ||
                          std::is_same_v<Data, PrismaticJoint>)
            {
                return {&j.impulse.x,    &j.impulse.y,    &j.motorImpulse,
                        &j.lowerImpulse, &j.upperImpulse, &j.springImpulse};
            }
            else if constexpr (std::is_same_v<Data, DistanceJoint>)
            {
                return {&j.impulse, &j.lowerImpulse, &j.upperImpulse};
            }
            else if constexpr (std::is_same_v<Data, WheelJoint>)
            {
                return {&j.impulse, &j.motorImpulse, &j.springImpulse, &j.lowerImpulse,
                        &j.upperImpulse};
            }
            else if constexpr (std::is_same_v<Data, WeldJoint>)
            {
                return {&j.impulse.x, &j.impulse.y, &j.impulse.z};
            }
            else if constexpr (std::is_same_v<Data, MotorJoint> ||
                               std::is_same_v<Data, FrictionJoint>)
            {
                return {&j.linearImpulse.x, &j.linearImpulse.y, &j.angularImpulse};
            }
            else if constexpr (std::is_same_v<Data, MouseJoint>)
            {
                return {&j.impulse.x, &j.impulse.y};
            }
            else // pulley, gear
            {
                return {&j.impulse};
            }
        },
        joint.data);
}

} // namespace

std::vector<Real> World::GetJointImpulses(JointId id) const
{
    const auto* const found = Resolve(State().joints, id, "joint");
    if (found == nullptr)
    {
        return {};
    }
    std::vector<Real> impulses;
    for (const Real* impulse : ImpulsesOf(found->joint))
    {
        impulses.push_back(*impulse);
    }
    return impulses;
}

void World::SetJointImpulses(JointId id, std::span<const Real> impulses)
{
    if (!RequireNotStepping(State(), "World::SetJointImpulses"))
    {
        return;
    }
    auto* const found = Resolve(State().joints, id, "joint");
    if (found == nullptr)
    {
        return;
    }
    Joint& joint = found->joint;
    const std::vector<Real*> rows = ImpulsesOf(joint);
    if (!Require(impulses.size() == std::size_t(JointImpulseCount(joint.type)),
                 [&]
                 {
                     return "World::SetJointImpulses: this joint has " +
                            std::to_string(rows.size()) + " impulses, got " +
                            std::to_string(impulses.size());
                 }))
    {
        return;
    }
    for (const Real impulse : impulses)
    {
        if (!RequireFinite(impulse, "World::SetJointImpulses: impulses"))
        {
            return; // nothing was changed yet
        }
    }
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
        *rows[i] = impulses[i];
    }
}

} // namespace meff
