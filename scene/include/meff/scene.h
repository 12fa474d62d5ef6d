// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Scene files: a whole simulation setup described once, in JSON, and run by meff, by the Box2D
// validation mirror, by the renderer and by the benchmarks. The format is documented field by
// field in docs/scene-format.md.
//
// Numbers are kept as double, exactly as written in the file, so that every consumer converts
// them to its own scalar type the same way (meff's Real and Box2D's float agree bit for bit).
#pragma once

#include "meff/body.h"
#include "meff/error.h"
#include "meff/ids.h"
#include "meff/joint.h"
#include "meff/world.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace meff
{

/// The only version of the format there is; files say so in "meff_scene".
inline constexpr int kSceneFormatVersion = 1;

/// A point or vector as written in a scene file: [x, y].
struct SceneVec2
{
    double x = 0;
    double y = 0;

    friend bool operator==(const SceneVec2&, const SceneVec2&) = default;
};

/// "world": gravity, time step and solver settings.
struct SceneWorldSettings
{
    SceneVec2 gravity{0, -10}; ///< m/s²
    double dt = 1.0 / 60.0;    ///< s, > 0
    int frames = 240;          ///< steps to run, ≥ 0
    /// "solver" (the back end) and the solver's fields, as the engine takes them: the world is
    /// built with exactly these (velocity iterations 1..1000, position iterations 0..1000).
    SolverSettings solver{};
    bool allowSleep = false; ///< let resting islands sleep (Box2D's rules)
    bool continuous = false; ///< Box2D's continuous physics (time of impact)
    /// "last_step_inv_dt": 1/dt of the step before a saved world was saved
    /// (World::GetLastStepInverseDt), which scales its first step's warm start; 0 for a world
    /// that had not stepped (its first step starts cold).
    double lastStepInverseDt = 0;

    friend bool operator==(const SceneWorldSettings&, const SceneWorldSettings&) = default;
};

enum class SceneShapeType
{
    Circle,
    Box,
    Polygon,
    Segment,
    Chain,
    Capsule,
};

/// "filter": which shapes may collide (see meff::Filter).
struct SceneFilter
{
    std::uint16_t category = 0x0001;
    std::uint16_t mask = 0xFFFF;
    std::int16_t group = 0;

    friend bool operator==(const SceneFilter&, const SceneFilter&) = default;
};

/// One entry of a body's "shapes". Only the geometry fields of its type are meaningful.
struct SceneShape
{
    SceneShapeType type = SceneShapeType::Circle;
    // circle and capsule
    double radius = 0; ///< m, > 0
    // circle and box
    SceneVec2 center; ///< body coordinates (m)
    // box
    double halfWidth = 0;  ///< m, > 0
    double halfHeight = 0; ///< m, > 0
    double angle = 0;      ///< rad, the box's turn within the body
    /// box and polygon: the file's "radius", rounding it (Box2D v3's rounded polygon): 0 for
    /// sharp corners, else above the polygon skin (0.01 m)
    double rounding = 0;
    // polygon: the corners of a convex polygon, body coordinates (m), any order
    std::vector<SceneVec2> vertices;
    // capsule: the centres of its two caps, body coordinates (m)
    SceneVec2 centerA;
    SceneVec2 centerB;
    // segment: its two ends, body coordinates (m)
    SceneVec2 point1;
    SceneVec2 point2;
    /// segment: one-sided, with ghosts `prev` and `next` (meff::ChainSegment)
    bool oneSided = false;
    // chain: its points in order, body coordinates (m)
    std::vector<SceneVec2> points;
    bool loop = false; ///< chain: closed, the last point joined to the first
    /// One-sided segment and open chain: the ghost vertices before the first point and after
    /// the last (m), resolved by the loader (the file's, or the end segments continued in
    /// straight lines); unset for a loop and for a two-sided segment.
    std::optional<SceneVec2> prev;
    std::optional<SceneVec2> next;
    // material
    double density = 1;              ///< kg/m², ≥ 0
    double friction = 0.6;           ///< ≥ 0
    double restitution = 0;          ///< [0, 1]
    double restitutionThreshold = 1; ///< m/s, ≥ 0
    double tangentSpeed = 0;         ///< m/s, conveyor belt (ShapeDef::tangentSpeed)
    double rollingResistance = 0;    ///< ≥ 0 (ShapeDef::rollingResistance)
    SceneFilter filter;
    bool sensor = false;

    friend bool operator==(const SceneShape&, const SceneShape&) = default;
};

/// One entry of "bodies".
struct SceneBody
{
    std::string name;
    BodyType type = BodyType::Static;
    SceneVec2 position;         ///< world position of the body origin (m)
    double angle = 0;           ///< rad
    SceneVec2 linearVelocity;   ///< m/s
    double angularVelocity = 0; ///< rad/s
    double linearDamping = 0;   ///< 1/s, ≥ 0
    double angularDamping = 0;  ///< 1/s, ≥ 0
    double gravityScale = 1;
    bool fixedRotation = false;
    bool bullet = false;
    bool allowSleep = true;         ///< may sleep, when the world allows sleeping
    bool awake = true;              ///< false: starts asleep (dynamic and kinematic bodies)
    std::vector<SceneShape> shapes; ///< in file order, which is also creation order

    friend bool operator==(const SceneBody&, const SceneBody&) = default;
};

/// One entry of "joints". Anchors are world points at creation. Only the fields of its type
/// are meaningful.
struct SceneJoint
{
    JointType type = JointType::Revolute;
    std::string name;
    std::string bodyA;          ///< name as written
    std::string bodyB;          ///< name as written
    std::size_t bodyIndexA = 0; ///< index into Scene::bodies
    std::size_t bodyIndexB = 0; ///< index into Scene::bodies
    bool collideConnected = false;
    // revolute, prismatic, wheel, weld, friction; mouse: the grabbed point on body B (limit and
    // motor fields are shared by revolute, prismatic and wheel)
    SceneVec2 anchor; ///< world point (m)
    bool enableLimit = false;
    double lowerAngle = 0; ///< rad, ≤ upperAngle
    double upperAngle = 0; ///< rad
    bool enableMotor = false;
    double motorSpeed = 0;     ///< rad/s (revolute, wheel) or m/s along the axis (prismatic)
    double maxMotorTorque = 0; ///< N·m, ≥ 0 (revolute, wheel)
    // revolute and prismatic: Box2D v3's joint spring (its stiffnessHz and dampingRatio below)
    bool enableSpring = false;
    double targetAngle = 0;       ///< rad (revolute)
    double targetTranslation = 0; ///< m along the axis (prismatic)
    // prismatic and wheel
    SceneVec2 axis{1, 0};        ///< world direction of the slide (non-zero)
    double lowerTranslation = 0; ///< m along the axis from the anchor, ≤ upperTranslation
    double upperTranslation = 0; ///< m
    double maxMotorForce = 0;    ///< N, ≥ 0 (prismatic)
    // distance (stiffnessHz and dampingRatio also set a wheel's suspension); pulley
    SceneVec2 anchorA;      ///< world point on body A (m)
    SceneVec2 anchorB;      ///< world point on body B (m)
    double length = 0;      ///< m, > 0; the file's value or the distance between the anchors
    double minLength = 0;   ///< m; the file's value or `length`
    double maxLength = 0;   ///< m; the file's value or `length`
    double stiffnessHz = 0; ///< Hz, ≥ 0; 0 = no spring (distance, weld, mouse, revolute, prismatic)
    double dampingRatio = 0; ///< ≥ 0 (distance, weld, mouse, revolute, prismatic)
    // revolute, prismatic, wheel, weld, distance, friction: the anchors in the bodies' own frames,
    // as Box2D's joint definitions and b2dJson files hold them, instead of world points
    bool localAnchors = false; ///< true: localAnchorA/B hold the anchors (anchor is unused)
    SceneVec2 localAnchorA;    ///< body A's frame (m)
    SceneVec2 localAnchorB;    ///< body B's frame (m)
    /// prismatic, wheel: the axis in body A's frame (non-zero); unset: `axis`, a world direction
    std::optional<SceneVec2> localAxisA;
    /// revolute, prismatic, weld: angleB − angleA where the joint angle is zero (rad); unset:
    /// the bodies' relative angle at creation
    std::optional<double> referenceAngle;
    // motor
    std::optional<SceneVec2> linearOffset; ///< B's origin in A's frame (m); unset: as created
    std::optional<double> angularOffset;   ///< angleB − angleA (rad); unset: as created
    double maxTorque = 1;                  ///< N·m, ≥ 0 (also friction's; its default 0)
    double correctionFactor = 0.3;         ///< in [0, 1]
    // motor, mouse, friction
    double maxForce = 1; ///< N, ≥ 0 (friction's default 0)
    // mouse
    SceneVec2 target; ///< world point body B's anchor is dragged towards (m)
    // pulley (its anchors on the bodies are anchorA and anchorB, world points)
    SceneVec2 groundAnchorA; ///< fixed world point body A's side hangs from (m)
    SceneVec2 groundAnchorB; ///< fixed world point body B's side hangs from (m)
    double ratio = 1;        ///< > 0: lengthA + ratio·lengthB is kept (pulley); gear: finite
    // gear: the two joints it couples (revolute or prismatic, earlier in the list); its bodies
    // A and B are their bodies B (bodyIndexA/B and bodyA/B are filled in from them)
    std::string jointA;          ///< name as written
    std::string jointB;          ///< name as written
    std::size_t jointIndexA = 0; ///< index into Scene::joints
    std::size_t jointIndexB = 0; ///< index into Scene::joints
    /// "impulses": the impulses the joint had accumulated when its world was saved
    /// (World::GetJointImpulses, JointImpulseCount(type) of them), which warm-start its first
    /// step; empty: none (a joint starts without impulses).
    std::vector<double> impulses;

    friend bool operator==(const SceneJoint&, const SceneJoint&) = default;
};

/// "validate.tolerances": how far meff may drift from Box2D before validation fails.
struct SceneTolerances
{
    double position = 1e-4; ///< m
    double angle = 1e-4;    ///< rad
    double velocity = 1e-3; ///< m/s and rad/s
    double impulse = 1e-3;  ///< N·s
    /// Impulses also pass when within this fraction of Box2D's value (whichever allows more).
    double impulseRelative = 1e-3;

    friend bool operator==(const SceneTolerances&, const SceneTolerances&) = default;
};

/// "validate.settle": checks of the final frame, for chaotic scenes.
struct SceneSettleCheck
{
    double position = 0.05;              ///< m: every body's final position vs Box2D's
    std::optional<double> angle;         ///< rad: every body's final angle vs Box2D's
    std::optional<double> minimumHeight; ///< m: no dynamic body's origin ends below this y

    friend bool operator==(const SceneSettleCheck&, const SceneSettleCheck&) = default;
};

/// "validate" beyond tolerances: how a chaotic scene (stacks, pyramids: round-off grows until
/// the two engines part) is judged. Frame by frame up to the horizon, then the settled state.
struct SceneValidation
{
    bool chaotic = false;  ///< "chaotic"
    int horizonFrames = 0; ///< "horizon_frames": frames that must agree (chaotic scenes)
    std::optional<SceneSettleCheck> settle; ///< "settle"

    friend bool operator==(const SceneValidation&, const SceneValidation&) = default;
};

/// "plausibility.rest": the scene comes to rest, so that its last frames are checked for it.
struct ScenePlausibilityRest
{
    double after = 0;    ///< s: from this time on, every dynamic body is checked (≥ 0)
    double speed = 0.05; ///< m/s: the most any point of a dynamic body may move then (≥ 0)

    friend bool operator==(const ScenePlausibilityRest&, const ScenePlausibilityRest&) = default;
};

/// "plausibility.hold": the scene holds its shape (a structure built to stand, a settled stack), so
/// that no dynamic body may move far from where it was once `after` has passed.
struct ScenePlausibilityHold
{
    double after = 0;    ///< s: where every dynamic body is at this time is its place (≥ 0)
    double distance = 0; ///< m: the furthest any dynamic body's centre of mass may move from it
                         ///< later (≥ 0; required in the file)

    friend bool operator==(const ScenePlausibilityHold&, const ScenePlausibilityHold&) = default;
};

/// "plausibility": the thresholds of the physics checks every back end is held to (no NaN,
/// energy, rebound, joint gaps, penetration, speed, rest, hold),
/// meff::validation::CheckPlausibility and docs/validation.md. Each field has a default; a scene
/// sets the ones it needs.
struct ScenePlausibility
{
    /// Energy may grow beyond the work done on the scene by at most this fraction of the
    /// largest kinetic energy of the run ("energy_gain") ...
    double energyGain = 0.05;
    /// ... plus every dynamic body lifted this far against gravity, and moving at
    /// `energySpeed` ("energy_lift", m; "energy_speed", m/s).
    double energyLift = 0.02;
    double energySpeed = 0.05;
    /// A body that hits a static body faster than `reboundApproach` (m/s) where restitution
    /// is 0 may leave it at most this fast (m/s) ("rebound_speed", "rebound_approach").
    double reboundSpeed = 0.25;
    double reboundApproach = 1.0;
    /// The deepest overlap any contact may report (m) ("penetration").
    double penetration = 0.05;
    /// The largest joint gap (anchors apart, or a rod off its length) over the last second
    /// of the run (m) ("joint_gap").
    double jointGap = 0.05;
    /// The fastest any point of a dynamic body may move (m/s), unchecked when absent
    /// ("max_speed").
    std::optional<double> maxSpeed;
    /// How far any dynamic body's centre of mass may rise above where it started, against
    /// gravity (m), unchecked when absent ("max_rise").
    std::optional<double> maxRise;
    std::optional<ScenePlausibilityRest> rest; ///< "rest": absent, not checked
    std::optional<ScenePlausibilityHold> hold; ///< "hold": absent, not checked

    friend bool operator==(const ScenePlausibility&, const ScenePlausibility&) = default;
};

/// "render.camera": what the renderer shows.
struct SceneCamera
{
    SceneVec2 center;   ///< world point at the middle of the image (m)
    double height = 10; ///< world height the image spans (m), > 0

    friend bool operator==(const SceneCamera&, const SceneCamera&) = default;
};

/// What "analytic" says the exact answer is.
enum class SceneAnalyticKind
{
    Pendulum, ///< one body swinging on one joint from a static body
    Cradle,   ///< a Newton's cradle: balls on rods, the first released, all collisions elastic
    Bounce,   ///< a ball dropped on flat ground, rebounding by its restitution
};

/// "analytic": the scene has an exact answer (computed by `meff sweep`, which measures each
/// setting's error against it; scenes without one are compared with a converged run).
struct SceneAnalytic
{
    SceneAnalyticKind kind = SceneAnalyticKind::Pendulum;
    /// Pendulum: its one joint ("joint"). Cradle: the rods in order along the row, the
    /// released ball's first ("joints"). Indices into Scene::joints; body A of each is static.
    std::vector<std::size_t> joints;
    std::size_t body = 0;     ///< bounce: the ball ("body"), index into Scene::bodies
    double contactHeight = 0; ///< bounce: height of its centre of mass when touching (m)

    friend bool operator==(const SceneAnalytic&, const SceneAnalytic&) = default;
};

/// One entry of a character's "inputs": what the player does from `time` on.
struct SceneCharacterInput
{
    double time = 0;            ///< s, ≥ 0, not before the previous input's
    std::optional<double> walk; ///< horizontal speed held from now on (m/s)
    std::optional<double> jump; ///< vertical speed given once, now (m/s)

    friend bool operator==(const SceneCharacterInput&, const SceneCharacterInput&) = default;
};

/// One entry of "characters": a kinematic body carrying one capsule, moved every step by the
/// character mover (World::MoveCharacter) under gravity and its inputs, as a game moves its
/// player. BuiltScene::Step drives it.
struct SceneCharacter
{
    std::string name;
    std::string body;                        ///< the body's name
    std::size_t bodyIndex = 0;               ///< index into Scene::bodies
    std::vector<SceneCharacterInput> inputs; ///< in time order

    friend bool operator==(const SceneCharacter&, const SceneCharacter&) = default;
};

/// A loaded, validated scene with every default filled in.
struct Scene
{
    std::string sourcePath;  ///< the file it came from, for messages
    std::string name;        ///< "name", or the file name without ".json"
    std::string description; ///< "description", or empty
    SceneWorldSettings world;
    std::vector<SceneBody> bodies;
    std::vector<SceneJoint> joints;
    std::vector<SceneCharacter> characters;
    SceneTolerances tolerances;
    SceneValidation validation;
    std::optional<SceneCamera> camera;     ///< absent: the renderer chooses
    std::optional<SceneAnalytic> analytic; ///< absent: no exact answer is known
    ScenePlausibility plausibility;        ///< "plausibility": the checks' thresholds
    /// What was accepted but does nothing, as Box2D accepts it (a joint between two bodies
    /// that cannot move): "FILE: FIELD.PATH: warning: MESSAGE", for the user to see.
    std::vector<std::string> warnings;

    /// Index into bodies of the body with this name, or nullopt.
    std::optional<std::size_t> FindBody(std::string_view bodyName) const;
    /// Index into joints of the joint with this name, or nullopt.
    std::optional<std::size_t> FindJoint(std::string_view jointName) const;

    /// Every field equal (sourcePath included).
    friend bool operator==(const Scene&, const Scene&) = default;
};

/// A scene that cannot be used. messages() holds every problem found, one line each, in the
/// form "FILE: FIELD.PATH: MESSAGE, got VALUE"; what() is all of them joined by newlines.
class SceneError : public Error
{
  public:
    explicit SceneError(std::vector<std::string> messages);
    const std::vector<std::string>& messages() const { return m_messages; }

  private:
    std::vector<std::string> m_messages;
};

/// The largest scene file LoadScene reads (bytes), by default (SceneLimits::fileBytes).
inline constexpr std::size_t kMaxSceneFileBytes = std::size_t(64) << 20;

/// What a scene may hold. Each is checked before the memory for it is taken (the file's size
/// before it is read, the counts as soon as the JSON is parsed, before any body is read or
/// built; the pairs before the first step) and refused with SceneError "FILE: FIELD: N THINGS,
/// more than the limit of M (raise it with --max-THINGS)", the option of the `meff` tool that
/// sets it. A 10 MB level of 100,000 bodies took 1.4 GB to import; 3,000 circles at one point
/// (4.5 million pairs) 2.7 GB and 90 s for two steps.
struct SceneLimits
{
    std::size_t fileBytes = kMaxSceneFileBytes; ///< --max-file-size (MiB in the tool)
    std::size_t bodies = 50'000;                ///< --max-bodies
    std::size_t shapes = 100'000;               ///< --max-shapes (a chain counts once)
    std::size_t joints = 50'000;                ///< --max-joints
    /// --max-pairs: pairs of shapes on different bodies, one of them dynamic, whose boxes
    /// overlap where the scene starts (the contacts of its first step, before filters).
    std::size_t pairs = 250'000;
};

/// Reads and validates a scene file. Throws SceneError listing every problem found.
Scene LoadScene(const std::string& path, const SceneLimits& limits = {});
/// The same for text already in memory; `sourcePath` only names it in messages and gives the
/// default scene name.
Scene ParseScene(std::string_view text, const std::string& sourcePath,
                 const SceneLimits& limits = {});

/// A world built from a scene, with the ids of everything in it in scene order.
/// A character as BuiltScene::Step drives it (SceneCharacter): its script and the mover's
/// state between steps.
struct BuiltCharacter
{
    BodyId body{};
    Capsule capsule{};    ///< in the body's coordinates (m)
    QueryFilter filter{}; ///< its capsule's category and mask: what the mover finds
    Real gravityScale = 1;
    std::vector<SceneCharacterInput> inputs{};
    std::size_t nextInput = 0; ///< the first input not yet acted on
    Real walk = 0;             ///< the horizontal speed held (m/s)
    Vec2 velocity{};           ///< the mover's velocity (m/s)
};

struct BuiltScene
{
    World world;
    std::vector<BodyId> bodies{}; ///< bodies[i] is scene.bodies[i]
    /// shapes[i][k] is scene.bodies[i].shapes[k]; for a chain, its first segment.
    std::vector<std::vector<ShapeId>> shapes{};
    /// chains[i][k] is the chain scene.bodies[i].shapes[k] made; null for other shapes.
    std::vector<std::vector<ChainId>> chains{};
    std::vector<JointId> joints{}; ///< joints[j] is scene.joints[j]
    std::unordered_map<std::string, BodyId> bodyByName{};
    std::unordered_map<std::string, JointId> jointByName{};
    std::vector<BuiltCharacter> characters{}; ///< characters[c] is scene.characters[c]

    /// One frame: moves each character by its inputs, gravity and World::MoveCharacter (its
    /// body's velocity set to carry it there), then World::Step(dt). Every tool steps a scene
    /// through this, so that a scene behaves the same in run, render, bench and sweep.
    void Step(Real dt);

    /// The scene index of a body given its id or its pool index (BodyId::index, also
    /// SimulationError::bodyIndex), or nullopt for a body the scene did not create.
    std::optional<std::size_t> SceneIndexOf(BodyId id) const;
    std::optional<std::size_t> SceneIndexOfPoolIndex(std::int32_t poolIndex) const;

    /// Scene index by BodyId::index; -1 where no scene body lives.
    std::vector<std::ptrdiff_t> sceneIndexByPoolIndex{};
};

/// Creates the scene's world, bodies, shapes and joints. Throws SceneError if the engine
/// refuses something the loader let through (a scene that did not come from LoadScene).
BuiltScene BuildWorld(const Scene& scene);

/// What SceneFromWorld cannot learn from the world: the file's name and run length, and what
/// to call the bodies and joints.
struct SceneFromWorldOptions
{
    std::string name = "world"; ///< Scene::name
    double dt = 1.0 / 60.0;     ///< world.dt (s, > 0): the step the world is run with
    int frames = 240;           ///< world.frames: how many steps `meff run` takes
    /// The scene name of each body (unique names of 1 to 64 characters from A-Z a-z 0-9 _ - .);
    /// empty, or an empty answer: "body" and its place in World::GetBodies ("body0", ...).
    std::function<std::string(BodyId)> bodyName{};
    /// The same for joints ("joint0", ... by their place in World::GetJoints).
    std::function<std::string(JointId)> jointName{};
};

/// The world as it is now, as a scene: its settings (gravity, the solver back end and all its
/// settings, sleeping, continuous collision), every body in creation order (type, pose,
/// velocities, damping, gravity scale, flags, awake state) with its shapes in creation order
/// (geometry, material, filter, sensor; a box made by MakeBox or MakeOffsetBox as a "box", a
/// chain as one "chain") and every joint in creation order, in the bodies' frames (local
/// anchors and axes, reference angles, limits, motors, springs, offsets; World::GetJointDef)
/// with its accumulated impulses (World::GetJointImpulses). Built with BuildWorld, it gives the
/// same world; stepping on from it is bit-identical to stepping the original when nothing a
/// scene cannot hold matters at that moment: no contact touches (their warm start is not in
/// the file), and see docs/api-guide.md, "Saving a world as a scene", for the rest (rest times
/// towards sleep, a gear's or pulley's drift, a centre of mass off its body's origin, to the
/// last bit). Shapes' user data and hit-event flags, bodies' user data and forces applied since
/// the last step are left out. Throws SceneError for what a scene cannot say at all: tolerances
/// other than the defaults, a name `options` gives twice or malformed.
Scene SceneFromWorld(const World& world, const SceneFromWorldOptions& options = {});

/// A built scene's world as it is now (SceneFromWorld), keeping the scene's name, names of
/// bodies and joints, dt, frames, description and its validate, plausibility and render
/// sections; not its analytic answer, which holds from the scene's start. Throws SceneError
/// for a scene with characters: their mover's state lives in BuiltScene, not in the world.
Scene SceneFromBuilt(const BuiltScene& built, const Scene& scene);

/// The world a snapshot holds, as a scene (SceneFromWorld); throws InvalidArgument for an
/// empty snapshot.
Scene SceneFromSnapshot(const WorldSnapshot& snapshot, const SceneFromWorldOptions& options = {});

/// The scene as a meff scene file (docs/scene-format.md), which LoadScene reads back as the same
/// scene (sourcePath and warnings aside): every number as the shortest decimal that reads back
/// as the same double (a zero's sign kept), every field that differs from its default, and
/// always the fields that say what a body or joint is. Write it whole or not at all (the `meff`
/// tool does: `meff run --save-at`).
std::string WriteScene(const Scene& scene);

} // namespace meff
