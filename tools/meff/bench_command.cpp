// `meff bench`: times meff and the Box2D 2.4.1 mirror on the same scenes in the same process,
// or meff alone (`--against none`, for scenes where Box2D 2.4.1 takes minutes).
//
// Each run builds both worlds from the scene and steps each one through the whole run; the
// engines alternate which goes first from run to run so neither always enjoys a warm cache.
// The first step is timed apart (it builds the broad phase and every contact), the rest give
// ms/step. Ratios are taken run by run (paired) and summarised by their median; the largest
// difference of the two engines' body positions at the end shows they simulated the same thing.
#include "commands.h"
#include "output_file.h"

#include "meff/box2d_mirror.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
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
enum class Against
{
    Box2D, ///< the Box2D 2.4.1 mirror, built from the same scene, paired run by run
    None,  ///< nothing: meff alone
};

struct BenchOptions
{
    std::vector<std::string> scenePaths;
    std::optional<int> steps;
    int runs = 5;
    int threads = 1;
    std::optional<SolverKind> solver; ///< meff's back end, instead of the scene's
    Against against = Against::Box2D;
    std::string jsonPath;
};

/// The timing of one engine over one run.
struct EngineRun
{
    double firstStepMs = 0;
    double msPerStep = 0; ///< mean over the steps after the first
};

struct SceneBench
{
    std::string name;
    std::size_t bodies = 0;
    int contacts = 0; ///< meff's contacts at the end of the last run
    int steps = 0;
    std::vector<EngineRun> meff;
    std::vector<EngineRun> box2d;     ///< empty with --against none
    double maxPositionDifference = 0; ///< m, at the end of the last run (with Box2D)
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

/// Run `run` of meff against Box2D 2.4.1: builds the mirror, times both (taking turns to go
/// first from run to run) and records how far apart their bodies end.
template <typename RunMeff>
void TimeAgainstBox2D(const Scene& scene, const BuiltScene& built, int run, RunMeff&& runMeff,
                      SceneBench& bench)
{
    validation::Box2DMirror mirror(scene);
    // Box2D runs as a game that reads no impulses runs it: without the mirror's PostSolve
    // listener, whose recording would otherwise count as Box2D's time (meff always builds
    // its contact reports, so this favours Box2D slightly).
    mirror.World().SetContactListener(nullptr);
    const auto runBox2D = [&] { return TimeSteps(bench.steps, [&] { mirror.Step(); }); };
    if (run % 2 == 0)
    {
        bench.meff.push_back(runMeff());
        bench.box2d.push_back(runBox2D());
    }
    else
    {
        bench.box2d.push_back(runBox2D());
        bench.meff.push_back(runMeff());
    }
    bench.maxPositionDifference = 0;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    {
        const Vec2 p = built.world.GetPosition(built.bodies[i]);
        const b2Vec2 q = mirror.Body(i)->GetPosition();
        bench.maxPositionDifference =
            std::max(bench.maxPositionDifference,
                     std::hypot(double(p.x) - double(q.x), double(p.y) - double(q.y)));
    }
}

/// Times meff `runs` times, alone or paired with Box2D 2.4.1 run by run.
SceneBench BenchScene(const Scene& scene, int steps, int runs, Against against)
{
    SceneBench bench;
    bench.name = scene.name;
    bench.bodies = scene.bodies.size();
    bench.steps = steps;
    const Real dt = static_cast<Real>(scene.world.dt);
    for (int r = 0; r < runs; ++r)
    {
        BuiltScene built = BuildWorld(scene);
        const auto runMeff = [&] { return TimeSteps(steps, [&] { built.world.Step(dt); }); };
        if (against == Against::None)
        {
            bench.meff.push_back(runMeff());
        }
        else
        {
            TimeAgainstBox2D(scene, built, r, runMeff, bench);
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

/// Box2D's time over meff's, run by run: above 1 means meff is faster.
std::vector<double> PairedRatios(const SceneBench& bench)
{
    std::vector<double> out;
    for (std::size_t r = 0; r < bench.meff.size(); ++r)
    {
        out.push_back(bench.box2d[r].msPerStep / bench.meff[r].msPerStep);
    }
    return out;
}

nlohmann::json ToJson(const Summary& s)
{
    return {{"median", s.median}, {"min", s.min}, {"max", s.max}};
}

void PrintHeader(Against against)
{
    if (against == Against::None)
    {
        std::printf("%-14s %6s %8s | %-26s\n", "scene", "bodies", "contacts",
                    "meff ms/step med (min-max)");
        return;
    }
    std::printf("%-14s %6s %8s | %-26s | %-26s | %-19s | %9s\n", "scene", "bodies", "contacts",
                "meff ms/step med (min-max)", "Box2D ms/step med (min-max)", "Box2D/meff med (min)",
                "|dp| end");
}

/// Prints the scene's line and returns its entry of the JSON report.
nlohmann::json Report(const SceneBench& bench, Against against, int runs)
{
    const Summary meff = Summarize(Field(bench.meff, &EngineRun::msPerStep));
    const Summary meffFirst = Summarize(Field(bench.meff, &EngineRun::firstStepMs));
    std::printf("%-14s %6zu %8d | %8.4f (%8.4f-%8.4f)", bench.name.c_str(), bench.bodies,
                bench.contacts, meff.median, meff.min, meff.max);
    nlohmann::json entry = {{"scene", bench.name},
                            {"against", against == Against::None ? "none" : "box2d"},
                            {"bodies", bench.bodies},
                            {"contacts", bench.contacts},
                            {"steps", bench.steps},
                            {"runs", runs},
                            {"meff_ms_per_step", ToJson(meff)},
                            {"meff_first_step_ms", ToJson(meffFirst)}};
    if (against == Against::None)
    {
        std::printf("\n");
        return entry;
    }
    const Summary box2d = Summarize(Field(bench.box2d, &EngineRun::msPerStep));
    const Summary ratio = Summarize(PairedRatios(bench));
    const Summary box2dFirst = Summarize(Field(bench.box2d, &EngineRun::firstStepMs));
    std::printf(" | %8.4f (%8.4f-%8.4f) | %8.3f (%8.3f) | %9.2e\n", box2d.median, box2d.min,
                box2d.max, ratio.median, ratio.min, bench.maxPositionDifference);
    entry["box2d_ms_per_step"] = ToJson(box2d);
    entry["box2d_over_meff"] = ToJson(ratio);
    entry["box2d_first_step_ms"] = ToJson(box2dFirst);
    entry["max_position_difference_m"] = bench.maxPositionDifference;
    return entry;
}

int RunBench(const BenchOptions& options)
{
    if (options.threads != 1)
    {
        std::fprintf(stderr,
                     "meff bench: --threads %d: meff steps on one thread for now; only "
                     "--threads 1 is supported\n",
                     options.threads);
        return kExitBadInput;
    }
    std::vector<Scene> scenes;
    for (const std::string& path : options.scenePaths)
    {
        std::optional<Scene> scene = LoadSceneOrReport(path);
        if (!scene)
        {
            return kExitBadInput;
        }
        if (options.solver)
        {
            scene->world.solver.kind = *options.solver; // Box2D keeps its own order
        }
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
            bench = BenchScene(scene, steps, options.runs, options.against);
        }
        catch (const Error& error)
        {
            std::fprintf(stderr, "meff bench: %s: %s\n", scene.name.c_str(), error.what());
            return kExitRunFailed;
        }
        report.push_back(Report(bench, options.against, options.runs));
    }
    if (options.against == Against::None)
    {
        std::printf("Times exclude the first step (timed apart: see --json); meff alone "
                    "(--against none).\n");
    }
    else
    {
        std::printf("Times exclude the first step (timed apart: see --json). Ratios above 1 mean "
                    "meff is faster; |dp| end is the largest difference of body positions "
                    "between the engines after the last step.\n");
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
        "bench", "Time meff against Box2D 2.4.1 on the same scenes, in the same process.\n"
                 "Each run builds both worlds and steps each through the whole run, the two "
                 "engines taking turns to go first. Prints ms/step (median, min, max over the "
                 "runs, first step excluded) and the paired ratio Box2D/meff; with --against "
                 "none, meff's times alone.");
    app->add_option("scenes", options->scenePaths, "Scene files (JSON)")
        ->required()
        ->check(CLI::ExistingFile);
    AddFormatOption(app);
    app->add_option("--steps", options->steps, "Steps per run (default: the scene's frames)")
        ->check(CLI::Range(2, 1000000));
    app->add_option("--runs", options->runs, "Runs per engine and scene (default 5)")
        ->check(CLI::Range(1, 1000));
    app->add_option("--threads", options->threads, "Threads for meff (only 1 for now)");
    app->add_option("--json", options->jsonPath,
                    "Also write the results to this JSON file (each scene's \"against\" says "
                    "what meff was timed against)");
    app->add_option("--against", options->against,
                    "What meff is timed against: box2d (default: the Box2D 2.4.1 mirror, paired "
                    "runs, ratio and |dp|) or none (meff alone, for scenes where Box2D 2.4.1 "
                    "takes minutes)")
        ->transform(CLI::CheckedTransformer(
            std::map<std::string, Against>{{"box2d", Against::Box2D}, {"none", Against::None}}));
    AddSolverOption(*app, options->solver);
    // The older spelling of `--solver colour`.
    app->add_flag_callback(
           "--graph-coloring", [options] { options->solver = SolverKind::Colour; },
           "The same as --solver colour: meff's results then differ from Box2D's (|dp| end)")
        ->excludes("--solver");
    return {app, [options] { return RunBench(*options); }};
}

} // namespace meff::cli
