// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Cross-validation of meff against Box2D 2.4.1: the same scene stepped in both engines in
// lockstep, compared frame by frame.
//
// What is compared after every step (all in double, from each engine's float state):
//   position   |Δp| of the body origin (m), the Euclidean distance between the two engines
//   angle      |Δθ| (rad)
//   velocity   max(|Δv|, |Δω|): the linear velocity of the centre of mass (m/s, Euclidean) and
//              the angular velocity (rad/s), both judged against the one velocity tolerance
//   contact    every contact point's normal and tangent impulse (N·s), points matched by the
//   impulse    unordered pair of shapes (scene body and shape index) plus the manifold point's
//              feature key; a point one engine has and the other lacks is counted, and its
//              impulse is compared against zero
//   joint      reaction force × dt (N·s, Euclidean) and reaction torque × dt (N·m·s), as
//   impulse    GetReactionForce/GetReactionTorque(1/dt) in Box2D and World::GetReaction in meff
// An impulse passes when |Δ| ≤ max(impulse, impulseRelative × |Box2D's value|), the other
// quantities when |Δ| ≤ their tolerance. The first frame where anything fails is the
// divergence frame.
#pragma once

#include "meff/scene.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace meff::validation
{

/// One body's state after a step, from either engine.
struct BodySample
{
    double x = 0; ///< body origin (m)
    double y = 0;
    double angle = 0; ///< rad
    double vx = 0;    ///< centre of mass velocity (m/s)
    double vy = 0;
    double angularVelocity = 0; ///< rad/s
    bool awake = true;          ///< IsAwake (static bodies: false in both engines)
};

/// Which contact point: the two shapes, by scene body index and shape index within the body,
/// and the manifold point's feature key. A and B as the engine ordered them.
struct ContactKey
{
    std::size_t bodyA = 0;
    std::size_t shapeA = 0;
    std::size_t bodyB = 0;
    std::size_t shapeB = 0;
    std::uint32_t featureKey = 0;
    /// Which segment of a chain shape (Box2D's child index); 0 for every other shape.
    std::size_t childA = 0;
    std::size_t childB = 0;
};

/// One contact point's impulses over the last step (Box2D's PostSolve data).
struct ContactSample
{
    ContactKey key;
    double normalImpulse = 0;  ///< N·s
    double tangentImpulse = 0; ///< N·s
};

/// One joint's reaction on body B over the last step.
struct JointSample
{
    double fx = 0; ///< N
    double fy = 0;
    double torque = 0; ///< N·m
};

/// Everything compared after one step. bodies[i] is scene.bodies[i], joints[j] scene.joints[j].
struct FrameSample
{
    std::vector<BodySample> bodies;
    std::vector<ContactSample> contacts;
    std::vector<JointSample> joints;
};

/// The limits of agreement (from the scene's "validate.tolerances").
struct Tolerances
{
    double position = 1e-4;        ///< m
    double angle = 1e-4;           ///< rad
    double velocity = 1e-3;        ///< m/s and rad/s
    double impulse = 1e-3;         ///< N·s
    double impulseRelative = 1e-3; ///< fraction of Box2D's impulse
};

Tolerances TolerancesOf(const SceneTolerances& scene);

/// The comparison of one frame. Indices are scene indices; -1 where nothing was compared.
struct FrameErrors
{
    int frame = 0; ///< 0 is the initial state, k the state after step k

    double position = 0; ///< m
    int positionBody = -1;
    double angle = 0; ///< rad
    int angleBody = -1;
    double linearVelocity = 0;  ///< m/s
    double angularVelocity = 0; ///< rad/s
    double velocity = 0;        ///< max of the two
    int velocityBody = -1;

    double contactImpulse = 0; ///< largest |Δ| of a normal or tangent impulse (N·s)
    /// Largest |Δ| / allowance over the contact points (> 1 fails); the impulse allowance is
    /// max(impulse, impulseRelative × |Box2D's impulse|).
    double contactRatio = 0;
    std::optional<ContactKey> contact; ///< the point holding contactImpulse
    int contactPointsMeff = 0;
    int contactPointsBox2D = 0;
    int onlyInMeff = 0;      ///< points meff has and Box2D lacks
    int onlyInBox2D = 0;     ///< points Box2D has and meff lacks
    int awakeMismatches = 0; ///< bodies awake in one engine and asleep in the other

    double jointImpulse = 0; ///< largest |ΔF|·dt or |ΔT|·dt (N·s, N·m·s)
    double jointRatio = 0;   ///< largest |Δ| / allowance over the joints
    int joint = -1;

    /// Which quantities exceeded their tolerance: "position", "angle", "velocity",
    /// "contact_impulse", "joint_impulse", and "awake" (no tolerance: any mismatch).
    std::vector<std::string> exceeded;
    bool Exceeds() const { return !exceeded.empty(); }
};

/// Compares meff's frame with Box2D's. Both must describe the same scene (same body and joint
/// counts). `dt` turns reaction forces into impulses.
FrameErrors CompareFrames(const FrameSample& meff, const FrameSample& box2d, double dt,
                          const Tolerances& tolerances, int frame = 0);

/// One quantity that exceeded its tolerance at the divergence frame, with both engines' values
/// there: what a CI report shows about a failed scene.
struct DivergenceDetail
{
    /// "position", "angle", "velocity", "contact_impulse", "joint_impulse" or "awake".
    std::string quantity;
    std::string where; ///< the body, contact point or joint (DescribeBody/Contact/Joint)
    std::string meff;  ///< meff's value with its unit, e.g. "(1.25, 0.5) m"
    std::string box2d; ///< Box2D's value, the same way
    double error = 0;  ///< the difference compared (the tolerance's unit; awake: 1)
    /// The allowance it exceeded (impulses: the larger of the absolute and relative ones).
    double tolerance = 0;
};

/// Describes each quantity `errors` says exceeded, from the two engines' samples of that frame.
std::vector<DivergenceDetail> DescribeDivergence(const Scene& scene, const FrameErrors& errors,
                                                 const FrameSample& meff, const FrameSample& box2d,
                                                 double dt, const Tolerances& tolerances);

/// What may differ from the scene for one run.
struct RunOptions
{
    std::optional<int> frames;       ///< overrides scene.world.frames
    std::optional<bool> blockSolver; ///< overrides scene.world.solver.blockSolver in both engines
    /// meff only, to prove the comparison can fail: its velocity iterations (Box2D keeps the
    /// scene's).
    std::optional<int> meffVelocityIterations;
};

/// One maximum over a run, and where it happened.
struct RunMaximum
{
    double value = 0;
    int frame = -1;    ///< -1: never above zero
    std::string where; ///< the body, contact or joint holding it
};

/// The settled-state checks ("validate.settle", meant for chaotic scenes), on the last frame.
struct SettleResult
{
    bool passed = true;
    double position = 0; ///< largest |Δp| of a body (m)
    std::string positionBody;
    double angle = 0; ///< largest |Δθ| (rad)
    std::string angleBody;
    std::optional<double> lowestHeight; ///< lowest dynamic body origin in meff (m)
    std::string lowestBody;
    std::vector<std::string> failures; ///< one line per failed check
};

/// A check beside the frame-by-frame comparison that did not hold (a back end's own
/// invariants, say): it fails the scene, and every report carries it.
struct CheckFailure
{
    std::string check;                ///< what was checked: the JUnit failure type
    std::string message;              ///< one line
    std::vector<std::string> details; ///< the evidence, one line each (may be empty)
};

struct ValidationResult
{
    std::string scene;      ///< scene name
    std::string sourcePath; ///< the file
    /// What meff was compared with, as the reports name it: "Box2D" (2.4.1, Validate) or
    /// "baseline" (a recorded run of meff, CompareWithBaseline in meff/baseline.h).
    std::string reference = "Box2D";
    int frames = 0;          ///< steps compared
    Tolerances tolerances;   ///< used
    bool blockSolver = true; ///< as run in both engines
    int meffVelocityIterations = 0;
    int box2dVelocityIterations = 0;
    bool chaotic = false;
    int horizonFrames = 0; ///< chaotic scenes: frames that had to agree

    std::vector<FrameErrors> perFrame; ///< frames 0..frames (0 is the initial state)
    std::optional<int> divergenceFrame;
    std::vector<std::string> divergenceQuantities;   ///< what exceeded at the divergence frame
    std::vector<DivergenceDetail> divergenceDetails; ///< the same, with both engines' values

    RunMaximum position;
    RunMaximum angle;
    RunMaximum velocity;
    RunMaximum contactImpulse;
    RunMaximum jointImpulse;
    long long onlyInMeff = 0; ///< contact points over the run
    long long onlyInBox2D = 0;
    long long awakeMismatches = 0; ///< body-frames whose awake flags differ

    std::optional<SettleResult> settle;
    /// The scene's settings Box2D 2.4.1 cannot mirror ("world.solver \"colour\"",
    /// "world.restitution_from_step_start", "world.block_joints false"), when they change this
    /// scene's results. Then the run is judged by what can be compared: frame 0 must agree,
    /// and the settled state (the scene's validate.settle, or its defaults); unless the scene
    /// is declared chaotic, which is judged as it says.
    std::vector<std::string> unmirrored;
    std::vector<std::string> notes; ///< what the mirror cannot reproduce, and other warnings
    std::string failure;            ///< a simulation that stopped (non-finite state), or empty
    /// Extra checks that failed (AddCheckFailure); each fails the scene.
    std::vector<CheckFailure> checkFailures;
    /// The comparison with Box2D held (frame by frame, or as the notes say); `passed` also
    /// needs every extra check to hold and the simulation to run to its end.
    bool comparisonPassed = false;
    bool passed = false;
};

/// Records a failed extra check on a result; the scene then fails.
void AddCheckFailure(ValidationResult& result, CheckFailure failure);

/// What the scene uses that Box2D 2.4.1 has no form of at all (Box2D v3's shapes, joint
/// springs and character mover; rolling resistance): one message per field, naming it. A scene
/// with any cannot be validated: Validate refuses it (these are documented, so a run of many
/// levels skips it rather than failing).
std::vector<std::string> Unmirrorable(const Scene& scene);

/// Builds both worlds from the scene, steps them in lockstep and compares every frame.
/// Throws SceneError when the scene cannot be built or is Unmirrorable.
ValidationResult Validate(const Scene& scene, const RunOptions& options = {});

/// The same point in both engines: the same unordered pair of shapes and the same feature key.
bool SameContactPoint(const ContactKey& a, const ContactKey& b);

/// "ball" for a body; "ball[1]/ground[0] key 0x10003" for a contact point.
std::string DescribeBody(const Scene& scene, int body);
std::string DescribeContact(const Scene& scene, const ContactKey& key);
std::string DescribeJoint(const Scene& scene, int joint);

} // namespace meff::validation
