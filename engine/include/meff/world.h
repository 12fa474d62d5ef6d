// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// SPDX-FileCopyrightText: 2019 Erin Catto (Box2D 2.4.1, MIT; see THIRD_PARTY_NOTICES)
// The world: owns bodies, shapes, joints and contacts, and advances them in time. This header
// holds only World; what it takes and gives lives by concept beside it (settings.h: WorldDef and
// the solver settings; events.h; callbacks.h; queries.h; profile.h; snapshot.h; body.h, shape.h,
// joint.h: the definitions), all included here so that including meff/world.h alone is enough.
#pragma once

#include "meff/body.h"
#include "meff/callbacks.h"
#include "meff/collision.h"
#include "meff/debug_draw.h"
#include "meff/error.h"
#include "meff/events.h"
#include "meff/function_ref.h"
#include "meff/ids.h"
#include "meff/joint.h"
#include "meff/math.h"
#include "meff/mover.h"
#include "meff/profile.h"
#include "meff/queries.h"
#include "meff/settings.h"
#include "meff/shape.h"
#include "meff/snapshot.h"
#include "meff/task_system.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

namespace meff
{

/// A physics world: its bodies, shapes, joints and contacts, stepped by World::Step. Every
/// object in it is named by an id and reached through the world's calls.
class World
{
  public:
    /// An empty world with `def`'s settings.
    explicit World(const WorldDef& def = {});
    ~World();
    World(const World&) = delete;
    World& operator=(const World&) = delete;
    /// Moving leaves the source empty: every call on it but destruction and assignment throws
    /// InvalidArgument ("this World was moved from").
    World(World&&) noexcept;
    /// Moves `other`'s world here (see the move constructor).
    World& operator=(World&&) noexcept;

    // Bodies
    /// A new body (see BodyDef); throws InvalidArgument for a non-finite position, angle or
    /// velocity, or a negative damping.
    BodyId CreateBody(const BodyDef& def);
    /// Also destroys its shapes, joints and contacts, and wakes the bodies it touched or was
    /// jointed to (as Box2D 2.4.1, whose contact destruction wakes both bodies of a touching
    /// contact).
    void DestroyBody(BodyId id);
    /// Whether `id` names a live body of this world.
    bool IsValid(BodyId id) const;
    /// Static, kinematic or dynamic.
    BodyType GetType(BodyId id) const;
    Vec2 GetPosition(BodyId id) const; ///< world position of the body origin (m)
    Real GetAngle(BodyId id) const;    ///< rad
    /// The body origin's position and rotation.
    Transform GetTransform(BodyId id) const;
    Vec2 GetWorldCenter(BodyId id) const;       ///< centre of mass (m)
    Vec2 GetLocalCenter(BodyId id) const;       ///< centre of mass in body coordinates (m)
    Vec2 GetLinearVelocity(BodyId id) const;    ///< of the centre of mass (m/s)
    Real GetAngularVelocity(BodyId id) const;   ///< rad/s
    Real GetMass(BodyId id) const;              ///< kg
    Real GetRotationalInertia(BodyId id) const; ///< about the centre of mass (kg·m²)
    std::uint64_t GetUserData(BodyId id) const; ///< BodyDef::userData
    /// A point in the body's frame, in world coordinates (m).
    Vec2 GetWorldPoint(BodyId id, Vec2 localPoint) const;
    /// A world point in the body's frame (m).
    Vec2 GetLocalPoint(BodyId id, Vec2 worldPoint) const;
    /// Moves the body and wakes it and the bodies it touches. (Box2D 2.4.1 does not wake here;
    /// meff does, so that a body the user moves is never left asleep in mid-air.)
    void SetTransform(BodyId id, Vec2 position, Real angle);
    void SetLinearVelocity(BodyId id, Vec2 v);  ///< a non-zero v wakes the body, as Box2D
    void SetAngularVelocity(BodyId id, Real w); ///< a non-zero w wakes the body, as Box2D
    // Forces and impulses act on dynamic bodies only. As Box2D 2.4.1: `wake` wakes a sleeping
    // body first; a body left asleep (wake = false) ignores the force or impulse.
    void ApplyForce(BodyId id, Vec2 force, Vec2 worldPoint,
                    bool wake = true);                                ///< N, until the step ends
    void ApplyForceToCenter(BodyId id, Vec2 force, bool wake = true); ///< N
    void ApplyTorque(BodyId id, Real torque, bool wake = true);       ///< N·m
    void ApplyLinearImpulse(BodyId id, Vec2 impulse, Vec2 worldPoint, bool wake = true); ///< N·s
    /// An explosion (Box2D v3's b2World_Explode): each dynamic body's non-sensor circle,
    /// polygon or capsule within radius + falloff of the centre (distance to its surface), and
    /// whose category is in maskBits, gets the impulse impulsePerLength × (its width across the
    /// line from the centre) × (1, or (radius + falloff − d)/falloff beyond radius), pushing along
    /// that line from the centre to its closest point (to its centroid when the centre is
    /// inside it), applied at that point, and is woken. Segments and chains are left alone.
    /// Throws InvalidArgument for a non-finite position or impulse, or a negative radius or
    /// falloff, naming the field.
    void Explode(const ExplosionDef& def);
    void ApplyAngularImpulse(BodyId id, Real impulse, bool wake = true); ///< N·m·s
    /// A definition that creates this body as it is now (World::CreateBody, then the same
    /// shapes): its type, origin, angle (its centre of mass's angle), velocities, damping,
    /// gravity scale, flags, awake state and user data. What a definition cannot hold is left
    /// out: the time it has rested (Tolerances::timeToSleep) and the force and torque applied
    /// since the last step.
    BodyDef GetBodyDef(BodyId id) const;
    /// Sleeping. Static bodies are never awake.
    bool IsAwake(BodyId id) const;
    /// Box2D's SetAwake: true wakes the body and restarts its rest time; false puts it to
    /// sleep now, zeroing its velocity, force, torque and rest time. No effect on static bodies.
    void SetAwake(BodyId id, bool awake);
    /// BodyDef::allowSleep, or the last SetSleepingAllowed.
    bool IsSleepingAllowed(BodyId id) const;
    /// false also wakes the body (Box2D's SetSleepingAllowed).
    void SetSleepingAllowed(BodyId id, bool allowed);
    /// Live bodies in creation order: a copy, so the world may change while a game walks it.
    /// Destroying bodies in the walk is safe and destroys exactly the ones chosen:
    ///     for (BodyId body : world.GetBodies())
    ///         if (IsOffScreen(world, body)) world.DestroyBody(body);
    /// An id the walk has not reached yet may have been destroyed by then (with a body it was
    /// jointed to, say): IsValid(id) says so. Bodies created during the walk are not in it.
    std::vector<BodyId> GetBodies() const;

    // Shapes
    /// Gives `body` a shape (see ShapeDef); a dynamic body's mass is recomputed. Throws
    /// InvalidArgument for what validity.h refuses.
    ShapeId CreateShape(BodyId body, const ShapeDef& def, const Circle& circle);
    /// A polygon whose radius is above Tolerances::polygonSkin is rounded (see Polygon).
    ShapeId CreateShape(BodyId body, const ShapeDef& def, const Polygon& polygon);
    /// Box2D v3's capsule (see Capsule; CheckCapsule says what is refused).
    ShapeId CreateShape(BodyId body, const ShapeDef& def, const Capsule& capsule);
    /// A two-sided segment (Box2D 2.4.1's b2EdgeShape); it has no mass.
    ShapeId CreateShape(BodyId body, const ShapeDef& def, const Segment& segment);
    /// A one-sided segment with ghost vertices, alone (Box2D 2.4.1's b2EdgeShape after
    /// SetOneSided; see ChainSegment). Throws InvalidArgument for non-finite points, or ends
    /// (or a ghost and its end) no further apart than the linear slop. Like segments, it has
    /// no mass.
    ShapeId CreateShape(BodyId body, const ShapeDef& def, const ChainSegment& segment);
    /// Wakes the bodies of the contacts it was touching in (as Box2D 2.4.1 does). Throws
    /// InvalidArgument for a segment of a chain (destroy the chain with DestroyChain).
    void DestroyShape(ShapeId id);
    /// Whether `id` names a live shape of this world.
    bool IsValid(ShapeId id) const;
    /// The body the shape belongs to.
    BodyId GetBody(ShapeId id) const;
    /// Which geometry the shape has (GetCircle, GetPolygon, ... read it).
    ShapeType GetShapeType(ShapeId id) const;
    const Circle& GetCircle(ShapeId id) const;   ///< throws unless a circle
    const Polygon& GetPolygon(ShapeId id) const; ///< throws unless a polygon
    const Segment& GetSegment(ShapeId id) const; ///< throws unless a segment
    const Capsule& GetCapsule(ShapeId id) const; ///< throws unless a capsule
    /// Throws unless a chain segment (of a chain, or made alone).
    const ChainSegment& GetChainSegment(ShapeId id) const;
    /// The definition the shape was created with.
    const ShapeDef& GetShapeDef(ShapeId id) const;
    /// A body's shapes, newest first (Box2D's fixture-list order); a chain's segments are
    /// listed together, in order along the chain. A copy, so destroying them while walking it
    /// is safe (see GetBodies).
    std::vector<ShapeId> GetShapes(BodyId body) const;

    // Chains (world_chain.cpp)
    /// Makes a chain of one-sided segments (Box2D 2.4.1's b2ChainShape; see Chain): one
    /// ChainSegment shape per link, created in order along the chain and each given `def`,
    /// with its neighbours as ghosts (an open chain's ends get Chain::prev and Chain::next).
    /// Contacts, events and queries name the segment shapes; GetChain maps one back to its
    /// chain. As Box2D 2.4.1, a ray hits a chain's segments from both sides (shapes collide
    /// with the solid side only), and chains have no mass. Throws InvalidArgument for fewer
    /// than 2 points (3 for a loop), non-finite points, consecutive points (a loop's last and
    /// first too) no further apart than the linear slop, ghosts given for a loop, or an open
    /// chain's ghost within the linear slop of its end point.
    ChainId CreateChain(BodyId body, const ShapeDef& def, const Chain& chain);
    /// Destroys the chain's segments, their contacts (waking the bodies they touched, as
    /// DestroyShape) and their broad-phase proxies, in order along the chain (as
    /// b2Body::DestroyFixture does for a chain).
    void DestroyChain(ChainId id);
    /// Whether `id` names a live chain of this world.
    bool IsValid(ChainId id) const;
    /// The chain's segment shapes in order along the chain (for a loop, the closing segment,
    /// last point to first, is the last).
    std::span<const ShapeId> GetChainSegments(ChainId id) const;
    /// Whether the chain is a loop (Chain::loop). Its points are its segments' first points,
    /// in order; an open chain's last point is its last segment's second point, and its ghosts
    /// (Chain::prev, Chain::next) are its first segment's ghost1 and its last segment's ghost2.
    bool IsChainLoop(ChainId id) const;
    /// The chain a shape belongs to; null for any other shape (a one-sided segment made alone
    /// included).
    ChainId GetChain(ShapeId id) const;

    // Joints. Creating or destroying a joint wakes both bodies (Box2D 2.4.1 wakes them only
    // on destruction; meff also on creation, so a new joint acts at once).
    /// A revolute joint (see RevoluteJointDef; the Make...JointDef helpers fill one in).
    JointId CreateJoint(const RevoluteJointDef& def);
    /// A distance joint: a rod, a rope or a spring (see DistanceJointDef).
    JointId CreateJoint(const DistanceJointDef& def);
    /// A prismatic joint (see PrismaticJointDef).
    JointId CreateJoint(const PrismaticJointDef& def);
    /// The suspension spring's stiffness comes from hertz and both bodies' masses now.
    JointId CreateJoint(const WheelJointDef& def);
    /// A weld joint (see WeldJointDef).
    JointId CreateJoint(const WeldJointDef& def);
    /// A motor joint (see MotorJointDef).
    JointId CreateJoint(const MotorJointDef& def);
    JointId CreateJoint(const MouseJointDef& def); ///< throws unless bodyB is dynamic
    /// A friction joint (see FrictionJointDef).
    JointId CreateJoint(const FrictionJointDef& def);
    /// A pulley joint (see PulleyJointDef).
    JointId CreateJoint(const PulleyJointDef& def);
    /// Throws InvalidArgument unless joint1 and joint2 are two different live revolute or
    /// prismatic joints whose bodies B are dynamic, and the ratio is finite. The gear's bodies
    /// A and B are joint1's and joint2's bodies B.
    JointId CreateJoint(const GearJointDef& def);
    /// Destroys the joint, and first every gear joint that couples it.
    void DestroyJoint(JointId id);
    /// Whether `id` names a live joint of this world.
    bool IsValid(JointId id) const;
    /// Which kind of joint it is.
    JointType GetJointType(JointId id) const;
    /// A definition that creates this joint again with its present settings (the alternative
    /// of its type): the bodies (or, for a gear, the joints), local anchors and axes as the
    /// joint holds them (an axis as it was given, before the joint normalized it), reference
    /// angles, limits, motors, springs (their frequencies and damping ratios, from which a new
    /// joint computes its stiffness with the bodies' masses then), a pulley's ground anchors
    /// and reference lengths, a motor joint's offsets. A mouse joint's target is the point it
    /// grabs body B at, where that point is now (GetMouseTarget gives where it is pulled to).
    /// A gear takes its constant from the poses it is created at, and every joint starts
    /// without the impulses this one has accumulated.
    AnyJointDef GetJointDef(JointId id) const;
    /// The impulses the joint has accumulated, which start its next step when warm starting is
    /// on (SolverSettings::warmStarting), what GetJointDef leaves out: N·s for linear rows,
    /// N·m·s for angular ones, in this order: revolute: point x, point y, motor, lower, upper,
    /// spring; distance: rod, lower, upper; prismatic: perpendicular, angular, motor, lower,
    /// upper, spring; wheel: perpendicular, motor, spring, lower, upper; weld: point x, point y,
    /// angle; motor and friction: linear x, linear y, angular; mouse: x, y; pulley, gear: one.
    std::vector<Real> GetJointImpulses(JointId id) const;
    /// Sets them, as GetJointImpulses orders them (a joint made again from a saved world,
    /// carrying on where it was). Throws InvalidArgument for another count than the joint
    /// type's or a value that is not finite.
    void SetJointImpulses(JointId id, std::span<const Real> impulses);
    /// The joint's body A.
    BodyId GetBodyA(JointId id) const;
    /// The joint's body B.
    BodyId GetBodyB(JointId id) const;
    /// World point (m); a motor joint's anchors are the bodies' origins, a mouse joint's
    /// anchor A is its target.
    Vec2 GetAnchorA(JointId id) const;
    Vec2 GetAnchorB(JointId id) const; ///< world point (m)
    /// Reaction on body B over the last step: the joint's accumulated impulse times invDt.
    JointReaction GetReaction(JointId id, Real invDt) const;
    /// Live joints in creation order: a copy, so destroying joints (or their bodies) while
    /// walking it is safe; check IsValid for ids the walk has not reached (see GetBodies).
    std::vector<JointId> GetJoints() const;
    /// Target speed of a joint's motor: rad/s for revolute and wheel joints (B relative to
    /// A), m/s along the axis for prismatic joints. Throws InvalidArgument for other types or
    /// a non-finite speed. Does not enable the motor.
    void SetJointMotorSpeed(JointId id, Real speed);
    /// Sets a revolute or prismatic joint's spring (see JointSpring) and wakes both bodies
    /// when it changes. Throws InvalidArgument for other joint types, a hertz or damping ratio
    /// that is negative or not finite, or a target that is not finite.
    void SetJointSpring(JointId id, const JointSpring& spring);
    /// A revolute or prismatic joint's spring; throws InvalidArgument for other joint types.
    JointSpring GetJointSpring(JointId id) const;
    /// Where body B's anchor is along a prismatic or wheel joint's axis, measured from body
    /// A's anchor (m), as b2PrismaticJoint's and b2WheelJoint's GetJointTranslation. Throws
    /// InvalidArgument for other joint types.
    Real GetJointTranslation(JointId id) const;
    /// Relative speed of a joint: along the axis for prismatic and wheel joints (m/s, as
    /// b2PrismaticJoint::GetJointSpeed and b2WheelJoint::GetJointLinearSpeed), wB − wA for
    /// revolute joints (rad/s). Throws InvalidArgument for other joint types.
    Real GetJointSpeed(JointId id) const;
    /// Definition helpers from world points, as Box2D's b2*JointDef Initialize.
    RevoluteJointDef MakeRevoluteJointDef(BodyId a, BodyId b, Vec2 worldAnchor) const;
    /// Anchors at the two world points; the length is their distance (rigid: min = max).
    DistanceJointDef MakeDistanceJointDef(BodyId a, BodyId b, Vec2 worldAnchorA,
                                          Vec2 worldAnchorB) const;
    /// Slides along worldAxis through worldAnchor; the current relative angle is kept.
    PrismaticJointDef MakePrismaticJointDef(BodyId a, BodyId b, Vec2 worldAnchor,
                                            Vec2 worldAxis) const;
    /// Wheel hub at worldAnchor (usually the wheel's centre), suspension along worldAxis.
    WheelJointDef MakeWheelJointDef(BodyId a, BodyId b, Vec2 worldAnchor, Vec2 worldAxis) const;
    /// Welds at worldAnchor, holding the bodies' present relative angle.
    WeldJointDef MakeWeldJointDef(BodyId a, BodyId b, Vec2 worldAnchor) const;
    /// Holds the bodies' present relative pose: B's origin in A's frame and angleB − angleA.
    MotorJointDef MakeMotorJointDef(BodyId a, BodyId b) const;
    /// Both local anchors at the world point (b2FrictionJointDef::Initialize).
    FrictionJointDef MakeFrictionJointDef(BodyId a, BodyId b, Vec2 worldAnchor) const;
    /// Ground anchors as given, local anchors from the world anchors, and each side's length
    /// from its ground anchor to its anchor (b2PulleyJointDef::Initialize).
    PulleyJointDef MakePulleyJointDef(BodyId a, BodyId b, Vec2 groundAnchorA, Vec2 groundAnchorB,
                                      Vec2 anchorA, Vec2 anchorB, Real ratio) const;
    /// Moves a mouse joint's target (the pointer moved). Throws unless id is a mouse joint.
    void SetMouseTarget(JointId id, Vec2 target);
    /// A mouse joint's target (m). Throws unless id is a mouse joint.
    Vec2 GetMouseTarget(JointId id) const;
    /// Changes a motor joint's target pose of B relative to A (m in A's frame, rad). Throws
    /// unless id is a motor joint.
    void SetMotorJointOffsets(JointId id, Vec2 linearOffset, Real angularOffset);

    // Stepping
    /// Advances the world by dt seconds (> 0 and finite). Throws SimulationError if a body's
    /// state becomes non-finite; the world is then frozen but readable. Called during a step
    /// (from the pre-solve callback) or from a query's callback, it throws InvalidArgument
    /// instead of recursing; an exception that leaves a step half done (thrown by the callback)
    /// also freezes the world.
    /// RestoreSnapshot thaws a frozen world.
    void Step(Real dt);
    /// How many steps the world has taken.
    std::uint64_t GetStepCount() const;
    /// Where the last step's time went, stage by stage (see StepProfile); zeros before the
    /// first step.
    const StepProfile& GetProfile() const;
    /// The back end and its settings.
    const SolverSettings& GetSolverSettings() const;
    /// Changes the back end or its settings from the next step; throws InvalidArgument for an
    /// out-of-range value.
    void SetSolverSettings(const SolverSettings& settings);
    Vec2 GetGravity() const; ///< m/s²
    /// Changes gravity (m/s²) from the next step.
    void SetGravity(Vec2 gravity);
    /// The world's tolerances (WorldDef::tolerances).
    const Tolerances& GetTolerances() const;
    /// Whether continuous collision is on.
    bool GetContinuous() const;
    void SetContinuous(bool continuous); ///< takes effect from the next step
    /// 1/dt of the last step taken (1/s; 0 before the first): the next step scales the
    /// warm-starting impulses of contacts and joints by its dt times this (Box2D's dtRatio), so
    /// a fresh world's first step starts them from zero.
    Real GetLastStepInverseDt() const;
    /// Sets it, for a world made again from a saved one (SceneFromWorld: "last_step_inv_dt"),
    /// whose first step then warm-starts as the original's next step would. Throws
    /// InvalidArgument for a value that is negative or not finite, or during a step.
    void SetLastStepInverseDt(Real invDt);
    /// Whether islands may fall asleep.
    bool GetAllowSleeping() const;
    /// Turning sleeping off wakes every body (Box2D's SetAllowSleeping).
    void SetAllowSleeping(bool allow);
    /// Installs (or, with an empty function, removes) the pre-solve callback.
    /// WARNING: it runs INSIDE World::Step, in the narrow phase and in continuous collision.
    /// It must not modify the world — no Create/Destroy/Set/Apply/Step calls — and should only
    /// read meff's data (the contact it is given, const getters of this world), and must not
    /// throw (the step would be left half done, and the world frozen). Step, the Create and
    /// Destroy calls, SetTransform, SaveSnapshot and RestoreSnapshot throw InvalidArgument when
    /// called from it. It is configuration, not state: RestoreSnapshot keeps the current callback.
    void SetPreSolveCallback(PreSolveCallback callback);
    /// Installs (or, with an empty function, removes) the custom collision filter. It is
    /// called INSIDE World::Step where Box2D 2.4.1 calls its contact filter: when a pair of
    /// shapes without a contact is first found by the broad phase (shapes as the broad phase
    /// pairs them), and for an existing contact flagged for re-filtering by the creation or
    /// destruction of a joint between its bodies (the contact's shapes; false destroys it).
    /// Contacts that exist when it is installed are kept. The same rules as for the pre-solve
    /// callback: it must not modify the world or throw, and it must answer the same for the
    /// same pair for runs to be deterministic. Configuration, not state: RestoreSnapshot keeps
    /// the current filter.
    void SetCustomFilterCallback(CustomFilterCallback callback);
    /// Lends the world threads for its steps (task_system.h: a game's job system, or
    /// MakeThreadPool's), or with null takes them back: one thread, the default. Not owned: it
    /// must outlive its use by the world. The results are the same, bit for bit, for any
    /// thread count. The colour and soft-step back ends use them (the narrow phase, the broad
    /// phase's boxes and pairs, continuous collision's first search, their contact and joint
    /// lanes, integration); the Box2D back end stays single-threaded and bit-identical to Box2D
    /// 2.4.1, whatever task system it is lent (UsesThreads says which).
    /// Configuration, not state: RestoreSnapshot keeps the current one, and it is outside
    /// snapshots and the state hash. Throws InvalidArgument during a step or when its
    /// ThreadCount() is outside 1 to 1024; Step throws it when the count has changed since.
    /// Every range its ParallelFor runs is checked against task_system.h's contract: one that
    /// breaks it stops the step with an Error naming TaskSystem::ParallelFor, and the world is
    /// frozen as after any failed step.
    void SetTaskSystem(TaskSystem* tasks);
    /// The task system the world steps on; null: the calling thread.
    TaskSystem* GetTaskSystem() const;
    /// Whether Step hands work to the task system: true when one is set and the back end is
    /// Colour or SoftStep; false without one, and always with the Box2D back end, which steps
    /// on the calling thread (Box2D 2.4.1's serial order) even when lent threads.
    bool UsesThreads() const;

    // Reports of the last step
    /// Every point of every touching, solved contact, with its impulses (Box2D's PostSolve).
    /// The step records only which contacts it solved; the points, normals and separations
    /// are computed on the first call after a step (so a game that never asks pays almost
    /// nothing), from the state the step left, even if bodies are moved or destroyed before.
    /// Because that first call writes inside the world, two threads must not call it (or
    /// Draw) on one world at the same time, though both are const. With continuous collision, the
    /// contacts of each time-of-impact sub-step are appended after the step's own, as Box2D calls
    /// PostSolve again for them, so a contact can appear more than once in one step.
    std::span<const ContactPointReport> GetContactReports() const;
    /// Contacts that started touching in the last step.
    std::span<const ContactEvent> GetContactBeginEvents() const;
    /// Contacts that stopped touching in the last step. Destroying a touching shape or body
    /// between steps adds its end events at once, and they stay, first in the list, through
    /// the next step: a game reading events once per step sees them. Their ids may be
    /// invalid by then (compare them, do not look them up). Sensor end events do the same: so
    /// a destroy invalidates the spans these return; copy them before destroying what they name.
    std::span<const ContactEvent> GetContactEndEvents() const;
    /// Shapes that started / stopped overlapping a sensor, in the order Box2D 2.4.1 calls
    /// BeginContact/EndContact for sensor fixtures. Sensor contacts never appear among the
    /// contact begin/end events or the contact reports (as in Box2D v3).
    std::span<const SensorEvent> GetSensorBeginEvents() const;
    /// Shapes that stopped overlapping a sensor (see GetSensorBeginEvents).
    std::span<const SensorEvent> GetSensorEndEvents() const;
    /// One event per contact that hit faster than Tolerances::hitEventThreshold (its fastest
    /// point), for contacts with a shape that has ShapeDef::enableHitEvents; in solver order.
    std::span<const ContactHitEvent> GetContactHitEvents() const;
    int GetContactCount() const; ///< contacts whose fat boxes overlap (touching or not)

    // Queries (world_query.cpp). They go through the broad phase, so a query only visits the
    // part of the tree near what it asks about, not every shape. A callback may push what it
    // finds (impulses, velocities, waking) but not create, destroy or move anything, restore a
    // snapshot or step: the broad phase being walked would change under the query, so such calls
    // from a callback (or from DebugDraw's methods during Draw) are refused (InvalidArgument
    // "... called while a query or World::Draw walks the world ..."); collect the ids and make
    // them after the query. Each walk of the tree keeps its own stack, so queries write nothing
    // in the world (each thread notes its own walks): several threads may query one world at
    // once while none changes it. Bad arguments (non-finite numbers, an inverted box, a
    // degenerate shape) throw InvalidArgument naming the argument. Sensor shapes are found like any
    // other (as Box2D 2.4.1): filter them with QueryFilter or the callback.

    /// The closest shape the ray origin → origin + translation hits, as Box2D 2.4.1's
    /// b2World::RayCast with a callback returning every fraction (the same shape, point,
    /// normal and fraction, bit for bit; on an exact tie the hit found last in tree order wins,
    /// as in Box2D). Polygon and segment skins are ignored: hits are on the sharp outline;
    /// capsules and rounded polygons are hit on their rounded outline. A
    /// ray that starts inside a shape does not hit that shape; a zero translation hits nothing.
    RayResult CastRayClosest(Vec2 origin, Vec2 translation, QueryFilter filter = {}) const;
    /// Every shape the ray hits, through `callback` (see CastCallback for what it returns).
    void CastRay(Vec2 origin, Vec2 translation, QueryFilter filter, CastCallback callback) const;

    /// Every shape whose broad-phase box overlaps `box`, as Box2D 2.4.1's b2World::QueryAABB.
    /// The broad-phase box is the shape's bounding box fattened by the solver back end's margin
    /// (Box2D's: Tolerances::aabbMargin, stretched ahead of fast motion; colour's and the soft
    /// step's: half of it, around the end pose alone when continuous collision is off), so
    /// shapes up to a margin away are found too: a cheap candidate list. For the exact answer,
    /// test GetShapeAABB(shape) in the callback.
    void OverlapAABB(const AABB& box, QueryFilter filter, OverlapCallback callback) const;
    /// Every shape containing the point (its boundary included), by each shape's exact test:
    /// circles and polygons (skin not counted); segments contain nothing.
    void OverlapPoint(Vec2 point, QueryFilter filter, OverlapCallback callback) const;

    /// Sweeps `shape`, placed at `start`, along `translation` and reports every shape it hits
    /// (point and normal on the hit shape's surface, normal pointing out of it; fraction of
    /// the translation) through `callback`, as CastRay does. Candidates come from the broad
    /// phase (a ray cast of the swept bounding box), and each is tested by ShapeCast
    /// (meff/distance.h) with the world's polygonSkin and linearSlop: as Box2D's b2ShapeCast,
    /// it stops where the two surfaces (each radius at least polygonSkin) overlap by
    /// polygonSkin — a circle cast onto a polygon stops touching its sharp outline — or up to
    /// linearSlop/2 before. The cast shape's rotation stays fixed. Shapes the cast shape already
    /// overlaps at `start` are not reported.
    void CastShape(const Circle& shape, const Transform& start, Vec2 translation,
                   QueryFilter filter, CastCallback callback) const;
    /// A polygon, as the circle above.
    void CastShape(const Polygon& shape, const Transform& start, Vec2 translation,
                   QueryFilter filter, CastCallback callback) const;
    /// A capsule (Box2D v3's; the character mover's shape, meff/mover.h).
    void CastShape(const Capsule& shape, const Transform& start, Vec2 translation,
                   QueryFilter filter, CastCallback callback) const;
    /// Every shape whose box overlaps the mover's (a capsule in world coordinates) as a plane
    /// (meff/mover.h): the surfaces' separation and the normal from the shape to the mover,
    /// by GJK between the cores. A shape the mover's core reaches into has no normal and is
    /// not reported. `callback` returns false to stop.
    void CollideMover(const Capsule& mover, QueryFilter filter,
                      FunctionRef<bool(ShapeId shape, const CollisionPlane& plane)> callback) const;
    /// How far along `translation` (a fraction in [0, 1]) the mover (a capsule in world
    /// coordinates) can go before it hits a shape it moves into. A shape it starts touching
    /// or slides along (the hit normal not against the motion) does not stop it, so a mover
    /// resting on the ground can walk.
    Real CastMover(const Capsule& mover, Vec2 translation, QueryFilter filter = {}) const;
    /// One move of a kinematic character (the mover, a capsule in world coordinates) with
    /// `velocity` (m/s) over `dt` (s, > 0), as meff/mover.h lays it out: CollideMover at the
    /// target, SolvePlanes, CastMover towards the solved goal, ClipVector. Allocates nothing;
    /// gathers at most kMaxMoverPlanes planes. The filter must leave out the mover's own
    /// shape if it has one in the world.
    CharacterMove MoveCharacter(const Capsule& mover, Vec2 velocity, Real dt,
                                QueryFilter filter = {}) const;
    /// The closest hit of CastShape.
    RayResult CastShapeClosest(const Capsule& shape, const Transform& start, Vec2 translation,
                               QueryFilter filter = {}) const;
    /// The closest hit of CastShape, for a circle.
    RayResult CastShapeClosest(const Circle& shape, const Transform& start, Vec2 translation,
                               QueryFilter filter = {}) const;
    /// The closest hit of CastShape, for a polygon.
    RayResult CastShapeClosest(const Polygon& shape, const Transform& start, Vec2 translation,
                               QueryFilter filter = {}) const;

    /// The shape's bounding box at its body's current transform, skin included (m).
    AABB GetShapeAABB(ShapeId id) const;
    /// The shape's box in the broad phase: the bounding box fattened by the back end's margin
    /// (and, in Box2D's back end, stretched along the motion: OverlapAABB), as the broad phase
    /// last updated it (m).
    /// OverlapAABB tests these.
    AABB GetShapeFatAABB(ShapeId id) const;

    // Determinism and rollback
    /// A 64-bit FNV-1a hash of every live body's transform, centre of mass, velocities, awake
    /// flag and rest time and every contact's impulses, bit for bit: equal hashes step after step
    /// show two runs identical.
    std::uint64_t GetStateHash() const;
    /// Copies the whole world state. Stepping on from RestoreSnapshot(s) is bit-identical to
    /// stepping on from the moment s was saved. Throws InvalidArgument during a step (from the
    /// pre-solve callback or the custom filter): half a step is no state to step on from.
    WorldSnapshot SaveSnapshot() const;
    /// Returns the world to a snapshot of itself. Ids saved with the snapshot are valid again;
    /// ids created later are not. Throws InvalidArgument for an empty snapshot.
    void RestoreSnapshot(const WorldSnapshot& snapshot);
    /// Contacts whose shapes touch (a subset of GetContactCount's).
    int GetTouchingContactCount() const;

    // Drawing
    /// Describes the world to `draw` (shapes, joints and, from the last step's reports,
    /// contacts and impulses), as `flags` asks. Draws nothing itself. Drawing contacts builds
    /// the reports if they are not built yet (see GetContactReports): not thread-safe. DebugDraw's
    /// methods are refused what a query's callback is (above).
    void Draw(DebugDraw& draw, const DrawFlags& flags = {}) const;

  private:
    /// The state; throws InvalidArgument for a world that was moved from.
    detail::WorldState& State();
    const detail::WorldState& State() const;

    std::unique_ptr<detail::WorldState> m_state;
};

} // namespace meff
