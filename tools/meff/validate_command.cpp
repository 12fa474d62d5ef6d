// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// `meff validate`: runs scenes in meff and in Box2D 2.4.1 side by side and compares them frame
// by frame (see validation/include/meff/validation.h for what is compared and how).
#include "baseline_files.h"
#include "commands.h"
#include "html_report.h"
#include "junit.h"
#include "output_file.h"
#include "parallel.h"
#include "plausibility_report.h"
#include "plot_program.h"
#include "progress.h"

#include "meff_version.h"

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
    bool pngPlots = false; ///< also errors.png, drawn by matplotlib
    int jobs = 0;          ///< 0: one per core
    Shard shard;
    std::string junitPath;
    std::optional<int> meffVelocityIterations; // hidden: proves the comparison can fail
    /// --solver: every scene's back end (unset: each its own). Another than box2d cannot be
    /// compared with Box2D frame by frame, so it is held to the plausibility checks instead.
    std::optional<SolverKind> solver;
    bool plausibility = false; ///< --plausibility: the checks also beside the comparison
    /// --baseline DIR: compare each scene with its run recorded there, not with Box2D
    std::string baselineDir;
    bool record = false;                 ///< --record: record the baselines instead
    std::vector<std::string> tolerances; ///< --tolerance NAME=VALUE (baselines)
    bool bitExact = false;               ///< --bit-exact: every baseline tolerance 0
    bool acceptSceneChange = false;      ///< --accept-scene-change
};

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
                " / " + result.reference + " " + std::to_string(result.box2dVelocityIterations);
    }
    line += "; max " + FormatMaximum("position", "m", result.position) + ", " +
            FormatMaximum("angle", "rad", result.angle) + ", " +
            FormatMaximum("velocity", "m/s", result.velocity) + ", " +
            FormatMaximum("contact impulse", "N·s", result.contactImpulse) + ", " +
            FormatMaximum("joint impulse", "N·s", result.jointImpulse);
    line += "; contact points only in meff " + std::to_string(result.onlyInMeff) + ", only in " +
            result.reference + " " + std::to_string(result.onlyInBox2D) +
            "; awake flags differing " + std::to_string(result.awakeMismatches);
    // With a setting Box2D cannot mirror (and no chaotic horizon), frames after the first are
    // reported, not judged: the line says what was compared, never "PASS ... diverged".
    const bool judgedFrameByFrame = result.unmirrored.empty() || result.chaotic;
    if (!judgedFrameByFrame)
    {
        line += "; compared: frame 0 and the settled state";
    }
    if (result.divergenceFrame)
    {
        std::string what;
        for (const std::string& quantity : result.divergenceQuantities)
        {
            what += (what.empty() ? "" : ", ") + quantity;
        }
        line += (judgedFrameByFrame || *result.divergenceFrame == 0
                     ? "; diverged at frame "
                     : "; frame by frame (not judged) first apart at frame ") +
                std::to_string(*result.divergenceFrame) + " (" + what + ")";
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
    for (const validation::CheckFailure& failure : result.checkFailures)
    {
        text += "  " + failure.check + ": " + failure.message + "\n";
        for (const std::string& detail : failure.details)
        {
            text += "    " + detail + "\n";
        }
    }
    for (const std::string& note : result.notes)
    {
        text += "  note: " + note + "\n";
    }
    return text;
}

/// "position 0.00012 > 0.0001 at box3: meff (1, 2) m, Box2D (1, 2.0001) m" (or "baseline")
std::string DetailText(const validation::DivergenceDetail& detail, const std::string& reference)
{
    return detail.quantity + " " + Number(detail.error) + " > " + Number(detail.tolerance) +
           " at " + detail.where + ": meff " + detail.meff + ", " + reference + " " + detail.box2d;
}

/// The scene as a JUnit test case: a failure carries the divergence frame, each quantity that
/// exceeded, where, and both engines' values there.
JUnitCase JUnitCaseOf(const ValidationResult& result, double seconds)
{
    JUnitCase testCase;
    testCase.name = result.sourcePath;
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
    if (!result.comparisonPassed)
    {
        if (result.divergenceFrame &&
            (!result.chaotic || *result.divergenceFrame <= result.horizonFrames))
        {
            testCase.type = "divergence";
            std::string what;
            for (const std::string& quantity : result.divergenceQuantities)
            {
                what += (what.empty() ? "" : ", ") + quantity;
            }
            testCase.message = "diverged from " + result.reference + " at frame " +
                               std::to_string(*result.divergenceFrame) + ": " + what;
            for (const validation::DivergenceDetail& detail : result.divergenceDetails)
            {
                testCase.text += "frame " + std::to_string(*result.divergenceFrame) + ": " +
                                 DetailText(detail, result.reference) + "\n";
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
    }
    // The extra checks' failures: the first names the case's type when the comparison held.
    for (const validation::CheckFailure& failure : result.checkFailures)
    {
        if (testCase.type.empty())
        {
            testCase.type = failure.check;
            testCase.message = failure.message;
        }
        testCase.text += failure.check + ": " + failure.message + "\n";
        for (const std::string& detail : failure.details)
        {
            testCase.text += "  " + detail + "\n";
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
    summary["meff_version"] = MEFF_VERSION;
    summary["status"] = result.passed ? "passed" : "failed";
    summary["reference"] = result.reference;
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
    nlohmann::json checks = nlohmann::json::array();
    for (const validation::CheckFailure& failure : result.checkFailures)
    {
        checks.push_back(
            {{"check", failure.check}, {"message", failure.message}, {"details", failure.details}});
    }
    summary["check_failures"] = checks;
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
    /// Looks for python3 with matplotlib once, before any thread writes (`pngPlots`).
    Reporter(std::string directory, bool plot, bool pngPlots)
        : m_directory(std::move(directory)), m_plot(plot)
    {
        if (plot && pngPlots)
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

    /// Writes DIRECTORY/summary.json (with the plausibility checks' results, when they ran),
    /// divergence.csv, errors.png (with --png-plots) and, for a level that diverged, the frames
    /// before and at the divergence; puts the page's plot and pictures in `row`. Throws
    /// std::runtime_error when a file cannot be written. A plot or picture that cannot be drawn
    /// is said, not fatal. Several threads may write at once, each to its own scene's folder.
    void Write(const Scene& scene, const ValidationResult& result, const std::string& directoryName,
               const validation::PlausibilityResult* plausibility, ReportRow& row) const
    {
        const std::filesystem::path directory = Folder(directoryName);
        std::error_code error;
        if (m_plot)
        {
            row.plotSvg = ErrorPlotSvg(result);
        }
        // The pictures overlay Box2D 2.4.1's bodies: a baseline has no world to draw.
        if (!result.passed && result.divergenceFrame && result.reference == "Box2D")
        {
            try
            {
                row.images = DrawDivergenceFrames(scene, result, m_directory, directoryName);
            }
            catch (const Error& error) // render::RenderError, and what the engines throw
            {
                std::fprintf(stderr, "meff validate: %s: the divergence could not be drawn: %s\n",
                             result.sourcePath.c_str(), error.what());
            }
        }
        else
        {
            std::filesystem::remove(directory / "before.png", error);
            std::filesystem::remove(directory / "at.png", error);
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

    /// Writes DIRECTORY/summary.json alone (a level not compared: skipped, refused, or held
    /// only to the plausibility checks), and removes what an earlier run left beside it.
    void WriteSummary(const nlohmann::json& summary, const std::string& directoryName) const
    {
        const std::filesystem::path directory = Folder(directoryName);
        std::error_code error;
        OutputFile file((directory / "summary.json").string());
        const std::string text = summary.dump(2) + "\n";
        std::fputs(text.c_str(), file.Stream());
        file.Commit();
        for (const char* stale : {"divergence.csv", "errors.png", "before.png", "at.png"})
        {
            std::filesystem::remove(directory / stale, error);
        }
    }

  private:
    /// The level's folder, created if missing; throws std::runtime_error when it cannot be.
    std::filesystem::path Folder(const std::string& directoryName) const
    {
        const std::filesystem::path directory = std::filesystem::path(m_directory) / directoryName;
        std::error_code error;
        std::filesystem::create_directories(directory, error);
        if (error)
        {
            throw std::runtime_error("cannot create " + directory.string() + ": " +
                                     error.message());
        }
        return directory;
    }

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
    bool m_plot = true;   ///< the page's plots
    std::string m_python; ///< empty: no errors.png
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

/// Why a level was refused, unless its baseline was (RunWithBaseline).
const std::string kCannotLoad = "cannot be loaded or built";

/// What became of one level given on the command line.
enum class LevelStatus
{
    Runnable, ///< loaded and built: it is validated
    Skipped,  ///< uses what Box2D 2.4.1 lacks (validation::Unmirrorable): documented, not run
    Refused,  ///< could not be loaded or built: bad input, said as an error case
};

/// One level given on the command line, loaded (or why not), and what its run gave.
struct Level
{
    std::string path;
    LevelStatus status = LevelStatus::Runnable;
    std::optional<Scene> scene;
    std::vector<std::string> problems; ///< why it was skipped or refused, one line each
    std::string directory;             ///< its folder under --report

    ValidationResult result; ///< without perFrame, once the report is written
    bool compared = true;    ///< false: only the plausibility checks ran (--solver not box2d)
    std::optional<validation::PlausibilityResult> plausibility;
    double seconds = 0;
    std::string reportError;   ///< the report could not be written: why
    bool refusedByRun = false; ///< refused by validation::Validate: problems not printed yet
    std::string refusal = kCannotLoad; ///< why it was refused, in short
    std::string recorded;              ///< --record: the line saying where its baseline went
    ReportRow row;                     ///< its part of index.html (--report)
};

/// Loads and builds each level once. A level that does not load or build is refused (its
/// messages printed to stderr), and one to be compared with Box2D that needs what Box2D 2.4.1
/// lacks is skipped; the others run. `solver` (--solver) decides which are compared: all with
/// box2d or unset, none with another back end (plausibility checks instead); with a baseline
/// (`baseline`), every level is compared with it, whatever it uses.
std::vector<Level> LoadLevels(const std::vector<std::string>& paths,
                              const std::optional<SolverKind>& solver, bool baseline)
{
    std::vector<Level> levels;
    for (const std::string& path : paths)
    {
        Level& level = levels.emplace_back();
        level.path = path;
        level.scene = LoadSceneOrReport(path, &level.problems);
        if (!level.scene)
        {
            level.status = LevelStatus::Refused;
            continue;
        }
        level.compared = baseline || solver.value_or(SolverKind::Box2D) == SolverKind::Box2D;
        if (level.compared && !baseline)
        {
            level.problems = validation::Unmirrorable(*level.scene);
        }
        if (!level.problems.empty())
        {
            level.status = LevelStatus::Skipped; // NotRunText names each field
        }
        else if (!BuildWorldOrReport(*level.scene, &level.problems))
        {
            level.status = LevelStatus::Refused;
        }
    }
    return levels;
}

/// The test case name of each level: its file path, made unique when a path is given twice.
std::vector<std::string> CaseNames(const std::vector<Level>& levels)
{
    std::vector<std::string> names;
    std::set<std::string> used;
    for (const Level& level : levels)
    {
        std::string name = level.path;
        for (int n = 2; !used.insert(name).second; ++n)
        {
            name = level.path + " #" + std::to_string(n);
        }
        names.push_back(name);
    }
    return names;
}

/// A level that was not run, as its PASS/FAIL line would stand: "SKIP ..." with each field
/// Box2D lacks, or "ERROR ..." (its problems are on stderr, as every command says bad input).
std::string NotRunText(const Level& level)
{
    if (level.status == LevelStatus::Refused)
    {
        return "ERROR " + level.path + ": " + level.refusal + " (" +
               std::to_string(level.problems.size()) +
               (level.problems.size() == 1 ? " problem" : " problems") + ", on stderr)\n";
    }
    std::string text =
        "SKIP " + level.path + ": uses what Box2D 2.4.1 does not have, so it cannot be compared\n";
    for (const std::string& problem : level.problems)
    {
        text += "  " + problem + "\n";
    }
    return text;
}

/// The level's test case, passing until told otherwise.
JUnitCase PlainCase(const Level& level, const std::string& name)
{
    JUnitCase testCase;
    testCase.name = name;
    testCase.className = "meff.validate";
    testCase.file = level.path;
    testCase.seconds = level.seconds;
    return testCase;
}

JUnitCase NotRunCase(const Level& level, const std::string& name)
{
    JUnitCase testCase = PlainCase(level, name);
    testCase.output = NotRunText(level);
    testCase.outcome = level.status == LevelStatus::Skipped ? JUnitCase::Outcome::Skipped
                                                            : JUnitCase::Outcome::Error;
    testCase.type = level.status == LevelStatus::Skipped ? "unmirrored"
                    : level.refusal == kCannotLoad       ? "scene"
                                                         : "baseline";
    testCase.message =
        level.problems.empty() ? std::string("cannot be loaded") : level.problems.front();
    for (const std::string& problem : level.problems)
    {
        testCase.text += problem + "\n";
    }
    return testCase;
}

/// summary.json of a level that was not run: why.
nlohmann::json NotRunSummary(const Level& level)
{
    return {{"meff_version", MEFF_VERSION},
            {"status", level.status == LevelStatus::Skipped ? "skipped" : "error"},
            {"scene", level.scene ? nlohmann::json(level.scene->name) : nlohmann::json()},
            {"source", level.path},
            {"passed", false},
            {"problems", level.problems}};
}

/// A level's row of index.html: its outcome, errors and pictures.
ReportRow RowOf(Level& level, const JUnitCase& testCase)
{
    ReportRow row = std::move(level.row);
    row.path = level.path;
    row.scene = level.scene ? level.scene->name : "";
    row.directory = level.directory;
    row.text = testCase.output;
    if (level.status != LevelStatus::Runnable)
    {
        row.status = level.status == LevelStatus::Skipped ? "skipped" : "error";
        if (level.status == LevelStatus::Refused) // its problems went to stderr
        {
            for (const std::string& problem : level.problems)
            {
                row.text += "  " + problem + "\n";
            }
        }
        return row;
    }
    if (!level.recorded.empty())
    {
        row.status = "passed";
        return row;
    }
    const bool plausible = !level.plausibility || level.plausibility->passed;
    if (level.plausibility)
    {
        row.text = (level.compared ? ResultText(level.result) : "") +
                   PlausibilityText(*level.plausibility);
    }
    if (!level.compared) // held to the plausibility checks alone
    {
        row.status = plausible ? "passed" : "failed";
        return row;
    }
    const ValidationResult& result = level.result;
    row.status = result.passed && plausible ? "passed" : "failed";
    row.ran = true;
    row.frames = result.frames;
    row.divergenceFrame = result.divergenceFrame;
    for (const validation::DivergenceDetail& detail : result.divergenceDetails)
    {
        row.divergence +=
            (row.divergence.empty() ? "" : "; ") + DetailText(detail, result.reference);
    }
    if (!row.divergence.empty())
    {
        row.divergence = "frame " + std::to_string(*result.divergenceFrame) + ": " + row.divergence;
    }
    row.position = result.position.value;
    row.angle = result.angle.value;
    row.velocity = result.velocity.value;
    row.contactImpulse = result.contactImpulse.value;
    row.jointImpulse = result.jointImpulse.value;
    return row;
}

/// Creates the folder a file is to be written in, if missing; false (said) when it cannot.
bool CreateParentFolder(const std::string& path)
{
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    std::error_code error;
    if (!parent.empty())
    {
        std::filesystem::create_directories(parent, error);
    }
    if (error)
    {
        std::fprintf(stderr, "meff validate: cannot create %s: %s\n", parent.string().c_str(),
                     error.message().c_str());
        return false;
    }
    return true;
}

/// --baseline: records the level's run (--record) or compares it with the recorded one, in the
/// back end --solver names or the scene's own. A baseline that cannot be written, read or used
/// refuses the level with its one line; the other levels still run.
void RunWithBaseline(const ValidateOptions& options, const validation::RunOptions& run,
                     Level& level)
{
    Scene scene = *level.scene;
    scene.world.solver.kind = options.solver.value_or(scene.world.solver.kind);
    const std::string file = BaselineFile(options.baselineDir, level.path);
    try
    {
        if (options.record)
        {
            level.recorded = RecordBaselineFile(scene, run, file);
            return;
        }
        level.result = CompareWithBaselineFile(
            scene, run, file, BaselineTolerances(options.tolerances, options.bitExact),
            options.acceptSceneChange);
    }
    catch (const std::runtime_error& error) // validation::BaselineError, OutputFile's
    {
        level.status = LevelStatus::Refused;
        level.problems = {error.what()};
        level.refusedByRun = true;
        level.refusal =
            options.record ? "its baseline could not be recorded" : "its baseline cannot be used";
    }
}

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
    // Every level is loaded and built before anything runs; one that cannot be is reported
    // as its own case, and the others still run.
    std::vector<Level> levels = LoadLevels(paths, options.solver, !options.baselineDir.empty());
    const std::vector<std::string> caseNames = CaseNames(levels);

    validation::RunOptions run;
    run.frames = options.frames;
    run.meffVelocityIterations = options.meffVelocityIterations;
    if (options.blockSolver != "scene")
    {
        run.blockSolver = options.blockSolver == "on";
    }

    if (!options.junitPath.empty())
    {
        // As for the report folder: its folder is created, and a JUnit file that cannot be
        // written is said before the run.
        if (!CreateParentFolder(options.junitPath))
        {
            return kExitBadInput;
        }
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
    if (!options.reportDir.empty())
    {
        // A report folder that cannot be written is bad input, said before anything runs.
        if (!CanWriteInto(options.reportDir))
        {
            return kExitBadInput;
        }
        reporter.emplace(options.reportDir, !options.noPlot, options.pngPlots);
        // Named in input order, whatever order the threads finish in.
        std::set<std::string> used;
        for (Level& level : levels)
        {
            level.directory = DirectoryName(
                level.scene ? level.scene->name : std::filesystem::path(level.path).stem().string(),
                used);
        }
    }

    std::vector<JUnitCase> cases;
    std::vector<ReportRow> rows; // index.html's, in input order
    bool allPassed = true;
    bool anyRefused = false;
    bool writeFailed = false;
    Progress progress("validate", int(levels.size()), "scenes");
    const auto work = [&](std::size_t i)
    {
        const auto levelStart = std::chrono::steady_clock::now();
        Level& level = levels[i];
        if (level.status == LevelStatus::Runnable)
        {
            try
            {
                if (!options.baselineDir.empty())
                {
                    RunWithBaseline(options, run, level);
                }
                else if (level.compared)
                {
                    Scene compared = *level.scene;
                    compared.world.solver.kind = SolverKind::Box2D;
                    level.result =
                        validation::Validate(options.solver ? compared : *level.scene, run);
                }
                if ((!level.compared || options.plausibility) && level.recorded.empty() &&
                    level.status == LevelStatus::Runnable)
                {
                    level.plausibility =
                        validation::CheckPlausibility(*level.scene, options.solver, options.frames);
                }
            }
            catch (const SceneError& error)
            {
                // Built before the run, so not expected (Box2D's mirror refusing, say); said as
                // the level's error all the same.
                level.status = LevelStatus::Refused;
                level.problems = error.messages();
                level.refusedByRun = true;
            }
        }
        if (reporter)
        {
            try
            {
                if (!level.recorded.empty())
                {
                    reporter->WriteSummary({{"meff_version", MEFF_VERSION},
                                            {"status", "recorded"},
                                            {"scene", level.scene->name},
                                            {"source", level.path},
                                            {"passed", true}},
                                           level.directory);
                }
                else if (level.status == LevelStatus::Runnable && level.compared)
                {
                    reporter->Write(*level.scene, level.result, level.directory,
                                    level.plausibility ? &*level.plausibility : nullptr, level.row);
                }
                else if (level.status == LevelStatus::Runnable)
                {
                    reporter->WriteSummary(
                        {{"meff_version", MEFF_VERSION},
                         {"status", level.plausibility->passed ? "passed" : "failed"},
                         {"scene", level.scene->name},
                         {"source", level.path},
                         {"passed", level.plausibility->passed},
                         {"plausibility", PlausibilityJson(*level.plausibility)}},
                        level.directory);
                }
                else
                {
                    reporter->WriteSummary(NotRunSummary(level), level.directory);
                }
            }
            catch (const std::runtime_error& error)
            {
                level.reportError = error.what();
            }
        }
        level.result.perFrame = {}; // written: no need to hold every frame until the end
        level.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - levelStart).count();
    };
    const auto finish = [&](std::size_t i)
    {
        Level& level = levels[i];
        progress.Clear();
        if (!level.recorded.empty())
        {
            std::fputs(level.recorded.c_str(), stdout);
            cases.push_back(PlainCase(level, caseNames[i]));
            cases.back().output = level.recorded;
        }
        else if (level.status == LevelStatus::Runnable && level.compared)
        {
            std::fputs(ResultText(level.result).c_str(), stdout);
            allPassed = allPassed && level.result.passed;
            cases.push_back(JUnitCaseOf(level.result, level.seconds));
            cases.back().name = caseNames[i];
        }
        else if (level.status == LevelStatus::Runnable)
        {
            cases.push_back(PlainCase(level, caseNames[i]));
        }
        if (level.status == LevelStatus::Runnable && level.plausibility)
        {
            std::fputs(PlausibilityText(*level.plausibility).c_str(), stdout);
            AddPlausibilityToCase(*level.plausibility, cases.back());
            allPassed = allPassed && level.plausibility->passed;
        }
        if (level.status != LevelStatus::Runnable)
        {
            for (const std::string& problem :
                 level.refusedByRun ? level.problems : std::vector<std::string>{})
            {
                std::fprintf(stderr, "%s\n", problem.c_str());
            }
            std::fputs(NotRunText(level).c_str(), stdout);
            anyRefused = anyRefused || level.status == LevelStatus::Refused;
            cases.push_back(NotRunCase(level, caseNames[i]));
        }
        std::fflush(stdout);
        if (reporter)
        {
            rows.push_back(RowOf(level, cases.back()));
        }
        if (!level.reportError.empty())
        {
            std::fprintf(stderr, "meff validate: %s\n", level.reportError.c_str());
            writeFailed = true;
        }
        level = {}; // printed: keep only the JUnit case
        progress.Update(int(i + 1));
    };
    RunInOrder(levels.size(), ResolveJobs(options.jobs), work, finish);
    progress.Finish();
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
    if (reporter)
    {
        try
        {
            WriteHtmlReport(options.reportDir, rows,
                            options.baselineDir.empty()
                                ? kBox2DReference
                                : "the baselines in " + options.baselineDir);
        }
        catch (const std::runtime_error& error)
        {
            std::fprintf(stderr, "meff validate: %s\n", error.what());
            writeFailed = true;
        }
    }
    if (reporter && !writeFailed)
    {
        std::printf("reports in %s/ (open %s/index.html)\n", options.reportDir.c_str(),
                    options.reportDir.c_str());
    }
    if (anyRefused)
    {
        return kExitBadInput;
    }
    return allPassed && !writeFailed ? kExitOk : kExitRunFailed;
}

} // namespace

/// --baseline and what goes with it (docs/validation.md, "Baselines").
void AddBaselineOptions(CLI::App& app, ValidateOptions& options)
{
    CLI::Option* baseline =
        app.add_option("--baseline", options.baselineDir,
                       "Compare each scene with its own run recorded in DIR instead of Box2D "
                       "(any back end, the scene's or --solver's): every frame's bodies, contact "
                       "impulses and joint reactions, with the same reports; a missing, stale or "
                       "damaged baseline is an ERROR case")
            ->type_name("DIR");
    CLI::Option* record = app.add_flag("--record", options.record,
                                       "With --baseline: record each scene's run into "
                                       "DIR/<scene path>.baseline.gz instead of comparing")
                              ->needs(baseline);
    const CLI::Validator setting([](std::string& text) { return CheckToleranceSetting(text); }, "");
    CLI::Option* tolerance =
        app.add_option("--tolerance", options.tolerances,
                       "With --baseline: a limit, NAME=VALUE: position (m), angle (rad), "
                       "velocity (m/s, rad/s), impulse (N·s), impulse_relative; repeatable. "
                       "Defaults as against Box2D: 1e-4, 1e-4, 1e-3, 1e-3, 1e-3")
            ->type_name("NAME=VALUE")
            ->check(setting)
            ->needs(baseline)
            ->excludes(record);
    app.add_flag("--bit-exact", options.bitExact,
                 "With --baseline: every limit 0, the run must repeat its baseline bit for bit")
        ->needs(baseline)
        ->excludes(record)
        ->excludes(tolerance);
    app.add_flag("--accept-scene-change", options.acceptSceneChange,
                 "With --baseline: compare even when the scene file or its world settings "
                 "changed since the recording (back end, frames, body and joint counts must "
                 "still match)")
        ->needs(baseline)
        ->excludes(record);
}

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
        "A level that cannot be loaded or built is an ERROR case and one that uses what Box2D "
        "2.4.1 lacks (Box2D v3's shapes, joint springs, characters; rolling resistance) a SKIP "
        "case when it is to be compared; the other levels still run. With --baseline DIR, each "
        "scene is compared with its own run recorded there (--record), in any back end. Exit "
        "status 0 when every level passes or is skipped, 1 when any fails, 2 when any could not "
        "be loaded or built (or its baseline used).");
    app->add_option("scenes", options->scenePaths, "Scene files (JSON)")
        ->required()
        ->type_name("SCENE.json...");
    AddFormatOption(app);
    app->add_option("--frames", options->frames,
                    "Number of steps to compare (default: each scene's world.frames)")
        ->type_name("N")
        ->check(CLI::NonNegativeNumber);
    app->add_option("--report", options->reportDir,
                    "Write DIR/index.html (a row per level: outcome, first divergent frame, "
                    "largest errors; each level's errors plotted; for a divergence, the frames "
                    "before and at it zoomed on the body, Box2D's outlines over meff's) and "
                    "DIR/<level>/summary.json, divergence.csv (one row per frame)")
        ->type_name("DIR");
    app->add_option("--block-solver", options->blockSolver,
                    "Contact block solver in both engines: on, off (pure scalar form), or as "
                    "the scene says (default)")
        ->check(CLI::IsMember({"on", "off", "scene"}));
    app->add_flag("--no-plot", options->noPlot, "Skip the plots (the page's and errors.png)");
    app->add_flag("--png-plots", options->pngPlots,
                  "Also draw DIR/<level>/errors.png with matplotlib (python3-matplotlib; slow: "
                  "seconds per level)");
    AddJobsOption(app, options->jobs, "Validate scenes");
    AddShardOption(app, options->shard, "scenes");
    app->add_option("--junit", options->junitPath,
                    "Also write JUnit XML: one test case per scene; a failure gives the "
                    "divergence frame, each quantity that exceeded its tolerance, the body, "
                    "contact point or joint, and both engines' values there")
        ->type_name("FILE.xml");
    AddSolverOption(*app, options->solver,
                    "Run every scene with this back end: box2d (compared with Box2D frame by "
                    "frame), colour or soft_step (held to the plausibility checks instead: "
                    "no NaN, energy, rebound, joint gaps, penetration, speed, rest, hold; "
                    "docs/validation.md); with --baseline, any is compared with its baseline; "
                    "default: each scene's own");
    app->add_flag("--plausibility", options->plausibility,
                  "Also run the plausibility checks where the scenes are compared with Box2D");
    AddBaselineOptions(*app, *options);
    // Hidden: makes meff differ from Box2D on purpose, to show that validation can fail.
    app->add_option("--meff-velocity-iterations", options->meffVelocityIterations,
                    "meff's velocity iterations (Box2D keeps the scene's)")
        ->check(CLI::Range(1, 1000))
        ->group("");
    return {app, [options] { return Validate(*options); }};
}

} // namespace meff::cli
