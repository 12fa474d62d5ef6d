// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// `meff bench`: times meff against a peer on the same scenes in the same process — the Box2D
// 2.4.1 mirror (default), meff with another solver back end (`--against meff:colour`, to weigh
// one back end's cost against another's), or nothing (`--against none`, for scenes where Box2D
// 2.4.1 takes minutes).
//
// Each run builds both worlds from the scene and steps each one through the whole run; the
// engines alternate which goes first from run to run so neither always enjoys a warm cache.
// The first step is timed apart (it builds the broad phase and every contact), the rest give
// ms/step. Ratios are taken run by run (paired) and summarised by their median; the largest
// difference of the two engines' body positions at the end shows they simulated the same thing.
// With --profile, meff's time per step is also split into the step's stages (World::GetProfile).
// With --threads N, meff's world (not its peer) steps on a pool of N threads.
#include "commands.h"
#include "output_file.h"
#include "threads_option.h"

#include "meff/box2d_mirror.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace meff::cli
{

namespace
{

/// What meff is timed against.
struct Against
{
    enum class Kind
    {
        Box2D, ///< the Box2D 2.4.1 mirror, built from the same scene, paired run by run
        Meff,  ///< meff with the back end `solver`, built from the same scene, paired likewise
        None,  ///< nothing: meff alone
    };
    Kind kind = Kind::Box2D;
    SolverKind solver = SolverKind::Box2D; ///< the peer's back end, with Kind::Meff

    /// As --against spells it: "box2d", "none", "meff:colour".
    std::string Name() const
    {
        switch (kind)
        {
        case Kind::Box2D:
            return "box2d";
        case Kind::None:
            return "none";
        case Kind::Meff:
            break;
        }
        return std::string("meff:") + SolverKindName(solver);
    }
    /// As the table's columns name the peer.
    std::string Label() const { return kind == Kind::Box2D ? "Box2D" : Name(); }
};

/// --against's values: box2d, none, and meff:<back end> for each back end.
std::map<std::string, Against> AgainstNames()
{
    std::map<std::string, Against> names{{"box2d", {}}, {"none", {Against::Kind::None}}};
    for (const SolverKind k : {SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep})
    {
        const Against peer{Against::Kind::Meff, k};
        names.emplace(peer.Name(), peer);
    }
    return names;
}

struct BenchOptions
{
    std::vector<std::string> scenePaths;
    std::optional<int> steps;
    int runs = 5;
    int threads = 1;
    std::optional<SolverKind> solver; ///< meff's back end, instead of the scene's
    Against against{};
    std::string jsonPath;
    bool profile = false; ///< print meff's time per step stage by stage
};

/// The timing of one engine over one run.
struct EngineRun
{
    double firstStepMs = 0;
    double msPerStep = 0;  ///< mean over the steps after the first
    StepProfile profile{}; ///< meff only: each stage's mean ms over the steps after the first
};

struct SceneBench
{
    std::string name;
    std::size_t bodies = 0;
    int contacts = 0; ///< meff's contacts at the end of the last run
    int steps = 0;
    std::vector<EngineRun> meff;
    std::vector<EngineRun> peer;      ///< empty with --against none
    double maxPositionDifference = 0; ///< m, at the end of the last run (with a peer)
};

struct Summary
{
    double median = 0, min = 0, max = 0;
};

Summary Summarize(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    const double median = n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    return {median, values.front(), values.back()};
}

using Clock = std::chrono::steady_clock;

double Milliseconds(Clock::duration d)
{
    return std::chrono::duration<double, std::milli>(d).count();
}

/// Steps `step` `steps` times; the first step is timed apart.
template <typename StepFn>
EngineRun TimeSteps(int steps, StepFn&& step)
{
    EngineRun run;
    const Clock::time_point t0 = Clock::now();
    step();
    const Clock::time_point t1 = Clock::now();
    for (int i = 1; i < steps; ++i)
    {
        step();
    }
    const Clock::time_point t2 = Clock::now();
    run.firstStepMs = Milliseconds(t1 - t0);
    run.msPerStep = steps > 1 ? Milliseconds(t2 - t1) / (steps - 1) : 0;
    return run;
}

/// Adds `b`'s stage times to `a`'s, scaled by `scale`.
void Accumulate(StepProfile& a, const StepProfile& b, double scale)
{
    a.step += scale * b.step;
    a.findContacts += scale * b.findContacts;
    a.collide += scale * b.collide;
    a.solve += scale * b.solve;
    a.synchronize += scale * b.synchronize;
    a.continuous += scale * b.continuous;
}

/// Steps a meff scene through one run; with the steps after the first, its profile's mean.
EngineRun RunMeff(BuiltScene& built, int steps, Real dt)
{
    StepProfile profile{};
    int step = 0;
    EngineRun run =
        TimeSteps(steps,
                  [&]
                  {
                      built.Step(dt);
                      if (step++ > 0)
                      {
                          Accumulate(profile, built.world.GetProfile(), 1.0 / (steps - 1));
                      }
                  });
    run.profile = profile;
    return run;
}

/// The largest distance between body i's position in `built` and `position(i)`, in m.
template <typename PositionFn>
double MaxPositionDifference(const BuiltScene& built, PositionFn&& position)
{
    double largest = 0;
    for (std::size_t i = 0; i < built.bodies.size(); ++i)
    {
        const Vec2 p = built.world.GetPosition(built.bodies[i]);
        const auto [qx, qy] = position(i);
        largest = std::max(largest, std::hypot(double(p.x) - qx, double(p.y) - qy));
    }
    return largest;
}

/// Run `run` of meff paired with its peer: builds the peer's world, times both (taking turns to
/// go first from run to run) and records how far apart their bodies end.
void TimePaired(const Scene& scene, const Against& against, BuiltScene& built, int run,
                SceneBench& bench)
{
    const Real dt = static_cast<Real>(scene.world.dt);
    const auto runMeff = [&] { return RunMeff(built, bench.steps, dt); };
    std::function<EngineRun()> runPeer;
    std::function<std::pair<double, double>(std::size_t)> peerPosition;
    std::optional<validation::Box2DMirror> mirror;
    std::optional<BuiltScene> peer;
    if (against.kind == Against::Kind::Box2D)
    {
        mirror.emplace(scene);
        // Box2D runs as a game that reads no impulses runs it: without the mirror's PostSolve
        // listener, whose recording would otherwise count as Box2D's time (meff always builds
        // its contact reports, so this favours Box2D slightly).
        mirror->World().SetContactListener(nullptr);
        runPeer = [&] { return TimeSteps(bench.steps, [&] { mirror->Step(); }); };
        peerPosition = [&](std::size_t i)
        {
            const b2Vec2 q = mirror->Body(i)->GetPosition();
            return std::pair{double(q.x), double(q.y)};
        };
    }
    else
    {
        Scene peerScene = scene;
        peerScene.world.solver.kind = against.solver;
        peer.emplace(BuildWorld(peerScene));
        runPeer = [&] { return RunMeff(*peer, bench.steps, dt); };
        peerPosition = [&](std::size_t i)
        {
            const Vec2 q = peer->world.GetPosition(peer->bodies[i]);
            return std::pair{double(q.x), double(q.y)};
        };
    }
    if (run % 2 == 0)
    {
        bench.meff.push_back(runMeff());
        bench.peer.push_back(runPeer());
    }
    else
    {
        bench.peer.push_back(runPeer());
        bench.meff.push_back(runMeff());
    }
    bench.maxPositionDifference = MaxPositionDifference(built, peerPosition);
}

/// Times meff `runs` times (on `threads`, if any), alone or paired with its peer run by run.
SceneBench BenchScene(const Scene& scene, int steps, int runs, const Against& against,
                      TaskSystem* threads)
{
    SceneBench bench;
    bench.name = scene.name;
    bench.bodies = scene.bodies.size();
    bench.steps = steps;
    for (int r = 0; r < runs; ++r)
    {
        BuiltScene built = BuildWorld(scene);
        built.world.SetTaskSystem(threads);
        if (against.kind == Against::Kind::None)
        {
            bench.meff.push_back(RunMeff(built, steps, static_cast<Real>(scene.world.dt)));
        }
        else
        {
            TimePaired(scene, against, built, r, bench);
        }
        bench.contacts = built.world.GetContactCount();
    }
    return bench;
}

std::vector<double> Field(const std::vector<EngineRun>& runs, double EngineRun::*field)
{
    std::vector<double> out;
    for (const EngineRun& run : runs)
    {
        out.push_back(run.*field);
    }
    return out;
}

/// The peer's time over meff's, run by run: above 1 means meff is faster.
std::vector<double> PairedRatios(const SceneBench& bench)
{
    std::vector<double> out;
    for (std::size_t r = 0; r < bench.meff.size(); ++r)
    {
        out.push_back(bench.peer[r].msPerStep / bench.meff[r].msPerStep);
    }
    return out;
}

nlohmann::json ToJson(const Summary& s)
{
    return {{"median", s.median}, {"min", s.min}, {"max", s.max}};
}

void PrintHeader(const Against& against)
{
    if (against.kind == Against::Kind::None)
    {
        std::printf("%-14s %6s %8s | %-26s\n", "scene", "bodies", "contacts",
                    "meff ms/step med (min-max)");
        return;
    }
    const std::string label = against.Label();
    std::printf("%-14s %6s %8s | %-26s | %-26s | %-19s | %9s\n", "scene", "bodies", "contacts",
                "meff ms/step med (min-max)", (label + " ms/step med (min-max)").c_str(),
                (label + "/meff med (min)").c_str(), "|dp| end");
}

/// meff's stages, each the median over the runs of its mean ms/step, as one indented line and
/// as JSON. "other" is the step's time outside the named stages (events, sleep bookkeeping).
nlohmann::json ReportProfile(const SceneBench& bench)
{
    const auto stage = [&](double StepProfile::*field)
    {
        std::vector<double> values;
        for (const EngineRun& run : bench.meff)
        {
            values.push_back(run.profile.*field);
        }
        return Summarize(values).median;
    };
    const double step = stage(&StepProfile::step), find = stage(&StepProfile::findContacts),
                 collide = stage(&StepProfile::collide), solve = stage(&StepProfile::solve),
                 sync = stage(&StepProfile::synchronize),
                 continuous = stage(&StepProfile::continuous);
    const double other = std::max(0.0, step - find - collide - solve - sync - continuous);
    std::printf("  meff stages ms/step: find contacts %.4f, collide %.4f, solve %.4f, "
                "synchronize %.4f, continuous %.4f, other %.4f (step %.4f)\n",
                find, collide, solve, sync, continuous, other, step);
    return {{"step", step},   {"find_contacts", find}, {"collide", collide},
            {"solve", solve}, {"synchronize", sync},   {"continuous", continuous},
            {"other", other}};
}

/// Prints the scene's line (and, with `profile`, its stages) and returns its JSON entry.
nlohmann::json Report(const SceneBench& bench, const Against& against, int runs, int threads,
                      bool profile)
{
    const Summary meff = Summarize(Field(bench.meff, &EngineRun::msPerStep));
    const Summary meffFirst = Summarize(Field(bench.meff, &EngineRun::firstStepMs));
    std::printf("%-14s %6zu %8d | %8.4f (%8.4f-%8.4f)", bench.name.c_str(), bench.bodies,
                bench.contacts, meff.median, meff.min, meff.max);
    nlohmann::json entry = {{"scene", bench.name},
                            {"against", against.Name()},
                            {"bodies", bench.bodies},
                            {"contacts", bench.contacts},
                            {"steps", bench.steps},
                            {"runs", runs},
                            {"threads", threads},
                            {"meff_ms_per_step", ToJson(meff)},
                            {"meff_first_step_ms", ToJson(meffFirst)}};
    if (against.kind != Against::Kind::None)
    {
        const Summary peer = Summarize(Field(bench.peer, &EngineRun::msPerStep));
        const Summary ratio = Summarize(PairedRatios(bench));
        const Summary peerFirst = Summarize(Field(bench.peer, &EngineRun::firstStepMs));
        std::printf(" | %8.4f (%8.4f-%8.4f) | %8.3f (%8.3f) | %9.2e", peer.median, peer.min,
                    peer.max, ratio.median, ratio.min, bench.maxPositionDifference);
        // Box2D's keys keep their names; a meff back end as the peer is "peer_...".
        const std::string key = against.kind == Against::Kind::Box2D ? "box2d" : "peer";
        entry[key + "_ms_per_step"] = ToJson(peer);
        entry[key + "_over_meff"] = ToJson(ratio);
        entry[key + "_first_step_ms"] = ToJson(peerFirst);
        entry["max_position_difference_m"] = bench.maxPositionDifference;
    }
    std::printf("\n");
    if (profile)
    {
        entry["meff_stage_ms_per_step"] = ReportProfile(bench);
    }
    return entry;
}

int RunBench(const BenchOptions& options)
{
    std::vector<Scene> scenes;
    for (const std::string& path : options.scenePaths)
    {
        std::optional<Scene> scene = LoadSceneOrReport(path);
        if (!scene)
        {
            return kExitBadInput;
        }
        ApplySolverOption(options.solver, *scene); // Box2D keeps its own order
        scenes.push_back(std::move(*scene));
    }
    std::optional<OutputFile> json;
    try
    {
        if (!options.jsonPath.empty())
        {
            json.emplace(options.jsonPath);
        }
    }
    catch (const std::exception& error)
    {
        std::fprintf(stderr, "meff bench: %s\n", error.what());
        return kExitBadInput;
    }

    const std::unique_ptr<TaskSystem> threads = MakeThreads(options.threads);
    PrintHeader(options.against);
    nlohmann::json report = nlohmann::json::array();
    for (const Scene& scene : scenes)
    {
        const int steps = options.steps.value_or(scene.world.frames);
        if (steps < 2)
        {
            std::fprintf(stderr, "meff bench: %s: needs at least 2 steps, got %d\n",
                         scene.name.c_str(), steps);
            return kExitBadInput;
        }
        SceneBench bench;
        try
        {
            bench = BenchScene(scene, steps, options.runs, options.against, threads.get());
        }
        catch (const SceneError& error)
        {
            // Box2D 2.4.1 cannot mirror it (Box2D v3's features): the input, not the run.
            std::fprintf(stderr, "meff bench: %s: %s\n", scene.name.c_str(), error.what());
            return kExitBadInput;
        }
        catch (const Error& error)
        {
            std::fprintf(stderr, "meff bench: %s: %s\n", scene.name.c_str(), error.what());
            return kExitRunFailed;
        }
        report.push_back(
            Report(bench, options.against, options.runs, options.threads, options.profile));
    }
    if (options.against.kind == Against::Kind::None)
    {
        std::printf("Times exclude the first step (timed apart: see --json); meff alone "
                    "(--against none).\n");
    }
    else
    {
        std::printf("Times exclude the first step (timed apart: see --json). Ratios above 1 mean "
                    "meff is faster; |dp| end is the largest difference of body positions "
                    "between the engines after the last step.\n");
        if (options.against.kind == Against::Kind::Meff)
        {
            std::printf("meff and %s differ only in their solver back end.\n",
                        options.against.Name().c_str());
        }
    }
    if (json)
    {
        try
        {
            const std::string text = report.dump(2) + "\n";
            std::fputs(text.c_str(), json->Stream());
            json->Commit();
        }
        catch (const std::exception& error)
        {
            std::fprintf(stderr, "meff bench: %s\n", error.what());
            return kExitRunFailed;
        }
    }
    return kExitOk;
}

} // namespace

Command AddBenchCommand(CLI::App& parent)
{
    auto options = std::make_shared<BenchOptions>();
    CLI::App* app = parent.add_subcommand(
        "bench", "Time meff against Box2D 2.4.1 (or against meff with another solver back "
                 "end) on the same scenes, in the same process.\n"
                 "Each run builds both worlds and steps each through the whole run, the two "
                 "engines taking turns to go first. Prints ms/step (median, min, max over the "
                 "runs, first step excluded) and the paired ratio peer/meff; with --against "
                 "none, meff's times alone; with --profile, meff's stages.");
    app->add_option("scenes", options->scenePaths, "Scene files (JSON)")
        ->required()
        ->check(CLI::ExistingFile);
    AddFormatOption(app);
    CLI::Option* frames =
        app->add_option("--frames", options->steps, "Steps per run (default: the scene's frames)")
            ->type_name("N")
            ->check(CLI::Range(2, 1000000));
    // --steps, the older spelling of --frames: still accepted, with a warning, and not listed.
    app->add_option_function<int>(
           "--steps",
           [options](int steps)
           {
               std::fprintf(stderr, "meff bench: --steps is deprecated, use --frames\n");
               options->steps = steps;
           },
           "")
        ->check(CLI::Range(2, 1000000))
        ->excludes(frames)
        ->group("");
    app->add_option("--runs", options->runs, "Runs per engine and scene (default 5)")
        ->check(CLI::Range(1, 1000));
    AddThreadsOption(*app, options->threads, "Threads for meff's world (its peer steps on one)");
    app->add_option("--json", options->jsonPath,
                    "Also write the results to this JSON file (each scene's \"against\" says "
                    "what meff was timed against)");
    std::vector<std::string> againstNames;
    for (const auto& [name, peer] : AgainstNames())
    {
        againstNames.push_back(name);
    }
    app->add_option_function<std::string>(
           "--against",
           [options](const std::string& name) { options->against = AgainstNames().at(name); },
           "What meff is timed against: box2d (default: the Box2D 2.4.1 mirror, paired "
           "runs, ratio and |dp|), meff:box2d, meff:colour or meff:soft_step (meff "
           "with that solver back end, paired likewise: one back end's cost against "
           "another's) or none (meff alone, for scenes where Box2D 2.4.1 takes "
           "minutes)")
        ->check(CLI::IsMember(againstNames));
    app->add_flag("--profile", options->profile,
                  "Also print meff's ms/step stage by stage (find contacts, collide, solve, "
                  "synchronize, continuous, other: World::GetProfile), medians over the runs");
    AddSolverOption(*app, options->solver,
                    "meff's solver back end instead of the scene's world.solver (the Box2D 2.4.1 "
                    "peer keeps its own)");
    // The older spelling of `--solver colour`.
    app->add_flag_callback(
           "--graph-coloring", [options] { options->solver = SolverKind::Colour; },
           "The same as --solver colour: meff's results then differ from Box2D's (|dp| end)")
        ->excludes("--solver");
    return {app, [options] { return RunBench(*options); }};
}

} // namespace meff::cli
