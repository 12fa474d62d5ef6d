// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// Baselines (meff/baseline.h): recording a run of meff, checking that a baseline fits a run,
// and comparing a run with it frame by frame.
#include "meff/baseline.h"

#include "meff_sampler.h"
#include "run_tally.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iterator>
#include <set>

namespace meff::validation
{

namespace
{

/// "fnv1a64:" and the 64-bit FNV-1a hash of the file's bytes, in 16 hex digits.
std::string FileHash(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (!in.good() && !in.eof())
    {
        throw BaselineError(path + ": cannot read the scene file to hash it");
    }
    std::uint64_t hash = 0xcbf29ce484222325ull;
    for (const char c : bytes)
    {
        hash = (hash ^ std::uint8_t(c)) * 0x100000001b3ull;
    }
    char text[32];
    std::snprintf(text, sizeof text, "fnv1a64:%016llx", static_cast<unsigned long long>(hash));
    return text;
}

/// The scene with the run's options applied to its world.
Scene AsRun(const Scene& scene, const RunOptions& options)
{
    Scene run = scene;
    run.world.frames = options.frames.value_or(scene.world.frames);
    run.world.solver.blockSolver = options.blockSolver.value_or(scene.world.solver.blockSolver);
    return run;
}

/// The world section of a scene file for these settings.
std::string SettingsJson(const SceneWorldSettings& world)
{
    Scene settings;
    settings.world = world;
    return nlohmann::json::parse(WriteScene(settings)).at("world").dump();
}

/// Steps the scene as `options` say and hands over frame 0 and the state after each step;
/// returns "meff stopped at frame K: ..." when a step failed, or empty.
std::string RunFrames(const Scene& scene, const RunOptions& options,
                      const std::function<void(int, const FrameSample&)>& onFrame)
{
    BuiltScene built = BuildWorld(scene);
    if (options.meffVelocityIterations)
    {
        SolverSettings solver = built.world.GetSolverSettings();
        solver.velocityIterations = *options.meffVelocityIterations;
        built.world.SetSolverSettings(solver);
    }
    const MeffSampler sampler(built);
    const Real invDt = Real(1) / Real(scene.world.dt);
    onFrame(0, sampler.Sample(invDt));
    for (int frame = 1; frame <= scene.world.frames; ++frame)
    {
        try
        {
            built.Step(Real(scene.world.dt));
        }
        catch (const SimulationError& error)
        {
            return "meff stopped at frame " + std::to_string(frame) + ": " + error.what();
        }
        onFrame(frame, sampler.Sample(invDt));
    }
    return {};
}

[[noreturn]] void Differs(const std::string& path, const std::string& what,
                          const std::string& recorded, const std::string& now)
{
    throw BaselineError(path + ": recorded with " + what + " " + recorded + ", this run has " +
                        now + "; re-record it with --record");
}

/// The first world setting whose value differs, or empty: "world.KEY".
std::string FirstDifference(const nlohmann::json& recorded, const nlohmann::json& now)
{
    std::set<std::string> keys;
    for (const auto& [key, value] : recorded.items())
    {
        keys.insert(key);
    }
    for (const auto& [key, value] : now.items())
    {
        keys.insert(key);
    }
    for (const std::string& key : keys)
    {
        if (recorded.value(key, nlohmann::json()) != now.value(key, nlohmann::json()))
        {
            return key;
        }
    }
    return {};
}

} // namespace

BaselineHeader HeaderFor(const Scene& scene, const RunOptions& options,
                         const std::string& meffVersion)
{
    const Scene run = AsRun(scene, options);
    BaselineHeader header;
    header.meffVersion = meffVersion;
    header.backEnd = SolverKindName(run.world.solver.kind);
    header.scene = scene.name;
    header.sceneHash = FileHash(scene.sourcePath);
    header.settings = SettingsJson(run.world);
    header.frames = run.world.frames;
    header.bodies = int(scene.bodies.size());
    header.joints = int(scene.joints.size());
    return header;
}

Baseline RecordBaseline(const Scene& scene, const RunOptions& options,
                        const std::string& meffVersion)
{
    Baseline baseline;
    baseline.header = HeaderFor(scene, options, meffVersion);
    RunOptions asRecorded = options;
    asRecorded.meffVelocityIterations.reset(); // the scene's own run is what is recorded
    const std::string failure =
        RunFrames(AsRun(scene, options), asRecorded,
                  [&](int, const FrameSample& sample) { baseline.frames.push_back(sample); });
    if (!failure.empty())
    {
        throw BaselineError(scene.sourcePath + ": cannot record a baseline: " + failure);
    }
    return baseline;
}

void CheckBaseline(const BaselineHeader& recorded, const BaselineHeader& current,
                   const std::string& path, bool acceptSceneChange)
{
    if (recorded.backEnd != current.backEnd)
    {
        Differs(path, "back end", recorded.backEnd, current.backEnd);
    }
    if (recorded.frames != current.frames)
    {
        Differs(path, "frames", std::to_string(recorded.frames), std::to_string(current.frames));
    }
    if (recorded.bodies != current.bodies || recorded.joints != current.joints)
    {
        Differs(path, "bodies/joints",
                std::to_string(recorded.bodies) + "/" + std::to_string(recorded.joints),
                std::to_string(current.bodies) + "/" + std::to_string(current.joints));
    }
    if (acceptSceneChange)
    {
        return;
    }
    if (recorded.sceneHash != current.sceneHash)
    {
        throw BaselineError(path + ": recorded from another version of the scene file (" +
                            recorded.sceneHash + ", now " + current.sceneHash +
                            "); re-record it with --record, or compare anyway with "
                            "--accept-scene-change");
    }
    const nlohmann::json before = nlohmann::json::parse(recorded.settings);
    const nlohmann::json now = nlohmann::json::parse(current.settings);
    if (const std::string key = FirstDifference(before, now); !key.empty())
    {
        Differs(path, "world." + key, before.value(key, nlohmann::json()).dump(),
                now.value(key, nlohmann::json()).dump());
    }
}

ValidationResult CompareWithBaseline(const Scene& scene, const Baseline& baseline,
                                     const RunOptions& options, const Tolerances& tolerances)
{
    const Scene run = AsRun(scene, options);
    ValidationResult result;
    result.scene = scene.name;
    result.sourcePath = scene.sourcePath;
    result.reference = "baseline";
    result.frames = run.world.frames;
    result.tolerances = tolerances;
    result.blockSolver = run.world.solver.blockSolver;
    result.box2dVelocityIterations = run.world.solver.velocityIterations;
    result.meffVelocityIterations =
        options.meffVelocityIterations.value_or(result.box2dVelocityIterations);
    result.notes.push_back("compared with the baseline recorded by meff " +
                           baseline.header.meffVersion + ", back end " + baseline.header.backEnd);
    if (result.meffVelocityIterations != result.box2dVelocityIterations)
    {
        result.notes.push_back("meff runs " + std::to_string(result.meffVelocityIterations) +
                               " velocity iterations, the baseline " +
                               std::to_string(result.box2dVelocityIterations) +
                               " (a deliberate difference: this run is expected to fail)");
    }
    result.failure =
        RunFrames(run, options,
                  [&](int frame, const FrameSample& sample)
                  {
                      TallyFrame(result, scene, frame, sample,
                                 baseline.frames.at(std::size_t(frame)), scene.world.dt);
                  });
    result.comparisonPassed = !result.divergenceFrame;
    result.passed = result.comparisonPassed && result.failure.empty();
    return result;
}

} // namespace meff::validation
