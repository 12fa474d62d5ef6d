// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// `meff sweep`: what accuracy each solver setting buys and what it costs, in meff and in the
// Box2D 2.4.1 mirror, over a grid of settings.
//
// The grid (a full cross product of the five axes would be 6×4×5×2×2 = 480 settings, most of
// them telling nothing new) is:
//   iterations×dt  velocity iterations {1,2,4,8,16,32} × rate {30,60,120,240,480} Hz, with
//                  3 position iterations, block solver and warm starting on (30 settings);
//   position×dt    position iterations {0,1,8} × the five rates, 8 velocity iterations
//                  (15; 3 is in the first group);
//   block_off      block solver off at the five rates, 8/3 iterations (5);
//   warm_off       warm starting off at the five rates, 8/3 iterations (5);
//   colour         meff's colour back end at the five rates, 8/3 iterations (5; meff only);
//   soft_step      meff's soft step at its defaults but for substeps {1,2,4,8} × rates
//                  {30,60,120,240} (16; meff only);
//   soft_stiffness the soft step at 60 Hz and 4 substeps with joint stiffness {18,36,72} Hz
//                  (3; 72 is the default and in the group above only by its substeps).
// Box2D 2.4.1 has neither the colour order nor the soft step, so those settings are run by
// meff alone; each back end is its own "engine" in sweep.csv (meff, meff_colour,
// meff_soft_step, box2d) with its own Pareto front.
// Every setting runs the same simulated time (--seconds, 4 s by default), so a finer dt takes
// proportionally more steps. --quick runs 12 settings (9 in both engines, 3 by meff alone)
// over 2 s, for tests.
//
// Each setting is run once to measure (untimed: the measuring would disturb the timing), then
// --runs times to time, each timed run repeating the simulation until it has taken 20 ms.
// Cost is the median time of the steps after the first (which builds the broad phase and
// every contact, as `meff bench` times it apart), per simulated second: wall time, and this
// thread's CPU time of the same runs, both in sweep.csv; --cost chooses which one the plot and
// the printed Pareto fronts use (CPU time on a shared machine, where other processes' turns on
// the core inflate wall time and make it vary from run to run). The Box2D mirror is timed
// without a contact listener, as a game that needs no PostSolve data runs it; meff always
// builds its contact reports, so this favours Box2D a little.
//
// Error, in metres: against the scene's exact answer when it has an "analytic" section (see
// docs/scene-format.md), else against a converged reference run of the same scene by meff:
// dt/8 of the smallest in the grid, 64 velocity and 16 position iterations, in meff's own
// scalar type (float unless built with -DMEFF_DOUBLE=ON; a double reference would need that
// second build). Positions are compared at the centres of mass, every 1/30 s (a time every dt
// of the grid steps onto exactly).
#include "commands.h"
#include "output_file.h"
#include "parallel.h"
#include "plot_program.h"
#include "progress.h"
#include "threads_option.h"

#include "meff/analytic.h"
#include "meff/box2d_mirror.h"
#include "meff/box2d_v3_features.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <time.h>
#include <unistd.h>

#ifndef MEFF_SWEEP_PLOT_SCRIPT
#define MEFF_SWEEP_PLOT_SCRIPT ""
#endif

namespace meff::cli
{

namespace
{

/// Positions are compared at this rate: every rate of the grid is a multiple of it.
constexpr int kSampleHz = 30;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct SweepOptions
{
    std::string scenePath;
    std::string outDir;
    bool quick = false;
    std::optional<double> seconds;
    std::optional<int> runs;
    bool noPlot = false;
    std::string cost = "wall";
    /// Settings measured at once. 1 by default, unlike validate's: the costs are timings, and
    /// runs sharing the cores time each other's turns (the errors are the same for every N).
    int jobs = 1;
    /// Threads each meff world steps on (--threads); Box2D 2.4.1 steps on one.
    int threads = 1;
    Shard shard;
    /// Only the settings of this back end (Box2D's rows run in both engines).
    std::optional<SolverKind> solver;
};

struct Setting
{
    std::string group;
    int velocityIterations = 8;
    int positionIterations = 3;
    int hz = 60;
    bool blockSolver = true;
    bool warmStarting = true;
    SolverKind solver = SolverKind::Box2D; ///< meff's back end; Box2D runs only Box2D's
    int substeps = 4;                      ///< soft step only (SoftStepSettings::substeps)
    double jointHertz = 72;                ///< Hz, soft step only (SoftStepSettings::jointHertz)
};

/// The name of the meff row of a setting: one "engine" per back end.
std::string MeffEngineName(const Setting& setting)
{
    return setting.solver == SolverKind::Box2D
               ? std::string("meff")
               : std::string("meff_") + SolverKindName(setting.solver);
}

std::vector<Setting> MakeGrid(bool quick)
{
    std::vector<Setting> grid;
    const auto add = [&](const char* group, int velocity, int position, int hz, bool block,
                         bool warm) {
        grid.push_back({group, velocity, position, hz, block, warm});
    };
    const auto addColour = [&](int hz) {
        grid.push_back({"colour", 8, 3, hz, true, true, SolverKind::Colour});
    };
    const auto addSoft = [&](const char* group, int hz, int substeps, double jointHertz) {
        grid.push_back({group, 8, 3, hz, true, true, SolverKind::SoftStep, substeps, jointHertz});
    };
    if (quick)
    {
        for (const int velocity : {2, 8})
        {
            for (const int hz : {30, 60, 120})
            {
                add("iterations_dt", velocity, 3, hz, true, true);
            }
        }
        add("position_dt", 8, 0, 60, true, true);
        add("block_off", 8, 3, 60, false, true);
        add("warm_off", 8, 3, 60, true, false);
        addColour(60);
        addSoft("soft_step", 60, 1, 72);
        addSoft("soft_step", 60, 4, 72);
        return grid;
    }
    const int rates[] = {30, 60, 120, 240, 480};
    for (const int velocity : {1, 2, 4, 8, 16, 32})
    {
        for (const int hz : rates)
        {
            add("iterations_dt", velocity, 3, hz, true, true);
        }
    }
    for (const int position : {0, 1, 8})
    {
        for (const int hz : rates)
        {
            add("position_dt", 8, position, hz, true, true);
        }
    }
    for (const int hz : rates)
    {
        add("block_off", 8, 3, hz, false, true);
    }
    for (const int hz : rates)
    {
        add("warm_off", 8, 3, hz, true, false);
    }
    for (const int hz : rates)
    {
        addColour(hz);
    }
    for (const int substeps : {1, 2, 4, 8})
    {
        for (const int hz : {30, 60, 120, 240})
        {
            addSoft("soft_step", hz, substeps, 72);
        }
    }
    for (const double jointHertz : {18.0, 36.0, 72.0})
    {
        addSoft("soft_stiffness", 60, 4, jointHertz);
    }
    return grid;
}

/// The scene with one setting's world settings (the rest as the file says).
Scene WithSetting(const Scene& scene, const Setting& setting)
{
    Scene copy = scene;
    copy.world.dt = 1.0 / setting.hz;
    copy.world.solver.velocityIterations = setting.velocityIterations;
    copy.world.solver.positionIterations = setting.positionIterations;
    copy.world.solver.blockSolver = setting.blockSolver;
    copy.world.solver.warmStarting = setting.warmStarting;
    copy.world.solver.kind = setting.solver;
    copy.world.solver.softStep.substeps = setting.substeps;
    copy.world.solver.softStep.jointHertz = Real(setting.jointHertz);
    return copy;
}

using analytic::Vec2d;

Vec2d operator-(Vec2d a, Vec2d b)
{
    return {a.x - b.x, a.y - b.y};
}

double Length(Vec2d v)
{
    return std::hypot(v.x, v.y);
}

double Cross(Vec2d a, Vec2d b)
{
    return a.x * b.y - a.y * b.x;
}

/// What the measurements need of a body, in either engine, in double.
struct BodyState
{
    bool dynamic = false;
    Vec2d center;   ///< centre of mass (m)
    Vec2d velocity; ///< of the centre of mass (m/s)
    double angularVelocity = 0;
    double mass = 0;
    double inertia = 0; ///< about the centre of mass (kg·m²)
};

/// One engine stepping one scene: meff.
class MeffEngine
{
  public:
    MeffEngine(const Scene& scene, TaskSystem* threads)
        : m_built(BuildWorld(scene)), m_dt(static_cast<Real>(scene.world.dt))
    {
        m_built.world.SetTaskSystem(threads);
    }

    void Step() { m_built.Step(m_dt); }

    BodyState Body(std::size_t i) const
    {
        const World& world = m_built.world;
        const BodyId id = m_built.bodies[i];
        const Vec2 c = world.GetWorldCenter(id);
        const Vec2 v = world.GetLinearVelocity(id);
        return {world.GetType(id) == BodyType::Dynamic,
                {c.x, c.y},
                {v.x, v.y},
                world.GetAngularVelocity(id),
                world.GetMass(id),
                world.GetRotationalInertia(id)};
    }

    /// The smallest separation of the last step's contact points (+inf without contacts).
    double MinSeparation() const
    {
        double smallest = kInfinity;
        for (const ContactPointReport& report : m_built.world.GetContactReports())
        {
            smallest = std::min(smallest, double(report.separation));
        }
        return smallest;
    }

    double AnchorDistance(std::size_t j) const
    {
        const Vec2 a = m_built.world.GetAnchorA(m_built.joints[j]);
        const Vec2 b = m_built.world.GetAnchorB(m_built.joints[j]);
        return std::hypot(double(b.x) - double(a.x), double(b.y) - double(a.y));
    }

  private:
    BuiltScene m_built;
    Real m_dt;
};

/// One engine stepping one scene: the Box2D 2.4.1 mirror.
class Box2DEngine
{
  public:
    /// Box2D 2.4.1 steps on one thread: `threads` is not used.
    Box2DEngine(const Scene& scene, TaskSystem* /*threads*/) : m_mirror(scene)
    {
        // No PostSolve listener: the sweep reads contacts from the contact list itself, and a
        // game that needs no impulses runs Box2D this way.
        m_mirror.World().SetContactListener(nullptr);
    }

    void Step() { m_mirror.Step(); }

    BodyState Body(std::size_t i) const
    {
        const b2Body* body = m_mirror.Body(i);
        const b2Vec2 c = body->GetWorldCenter();
        const b2Vec2 v = body->GetLinearVelocity();
        const b2Vec2 local = body->GetLocalCenter();
        const double mass = body->GetMass();
        // b2Body::GetInertia is about the body origin; move it to the centre of mass.
        const double inertia = double(body->GetInertia()) -
                               mass * (double(local.x) * local.x + double(local.y) * local.y);
        return {body->GetType() == b2_dynamicBody, {c.x, c.y}, {v.x, v.y},
                body->GetAngularVelocity(),        mass,       inertia};
    }

    /// As meff's ContactPointReport::separation: each touching contact's manifold (from the
    /// step's collision) evaluated at the bodies' transforms after the step.
    double MinSeparation()
    {
        double smallest = kInfinity;
        for (b2Contact* contact = m_mirror.World().GetContactList(); contact != nullptr;
             contact = contact->GetNext())
        {
            if (!contact->IsTouching() || !contact->IsEnabled() ||
                contact->GetFixtureA()->IsSensor() || contact->GetFixtureB()->IsSensor())
            {
                continue;
            }
            b2WorldManifold manifold;
            contact->GetWorldManifold(&manifold);
            for (int32 k = 0; k < contact->GetManifold()->pointCount; ++k)
            {
                smallest = std::min(smallest, double(manifold.separations[k]));
            }
        }
        return smallest;
    }

    double AnchorDistance(std::size_t j) const
    {
        const b2Joint* joint = m_mirror.Joint(j);
        const b2Vec2 a = joint->GetAnchorA();
        const b2Vec2 b = joint->GetAnchorB();
        return std::hypot(double(b.x) - double(a.x), double(b.y) - double(a.y));
    }

  private:
    validation::Box2DMirror m_mirror;
};

/// What one measured run saw.
struct Trace
{
    bool failed = false;
    std::string failure;
    /// centers[k][i]: body i's centre of mass at time k/kSampleHz, k = 0 … seconds·kSampleHz.
    std::vector<std::vector<Vec2d>> centers;
    /// Every frame (0 … frames) of the body the error model follows frame by frame (bounce).
    std::vector<BodyState> followed;
    double maxPenetration = 0; ///< m, the most negative contact separation, as a depth ≥ 0
    double jointDrift = 0;     ///< m, the largest joint error (see JointError)
    double energyDrift = 0;    ///< J, max over frames of |E − E(0)|
    double energyChange = 0;   ///< J, E(end) − E(0)
    double initialEnergy = 0;  ///< J, E(0), potential energy from y = 0 of the world
};

/// How far a joint is from satisfied: a revolute or weld joint's anchors should coincide; a
/// distance joint's should be between its minimum and maximum length apart. Prismatic and wheel
/// joints let their anchors part along the axis, so the anchor distance says nothing about them;
/// motor and mouse joints are force-limited springs with no hard constraint; friction joints
/// hold no pose; a pulley's anchors part as the rope runs; a gear's anchors are its joints'. Those
/// are not measured (0).
double JointError(const SceneJoint& joint, double anchorDistance)
{
    switch (joint.type)
    {
    case JointType::Revolute:
    case JointType::Weld:
        return anchorDistance;
    case JointType::Distance:
        return std::max({0.0, anchorDistance - joint.maxLength, joint.minLength - anchorDistance});
    case JointType::Prismatic:
    case JointType::Wheel:
    case JointType::Motor:
    case JointType::Mouse:
    case JointType::Friction:
    case JointType::Pulley:
    case JointType::Gear:
        return 0.0;
    }
    return 0.0;
}

/// Kinetic plus gravitational potential energy of the dynamic bodies (the potential measured
/// from y = 0 along the world's gravity).
template <typename Engine>
double Energy(const Scene& scene, const Engine& engine)
{
    double energy = 0;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    {
        const BodyState body = engine.Body(i);
        if (!body.dynamic)
        {
            continue;
        }
        const double scale = scene.bodies[i].gravityScale;
        const double gx = scene.world.gravity.x * scale;
        const double gy = scene.world.gravity.y * scale;
        energy += 0.5 * body.mass *
                      (body.velocity.x * body.velocity.x + body.velocity.y * body.velocity.y) +
                  0.5 * body.inertia * body.angularVelocity * body.angularVelocity -
                  body.mass * (gx * body.center.x + gy * body.center.y);
    }
    return energy;
}

struct RunLength
{
    int frames = 0;          ///< steps of the whole run
    int framesPerSample = 0; ///< steps between two position samples
};

RunLength LengthOf(const Scene& scene, double seconds)
{
    const int hz = static_cast<int>(std::lround(1.0 / scene.world.dt));
    return {static_cast<int>(std::lround(seconds * hz)), hz / kSampleHz};
}

/// Runs the scene once, measuring everything at every frame. `followed` is the scene index of
/// the body to record frame by frame, if any.
template <typename Engine>
Trace Measure(const Scene& scene, TaskSystem* threads, double seconds,
              std::optional<std::size_t> followed)
{
    Trace trace;
    const RunLength length = LengthOf(scene, seconds);
    Engine engine(scene, threads);
    const auto sample = [&]
    {
        std::vector<Vec2d>& centers = trace.centers.emplace_back();
        for (std::size_t i = 0; i < scene.bodies.size(); ++i)
        {
            centers.push_back(engine.Body(i).center);
        }
    };
    sample();
    if (followed)
    {
        trace.followed.push_back(engine.Body(*followed));
    }
    trace.initialEnergy = Energy(scene, engine);
    double energy = trace.initialEnergy;
    try
    {
        for (int frame = 1; frame <= length.frames; ++frame)
        {
            engine.Step();
            trace.maxPenetration = std::max(trace.maxPenetration, -engine.MinSeparation());
            for (std::size_t j = 0; j < scene.joints.size(); ++j)
            {
                trace.jointDrift = std::max(trace.jointDrift,
                                            JointError(scene.joints[j], engine.AnchorDistance(j)));
            }
            energy = Energy(scene, engine);
            trace.energyDrift = std::max(trace.energyDrift, std::abs(energy - trace.initialEnergy));
            if (followed)
            {
                trace.followed.push_back(engine.Body(*followed));
            }
            if (frame % length.framesPerSample == 0)
            {
                sample();
            }
            if (!std::isfinite(energy))
            {
                // Box2D does not stop on a non-finite state as meff does; the run is lost.
                throw SimulationError("a body's state is not finite", std::uint64_t(frame - 1), -1);
            }
        }
    }
    catch (const SimulationError& error)
    {
        trace.failed = true;
        trace.failure = error.what();
    }
    trace.energyChange = energy - trace.initialEnergy;
    return trace;
}

/// A timed run repeats the simulation until its steps have taken at least this long, so that
/// a tiny scene's cost is not one scheduler tick's noise.
constexpr double kMinimumTimedMs = 20;

/// This thread's CPU time (ms): unlike wall time, it leaves out the time other processes on a
/// shared machine had the core.
double ThreadCpuMs()
{
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return now.tv_sec * 1e3 + now.tv_nsec * 1e-6;
}

struct Timing
{
    double wall = kNaN; ///< ms of wall time per simulated second
    double cpu = kNaN;  ///< ms of this thread's CPU time per simulated second
};

/// The steps after the first, per simulated second.
template <typename Engine>
Timing TimeRun(const Scene& scene, TaskSystem* threads, double seconds)
{
    using Clock = std::chrono::steady_clock;
    const RunLength length = LengthOf(scene, seconds);
    if (length.frames < 2)
    {
        return {};
    }
    double wallMs = 0;
    double cpuMs = 0;
    int repetitions = 0;
    while (wallMs < kMinimumTimedMs)
    {
        Engine engine(scene, threads);
        engine.Step();
        const Clock::time_point start = Clock::now();
        const double cpuStart = ThreadCpuMs();
        for (int frame = 2; frame <= length.frames; ++frame)
        {
            engine.Step();
        }
        cpuMs += ThreadCpuMs() - cpuStart;
        wallMs += std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        ++repetitions;
    }
    const double simulated = repetitions * (length.frames - 1) * scene.world.dt;
    return {wallMs / simulated, cpuMs / simulated};
}

// ---------------------------------------------------------------------------------------------
// The exact answers

/// A rigid pendulum's exact motion (meff/analytic.h), sampled at kSampleHz and integrated at a
/// step 500 times finer than the sampling (67 µs).
analytic::PendulumMotion PendulumSolution(double k, double psi0, double omega0, int samples)
{
    constexpr int kSubsteps = 500;
    return analytic::PendulumMotion(k, psi0, omega0, 1.0 / kSampleHz, kSubsteps, samples);
}

/// One error measure: the error of a run, in metres.
class ErrorModel
{
  public:
    virtual ~ErrorModel() = default;
    virtual const char* Kind() const = 0;
    virtual double Error(const Trace& trace) const = 0;
    /// The body the model follows frame by frame, if any.
    virtual std::optional<std::size_t> Followed() const { return std::nullopt; }
};

/// Expected positions of some bodies at every sample; the error is the largest distance from
/// them over the run.
class PositionsModel : public ErrorModel
{
  public:
    PositionsModel(const char* kind, std::vector<std::size_t> bodies,
                   std::vector<std::vector<Vec2d>> expected)
        : m_kind(kind), m_bodies(std::move(bodies)), m_expected(std::move(expected))
    {
    }

    const char* Kind() const override { return m_kind; }

    double Error(const Trace& trace) const override
    {
        if (trace.failed || trace.centers.size() != m_expected.size())
        {
            return kNaN;
        }
        double worst = 0;
        for (std::size_t k = 0; k < m_expected.size(); ++k)
        {
            for (std::size_t n = 0; n < m_bodies.size(); ++n)
            {
                worst = std::max(worst, Length(trace.centers[k][m_bodies[n]] - m_expected[k][n]));
            }
        }
        return worst;
    }

  private:
    const char* m_kind;
    std::vector<std::size_t> m_bodies;          ///< scene indices
    std::vector<std::vector<Vec2d>> m_expected; ///< [sample][n] for body m_bodies[n]
};

/// Gravity on a body, and the unit vector along it ("down").
struct Gravity
{
    double magnitude = 0;
    Vec2d down{0, -1};
};

Gravity GravityOn(const Scene& scene, std::size_t body)
{
    const double scale = scene.bodies[body].gravityScale;
    const Vec2d g{scene.world.gravity.x * scale, scene.world.gravity.y * scale};
    const double magnitude = Length(g);
    if (magnitude == 0)
    {
        return {};
    }
    return {magnitude, {g.x / magnitude, g.y / magnitude}};
}

/// A pendulum on one of the scene's joints: pivot, rod length and ψ'' = −k sin ψ, from the
/// world the scene builds (mass and inertia as the engine computes them).
struct PendulumSetup
{
    std::size_t body = 0;
    Vec2d pivot;
    Vec2d down;
    double length = 0; ///< pivot to centre of mass (m)
    double k = 0;      ///< 1/s²
    double psi0 = 0;
    double omega0 = 0;
};

PendulumSetup SetUpPendulum(const Scene& scene, const BuiltScene& built, std::size_t jointIndex)
{
    const SceneJoint& joint = scene.joints[jointIndex];
    const std::string where = scene.name + ": analytic: joint " + joint.name + ": ";
    PendulumSetup setup;
    setup.body = joint.bodyIndexB;
    const SceneBody& body = scene.bodies[setup.body];
    if (body.type != BodyType::Dynamic || body.linearDamping != 0 || body.angularDamping != 0)
    {
        throw std::invalid_argument(where + "body_b must be dynamic and undamped");
    }
    const World& world = built.world;
    const BodyId id = built.bodies[setup.body];
    const Vec2 c = world.GetWorldCenter(id);
    const Vec2 v = world.GetLinearVelocity(id);
    const Vec2d center{c.x, c.y};
    const double mass = world.GetMass(id);
    double inertia = 0; // about the pivot
    if (joint.type == JointType::Revolute)
    {
        if (joint.enableLimit || joint.enableMotor)
        {
            throw std::invalid_argument(where + "a free pendulum has no limit and no motor");
        }
        setup.pivot = {joint.anchor.x, joint.anchor.y};
        setup.length = Length(center - setup.pivot);
        // Pinned: the body turns with the rod.
        inertia = world.GetRotationalInertia(id) + mass * setup.length * setup.length;
    }
    else
    {
        if (joint.minLength != joint.length || joint.maxLength != joint.length ||
            joint.stiffnessHz != 0)
        {
            throw std::invalid_argument(where + "a distance joint must be a rigid rod");
        }
        if (Length(Vec2d{joint.anchorB.x, joint.anchorB.y} - center) > 1e-6 * joint.length)
        {
            throw std::invalid_argument(where + "anchor_b must be at body_b's centre of mass");
        }
        setup.pivot = {joint.anchorA.x, joint.anchorA.y};
        setup.length = joint.length;
        // On a rod to its centre the body spins freely: it swings as a point mass.
        inertia = mass * setup.length * setup.length;
    }
    const Gravity gravity = GravityOn(scene, setup.body);
    setup.down = gravity.down;
    setup.k = mass * gravity.magnitude * setup.length / inertia;
    const Vec2d r = center - setup.pivot;
    setup.psi0 = std::atan2(Cross(setup.down, r), setup.down.x * r.x + setup.down.y * r.y);
    setup.omega0 = joint.type == JointType::Revolute
                       ? double(world.GetAngularVelocity(id))
                       : Cross(r, Vec2d{v.x, v.y}) / (setup.length * setup.length);
    return setup;
}

int SampleCount(double seconds)
{
    return static_cast<int>(std::lround(seconds * kSampleHz));
}

std::unique_ptr<ErrorModel> PendulumModel(const Scene& scene, double seconds)
{
    const BuiltScene built = BuildWorld(scene);
    const PendulumSetup p = SetUpPendulum(scene, built, scene.analytic->joints.at(0));
    const int samples = SampleCount(seconds);
    const analytic::PendulumMotion solution = PendulumSolution(p.k, p.psi0, p.omega0, samples);
    std::vector<std::vector<Vec2d>> expected;
    for (int k = 0; k <= samples; ++k)
    {
        expected.push_back({analytic::OnRod(p.pivot, p.down, p.length, solution.Angle(k))});
    }
    return std::make_unique<PositionsModel>("analytic:pendulum", std::vector<std::size_t>{p.body},
                                            expected);
}

/// The ideal cradle (analytic::CradleBallAngle) on the scene's rods, the first ball released.
std::unique_ptr<ErrorModel> CradleModel(const Scene& scene, double seconds)
{
    const BuiltScene built = BuildWorld(scene);
    std::vector<PendulumSetup> balls;
    std::vector<std::size_t> bodies;
    for (const std::size_t joint : scene.analytic->joints)
    {
        if (scene.joints[joint].type != JointType::Distance)
        {
            throw std::invalid_argument(scene.name + ": analytic: a cradle's rods must be "
                                                     "distance joints");
        }
        balls.push_back(SetUpPendulum(scene, built, joint));
        bodies.push_back(balls.back().body);
    }
    const PendulumSetup& first = balls.front();
    const PendulumSetup& last = balls.back();
    if (std::abs(first.length - last.length) > 1e-6 * first.length ||
        std::abs(first.k - last.k) > 1e-6 * first.k)
    {
        throw std::invalid_argument(scene.name + ": analytic: the first and last rods of a "
                                                 "cradle must be equal");
    }
    const int samples = SampleCount(seconds);
    const analytic::PendulumMotion solution =
        PendulumSolution(first.k, first.psi0, first.omega0, samples);
    std::vector<std::vector<Vec2d>> expected;
    for (int k = 0; k <= samples; ++k)
    {
        const double psi = solution.Angle(k);
        std::vector<Vec2d>& row = expected.emplace_back();
        for (std::size_t n = 0; n < balls.size(); ++n)
        {
            const PendulumSetup& ball = balls[n];
            row.push_back(
                analytic::OnRod(ball.pivot, ball.down, ball.length,
                                analytic::CradleBallAngle(n, balls.size(), first.psi0, psi)));
        }
    }
    return std::make_unique<PositionsModel>("analytic:cradle", bodies, expected);
}

/// A ball dropped on flat ground (analytic::BounceApexes). The error is the largest difference
/// of the rebound heights (the highest centre of mass between two bounces) from the exact ones,
/// over the rebounds whose top the exact motion reaches within the run.
class BounceModel : public ErrorModel
{
  public:
    BounceModel(const Scene& scene, double seconds) : m_body(scene.analytic->body)
    {
        const SceneBody& body = scene.bodies[m_body];
        const Gravity gravity = GravityOn(scene, m_body);
        if (gravity.magnitude == 0 || gravity.down.x != 0 || body.shapes.empty())
        {
            throw std::invalid_argument(scene.name + ": analytic: a bounce needs gravity "
                                                     "along -y and a ball with a shape");
        }
        // Box2D mixes restitution by the larger and the threshold by the smaller: the ground is
        // taken to have no more restitution than the ball and no lower threshold.
        const double e = body.shapes.front().restitution;
        const double threshold = body.shapes.front().restitutionThreshold;
        const double g = gravity.magnitude;
        const BuiltScene built = BuildWorld(scene);
        const double y0 = built.world.GetWorldCenter(built.bodies[m_body]).y;
        const double v0 = built.world.GetLinearVelocity(built.bodies[m_body]).y;
        m_contactHeight = scene.analytic->contactHeight;
        m_apexes = analytic::BounceApexes(e, threshold, g, y0, v0, m_contactHeight, seconds);
    }

    const char* Kind() const override { return "analytic:bounce"; }
    std::optional<std::size_t> Followed() const override { return m_body; }

    double Error(const Trace& trace) const override
    {
        if (trace.failed)
        {
            return kNaN;
        }
        // A bounce is where the vertical velocity turns from down to up; the rebound height is
        // the highest point before the next one.
        std::vector<double> apexes;
        for (std::size_t f = 1; f < trace.followed.size(); ++f)
        {
            const BodyState& before = trace.followed[f - 1];
            const BodyState& now = trace.followed[f];
            if (before.velocity.y < 0 && now.velocity.y >= 0)
            {
                apexes.push_back(now.center.y);
            }
            else if (!apexes.empty())
            {
                apexes.back() = std::max(apexes.back(), now.center.y);
            }
        }
        double worst = 0;
        for (std::size_t n = 0; n < m_apexes.size(); ++n)
        {
            // A rebound that never happened counts as one that did not rise at all.
            const double seen = n < apexes.size() ? apexes[n] : m_contactHeight;
            worst = std::max(worst, std::abs(seen - m_apexes[n]));
        }
        return worst;
    }

    const std::vector<double>& Apexes() const { return m_apexes; }

  private:
    std::size_t m_body;
    double m_contactHeight = 0;
    std::vector<double> m_apexes; ///< exact rebound heights of the centre of mass (m)
};

/// No exact answer: every dynamic body against a converged run of meff.
std::unique_ptr<ErrorModel> ReferenceModel(const Scene& scene, const Trace& reference)
{
    std::vector<std::size_t> bodies;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    {
        if (scene.bodies[i].type == BodyType::Dynamic)
        {
            bodies.push_back(i);
        }
    }
    std::vector<std::vector<Vec2d>> expected;
    for (const std::vector<Vec2d>& centers : reference.centers)
    {
        std::vector<Vec2d>& row = expected.emplace_back();
        for (const std::size_t i : bodies)
        {
            row.push_back(centers[i]);
        }
    }
    return std::make_unique<PositionsModel>("reference", bodies, expected);
}

// ---------------------------------------------------------------------------------------------
// The sweep

struct Row
{
    std::string engine;
    std::string precision;
    Setting setting;
    int frames = 0;
    int runs = 0;
    std::vector<double> msPerSecond;    ///< wall time, one per timed run
    std::vector<double> cpuMsPerSecond; ///< CPU time, one per timed run
    double cost = kNaN;                 ///< median of msPerSecond
    double cpuCost = kNaN;              ///< median of cpuMsPerSecond
    double error = kNaN;
    Trace trace;
};

double Median(std::vector<double> values)
{
    if (values.empty())
    {
        return kNaN;
    }
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::string Describe(const Setting& s)
{
    char text[96];
    if (s.solver == SolverKind::SoftStep)
    {
        std::snprintf(text, sizeof text, "soft step %d substeps %3d Hz joints %g Hz", s.substeps,
                      s.hz, s.jointHertz);
        return text;
    }
    std::snprintf(text, sizeof text, "%sv%-2d p%d %3d Hz block %-3s warm %-3s",
                  s.solver == SolverKind::Colour ? "colour " : "", s.velocityIterations,
                  s.positionIterations, s.hz, s.blockSolver ? "on" : "off",
                  s.warmStarting ? "on" : "off");
    return text;
}

/// A setting must beat every cheaper one's error by this fraction to be on the Pareto front:
/// settings whose errors differ only in round-off (the pendulum's error does not depend on
/// the iteration counts, but its last digits do) would otherwise all be on it.
constexpr double kFrontMargin = 0.01;

/// Indices of the rows on the Pareto front of (cost, error): every cheaper row's error is more
/// than kFrontMargin higher. Sorted by cost.
std::vector<std::size_t> ParetoFront(const std::vector<Row>& rows, const std::string& engine,
                                     bool cpu)
{
    const auto cost = [&](std::size_t r) { return cpu ? rows[r].cpuCost : rows[r].cost; };
    std::vector<std::size_t> order;
    for (std::size_t r = 0; r < rows.size(); ++r)
    {
        if (rows[r].engine == engine && std::isfinite(rows[r].error) && std::isfinite(cost(r)))
        {
            order.push_back(r);
        }
    }
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return cost(a) < cost(b); });
    std::vector<std::size_t> front;
    double best = kInfinity;
    for (const std::size_t r : order)
    {
        if (rows[r].error < (1 - kFrontMargin) * best)
        {
            front.push_back(r);
            best = rows[r].error;
        }
    }
    return front;
}

void WriteNumber(std::FILE* out, double value)
{
    if (std::isfinite(value))
    {
        std::fprintf(out, ",%.6g", value);
    }
    else
    {
        std::fputs(",nan", out);
    }
}

constexpr const char* kCsvHeader =
    "scene,engine,precision,group,velocity_iterations,position_iterations,hz,dt,block_solver,"
    "warm_starting,seconds,frames,runs,ms_per_sim_s,ms_per_sim_s_min,ms_per_sim_s_max,"
    "ms_per_step,cpu_ms_per_sim_s,error_kind,error_m,max_penetration_m,joint_drift_m,energy_drift_"
    "j,"
    "energy_drift_rel,energy_change_j,status,solver,substeps,joint_hertz\n";

void WriteCsv(std::FILE* out, const Scene& scene, const char* errorKind, double seconds,
              const std::vector<Row>& rows)
{
    std::fputs(kCsvHeader, out);
    for (const Row& row : rows)
    {
        const Setting& s = row.setting;
        std::fprintf(out, "%s,%s,%s,%s,%d,%d,%d,%.9g,%d,%d,%g,%d,%d", scene.name.c_str(),
                     row.engine.c_str(), row.precision.c_str(), s.group.c_str(),
                     s.velocityIterations, s.positionIterations, s.hz, 1.0 / s.hz,
                     s.blockSolver ? 1 : 0, s.warmStarting ? 1 : 0, seconds, row.frames, row.runs);
        const auto [low, high] =
            std::minmax_element(row.msPerSecond.begin(), row.msPerSecond.end());
        WriteNumber(out, row.cost);
        WriteNumber(out, *low);
        WriteNumber(out, *high);
        WriteNumber(out, row.cost / s.hz);
        WriteNumber(out, row.cpuCost);
        std::fprintf(out, ",%s", errorKind);
        WriteNumber(out, row.error);
        WriteNumber(out, row.trace.maxPenetration);
        WriteNumber(out, row.trace.jointDrift);
        WriteNumber(out, row.trace.energyDrift);
        WriteNumber(out, row.trace.initialEnergy != 0
                             ? row.trace.energyDrift / std::abs(row.trace.initialEnergy)
                             : kNaN);
        WriteNumber(out, row.trace.energyChange);
        // The failure text may hold commas: the status column keeps only its kind.
        std::fprintf(out, ",%s,%s,%d,%g\n", row.trace.failed ? "failed" : "ok",
                     row.engine == "box2d" ? "box2d" : SolverKindName(s.solver), s.substeps,
                     s.jointHertz);
    }
}

/// Draws DIR/pareto.png with validation/plot_sweep.py; false when it could not.
bool Plot(const std::filesystem::path& directory, const std::string& csvPath,
          const std::string& title, const std::string& cost)
{
    const std::string script = MEFF_SWEEP_PLOT_SCRIPT;
    const std::string python = FindPlottingPython();
    if (python.empty())
    {
        std::fprintf(stderr, "meff sweep: no plot: no python3 with matplotlib found (install "
                             "python3-matplotlib, or set MEFF_PYTHON); sweep.csv is written\n");
        return false;
    }
    if (script.empty())
    {
        return false;
    }
    const std::filesystem::path png = directory / "pareto.png";
    const std::filesystem::path temporary = directory / (".pareto.png." + std::to_string(getpid()));
    std::error_code error;
    if (RunProgram({python, script, csvPath, temporary.string(), "--title", title, "--cost", cost},
                   false) != 0)
    {
        std::filesystem::remove(temporary, error);
        std::fprintf(stderr, "meff sweep: the plot could not be drawn (%s)\n", script.c_str());
        return false;
    }
    std::filesystem::rename(temporary, png, error);
    if (error)
    {
        std::filesystem::remove(temporary, error);
        throw std::runtime_error("cannot write " + png.string() + ": " + error.message());
    }
    return true;
}

template <typename Engine>
Row RunSetting(const Scene& scene, TaskSystem* threads, const Setting& setting, const char* engine,
               double seconds, const ErrorModel& model)
{
    Row row;
    row.engine = engine;
    row.precision =
        std::string(engine) == "box2d" || sizeof(Real) == sizeof(float) ? "float" : "double";
    row.setting = setting;
    row.frames = LengthOf(scene, seconds).frames;
    row.trace = Measure<Engine>(scene, threads, seconds, model.Followed());
    row.error = model.Error(row.trace);
    return row;
}

template <typename Engine>
void TimeSetting(const Scene& scene, TaskSystem* threads, double seconds, Row& row)
{
    if (row.trace.failed)
    {
        return; // a run that blows up has no cost worth quoting
    }
    const Timing timing = TimeRun<Engine>(scene, threads, seconds);
    row.msPerSecond.push_back(timing.wall);
    row.cpuMsPerSecond.push_back(timing.cpu);
    ++row.runs;
}

int RunSweep(const SweepOptions& options)
{
    std::optional<Scene> loaded = LoadSceneOrReport(options.scenePath);
    if (!loaded)
    {
        return kExitBadInput;
    }
    const Scene& scene = *loaded;
    const double seconds = options.seconds.value_or(options.quick ? 2.0 : 4.0);
    const int runs = options.runs.value_or(options.quick ? 1 : 3);
    if (std::abs(seconds * kSampleHz - std::round(seconds * kSampleHz)) > 1e-9 ||
        seconds * kSampleHz < 1)
    {
        std::fprintf(stderr, "meff sweep: --seconds must be a whole number of 1/%d s, got %g\n",
                     kSampleHz, seconds);
        return kExitBadInput;
    }
    std::vector<Setting> grid = MakeGrid(options.quick);
    if (options.solver)
    {
        std::erase_if(grid,
                      [&](const Setting& setting) { return setting.solver != *options.solver; });
    }
    const std::filesystem::path directory = options.outDir.empty()
                                                ? std::filesystem::path("out/sweep") / scene.name
                                                : std::filesystem::path(options.outDir);
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error)
    {
        std::fprintf(stderr, "meff sweep: cannot create %s: %s\n", directory.string().c_str(),
                     error.message().c_str());
        return kExitBadInput;
    }
    std::optional<OutputFile> csv;
    try
    {
        csv.emplace((directory / "sweep.csv").string());
    }
    catch (const std::exception& failure)
    {
        std::fprintf(stderr, "meff sweep: %s\n", failure.what());
        return kExitBadInput;
    }

    // The error model: the scene's exact answer, or a converged reference run.
    std::unique_ptr<ErrorModel> model;
    try
    {
        if (scene.analytic)
        {
            switch (scene.analytic->kind)
            {
            case SceneAnalyticKind::Pendulum:
                model = PendulumModel(scene, seconds);
                break;
            case SceneAnalyticKind::Cradle:
                model = CradleModel(scene, seconds);
                break;
            case SceneAnalyticKind::Bounce:
            {
                auto bounce = std::make_unique<BounceModel>(scene, seconds);
                std::printf("%s: exact rebound heights within %g s:", scene.name.c_str(), seconds);
                for (const double apex : bounce->Apexes())
                {
                    std::printf(" %.4f m", apex);
                }
                std::printf("\n");
                model = std::move(bounce);
                break;
            }
            }
            std::printf("%s: error against the exact answer (%s), %g s simulated\n",
                        scene.name.c_str(), model->Kind(), seconds);
        }
        else
        {
            int fastest = 0;
            for (const Setting& setting : grid)
            {
                fastest = std::max(fastest, setting.hz);
            }
            const Setting settings{"reference",
                                   64,
                                   16,
                                   8 * fastest,
                                   scene.world.solver.blockSolver,
                                   scene.world.solver.warmStarting};
            const Scene referenceScene = WithSetting(scene, settings);
            const auto start = std::chrono::steady_clock::now();
            // The reference steps in Box2D's order (the setting's default back end), which
            // takes no threads.
            const Trace reference =
                Measure<MeffEngine>(referenceScene, nullptr, seconds, std::nullopt);
            if (reference.failed)
            {
                std::fprintf(stderr, "meff sweep: %s: the reference run failed: %s\n",
                             scene.name.c_str(), reference.failure.c_str());
                return kExitRunFailed;
            }
            model = ReferenceModel(scene, reference);
            std::printf(
                "%s: error against a reference run of meff (%s): %d Hz, 64 velocity and "
                "16 position iterations, %g s simulated, in %.1f s; its max penetration "
                "%.3g m, joint drift %.3g m, energy drift %.3g J\n",
                scene.name.c_str(), sizeof(Real) == sizeof(float) ? "float" : "double", settings.hz,
                seconds,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                reference.maxPenetration, reference.jointDrift, reference.energyDrift);
        }
    }
    catch (const std::invalid_argument& failure)
    {
        std::fprintf(stderr, "meff sweep: %s\n", failure.what());
        return kExitBadInput;
    }

    // What Box2D 2.4.1 cannot run (Box2D v3's shapes, springs, characters) is swept by meff
    // alone: a mirror without it would be another scene.
    const std::vector<std::string> lacking =
        FieldsBox2D241Lacks(scene, "so every row of this sweep is meff's alone");
    const bool box2dCanRun = lacking.empty();
    if (!box2dCanRun)
    {
        std::printf("%s (%zu such field(s))\n", lacking.front().c_str(), lacking.size());
    }
    const bool cpu = options.cost == "cpu";
    std::printf("%zu settings (%s); cost: ms of %s time per simulated second, "
                "median of %d timed run(s)%s\n",
                grid.size(), box2dCanRun ? "Box2D's by both engines" : "meff's alone",
                cpu ? "CPU" : "wall", runs,
                options.shard.count > 1 ? (", shard " + std::to_string(options.shard.index) + "/" +
                                           std::to_string(options.shard.count))
                                              .c_str()
                                        : "");
    std::printf("%-38s | %10s %10s | %10s %10s\n", "setting", "meff ms/s", "error m", "Box2D ms/s",
                "error m");
    // This shard's settings, measured on --jobs threads and printed in grid order.
    std::vector<std::size_t> mine;
    for (std::size_t n = 0; n < grid.size(); ++n)
    {
        if (InShard(n, options.shard))
        {
            mine.push_back(n);
        }
    }
    std::vector<std::pair<Row, std::optional<Row>>> measured(mine.size());
    const auto measure = [&](std::size_t i)
    {
        const std::size_t n = mine[i];
        const Setting& setting = grid[n];
        const Scene settingScene = WithSetting(scene, setting);
        const std::string meffName = MeffEngineName(setting);
        // Each setting measured at once (--jobs) steps on a pool of its own: a pool is handed
        // one job at a time.
        const std::unique_ptr<TaskSystem> threads = MakeThreads(options.threads);
        Row meffRow = RunSetting<MeffEngine>(settingScene, threads.get(), setting, meffName.c_str(),
                                             seconds, *model);
        // Box2D 2.4.1 has only its own order: the other back ends' settings are meff's alone.
        const bool withBox2D = setting.solver == SolverKind::Box2D && box2dCanRun;
        std::optional<Row> box2dRow;
        if (withBox2D)
        {
            box2dRow =
                RunSetting<Box2DEngine>(settingScene, nullptr, setting, "box2d", seconds, *model);
        }
        // The engines take turns to go first, so that neither always runs on a warm cache.
        for (int r = 0; r < runs; ++r)
        {
            const bool meffFirst = (n + r) % 2 == 0;
            if (meffFirst)
            {
                TimeSetting<MeffEngine>(settingScene, threads.get(), seconds, meffRow);
            }
            if (box2dRow)
            {
                TimeSetting<Box2DEngine>(settingScene, nullptr, seconds, *box2dRow);
            }
            if (!meffFirst)
            {
                TimeSetting<MeffEngine>(settingScene, threads.get(), seconds, meffRow);
            }
        }
        std::vector<Row*> settingRows{&meffRow};
        if (box2dRow)
        {
            settingRows.push_back(&*box2dRow);
        }
        for (Row* row : settingRows)
        {
            row->cost = Median(row->msPerSecond);
            row->cpuCost = Median(row->cpuMsPerSecond);
            if (row->msPerSecond.empty())
            {
                row->msPerSecond.push_back(kNaN);
            }
        }
        measured[i] = {std::move(meffRow), std::move(box2dRow)};
    };
    std::vector<Row> rows;
    Progress progress("sweep " + scene.name, int(mine.size()), "settings");
    const auto report = [&](std::size_t i)
    {
        auto& [meffRow, box2dRow] = measured[i];
        const Setting& setting = grid[mine[i]];
        progress.Clear();
        for (const Row* row : {&meffRow, box2dRow ? &*box2dRow : nullptr})
        {
            if (row != nullptr && row->trace.failed)
            {
                std::fprintf(stderr, "meff sweep: %s, %s: %s\n", row->engine.c_str(),
                             Describe(setting).c_str(), row->trace.failure.c_str());
            }
        }
        std::printf("%-38s | %10.3g %10.3g | ", Describe(setting).c_str(),
                    cpu ? meffRow.cpuCost : meffRow.cost, meffRow.error);
        if (box2dRow)
        {
            std::printf("%10.3g %10.3g\n", cpu ? box2dRow->cpuCost : box2dRow->cost,
                        box2dRow->error);
        }
        else
        {
            std::printf("%10s %10s\n", "-", "-");
        }
        std::fflush(stdout);
        rows.push_back(std::move(meffRow));
        if (box2dRow)
        {
            rows.push_back(std::move(*box2dRow));
        }
        progress.Update(int(i + 1));
    };
    RunInOrder(mine.size(), ResolveJobs(options.jobs), measure, report);
    progress.Finish();

    for (const char* engine : {"meff", "meff_colour", "meff_soft_step", "box2d"})
    {
        if (ParetoFront(rows, engine, cpu).empty())
        {
            continue;
        }
        std::printf("Pareto front, %s (cheapest first):\n", engine);
        for (const std::size_t r : ParetoFront(rows, engine, cpu))
        {
            std::printf("  %-38s %10.3g ms/s  error %.3g m\n", Describe(rows[r].setting).c_str(),
                        cpu ? rows[r].cpuCost : rows[r].cost, rows[r].error);
        }
    }

    try
    {
        WriteCsv(csv->Stream(), scene, model->Kind(), seconds, rows);
        csv->Commit();
        // A plot left from an earlier run would no longer match sweep.csv.
        if (options.noPlot ||
            !Plot(directory, csv->Path(), scene.name + " (" + model->Kind() + ")", options.cost))
        {
            std::filesystem::remove(directory / "pareto.png", error);
            std::printf("wrote %s\n", csv->Path().c_str());
        }
        else
        {
            std::printf("wrote %s and %s\n", csv->Path().c_str(),
                        (directory / "pareto.png").string().c_str());
        }
    }
    catch (const std::exception& failure)
    {
        std::fprintf(stderr, "meff sweep: %s\n", failure.what());
        return kExitRunFailed;
    }
    return kExitOk;
}

} // namespace

Command AddSweepCommand(CLI::App& parent)
{
    auto options = std::make_shared<SweepOptions>();
    CLI::App* app = parent.add_subcommand(
        "sweep",
        "Measure what each solver setting costs and how accurate it is, in meff and in Box2D "
        "2.4.1, over a grid of velocity iterations, position iterations, time steps, block "
        "solver and warm starting, with meff's colour back end and its soft step (substeps × "
        "time step × joint stiffness) beside them (see docs/performance.md, \"Speed "
        "versus accuracy\").\n"
        "Writes DIR/sweep.csv, one row per engine and setting, and DIR/pareto.png (error "
        "against cost, if python3 with matplotlib is present).");
    app->add_option("scene", options->scenePath, "Scene file (JSON)")
        ->required()
        ->type_name("SCENE.json");
    AddFormatOption(app);
    app->add_option("--out", options->outDir, "Output directory (default out/sweep/<scene>)")
        ->type_name("DIR");
    app->add_flag(
        "--quick", options->quick,
        "A small grid (12 settings: 9 in both engines, 3 by meff alone) over 2 s, one timed run "
        "each: for tests");
    app->add_option("--seconds", options->seconds,
                    "Simulated time of every run (default 4, or 2 with --quick)")
        ->check(CLI::Range(1.0 / kSampleHz, 600.0));
    app->add_option("--runs", options->runs,
                    "Timed runs per setting and engine (default 3, or "
                    "1 with --quick)")
        ->check(CLI::Range(1, 100));
    app->add_option("--cost", options->cost,
                    "The cost the plot and the printed Pareto fronts use: wall time (default) "
                    "or this thread's CPU time, which leaves out other processes' turns on a "
                    "shared machine (sweep.csv has both)")
        ->check(CLI::IsMember({"wall", "cpu"}));
    app->add_flag("--no-plot", options->noPlot, "Skip the PNG plot");
    app->add_option("--jobs,-j", options->jobs,
                    "Measure N settings at once (default 1: the costs are timings, and runs "
                    "sharing cores slow each other; every error is the same for any N)")
        ->type_name("N")
        ->check(CLI::Range(1, 1024));
    AddThreadsOption(*app, options->threads,
                     "Threads each meff world steps on (Box2D 2.4.1 steps on one; with --cost "
                     "cpu only the stepping thread's CPU time is counted, not the pool's)");
    AddSolverOption(*app, options->solver,
                    "Sweep only the settings of one back end (box2d: the rows run in both "
                    "engines; default: all three)");
    AddShardOption(app, options->shard,
                   "settings (setting n to shard n mod N + 1; sweep.csv then holds that share)");
    return {app, [options] { return RunSweep(*options); }};
}

} // namespace meff::cli
