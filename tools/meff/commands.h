// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The subcommands of the `meff` tool. Each lives in its own file and registers itself on the
// top-level CLI11 app; main() runs the one the user chose.
#pragma once

#include "meff/b2djson.h"
#include "meff/scene.h"

#include <CLI/CLI.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace meff::cli
{

/// Exit statuses shared by every subcommand.
enum ExitStatus : int
{
    kExitOk = 0,
    kExitRunFailed = 1, ///< the simulation failed, or its output could not be written
    kExitBadInput = 2,  ///< bad scene file or command line: nothing was run
};

/// A registered subcommand: `run` is called when `app` was the one parsed.
struct Command
{
    CLI::App* app = nullptr;
    std::function<int()> run;
};

/// `meff run SCENE.json [--frames N] [--threads N] [--trajectory OUT.csv] [--contacts OUT.csv]
/// [--joints OUT.csv]`
Command AddRunCommand(CLI::App& parent);

/// `meff validate SCENE.json... [--frames N] [--report DIR] [--block-solver on|off|scene]
/// [--no-plot]`
Command AddValidateCommand(CLI::App& parent);

/// `meff render SCENE.json --out DIR [--frames N] [--every K] [--size WxH]
/// [--camera x,y,height] [--contacts] [--impulses] [--joints] [--overlay-box2d]
/// [--gif FILE | --mp4 FILE] [--jobs N] [--threads T]`
Command AddRenderCommand(CLI::App& parent);
/// "WxH" with each between 1 and render::kMaxImageSize (8192): an image's or window's size.
bool ParseImageSize(const std::string& text, int& width, int& height);

/// `meff view SCENE [--script FILE] [--size WxH]`: the scene in a window (tools/view).
Command AddViewCommand(CLI::App& parent);

/// `meff bench SCENE.json... [--steps N] [--runs R] [--threads T] [--json FILE]`
Command AddBenchCommand(CLI::App& parent);

/// `meff sweep SCENE.json [--out DIR] [--quick] [--seconds S] [--runs R] [--no-plot]
/// [--jobs N] [--threads T]`
Command AddSweepCommand(CLI::App& parent);

/// Adds `--solver box2d|colour|soft_step` to a subcommand; `kind` stays empty when the option is
/// not given. `what` opens its help: what the choice does in this command (most commands run
/// it instead of the scene's world.solver: ApplySolverOption).
CLI::Option* AddSolverOption(
    CLI::App& app, std::optional<SolverKind>& kind,
    const std::string& what = "Solver back end to run instead of the scene's world.solver");

/// The scene as `--solver` asks (its world.solver.kind replaced), or unchanged without it.
void ApplySolverOption(const std::optional<SolverKind>& kind, Scene& scene);

/// `meff import LEVEL.json -o SCENE.json`: a b2dJson level as a meff scene file
Command AddImportCommand(CLI::App& parent);

/// `meff export SCENE.json -o LEVEL.json [--hex-floats]`: a scene as a b2dJson level
Command AddExportCommand(CLI::App& parent);

/// Adds `--format auto|meff|b2djson` to a subcommand: how LoadSceneOrReport reads files; and
/// the limits' options (AddLimitOptions) and AddImportOptions.
void AddFormatOption(CLI::App* app);

/// Adds `--max-bodies`, `--max-shapes`, `--max-joints`, `--max-pairs` and `--max-file-size`:
/// the SceneLimits that LoadSceneOrReport and SceneLimitsOfOptions() give.
void AddLimitOptions(CLI::App* app);
const SceneLimits& SceneLimitsOfOptions();

/// Adds `--b2djson-chains two_sided|one_sided` and `--b2djson-springs 2.3|2.4.1`: how a
/// b2dJson level authored for Box2D 2.3 is read (ImportOptions()).
void AddImportOptions(CLI::App* app);

/// The options AddImportOptions set in this process.
const B2dJsonImportOptions& ImportOptions();

/// Loads a scene in either format (see AddFormatOption); prints what a b2dJson level loses
/// (one warning line each) to stderr. On failure prints every problem to stderr, one per line,
/// and returns nullopt; `problems`, when given, receives the same lines.
std::optional<Scene> LoadSceneOrReport(const std::string& path,
                                       std::vector<std::string>* problems = nullptr);

/// Builds a loaded scene's world; on failure prints every problem to stderr, one per line, and
/// returns nullopt; `problems`, when given, receives the same lines.
std::optional<BuiltScene> BuildWorldOrReport(const Scene& scene,
                                             std::vector<std::string>* problems = nullptr);

} // namespace meff::cli
