// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Stepping meff and its Box2D mirror in lockstep and judging the run.
#include "meff/box2d_mirror.h"
#include "meff/box2d_v3_features.h"
#include "meff/validation.h"

#include "meff_sampler.h"
#include "run_tally.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <utility>

namespace meff::validation
{

namespace
{

std::string Metres(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g m", value);
    return text;
}

bool AnyRestitution(const Scene& scene)
{
    for (const SceneBody& body : scene.bodies)
    {
        for (const SceneShape& shape : body.shapes)
        {
            if (shape.restitution > 0)
            {
                return true;
            }
        }
    }
    return false;
}

bool AnyBlockJoint(const Scene& scene)
{
    for (const SceneJoint& joint : scene.joints)
    {
        switch (joint.type)
        {
        case JointType::Revolute:
        case JointType::Prismatic:
        case JointType::Weld:
        case JointType::Motor:
        case JointType::Mouse:
        case JointType::Friction:
            return true;
        default:
            break;
        }
    }
    return false;
}

/// The scene's settings that Box2D 2.4.1 has no counterpart for and that change this scene's
/// results: the setting as the scene writes it, and why the engines cannot agree.
std::vector<std::pair<std::string, std::string>> Unmirrored(const Scene& scene)
{
    std::vector<std::pair<std::string, std::string>> settings;
    const SolverSettings& solver = scene.world.solver;
    if (solver.kind != SolverKind::Box2D)
    {
        const std::string name = SolverKindName(solver.kind);
        settings.emplace_back("world.solver \"" + name + "\"",
                              "world.solver is \"" + name +
                                  "\", which Box2D 2.4.1 does not "
                                  "have: it solves its rows in "
                                  "another order or way, so the engines part by round-off (or "
                                  "more) once constraints act");
    }
    if (solver.restitutionFromStepStart && AnyRestitution(scene))
    {
        settings.emplace_back("world.restitution_from_step_start",
                              "world.restitution_from_step_start is true: meff measures a "
                              "bounce's approach speed at the start of the step, Box2D 2.4.1 "
                              "after gravity, so every bounce differs by about g·dt");
    }
    if (!solver.blockJoints && AnyBlockJoint(scene))
    {
        settings.emplace_back("world.block_joints false",
                              "world.block_joints is false: Box2D 2.4.1 always solves a joint's "
                              "coupled rows as one block (revolute, prismatic and mouse points, "
                              "weld point and angle, motor linear part), so those joints cannot "
                              "agree");
    }
    return settings;
}

/// Rolling resistance, which Box2D 2.4.1 has no form of: one message per shape using it.
std::vector<std::string> RollingResistance(const Scene& scene)
{
    std::vector<std::string> messages;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    {
        for (std::size_t k = 0; k < scene.bodies[i].shapes.size(); ++k)
        {
            const double c = scene.bodies[i].shapes[k].rollingResistance;
            if (c != 0)
            {
                std::ostringstream message;
                message << scene.sourcePath << ": bodies[" << i << "].shapes[" << k
                        << "].rolling_resistance: Box2D 2.4.1 has no rolling resistance, so "
                           "meff validate cannot compare this scene (0 to validate), got "
                        << c;
                messages.push_back(message.str());
            }
        }
    }
    return messages;
}

/// What the mirror cannot reproduce exactly, and how the run is judged then: said, never
/// hidden.
std::vector<std::string> MirrorNotes(
    const Scene& scene, const RunOptions& options,
    const std::vector<std::pair<std::string, std::string>>& unmirrored)
{
    std::vector<std::string> notes;
    for (const auto& [setting, why] : unmirrored)
    {
        notes.push_back(why);
    }
    if (!unmirrored.empty())
    {
        notes.emplace_back(
            scene.validation.chaotic
                ? "judged as the scene says (chaotic): frame by frame up to the horizon, then "
                  "the settled state"
                : "judged by what can be compared: frame 0 (both worlds as built) must agree, "
                  "and the settled state (validate.settle, by default every body within " +
                      Metres(SceneSettleCheck{}.position) +
                      " of Box2D's final position); the frame-by-frame errors are reported, "
                      "not judged");
    }
    if (options.meffVelocityIterations &&
        *options.meffVelocityIterations != scene.world.solver.velocityIterations)
    {
        notes.emplace_back("meff runs " + std::to_string(*options.meffVelocityIterations) +
                           " velocity iterations, Box2D " +
                           std::to_string(scene.world.solver.velocityIterations) +
                           " (a deliberate difference: this run is expected to fail)");
    }
    return notes;
}

SettleResult CheckSettled(const Scene& scene, const SceneSettleCheck& check,
                          const FrameSample& meff, const FrameSample& box2d)
{
    SettleResult result;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    {
        if (scene.bodies[i].type == BodyType::Static)
        {
            continue;
        }
        const BodySample& m = meff.bodies[i];
        const BodySample& b = box2d.bodies[i];
        const double position = std::hypot(m.x - b.x, m.y - b.y);
        const double angle = std::abs(m.angle - b.angle);
        const std::string name = DescribeBody(scene, static_cast<int>(i));
        if (!(position <= result.position) || result.positionBody.empty())
        {
            result.position = position;
            result.positionBody = name;
        }
        if (!(angle <= result.angle) || result.angleBody.empty())
        {
            result.angle = angle;
            result.angleBody = name;
        }
        if (!result.lowestHeight || !(m.y >= *result.lowestHeight))
        {
            result.lowestHeight = m.y;
            result.lowestBody = name;
        }
    }
    const auto number = [](double value)
    {
        char text[32];
        std::snprintf(text, sizeof text, "%.3g", value);
        return std::string(text);
    };
    if (!(result.position <= check.position))
    {
        result.failures.push_back("settled position: " + result.positionBody + " ends " +
                                  number(result.position) + " m from Box2D's (tolerance " +
                                  number(check.position) + " m)");
    }
    if (check.angle && !(result.angle <= *check.angle))
    {
        result.failures.push_back("settled angle: " + result.angleBody + " ends " +
                                  number(result.angle) + " rad from Box2D's (tolerance " +
                                  number(*check.angle) + " rad)");
    }
    if (check.minimumHeight && result.lowestHeight &&
        !(*result.lowestHeight >= *check.minimumHeight))
    {
        result.failures.push_back("settled height: " + result.lowestBody +
                                  " ends at y = " + number(*result.lowestHeight) +
                                  " m, below min_height " + number(*check.minimumHeight) + " m");
    }
    result.passed = result.failures.empty();
    return result;
}

} // namespace

void AddCheckFailure(ValidationResult& result, CheckFailure failure)
{
    result.checkFailures.push_back(std::move(failure));
    result.passed = false;
}

std::vector<std::string> Unmirrorable(const Scene& scene)
{
    std::vector<std::string> messages = FieldsBox2D241Lacks(
        scene, "the scene cannot be validated against it (run it with meff run)");
    for (std::string& message : RollingResistance(scene))
    {
        messages.push_back(std::move(message));
    }
    return messages;
}

ValidationResult Validate(const Scene& scene, const RunOptions& options)
{
    std::vector<std::string> unmirrorable = Unmirrorable(scene);
    if (!unmirrorable.empty())
    {
        throw SceneError(std::move(unmirrorable));
    }
    ValidationResult result;
    result.scene = scene.name;
    result.sourcePath = scene.sourcePath;
    result.frames = options.frames.value_or(scene.world.frames);
    result.tolerances = TolerancesOf(scene.tolerances);
    result.blockSolver = options.blockSolver.value_or(scene.world.solver.blockSolver);
    result.box2dVelocityIterations = scene.world.solver.velocityIterations;
    result.meffVelocityIterations =
        options.meffVelocityIterations.value_or(scene.world.solver.velocityIterations);
    result.chaotic = scene.validation.chaotic;
    result.horizonFrames = scene.validation.horizonFrames;
    const std::vector<std::pair<std::string, std::string>> unmirrored = Unmirrored(scene);
    for (const auto& [setting, why] : unmirrored)
    {
        result.unmirrored.push_back(setting);
    }
    result.notes = MirrorNotes(scene, options, unmirrored);

    // Box2D 2.4.1 cannot be given a saved world's warm start (its joints' "impulses", the
    // last step's 1/dt): both engines start without it.
    Scene cold = scene;
    bool warmStart = cold.world.lastStepInverseDt != 0;
    cold.world.lastStepInverseDt = 0;
    for (SceneJoint& joint : cold.joints)
    {
        warmStart = warmStart || !joint.impulses.empty();
        joint.impulses.clear();
    }
    if (warmStart)
    {
        result.notes.emplace_back("the saved warm start (joints' \"impulses\", "
                                  "world.last_step_inv_dt) is left out: Box2D 2.4.1 cannot be "
                                  "given it, so both engines start without it");
    }
    BuiltScene built = BuildWorld(cold);
    SolverSettings solver = built.world.GetSolverSettings();
    solver.blockSolver = result.blockSolver;
    solver.velocityIterations = result.meffVelocityIterations;
    built.world.SetSolverSettings(solver);
    Box2DMirror mirror(scene, result.blockSolver);

    const MeffSampler meff(built);
    const double dt = scene.world.dt;
    const Real invDt = Real(1) / Real(dt);
    // Frame 0: both worlds as built, before any step (no contacts or reactions yet).
    TallyFrame(result, scene, 0, meff.Sample(invDt), mirror.Sample(), dt);
    FrameSample lastMeff;
    FrameSample lastBox2D;
    for (int frame = 1; frame <= result.frames; ++frame)
    {
        try
        {
            built.Step(Real(dt));
        }
        catch (const SimulationError& error)
        {
            result.failure =
                std::string("meff stopped at frame ") + std::to_string(frame) + ": " + error.what();
            break;
        }
        mirror.Step();
        lastMeff = meff.Sample(invDt);
        lastBox2D = mirror.Sample();
        TallyFrame(result, scene, frame, lastMeff, lastBox2D, dt);
    }

    bool agreed = !result.divergenceFrame;
    std::optional<SceneSettleCheck> settle = scene.validation.settle;
    if (result.chaotic)
    {
        // Round-off may part the engines after the horizon, not before it.
        agreed = !result.divergenceFrame || *result.divergenceFrame > result.horizonFrames;
    }
    else if (!result.unmirrored.empty())
    {
        // A setting Box2D cannot mirror: the worlds as built must agree; after that, only where
        // they come to rest can be compared.
        agreed = !result.divergenceFrame || *result.divergenceFrame > 0;
        settle = settle.value_or(SceneSettleCheck{});
    }
    if (settle && result.failure.empty() && result.frames > 0)
    {
        result.settle = CheckSettled(scene, *settle, lastMeff, lastBox2D);
    }
    result.comparisonPassed = agreed && (!result.settle || result.settle->passed);
    result.passed = result.comparisonPassed && result.failure.empty();
    return result;
}

} // namespace meff::validation
