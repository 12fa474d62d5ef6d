// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// `meff run`: steps a scene and writes what happened as CSV.
#include "commands.h"
#include "output_file.h"
#include "threads_option.h"

#include <cerrno>
#include <chrono>
#include <cinttypes>
#include <climits>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>
#include <vector>

namespace meff::cli
{

namespace
{

struct RunOptions
{
    std::string scenePath;
    std::optional<int> frames;
    std::string trajectoryPath;
    std::string contactsPath;
    std::string jointsPath;
    std::string savePath;      ///< --save: the world as a scene file
    std::optional<int> saveAt; ///< --save-at: after this frame (default: the last)
    int threads = 1;
    std::optional<SolverKind> solver; ///< instead of the scene's world.solver
};

/// Enough digits that every Real reads back as the same value.
constexpr const char* kRealFormat = sizeof(Real) == sizeof(float) ? "%.9g" : "%.17g";

void WriteReal(std::FILE* stream, Real value)
{
    std::fputc(',', stream);
    std::fprintf(stream, kRealFormat, double(value));
}

/// The three optional CSV outputs. Each row is written as the run goes; the files appear only
/// when the whole run succeeded.
class RunOutputs
{
  public:
    RunOutputs(const RunOptions& options, const Scene& scene, const BuiltScene& built)
        : m_scene(scene), m_built(built)
    {
        m_trajectory = Open(options.trajectoryPath, "frame,time,body,x,y,angle,vx,vy,omega\n");
        m_contacts = Open(options.contactsPath, "frame,body_a,body_b,point,px,py,nx,ny,"
                                                "normal_impulse,tangent_impulse\n");
        m_joints = Open(options.jointsPath, "frame,joint,fx,fy,torque\n");
        m_save = Open(options.savePath, "");
    }

    /// Throws std::runtime_error as soon as an output can no longer be written (a closed
    /// pipe, a full disk): the run stops there.
    void WriteFrame(int frame)
    {
        errno = 0; // CheckWrites reads the reason of a failed write from it
        WriteTrajectory(frame);
        if (frame > 0)
        {
            WriteContacts(frame);
            WriteJoints(frame);
        }
        ForEach([](OutputFile& file) { file.CheckWrites(); });
    }

    /// --save: the world as it is after `frame` as a scene file whose frames are the run's
    /// `frames` left, to replay from there. Throws SceneError (a scene with characters).
    void SaveWorld(int frame, int frames)
    {
        if (!m_save)
        {
            return;
        }
        Scene saved = SceneFromBuilt(m_built, m_scene);
        saved.world.frames = frames - frame;
        errno = 0;
        std::fputs(WriteScene(saved).c_str(), m_save->Stream());
        m_save->CheckWrites();
    }

    void Commit()
    {
        ForEach([](OutputFile& file) { file.Commit(); });
    }

    /// Whether an output is standard output (then the summary goes to standard error).
    bool ToStandardOutput()
    {
        bool any = false;
        ForEach([&](OutputFile& file) { any = any || file.ToStandardOutput(); });
        return any;
    }

  private:
    template <typename Function>
    void ForEach(Function function)
    {
        for (OutputFile* file :
             {m_trajectory.get(), m_contacts.get(), m_joints.get(), m_save.get()})
        {
            if (file != nullptr)
            {
                function(*file);
            }
        }
    }

    static std::unique_ptr<OutputFile> Open(const std::string& path, const char* header)
    {
        if (path.empty())
        {
            return nullptr;
        }
        auto file = std::make_unique<OutputFile>(path);
        std::fputs(header, file->Stream());
        return file;
    }

    const std::string& BodyName(BodyId id) const
    {
        static const std::string unknown = "?";
        const std::optional<std::size_t> index = m_built.SceneIndexOf(id);
        return index ? m_scene.bodies[*index].name : unknown;
    }

    void WriteTrajectory(int frame)
    {
        if (!m_trajectory)
        {
            return;
        }
        std::FILE* out = m_trajectory->Stream();
        const World& world = m_built.world;
        const double time = frame * m_scene.world.dt;
        for (std::size_t i = 0; i < m_scene.bodies.size(); ++i)
        {
            if (m_scene.bodies[i].type == BodyType::Static)
            {
                continue;
            }
            const BodyId id = m_built.bodies[i];
            const Vec2 position = world.GetPosition(id);
            const Vec2 velocity = world.GetLinearVelocity(id);
            std::fprintf(out, "%d,%.9g,%s", frame, time, m_scene.bodies[i].name.c_str());
            WriteReal(out, position.x);
            WriteReal(out, position.y);
            WriteReal(out, world.GetAngle(id));
            WriteReal(out, velocity.x);
            WriteReal(out, velocity.y);
            WriteReal(out, world.GetAngularVelocity(id));
            std::fputc('\n', out);
        }
    }

    void WriteContacts(int frame)
    {
        if (!m_contacts)
        {
            return;
        }
        std::FILE* out = m_contacts->Stream();
        for (const ContactPointReport& contact : m_built.world.GetContactReports())
        {
            std::fprintf(out, "%d,%s,%s,%d", frame, BodyName(contact.bodyA).c_str(),
                         BodyName(contact.bodyB).c_str(), contact.pointIndex);
            WriteReal(out, contact.point.x);
            WriteReal(out, contact.point.y);
            WriteReal(out, contact.normal.x);
            WriteReal(out, contact.normal.y);
            WriteReal(out, contact.normalImpulse);
            WriteReal(out, contact.tangentImpulse);
            std::fputc('\n', out);
        }
    }

    void WriteJoints(int frame)
    {
        if (!m_joints)
        {
            return;
        }
        std::FILE* out = m_joints->Stream();
        // As Box2D computes it: the reciprocal in the engine's precision.
        const Real inverseDt = Real(1) / Real(m_scene.world.dt);
        for (std::size_t j = 0; j < m_scene.joints.size(); ++j)
        {
            const JointReaction reaction = m_built.world.GetReaction(m_built.joints[j], inverseDt);
            std::fprintf(out, "%d,%s", frame, m_scene.joints[j].name.c_str());
            WriteReal(out, reaction.force.x);
            WriteReal(out, reaction.force.y);
            WriteReal(out, reaction.torque);
            std::fputc('\n', out);
        }
    }

    const Scene& m_scene;
    const BuiltScene& m_built;
    std::unique_ptr<OutputFile> m_trajectory;
    std::unique_ptr<OutputFile> m_contacts;
    std::unique_ptr<OutputFile> m_joints;
    std::unique_ptr<OutputFile> m_save;
};

/// Two options naming one file (through links, or both standard output) would race to rename
/// over each other, or interleave their rows.
bool OutputsAreDistinct(const RunOptions& options)
{
    std::vector<const std::string*> seen;
    for (const std::string* path :
         {&options.trajectoryPath, &options.contactsPath, &options.jointsPath, &options.savePath})
    {
        if (path->empty())
        {
            continue;
        }
        for (const std::string* other : seen)
        {
            if (SameOutput(*path, *other))
            {
                std::fprintf(stderr,
                             "meff run: %s and %s are the same file, given for two outputs\n",
                             other->c_str(), path->c_str());
                return false;
            }
        }
        seen.push_back(path);
    }
    return true;
}

int Run(const RunOptions& options)
{
    const auto start = std::chrono::steady_clock::now();
    std::optional<Scene> scene = LoadSceneOrReport(options.scenePath);
    if (!scene || !OutputsAreDistinct(options))
    {
        return kExitBadInput;
    }
    ApplySolverOption(options.solver, *scene);
    const int frames = options.frames.value_or(scene->world.frames);
    const int saveAt = options.saveAt.value_or(frames);
    if (saveAt > frames)
    {
        std::fprintf(stderr, "meff run: --save-at %d: after the run's last frame (%d)\n", saveAt,
                     frames);
        return kExitBadInput;
    }
    if (!options.savePath.empty() && !scene->characters.empty())
    {
        std::fprintf(stderr,
                     "%s: characters: --save cannot save a scene with characters (the character "
                     "mover's state is not in the world)\n",
                     options.scenePath.c_str());
        return kExitBadInput;
    }

    std::optional<BuiltScene> built = BuildWorldOrReport(*scene);
    if (!built)
    {
        return kExitBadInput;
    }
    const std::unique_ptr<TaskSystem> threads = MakeThreads(options.threads);
    built->world.SetTaskSystem(threads.get());

    std::optional<RunOutputs> outputs;
    try
    {
        outputs.emplace(options, *scene, *built);
    }
    catch (const std::runtime_error& error)
    {
        std::fprintf(stderr, "meff run: %s\n", error.what());
        return kExitBadInput;
    }

    const Real dt = Real(scene->world.dt);
    try
    {
        outputs->WriteFrame(0);
        for (int frame = 1; frame <= frames; ++frame)
        {
            if (frame - 1 == saveAt)
            {
                outputs->SaveWorld(saveAt, frames);
            }
            built->Step(dt);
            outputs->WriteFrame(frame);
        }
        if (saveAt == frames)
        {
            outputs->SaveWorld(saveAt, frames);
        }
    }
    catch (const SimulationError& error)
    {
        const std::optional<std::size_t> body = built->SceneIndexOfPoolIndex(error.bodyIndex);
        const std::string bodyText = body ? "body \"" + scene->bodies[*body].name + "\" (bodies[" +
                                                std::to_string(*body) + "])"
                                          : "body #" + std::to_string(error.bodyIndex);
        std::fprintf(
            stderr, "%s: simulation failed at step %" PRIu64 " (frame %" PRIu64 "): %s: %s\n",
            options.scenePath.c_str(), error.step, error.step + 1, bodyText.c_str(), error.what());
        return kExitRunFailed;
    }
    catch (const std::runtime_error& error)
    {
        std::fprintf(stderr, "meff run: %s\n", error.what());
        return kExitRunFailed;
    }

    try
    {
        outputs->Commit();
    }
    catch (const std::runtime_error& error)
    {
        std::fprintf(stderr, "meff run: %s\n", error.what());
        return kExitRunFailed;
    }

    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(outputs->ToStandardOutput() ? stderr : stdout,
                 "%s: %zu bodies, %zu joints, %d frames (%.6g s simulated) in %.3f s\n",
                 scene->name.c_str(), scene->bodies.size(), scene->joints.size(), frames,
                 frames * scene->world.dt, seconds);
    return kExitOk;
}

} // namespace

CLI::Option* AddSolverOption(CLI::App& app, std::optional<SolverKind>& kind,
                             const std::string& what)
{
    std::map<std::string, SolverKind> names;
    std::string typeName;
    for (const SolverKind k : {SolverKind::Box2D, SolverKind::Colour, SolverKind::SoftStep})
    {
        names.emplace(SolverKindName(k), k);
        typeName += typeName.empty() ? "" : "|";
        typeName += SolverKindName(k);
    }
    // The transformer's own description (its map, as "{box2d->0,...}") is left out of the
    // help: the type name lists the choices.
    return app
        .add_option("--solver", kind,
                    what + ": box2d (Box2D 2.4.1, bit-identical), colour (Box2D's rows by "
                           "colour, SIMD: fastest), soft_step (sub-stepped soft joints, rigid "
                           "contacts: most accurate for joints and fast motion; world.soft_step "
                           "holds its settings)")
        ->transform(CLI::CheckedTransformer(names).description(""))
        ->type_name(typeName);
}

void ApplySolverOption(const std::optional<SolverKind>& kind, Scene& scene)
{
    if (kind)
    {
        scene.world.solver.kind = *kind;
    }
}

namespace
{
/// --format of the subcommand that runs (one per process).
SceneFormat g_sceneFormat = SceneFormat::Auto;
/// --max-bodies, ... of the subcommand that runs.
SceneLimits g_sceneLimits;
} // namespace

void AddLimitOptions(CLI::App* app)
{
    const SceneLimits defaults;
    const auto count = [app](const char* name, std::size_t& limit, const char* what)
    {
        app->add_option(name, limit,
                        std::string("Refuse scenes with more ") + what + " (default " +
                            std::to_string(limit) + ")")
            ->check(CLI::PositiveNumber)
            ->group("Limits");
    };
    count("--max-bodies", g_sceneLimits.bodies, "bodies");
    count("--max-shapes", g_sceneLimits.shapes, "shapes");
    count("--max-joints", g_sceneLimits.joints, "joints");
    count("--max-pairs", g_sceneLimits.pairs,
          "pairs of shapes overlapping at the start (on different bodies, one dynamic)");
    app->add_option_function<std::size_t>(
           "--max-file-size", [](std::size_t mib) { g_sceneLimits.fileBytes = mib << 20; },
           "Refuse scene files larger than this many MiB (default " +
               std::to_string(defaults.fileBytes >> 20) + ")")
        ->check(CLI::Range(std::size_t(1), std::size_t(1) << 20))
        ->group("Limits");
}

const SceneLimits& SceneLimitsOfOptions()
{
    return g_sceneLimits;
}

namespace
{
/// --b2djson-chains and --b2djson-springs of the subcommand that runs.
B2dJsonImportOptions g_importOptions;
} // namespace

void AddImportOptions(CLI::App* app)
{
    app->add_option_function<std::string>(
           "--b2djson-chains",
           [](const std::string& form) { g_importOptions.twoSidedChains = form == "two_sided"; },
           "How a b2dJson level's chains (and edges with ghost vertices) are read: two_sided "
           "(default: as Box2D 2.3, which R.U.B.E. targets, collides them; one two-sided segment "
           "per edge) or one_sided (Box2D 2.4.1's chains)")
        ->check(CLI::IsMember({"two_sided", "one_sided"}).description(""))
        ->type_name("two_sided|one_sided");
    app->add_option_function<std::string>(
           "--b2djson-springs",
           [](const std::string& form) { g_importOptions.springsAs23 = form == "2.3"; },
           "How a b2dJson level's distance, wheel and weld springs are sized: 2.3 (default: "
           "Box2D 2.3's stiffness and damping, from the joint's effective mass, kept) or 2.4.1 "
           "(the level's frequency and damping ratio on the bodies' masses, as 2.4.1 reads them)")
        ->check(CLI::IsMember({"2.3", "2.4.1"}).description(""))
        ->type_name("2.3|2.4.1");
}

const B2dJsonImportOptions& ImportOptions()
{
    return g_importOptions;
}

void AddFormatOption(CLI::App* app)
{
    app->add_option_function<std::string>(
           "--format",
           [](const std::string& format)
           {
               g_sceneFormat = format == "meff"      ? SceneFormat::Meff
                               : format == "b2djson" ? SceneFormat::B2dJson
                                                     : SceneFormat::Auto;
           },
           "Format of the scene files: meff (docs/scene-format.md), b2djson (R.U.B.E.'s "
           "export, docs/b2djson.md), or auto: by the content (default)")
        ->check(CLI::IsMember({"auto", "meff", "b2djson"}).description(""))
        ->type_name("auto|meff|b2djson");
    AddLimitOptions(app);
    AddImportOptions(app);
}

namespace
{
/// Prints each message of a refused scene on a line of its own; keeps them if asked.
void ReportProblems(const SceneError& error, std::vector<std::string>* problems)
{
    for (const std::string& message : error.messages())
    {
        std::fprintf(stderr, "%s\n", message.c_str());
        if (problems != nullptr)
        {
            problems->push_back(message);
        }
    }
}
} // namespace

std::optional<Scene> LoadSceneOrReport(const std::string& path, std::vector<std::string>* problems)
{
    try
    {
        LoadedScene loaded = LoadSceneFile(path, g_sceneFormat, g_sceneLimits, g_importOptions);
        // What a b2dJson level loses on the way, and what the loader warns about.
        for (const std::string& warning : loaded.warnings)
        {
            std::fprintf(stderr, "%s\n", warning.c_str());
        }
        for (const std::string& warning : loaded.scene.warnings)
        {
            std::fprintf(stderr, "%s\n", warning.c_str());
        }
        return std::move(loaded.scene);
    }
    catch (const SceneError& error)
    {
        ReportProblems(error, problems);
        return std::nullopt;
    }
}

std::optional<BuiltScene> BuildWorldOrReport(const Scene& scene, std::vector<std::string>* problems)
{
    try
    {
        return BuildWorld(scene);
    }
    catch (const SceneError& error)
    {
        ReportProblems(error, problems);
        return std::nullopt;
    }
}

Command AddRunCommand(CLI::App& parent)
{
    auto options = std::make_shared<RunOptions>();
    CLI::App* app = parent.add_subcommand(
        "run", "Run a scene file and optionally write its trajectory, contacts and joint "
               "reactions as CSV.\n"
               "Each output file is written whole or not at all. Numbers have enough digits "
               "to read back exactly.");
    app->add_option("scene", options->scenePath,
                    "Scene file (JSON; see docs/scene-format.md), or a b2dJson level")
        ->required()
        ->type_name("SCENE.json");
    AddFormatOption(app);
    app->add_option("--frames", options->frames,
                    "Number of steps to run (default: the scene's world.frames)")
        ->type_name("N")
        ->check(CLI::Range(0, INT_MAX));
    app->add_option("--trajectory", options->trajectoryPath,
                    "Write frame,time,body,x,y,angle,vx,vy,omega: one row per non-static body "
                    "per frame, frame 0 being the initial state; x,y is the body origin")
        ->type_name("OUT.csv");
    app->add_option("--contacts", options->contactsPath,
                    "Write frame,body_a,body_b,point,px,py,nx,ny,normal_impulse,"
                    "tangent_impulse: every touching contact point after each step (normal "
                    "from body_a to body_b; impulses in N·s)")
        ->type_name("OUT.csv");
    app->add_option("--joints", options->jointsPath,
                    "Write frame,joint,fx,fy,torque: each joint's reaction force (N) and torque "
                    "(N·m) on body_b after each step, i.e. its impulse divided by dt")
        ->type_name("OUT.csv");
    app->add_option("--save", options->savePath,
                    "Write the world as it is after frame --save-at as a meff scene file, to "
                    "replay from there (its frames are the frames left; docs/api-guide.md, "
                    "\"Saving a world as a scene\", says what replays bit for bit)")
        ->type_name("OUT.json");
    app->add_option("--save-at", options->saveAt,
                    "The frame after which --save saves the world (default: the last)")
        ->type_name("FRAME")
        ->check(CLI::Range(0, INT_MAX));
    AddThreadsOption(*app, options->threads, "Threads to step the world on");
    AddSolverOption(*app, options->solver);
    return {app, [options] { return Run(*options); }};
}

} // namespace meff::cli
