// `meff validate`: runs scenes in meff and in Box2D 2.4.1 side by side and compares them frame
// by frame (see validation/include/meff/validation.h for what is compared and how).
#include "commands.h"
#include "junit.h"
#include "output_file.h"
#include "parallel.h"
#include "plausibility_report.h"
#include "plot_program.h"
#include "progress.h"

#include "meff/validation.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <set>
#include <stdexcept>
#include <vector>

#include <unistd.h>

#ifndef MEFF_PLOT_SCRIPT
#define MEFF_PLOT_SCRIPT ""
#endif

namespace meff::cli
{

namespace
{

using validation::FrameErrors;
using validation::RunMaximum;
using validation::ValidationResult;

struct ValidateOptions
{
    std::vector<std::string> scenePaths;
    std::optional<int> frames;
    std::string reportDir;
    std::string blockSolver = "scene";
    bool noPlot = false;
    int jobs = 0; ///< 0: one per core
    Shard shard;
    std::string junitPath;
    std::optional<int> meffVelocityIterations; // hidden: proves the comparison can fail
    /// --solver: every scene's back end ("scene": each its own). Another than box2d cannot be
    /// compared with Box2D frame by frame, so it is held to the plausibility checks instead.
    std::string solver = "scene";
    bool plausibility = false; ///< --plausibility: the checks also beside the comparison
};

/// The back end --solver names, or nullopt for "scene".
std::optional<SolverKind> SolverOption(const ValidateOptions& options)
{
    if (options.solver == "colour")
    {
        return SolverKind::Colour;
    }
    if (options.solver == "soft_step")
    {
        return SolverKind::SoftStep;
    }
    if (options.solver == "box2d")
    {
        return SolverKind::Box2D;
    }
    return std::nullopt;
}

std::string Number(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

std::string FormatMaximum(const char* label, const char* unit, const RunMaximum& maximum)
{
    std::string text = std::string(label) + " " + Number(maximum.value) + " " + unit;
    if (maximum.frame >= 0)
    {
        text += " @" + std::to_string(maximum.frame) + " (" + maximum.where + ")";
    }
    return text;
}

/// The PASS/FAIL line of a scene and the lines under it, each ending in a newline.
std::string ResultText(const ValidationResult& result)
{
    std::string line = std::string(result.passed ? "PASS " : "FAIL ") + result.scene + ": " +
                       std::to_string(result.frames) + " frames, block solver " +
                       (result.blockSolver ? "on" : "off");
    if (result.meffVelocityIterations != result.box2dVelocityIterations)
    {
        line += ", velocity iterations meff " + std::to_string(result.meffVelocityIterations) +
                " / Box2D " + std::to_string(result.box2dVelocityIterations);
    }
    line += "; max " + FormatMaximum("position", "m", result.position) + ", " +
            FormatMaximum("angle", "rad", result.angle) + ", " +
            FormatMaximum("velocity", "m/s", result.velocity) + ", " +
            FormatMaximum("contact impulse", "N·s", result.contactImpulse) + ", " +
            FormatMaximum("joint impulse", "N·s", result.jointImpulse);
    line += "; contact points only in meff " + std::to_string(result.onlyInMeff) +
            ", only in Box2D " + std::to_string(result.onlyInBox2D) + "; awake flags differing " +
            std::to_string(result.awakeMismatches);
    if (result.divergenceFrame)
    {
        std::string what;
        for (const std::string& quantity : result.divergenceQuantities)
        {
            what += (what.empty() ? "" : ", ") + quantity;
        }
        line +=
            "; diverged at frame " + std::to_string(*result.divergenceFrame) + " (" + what + ")";
    }
    else
    {
        line += "; no divergence";
    }
    if (!result.unmirrored.empty())
    {
        std::string settings;
        for (const std::string& setting : result.unmirrored)
        {
            settings += (settings.empty() ? "" : ", ") + setting;
        }
        line += "; not mirrored by Box2D: " + settings + " (see the notes)";
    }
    if (result.chaotic)
    {
        line += "; chaotic, horizon " + std::to_string(result.horizonFrames) + " frames";
    }
    if (result.settle)
    {
        line += result.settle->passed
                    ? "; settled within " + Number(result.settle->position) + " m of Box2D"
                    : "; NOT settled";
    }
    std::string text = line + "\n";
    if (result.settle)
    {
        for (const std::string& failure : result.settle->failures)
        {
            text += "  " + failure + "\n";
        }
    }
    if (!result.failure.empty())
    {
        text += "  " + result.failure + "\n";
    }
    for (const std::string& note : result.notes)
    {
        text += "  note: " + note + "\n";
    }
    return text;
}

/// "position 0.00012 > 0.0001 at box3: meff (1, 2) m, Box2D (1, 2.0001) m"
std::string DetailText(const validation::DivergenceDetail& detail)
{
    return detail.quantity + " " + Number(detail.error) + " > " + Number(detail.tolerance) +
           " at " + detail.where + ": meff " + detail.meff + ", Box2D " + detail.box2d;
}

/// The scene as a JUnit test case: a failure carries the divergence frame, each quantity that
/// exceeded, where, and both engines' values there.
JUnitCase JUnitCaseOf(const ValidationResult& result, double seconds)
{
    JUnitCase testCase;
    testCase.name = result.scene;
    testCase.className = "meff.validate";
    testCase.file = result.sourcePath;
    testCase.seconds = seconds;
    testCase.output = ResultText(result);
    if (result.passed)
    {
        return testCase;
    }
    if (!result.failure.empty())
    {
        testCase.outcome = JUnitCase::Outcome::Error;
        testCase.type = "simulation";
        testCase.message = result.failure;
        testCase.text = result.failure;
        return testCase;
    }
    testCase.outcome = JUnitCase::Outcome::Failed;
    if (result.divergenceFrame &&
        (!result.chaotic || *result.divergenceFrame <= result.horizonFrames))
    {
        testCase.type = "divergence";
        std::string what;
        for (const std::string& quantity : result.divergenceQuantities)
        {
            what += (what.empty() ? "" : ", ") + quantity;
        }
        testCase.message =
            "diverged from Box2D at frame " + std::to_string(*result.divergenceFrame) + ": " + what;
        for (const validation::DivergenceDetail& detail : result.divergenceDetails)
        {
            testCase.text += "frame " + std::to_string(*result.divergenceFrame) + ": " +
                             DetailText(detail) + "\n";
        }
    }
    else
    {
        testCase.type = "settle";
        testCase.message = "not settled where Box2D settled";
    }
    if (result.settle)
    {
        for (const std::string& failure : result.settle->failures)
        {
            testCase.text += failure + "\n";
        }
    }
    return testCase;
}

nlohmann::json MaximumJson(const RunMaximum& maximum)
{
    return {{"value", maximum.value},
            {"frame", maximum.frame >= 0 ? nlohmann::json(maximum.frame) : nlohmann::json()},
            {"where", maximum.where}};
}

nlohmann::json SummaryJson(const ValidationResult& result)
{
    nlohmann::json summary;
    summary["scene"] = result.scene;
    summary["source"] = result.sourcePath;
    summary["frames"] = result.frames;
    summary["passed"] = result.passed;
    summary["divergence_frame"] =
        result.divergenceFrame ? nlohmann::json(*result.divergenceFrame) : nlohmann::json();
    summary["divergence_quantities"] = result.divergenceQuantities;
    nlohmann::json details = nlohmann::json::array();
    for (const validation::DivergenceDetail& detail : result.divergenceDetails)
    {
        details.push_back({{"quantity", detail.quantity},
                           {"where", detail.where},
                           {"meff", detail.meff},
                           {"box2d", detail.box2d},
                           {"error", detail.error},
                           {"tolerance", detail.tolerance}});
    }
    summary["divergence"] = details;
    summary["max_position_error"] = result.position.value;
    summary["max_angle_error"] = result.angle.value;
    summary["max_velocity_error"] = result.velocity.value;
    summary["max_contact_impulse_error"] = result.contactImpulse.value;
    summary["max_joint_impulse_error"] = result.jointImpulse.value;
    summary["maxima"] = {{"position", MaximumJson(result.position)},
                         {"angle", MaximumJson(result.angle)},
                         {"velocity", MaximumJson(result.velocity)},
                         {"contact_impulse", MaximumJson(result.contactImpulse)},
                         {"joint_impulse", MaximumJson(result.jointImpulse)}};
    summary["tolerances"] = {{"position", result.tolerances.position},
                             {"angle", result.tolerances.angle},
                             {"velocity", result.tolerances.velocity},
                             {"impulse", result.tolerances.impulse},
                             {"impulse_relative", result.tolerances.impulseRelative}};
    summary["contact_points_only_in_meff"] = result.onlyInMeff;
    summary["contact_points_only_in_box2d"] = result.onlyInBox2D;
    summary["awake_mismatches"] = result.awakeMismatches;
    summary["block_solver"] = result.blockSolver;
    summary["velocity_iterations"] = {{"meff", result.meffVelocityIterations},
                                      {"box2d", result.box2dVelocityIterations}};
    summary["chaotic"] = result.chaotic;
    if (result.chaotic)
    {
        summary["horizon_frames"] = result.horizonFrames;
    }
    if (result.settle)
    {
        const validation::SettleResult& settle = *result.settle;
        summary["settle"] = {{"passed", settle.passed},
                             {"max_position_error", settle.position},
                             {"max_position_body", settle.positionBody},
                             {"max_angle_error", settle.angle},
                             {"max_angle_body", settle.angleBody},
                             {"lowest_height", settle.lowestHeight
                                                   ? nlohmann::json(*settle.lowestHeight)
                                                   : nlohmann::json()},
                             {"lowest_body", settle.lowestBody},
                             {"failures", settle.failures}};
    }
    summary["unmirrored"] = result.unmirrored;
    summary["notes"] = result.notes;
    summary["failure"] = result.failure.empty() ? nlohmann::json() : nlohmann::json(result.failure);
    return summary;
}

void WriteCsvNumber(std::FILE* out, double value)
{
    std::fprintf(out, ",%.9g", value);
}

void WriteDivergenceCsv(const Scene& scene, const ValidationResult& result, std::FILE* out)
{
    std::fputs("frame,position_error,position_body,angle_error,angle_body,"
               "linear_velocity_error,angular_velocity_error,velocity_error,velocity_body,"
               "contact_impulse_error,contact_impulse_ratio,contact,contact_points_meff,"
               "contact_points_box2d,only_in_meff,only_in_box2d,joint_impulse_error,"
               "joint_impulse_ratio,joint,exceeded\n",
               out);
    for (const FrameErrors& frame : result.perFrame)
    {
        std::fprintf(out, "%d", frame.frame);
        WriteCsvNumber(out, frame.position);
        std::fprintf(out, ",%s", validation::DescribeBody(scene, frame.positionBody).c_str());
        WriteCsvNumber(out, frame.angle);
        std::fprintf(out, ",%s", validation::DescribeBody(scene, frame.angleBody).c_str());
        WriteCsvNumber(out, frame.linearVelocity);
        WriteCsvNumber(out, frame.angularVelocity);
        WriteCsvNumber(out, frame.velocity);
        std::fprintf(out, ",%s", validation::DescribeBody(scene, frame.velocityBody).c_str());
        WriteCsvNumber(out, frame.contactImpulse);
        WriteCsvNumber(out, frame.contactRatio);
        std::fprintf(out, ",%s",
                     frame.contact ? validation::DescribeContact(scene, *frame.contact).c_str()
                                   : "-");
        std::fprintf(out, ",%d,%d,%d,%d", frame.contactPointsMeff, frame.contactPointsBox2D,
                     frame.onlyInMeff, frame.onlyInBox2D);
        WriteCsvNumber(out, frame.jointImpulse);
        WriteCsvNumber(out, frame.jointRatio);
        std::fprintf(out, ",%s", validation::DescribeJoint(scene, frame.joint).c_str());
        std::string exceeded;
        for (const std::string& quantity : frame.exceeded)
        {
            exceeded += (exceeded.empty() ? "" : ";") + quantity;
        }
        std::fprintf(out, ",%s\n", exceeded.c_str());
    }
}

/// Scene names as directory names: plain characters only, unique among this run's scenes.
std::string DirectoryName(const std::string& sceneName, std::set<std::string>& used)
{
    std::string name;
    for (const char c : sceneName)
    {
        const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                           (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
        name += plain ? c : '_';
    }
    if (name.empty() || name == "." || name == "..")
    {
        name = "scene";
    }
    std::string unique = name;
    for (int n = 2; !used.insert(unique).second; ++n)
    {
        unique = name + "-" + std::to_string(n);
    }
    return unique;
}

class Reporter
{
  public:
    /// Looks for python3 with matplotlib once, before any thread writes.
    Reporter(std::string directory, bool plot) : m_directory(std::move(directory))
    {
        if (plot)
        {
            m_python = FindPlottingPython();
            if (m_python.empty())
            {
                std::fprintf(stderr, "meff validate: no plots: no python3 with matplotlib found "
                                     "(install python3-matplotlib, or set MEFF_PYTHON); "
                                     "summary.json and divergence.csv are written\n");
            }
        }
    }

    /// Writes DIRECTORY/summary.json, divergence.csv and errors.png; throws
    /// std::runtime_error when a file cannot be written. A plot that cannot be drawn is said,
    /// not fatal. Several threads may write at once, each to its own scene's folder.
    void Write(const Scene& scene, const ValidationResult& result, const std::string& directoryName,
               const validation::PlausibilityResult* plausibility) const
    {
        const std::filesystem::path directory = std::filesystem::path(m_directory) / directoryName;
        std::error_code error;
        std::filesystem::create_directories(directory, error);
        if (error)
        {
            throw std::runtime_error("cannot create " + directory.string() + ": " +
                                     error.message());
        }
        OutputFile summary((directory / "summary.json").string());
        nlohmann::json json = SummaryJson(result);
        if (plausibility)
        {
            json["plausibility"] = PlausibilityJson(*plausibility);
        }
        const std::string text = json.dump(2) + "\n";
        std::fputs(text.c_str(), summary.Stream());
        OutputFile csv((directory / "divergence.csv").string());
        WriteDivergenceCsv(scene, result, csv.Stream());
        summary.Commit();
        csv.Commit();
        // A plot left from an earlier run would no longer match divergence.csv.
        if (m_python.empty() || !Plot(result, directory, csv.Path()))
        {
            std::filesystem::remove(directory / "errors.png", error);
        }
    }

    /// DIRECTORY/summary.json alone, for a scene held only to the plausibility checks.
    void WriteSummary(const nlohmann::json& summary, const std::string& directoryName) const
    {
        const std::filesystem::path directory = std::filesystem::path(m_directory) / directoryName;
        std::error_code error;
        std::filesystem::create_directories(directory, error);
        if (error)
        {
            throw std::runtime_error("cannot create " + directory.string() + ": " +
                                     error.message());
        }
        OutputFile file((directory / "summary.json").string());
        const std::string text = summary.dump(2) + "\n";
        std::fputs(text.c_str(), file.Stream());
        file.Commit();
    }

  private:
    /// Draws errors.png; false when it could not be drawn.
    bool Plot(const ValidationResult& result, const std::filesystem::path& directory,
              const std::string& csvPath) const
    {
        const std::string script = MEFF_PLOT_SCRIPT;
        if (script.empty())
        {
            return false;
        }
        const std::filesystem::path png = directory / "errors.png";
        const std::filesystem::path temporary =
            directory / (".errors.png." + std::to_string(getpid()));
        const validation::Tolerances& tol = result.tolerances;
        std::vector<std::string> arguments = {m_python,
                                              script,
                                              csvPath,
                                              temporary.string(),
                                              "--title",
                                              result.scene + " (block solver " +
                                                  (result.blockSolver ? "on" : "off") + ")",
                                              "--tolerances",
                                              Number(tol.position),
                                              Number(tol.angle),
                                              Number(tol.velocity),
                                              Number(tol.impulse)};
        if (result.divergenceFrame)
        {
            arguments.push_back("--divergence");
            arguments.push_back(std::to_string(*result.divergenceFrame));
        }
        if (result.chaotic)
        {
            arguments.push_back("--horizon");
            arguments.push_back(std::to_string(result.horizonFrames));
        }
        std::error_code error;
        const std::string temporaryText = temporary.string();
        const int registration = RegisterTemporary(temporaryText); // removed if interrupted
        const int status = RunProgram(arguments, false);
        if (status != 0)
        {
            std::filesystem::remove(temporary, error);
            UnregisterTemporary(registration);
            std::fprintf(stderr, "meff validate: %s: the plot could not be drawn (%s)\n",
                         result.scene.c_str(), script.c_str());
            return false;
        }
        std::filesystem::rename(temporary, png, error);
        if (error)
        {
            std::filesystem::remove(temporary, error);
            UnregisterTemporary(registration);
            throw std::runtime_error("cannot write " + png.string() + ": " + error.message());
        }
        UnregisterTemporary(registration);
        return true;
    }

    std::string m_directory;
    std::string m_python; ///< empty: no plots
};

/// Creates `directory` if needed and proves a file can be written in it (a trial file,
/// discarded unwritten); otherwise says why in one line.
bool CanWriteInto(const std::string& directory)
{
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error)
    {
        std::fprintf(stderr, "meff validate: cannot create %s: %s\n", directory.c_str(),
                     error.message().c_str());
        return false;
    }
    try
    {
        OutputFile probe((std::filesystem::path(directory) / "summary.json").string());
    }
    catch (const std::runtime_error& failure)
    {
        std::fprintf(stderr, "meff validate: %s\n", failure.what());
        return false;
    }
    return true;
}

/// Loads the scenes and builds each once: bad input (a file that does not load, or a scene the
/// engine refuses) is reported before anything runs, and then nothing runs.
std::optional<std::vector<Scene>> LoadScenes(const std::vector<std::string>& paths)
{
    std::vector<Scene> scenes;
    bool bad = false;
    for (const std::string& path : paths)
    {
        std::optional<Scene> scene = LoadSceneOrReport(path);
        if (scene && BuildWorldOrReport(*scene))
        {
            scenes.push_back(std::move(*scene));
        }
        else
        {
            bad = true;
        }
    }
    if (bad)
    {
        return std::nullopt;
    }
    return scenes;
}

/// One scene's outcome, kept until its turn to be printed comes.
struct SceneOutcome
{
    ValidationResult result; ///< without perFrame, once the report is written
    bool compared = true;    ///< false: only the plausibility checks ran (--solver not box2d)
    std::optional<validation::PlausibilityResult> plausibility;
    double seconds = 0;
    std::string reportError;              ///< the report could not be written: why
    std::vector<std::string> sceneErrors; ///< the engine refused the scene
};

void WriteJUnit(const ValidateOptions& options, const std::vector<JUnitCase>& cases, double seconds)
{
    std::string suite = "meff validate";
    if (options.shard.count > 1)
    {
        suite += " (shard " + std::to_string(options.shard.index) + "/" +
                 std::to_string(options.shard.count) + ")";
    }
    OutputFile file(options.junitPath);
    const std::string xml = JUnitDocument(suite, cases, seconds);
    std::fputs(xml.c_str(), file.Stream());
    file.Commit();
}

int Validate(const ValidateOptions& options)
{
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::string> paths;
    for (const std::size_t index : ShardOf(options.scenePaths, options.shard))
    {
        paths.push_back(options.scenePaths[index]);
    }
    // Every scene is loaded and built before anything runs: bad input runs nothing.
    const std::optional<std::vector<Scene>> scenes = LoadScenes(paths);
    if (!scenes)
    {
        return kExitBadInput;
    }

    validation::RunOptions run;
    run.frames = options.frames;
    run.meffVelocityIterations = options.meffVelocityIterations;
    if (options.blockSolver != "scene")
    {
        run.blockSolver = options.blockSolver == "on";
    }

    if (!options.junitPath.empty())
    {
        // As for the report folder: a JUnit file that cannot be written is said before the run.
        try
        {
            OutputFile probe(options.junitPath);
        }
        catch (const std::runtime_error& error)
        {
            std::fprintf(stderr, "meff validate: %s\n", error.what());
            return kExitBadInput;
        }
    }
    std::optional<Reporter> reporter;
    std::vector<std::string> directories;
    if (!options.reportDir.empty())
    {
        // A report folder that cannot be written is bad input, said before anything runs.
        if (!CanWriteInto(options.reportDir))
        {
            return kExitBadInput;
        }
        reporter.emplace(options.reportDir, !options.noPlot);
        // Named in input order, whatever order the threads finish in.
        std::set<std::string> used;
        for (const Scene& scene : *scenes)
        {
            directories.push_back(DirectoryName(scene.name, used));
        }
    }

    std::vector<SceneOutcome> outcomes(scenes->size());
    std::vector<JUnitCase> cases;
    bool allPassed = true;
    bool writeFailed = false;
    bool refused = false;
    Progress progress("validate", int(scenes->size()), "scenes");
    const auto work = [&](std::size_t i)
    {
        const auto sceneStart = std::chrono::steady_clock::now();
        SceneOutcome& outcome = outcomes[i];
        const Scene& scene = (*scenes)[i];
        const std::optional<SolverKind> solver = SolverOption(options);
        outcome.compared = solver.value_or(SolverKind::Box2D) == SolverKind::Box2D;
        try
        {
            if (outcome.compared)
            {
                Scene compared = scene;
                compared.world.solver.kind = SolverKind::Box2D;
                outcome.result = validation::Validate(solver ? compared : scene, run);
            }
            if (!outcome.compared || options.plausibility)
            {
                outcome.plausibility = validation::CheckPlausibility(scene, solver, options.frames);
            }
        }
        catch (const SceneError& error)
        {
            outcome.sceneErrors = error.messages();
            return;
        }
        if (reporter)
        {
            try
            {
                if (outcome.compared)
                {
                    reporter->Write(scene, outcome.result, directories[i],
                                    outcome.plausibility ? &*outcome.plausibility : nullptr);
                }
                else
                {
                    reporter->WriteSummary(
                        {{"scene", scene.name},
                         {"source", scene.sourcePath},
                         {"passed", outcome.plausibility->passed},
                         {"plausibility", PlausibilityJson(*outcome.plausibility)}},
                        directories[i]);
                }
            }
            catch (const std::runtime_error& error)
            {
                outcome.reportError = error.what();
            }
        }
        outcome.result.perFrame = {}; // written: no need to hold every frame until the end
        outcome.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - sceneStart).count();
    };
    const auto finish = [&](std::size_t i)
    {
        const SceneOutcome& outcome = outcomes[i];
        progress.Clear();
        if (refused || !outcome.sceneErrors.empty())
        {
            // Checked before the run, so not expected; said as bad input all the same.
            for (const std::string& message : outcome.sceneErrors)
            {
                std::fprintf(stderr, "%s\n", message.c_str());
            }
            refused = true;
            return;
        }
        JUnitCase testCase;
        if (outcome.compared)
        {
            std::fputs(ResultText(outcome.result).c_str(), stdout);
            testCase = JUnitCaseOf(outcome.result, outcome.seconds);
            allPassed = allPassed && outcome.result.passed;
        }
        else
        {
            testCase.name = (*scenes)[i].name;
            testCase.className = "meff.validate";
            testCase.file = (*scenes)[i].sourcePath;
            testCase.seconds = outcome.seconds;
        }
        if (outcome.plausibility)
        {
            std::fputs(PlausibilityText(*outcome.plausibility).c_str(), stdout);
            AddPlausibilityToCase(*outcome.plausibility, testCase);
            allPassed = allPassed && outcome.plausibility->passed;
        }
        std::fflush(stdout);
        if (!outcome.reportError.empty())
        {
            std::fprintf(stderr, "meff validate: %s\n", outcome.reportError.c_str());
            writeFailed = true;
        }
        cases.push_back(std::move(testCase));
        outcomes[i] = {}; // printed: keep only the JUnit case
        progress.Update(int(i + 1));
    };
    RunInOrder(scenes->size(), ResolveJobs(options.jobs), work, finish);
    progress.Finish();
    if (refused)
    {
        return kExitBadInput;
    }
    if (!options.junitPath.empty())
    {
        try
        {
            WriteJUnit(
                options, cases,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
        catch (const std::runtime_error& error)
        {
            std::fprintf(stderr, "meff validate: %s\n", error.what());
            writeFailed = true;
        }
    }
    if (reporter && !writeFailed)
    {
        std::printf("reports in %s/\n", options.reportDir.c_str());
    }
    return allPassed && !writeFailed ? kExitOk : kExitRunFailed;
}

} // namespace

Command AddValidateCommand(CLI::App& parent)
{
    auto options = std::make_shared<ValidateOptions>();
    CLI::App* app = parent.add_subcommand(
        "validate",
        "Run scenes in meff and in Box2D 2.4.1 side by side and compare them frame by frame: "
        "positions, angles, velocities, contact and joint impulses.\n"
        "Prints one line per scene, PASS or FAIL, with each maximum error and where it "
        "happened. With --solver colour or soft_step, each scene is instead held to the "
        "plausibility checks, a PASS or FAIL line per scene with each figure and its limit. "
        "Exit status 0 when every scene passes, 1 when any fails, 2 for bad input.");
    app->add_option("scenes", options->scenePaths, "Scene files (JSON)")
        ->required()
        ->type_name("SCENE.json...");
    AddFormatOption(app);
    app->add_option("--frames", options->frames,
                    "Number of steps to compare (default: each scene's world.frames)")
        ->type_name("N")
        ->check(CLI::NonNegativeNumber);
    app->add_option("--report", options->reportDir,
                    "Write DIR/<scene>/summary.json, divergence.csv (one row per frame) and "
                    "errors.png (a plot of the errors, if python3 with matplotlib is present)")
        ->type_name("DIR");
    app->add_option("--block-solver", options->blockSolver,
                    "Contact block solver in both engines: on, off (pure scalar form), or as "
                    "the scene says (default)")
        ->check(CLI::IsMember({"on", "off", "scene"}));
    app->add_flag("--no-plot", options->noPlot, "Skip the PNG plots");
    AddJobsOption(app, options->jobs, "Validate scenes");
    AddShardOption(app, options->shard, "scenes");
    app->add_option("--junit", options->junitPath,
                    "Also write JUnit XML: one test case per scene; a failure gives the "
                    "divergence frame, each quantity that exceeded its tolerance, the body, "
                    "contact point or joint, and both engines' values there")
        ->type_name("FILE.xml");
    app->add_option("--solver", options->solver,
                    "Run every scene with this back end: box2d (compared with Box2D frame by "
                    "frame), colour or soft_step (held to the plausibility checks instead: "
                    "no NaN, energy, rebound, joint gaps, penetration, speed, rest; "
                    "docs/validation.md), or each scene's own (scene, the default)")
        ->check(CLI::IsMember({"scene", "box2d", "colour", "soft_step"}));
    app->add_flag("--plausibility", options->plausibility,
                  "Also run the plausibility checks where the scenes are compared with Box2D");
    // Hidden: makes meff differ from Box2D on purpose, to show that validation can fail.
    app->add_option("--meff-velocity-iterations", options->meffVelocityIterations,
                    "meff's velocity iterations (Box2D keeps the scene's)")
        ->check(CLI::Range(1, 1000))
        ->group("");
    return {app, [options] { return Validate(*options); }};
}

} // namespace meff::cli
