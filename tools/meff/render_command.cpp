// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// `meff render`: steps a scene and writes every K-th frame as a PNG, drawn off-screen through
// OSMesa (render/), optionally with Box2D's bodies of the same frame on top, and optionally
// assembled into a GIF or MP4 by ffmpeg.
#include "commands.h"
#include "output_file.h"
#include "parallel.h"
#include "plot_program.h"
#include "progress.h"
#include "threads_option.h"

#include "meff/box2d_mirror.h"
#include "meff/render.h"

#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <climits>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

namespace meff::cli
{

bool ParseImageSize(const std::string& text, int& width, int& height)
{
    char x = 0;
    char rest = 0;
    long w = 0, h = 0;
    if (std::sscanf(text.c_str(), "%ld%c%ld%c", &w, &x, &h, &rest) != 3 || (x != 'x' && x != 'X'))
    {
        return false;
    }
    if (w < 1 || h < 1 || w > render::kMaxImageSize || h > render::kMaxImageSize)
    {
        return false;
    }
    width = int(w);
    height = int(h);
    return true;
}

namespace
{

struct RenderOptions
{
    std::string scenePath;
    std::string outDirectory;
    std::optional<int> frames;
    int every = 1;
    std::string size = "640x480";
    std::string camera;
    bool contacts = false;
    bool impulses = false;
    bool joints = false;
    bool overlayBox2D = false;
    std::string follow;     ///< a body's name (--follow)
    std::string fitFrames;  ///< "A:B" (--fit-frames)
    std::optional<int> fps; ///< of the GIF or MP4
    bool noCaption = false;
    bool noLegend = false;
    bool transparent = false;
    bool svg = false;
    std::string gifPath;
    std::string mp4Path;
    bool overwrite = false;
    int jobs = 0;                     ///< 0: one per core
    int threads = 1;                  ///< to step the world on (--threads)
    std::optional<SolverKind> solver; ///< instead of the scene's world.solver
    Shard shard;
};

/// Every message of this command is one line starting with this.
void Fail(const std::string& message)
{
    std::fprintf(stderr, "meff render: %s\n", message.c_str());
}

/// "x,y,height": numbers the engine's scalar holds, height > 0 (and not so small that it
/// rounds to nothing), and a view whose edges stay finite for an image `aspect` times as wide
/// as high.
bool ParseCamera(const std::string& text, double aspect, render::Camera& camera)
{
    std::vector<double> values;
    std::stringstream stream(text);
    std::string item;
    while (std::getline(stream, item, ','))
    {
        char* end = nullptr;
        const double value = std::strtod(item.c_str(), &end);
        if (item.empty() || end != item.c_str() + item.size() || !std::isfinite(value))
        {
            return false;
        }
        values.push_back(value);
    }
    if (values.size() != 3 || !(values[2] > 0))
    {
        return false;
    }
    const double maxReal = double(std::numeric_limits<Real>::max());
    const double halfWidth = 0.5 * values[2] * std::max(aspect, 1.0);
    if (std::abs(values[0]) + halfWidth > maxReal || std::abs(values[1]) + halfWidth > maxReal ||
        values[2] < double(std::numeric_limits<Real>::min()))
    {
        return false;
    }
    camera.center = Vec2{Real(values[0]), Real(values[1])};
    camera.height = Real(values[2]);
    return true;
}

/// The full path of `program` found on PATH, or empty.
std::string FindOnPath(const std::string& program)
{
    const char* path = std::getenv("PATH");
    std::stringstream stream(path != nullptr ? path : "");
    std::string directory;
    while (std::getline(stream, directory, ':'))
    {
        const std::string candidate = (directory.empty() ? "." : directory) + "/" + program;
        if (::access(candidate.c_str(), X_OK) == 0 && !std::filesystem::is_directory(candidate))
        {
            return candidate;
        }
    }
    return {};
}

/// OSMesa contexts for the threads that draw: each frame takes a free one and gives it back.
class RendererPool
{
  public:
    /// Throws render::RenderError when a context cannot be made.
    void Create(int count, int width, int height)
    {
        for (int i = 0; i < count; ++i)
        {
            m_renderers.push_back(std::make_unique<render::OffscreenRenderer>(width, height));
            m_free.push_back(m_renderers.back().get());
        }
    }

    int Supersample() const { return m_renderers.front()->Supersample(); }

    /// Runs draw(renderer) with a renderer no other thread is using.
    template <typename DrawFunction>
    render::Image Draw(const DrawFunction& draw)
    {
        render::OffscreenRenderer* renderer = nullptr;
        {
            std::unique_lock lock(m_mutex);
            m_returned.wait(lock, [&] { return !m_free.empty(); });
            renderer = m_free.back();
            m_free.pop_back();
        }
        const auto giveBack = [&]
        {
            {
                const std::lock_guard lock(m_mutex);
                m_free.push_back(renderer);
            }
            m_returned.notify_one();
        };
        try
        {
            render::Image image = draw(*renderer);
            giveBack();
            return image;
        }
        catch (...)
        {
            giveBack();
            throw;
        }
    }

  private:
    std::vector<std::unique_ptr<render::OffscreenRenderer>> m_renderers;
    std::vector<render::OffscreenRenderer*> m_free;
    std::mutex m_mutex;
    std::condition_variable m_returned;
};

/// Whether `name` is a frame file: frame_ and 5 or more digits, .png or .svg; its number in
/// `index`.
bool IsFrameFile(const std::string& name, long long& index)
{
    constexpr std::string_view prefix = "frame_";
    constexpr std::size_t suffixSize = 4; // ".png", ".svg"
    if (name.size() < prefix.size() + 5 + suffixSize || name.rfind(prefix, 0) != 0 ||
        (!name.ends_with(".png") && !name.ends_with(".svg")))
    {
        return false;
    }
    const std::string_view suffix(name.data() + name.size() - suffixSize, suffixSize);
    const std::string digits =
        name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    if (digits.size() > 12 ||
        !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
    {
        return false;
    }
    index = std::stoll(digits);
    return true;
}

/// The frames an earlier render left in `directory` (those of this shard's share, when the
/// frames are sharded: other machines' shares may be there too): refused without
/// `overwrite`, removed with it. False (said) when refused or a removal fails.
bool ClearOldFrames(const std::filesystem::path& directory, const Shard& shard, bool overwrite)
{
    std::vector<std::filesystem::path> old;
    std::error_code error;
    for (std::filesystem::directory_iterator it(directory, error), end; !error && it != end;
         it.increment(error))
    {
        long long index = 0;
        if (IsFrameFile(it->path().filename().string(), index) &&
            InShard(std::size_t(index), shard))
        {
            old.push_back(it->path());
        }
    }
    if (old.empty())
    {
        return true;
    }
    std::sort(old.begin(), old.end());
    if (!overwrite)
    {
        Fail(directory.string() + " already holds " + std::to_string(old.size()) + " frame" +
             (old.size() == 1 ? "" : "s") + " (" + old.front().filename().string() +
             (old.size() > 1 ? " ... " + old.back().filename().string() : "") +
             "); give --overwrite to replace them, or another --out");
        return false;
    }
    for (const std::filesystem::path& path : old)
    {
        if (!std::filesystem::remove(path, error) && error)
        {
            Fail("cannot remove " + path.string() + ": " + error.message());
            return false;
        }
    }
    return true;
}

/// Steps a separate world of the scene ahead of the real run, calling visit(frame, world)
/// after each of frames 1..`frames`. A run that fails part way stops there (the real run
/// reports the failure).
template <typename Visit>
void StepAhead(const Scene& scene, int frames, TaskSystem* threads, const Visit& visit)
{
    BuiltScene built = BuildWorld(scene);
    built.world.SetTaskSystem(threads);
    const Real dt = Real(scene.world.dt);
    try
    {
        for (int frame = 1; frame <= frames; ++frame)
        {
            built.Step(dt);
            visit(frame, built);
        }
    }
    catch (const SimulationError&)
    {
    }
}

/// The largest contact normal impulse and joint reaction impulse over the run: one arrow
/// scale for the whole sequence, so that arrows compare across frames.
double LargestImpulse(const Scene& scene, int frames, TaskSystem* threads)
{
    double largest = 0;
    StepAhead(scene, frames, threads,
              [&](int, const BuiltScene& built)
              {
                  for (const ContactPointReport& contact : built.world.GetContactReports())
                  {
                      largest = std::max(largest, std::abs(double(contact.normalImpulse)));
                  }
                  for (const JointId joint : built.joints)
                  {
                      const JointReaction reaction = built.world.GetReaction(joint, Real(1));
                      largest = std::max(largest, double(reaction.force.Length()));
                  }
              });
    return largest;
}

/// The box around every shape over frames first..last (the world as built is frame 0).
std::optional<AABB> RunBounds(const Scene& scene, const World& initial, int first, int last,
                              TaskSystem* threads)
{
    std::optional<AABB> bounds;
    const auto add = [&](const World& world)
    {
        if (const std::optional<AABB> box = render::WorldBounds(world))
        {
            bounds = bounds ? Combine(*bounds, *box) : *box;
        }
    };
    if (first == 0)
    {
        add(initial);
    }
    StepAhead(scene, last, threads,
              [&](int frame, const BuiltScene& built)
              {
                  if (frame >= first)
                  {
                      add(built.world);
                  }
              });
    return bounds;
}

/// "A:B" with 0 <= A <= B.
bool ParseFrameWindow(const std::string& text, int& first, int& last)
{
    char colon = 0;
    char rest = 0;
    long a = 0, b = 0;
    if (std::sscanf(text.c_str(), "%ld%c%ld%c", &a, &colon, &b, &rest) != 3 || colon != ':' ||
        a < 0 || b < a || b > INT_MAX)
    {
        return false;
    }
    first = int(a);
    last = int(b);
    return true;
}

std::string FramePath(const std::filesystem::path& directory, long long index,
                      const char* extension = "png")
{
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05lld.%s", index, extension);
    return (directory / name).string();
}

/// Assembles the frames with ffmpeg into a temporary file beside `output`, renamed into place
/// only when ffmpeg succeeded.
bool Assemble(const std::string& ffmpeg, const std::filesystem::path& directory, long long count,
              double framesPerSecond, const std::string& output, bool gif)
{
    const std::filesystem::path destination(output);
    const std::string temporary =
        (destination.parent_path() /
         ("." + destination.filename().string() + "." + std::to_string(::getpid()) + ".tmp"))
            .string();
    char rate[32];
    std::snprintf(rate, sizeof rate, "%.6g", framesPerSecond);
    std::vector<std::string> arguments = {ffmpeg, "-hide_banner", "-loglevel", "error", "-y",
                                          "-framerate", rate, "-i",
                                          (directory / "frame_%05d.png").string(),
                                          // Frames left over from an earlier, longer render
                                          // into the same directory are not part of this one.
                                          "-frames:v", std::to_string(count)};
    if (gif)
    {
        // A palette made from the frames themselves: GIF's 256 colours, chosen well.
        arguments.insert(
            arguments.end(),
            {"-filter_complex", "[0:v]split[a][b];[a]palettegen[p];[b][p]paletteuse", "-f", "gif"});
    }
    else
    {
        // H.264 in yuv420p (what players accept) needs even dimensions.
        arguments.insert(arguments.end(),
                         {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-vf",
                          "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-movflags", "+faststart", "-f", "mp4"});
    }
    arguments.push_back(temporary);
    // Without a shell: no quoting problems with odd file names.
    const int registration = RegisterTemporary(temporary); // removed if we are interrupted
    const int status = RunProgram(arguments, false);
    const bool renamed = status == 0 && std::rename(temporary.c_str(), output.c_str()) == 0;
    UnregisterTemporary(registration);
    if (!renamed)
    {
        std::remove(temporary.c_str());
        Fail(status != 0 ? "ffmpeg failed (exit status " + std::to_string(status) + ") making " +
                               output + "; the frames are in " + directory.string()
                         : "cannot write " + output);
        return false;
    }
    return true;
}

int Run(const RenderOptions& options)
{
    const auto start = std::chrono::steady_clock::now();

    // Everything that can be checked before any work is, so that bad input costs nothing and
    // leaves nothing behind.
    int width = 0, height = 0;
    if (!ParseImageSize(options.size, width, height))
    {
        Fail("--size must be WxH with each between 1 and " + std::to_string(render::kMaxImageSize) +
             ", got " + options.size);
        return kExitBadInput;
    }
    std::optional<render::Camera> camera;
    if (!options.camera.empty() &&
        !ParseCamera(options.camera, double(width) / height, camera.emplace()))
    {
        char limit[32];
        std::snprintf(limit, sizeof limit, "%.3g", double(std::numeric_limits<Real>::max()));
        Fail("--camera must be x,y,height with height > 0, the view's edges within ±" +
             std::string(limit) + " m (the engine's float), got " + options.camera);
        return kExitBadInput;
    }
    const bool gif = !options.gifPath.empty();
    const std::string moviePath = gif ? options.gifPath : options.mp4Path;
    std::string ffmpeg;
    if (!moviePath.empty())
    {
        ffmpeg = FindOnPath("ffmpeg");
        if (ffmpeg.empty())
        {
            Fail(std::string(gif ? "--gif" : "--mp4") +
                 " needs ffmpeg, which is not installed (not found on PATH); install it (Debian: "
                 "apt-get install ffmpeg) or render the PNG frames alone");
            return kExitBadInput;
        }
    }

    if (options.fps && moviePath.empty())
    {
        Fail("--fps is the frame rate of the GIF or MP4: give --gif or --mp4 too");
        return kExitBadInput;
    }
    if (options.fps && gif && *options.fps > 50)
    {
        Fail("--fps for a GIF must be at most 50, got " + std::to_string(*options.fps) +
             " (GIF delays are whole hundredths of a second, and browsers slow down shorter "
             "ones)");
        return kExitBadInput;
    }
    if (options.transparent && !moviePath.empty())
    {
        Fail(std::string("--transparent frames have an alpha channel, which ") +
             (gif ? "--gif" : "--mp4") + " cannot hold: render the PNG frames alone");
        return kExitBadInput;
    }
    int fitFirst = 0;
    int fitLast = 0;
    if (!options.fitFrames.empty() && !ParseFrameWindow(options.fitFrames, fitFirst, fitLast))
    {
        Fail("--fit-frames must be A:B with 0 <= A <= B, got " + options.fitFrames);
        return kExitBadInput;
    }

    if (!moviePath.empty() && options.shard.count > 1)
    {
        Fail(std::string(gif ? "--gif" : "--mp4") +
             " needs every frame, and --shard renders only a share of them: assemble the "
             "frames after all shards are done");
        return kExitBadInput;
    }

    std::optional<Scene> scene = LoadSceneOrReport(options.scenePath);
    if (!scene)
    {
        return kExitBadInput;
    }
    ApplySolverOption(options.solver, *scene);
    std::optional<BuiltScene> built = BuildWorldOrReport(*scene);
    if (!built)
    {
        return kExitBadInput;
    }
    const std::unique_ptr<TaskSystem> threads = MakeThreads(options.threads);
    built->world.SetTaskSystem(threads.get());
    const int frames = options.frames.value_or(scene->world.frames);
    if (!options.fitFrames.empty() && fitFirst > frames)
    {
        Fail("--fit-frames " + options.fitFrames + " starts after the run's last frame, " +
             std::to_string(frames));
        return kExitBadInput;
    }

    const std::filesystem::path directory(options.outDirectory);
    try
    {
        std::error_code error;
        std::filesystem::create_directories(directory, error);
        if (error)
        {
            throw std::runtime_error("cannot create " + directory.string() + ": " +
                                     error.message());
        }
        // Frames of an earlier render would mix with these (a shorter run leaves the old
        // ones after its last): refused unless --overwrite, which removes them first.
        if (!ClearOldFrames(directory, options.shard, options.overwrite))
        {
            return kExitBadInput;
        }
        // A trial file, discarded unwritten: proves the directory (and the movie's) can be
        // written to before a single frame is drawn.
        OutputFile probe(FramePath(directory, 0));
        if (!moviePath.empty())
        {
            OutputFile movieProbe(moviePath);
        }
    }
    catch (const std::runtime_error& error)
    {
        Fail(error.what());
        return kExitBadInput;
    }

    // One OSMesa context per thread that draws.
    const int jobs = ResolveJobs(options.jobs);
    RendererPool renderers;
    try
    {
        renderers.Create(jobs, width, height);
    }
    catch (const render::RenderError& error)
    {
        Fail(error.what());
        return kExitBadInput;
    }

    // The camera: --camera, else --fit-frames, else the scene's render.camera, else the bodies
    // over the whole run. With --follow, that camera's height and the followed body's centre.
    const auto fitRun = [&](int first, int last)
    {
        const std::optional<AABB> bounds =
            RunBounds(*scene, built->world, first, std::min(last, frames), threads.get());
        return bounds ? render::FitCamera(*bounds, width, height) : render::Camera{};
    };
    if (!camera && !options.fitFrames.empty())
    {
        camera = fitRun(fitFirst, fitLast);
    }
    if (!camera && scene->camera)
    {
        camera = render::Camera{Vec2{Real(scene->camera->center.x), Real(scene->camera->center.y)},
                                Real(scene->camera->height)};
    }
    std::optional<render::FollowCamera> follow;
    if (!options.follow.empty())
    {
        const auto named = built->bodyByName.find(options.follow);
        if (named == built->bodyByName.end() || !render::BodyBounds(built->world, named->second))
        {
            Fail("--follow: " + options.scenePath + " has no body named \"" + options.follow +
                 "\" with a shape");
            return kExitBadInput;
        }
        const Real viewHeight =
            camera ? camera->height : render::FitCamera(built->world, width, height).height;
        follow.emplace(built->world, named->second, viewHeight, double(width) / height);
        camera = follow->Current();
    }
    render::FrameOptions frameOptions;
    frameOptions.camera = camera ? *camera : fitRun(0, frames);
    frameOptions.legend = !options.noLegend;
    frameOptions.transparent = options.transparent;
    const double pixel = double(frameOptions.camera.height) / height;
    DrawFlags& flags = frameOptions.flags;
    flags.joints = options.joints;
    flags.contacts = options.contacts;
    flags.contactImpulses = options.impulses;
    flags.jointReactions = options.impulses;
    // Sizes in pixels, whatever the zoom, growing with the image as its lines do.
    const double line = render::LineWidth(width, height);
    flags.normalLength = Real(20 * line * pixel);
    flags.arrowHead = Real(7 * line * pixel);
    flags.pointSize = Real(5 * line);
    if (options.impulses)
    {
        // The largest arrow of the run spans a sixth of the image height; the legend shows a
        // round impulse near a quarter of it.
        const double largest = LargestImpulse(*scene, frames, threads.get());
        const double reference = largest > 0 ? largest : 1.0;
        flags.impulseScale = Real(double(frameOptions.camera.height) / 6 / reference);
        frameOptions.legendImpulse = render::NiceCeil(reference / 4);
    }

    std::optional<validation::Box2DMirror> mirror;
    if (options.overlayBox2D)
    {
        try
        {
            mirror.emplace(*scene);
        }
        catch (const SceneError& error)
        {
            Fail(error.what()); // Box2D v3's features: Box2D 2.4.1 cannot draw this scene
            return kExitBadInput;
        }
        frameOptions.overlayLegend.push_back({validation::kBox2DColor, "Box2D 2.4.1"});
    }

    // The frames to draw: every K-th (number k = 0 to count - 1), this shard's share of them
    // (k = index - 1 mod N), walked as they are drawn. No list of them is made (one of every
    // number took 4 GB before frame 0 at --frames 1000000000), and the counts are 64-bit
    // (frames / every + 1 overflowed an int at the largest --frames).
    const long long count = (long long)frames / options.every + 1;
    const long long first = options.shard.index - 1;
    const long long stride = options.shard.count;
    const long long mine = count > first ? (count - first - 1) / stride + 1 : 0;
    const Real dt = Real(scene->world.dt);
    Progress progress("rendering " + scene->name, mine, "frames");
    long long written = 0;
    // One thread steps the world and records a batch of frames; the batch is then drawn,
    // encoded and written on `jobs` threads. Every frame goes through the same recording, so
    // the files are the same for every --jobs.
    struct Pending
    {
        long long index = 0; ///< the file's number
        render::DrawList drawing;
        std::string caption;
        render::Camera camera;
    };
    const std::size_t batchSize = std::size_t(std::max(1, 2 * jobs));
    std::vector<Pending> batch;
    long long stepped = 0;
    const auto stepTo = [&](long long frame)
    {
        for (; stepped < frame; ++stepped)
        {
            built->Step(dt);
            if (mirror)
            {
                mirror->Step();
            }
            if (follow)
            {
                follow->Update(built->world, double(dt));
            }
        }
    };
    const bool writeSvg = options.svg;
    const auto drawBatch = [&]
    {
        RunInOrder(
            batch.size(), jobs,
            [&](std::size_t i)
            {
                render::FrameOptions options = frameOptions;
                options.caption = batch[i].caption;
                options.camera = batch[i].camera;
                const render::Image image = renderers.Draw(
                    [&](render::OffscreenRenderer& renderer)
                    { return render::RenderFrame(renderer, batch[i].drawing, options); });
                const std::vector<std::uint8_t> png = render::EncodePng(image);
                OutputFile file(FramePath(directory, batch[i].index));
                std::fwrite(png.data(), 1, png.size(), file.Stream());
                file.Commit();
                if (writeSvg)
                {
                    const std::string svg =
                        render::RenderSvg(batch[i].drawing, options, width, height);
                    OutputFile svgFile(FramePath(directory, batch[i].index, "svg"));
                    std::fwrite(svg.data(), 1, svg.size(), svgFile.Stream());
                    svgFile.Commit();
                }
            },
            [&](std::size_t)
            {
                ++written;
                progress.Update(written);
            });
        batch.clear();
    };
    try
    {
        for (long long k = first; k < count; k += stride)
        {
            const long long frame = k * options.every;
            stepTo(frame);
            Pending& pending = batch.emplace_back();
            pending.index = k;
            pending.camera = follow ? follow->Current() : frameOptions.camera;
            built->world.Draw(pending.drawing, flags);
            if (mirror)
            {
                mirror->Draw(pending.drawing, validation::kBox2DColor);
            }
            char caption[256];
            std::snprintf(caption, sizeof caption, "%s  frame %lld  t = %.3f s",
                          scene->name.c_str(), frame, double(frame) * scene->world.dt);
            if (!options.noCaption)
            {
                pending.caption = caption;
            }
            if (batch.size() == batchSize)
            {
                drawBatch();
            }
        }
        drawBatch();
    }
    catch (const SimulationError& error)
    {
        drawBatch(); // the frames recorded before the failure
        progress.Finish();
        std::fprintf(stderr,
                     "%s: simulation failed at step %" PRIu64 ": %s; %lld frames were written\n",
                     options.scenePath.c_str(), error.step, error.what(), written);
        return kExitRunFailed;
    }
    catch (const std::runtime_error& error)
    {
        progress.Finish();
        Fail(error.what());
        return kExitRunFailed;
    }
    progress.Finish();

    // By default the movie plays in simulated time; --fps plays each frame for 1/N s.
    const double framesPerSecond =
        options.fps ? double(*options.fps) : 1.0 / (scene->world.dt * options.every);
    if (!moviePath.empty() &&
        !Assemble(ffmpeg, directory, written, framesPerSecond, moviePath, gif))
    {
        return kExitRunFailed;
    }

    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: %lld frame%s (%dx%d, %dx supersampled) written to %s in %.3f s%s%s\n",
                scene->name.c_str(), written, written == 1 ? "" : "s", width, height,
                renderers.Supersample(), directory.string().c_str(), seconds,
                moviePath.empty() ? "" : "; ", moviePath.c_str());
    return kExitOk;
}

} // namespace

Command AddRenderCommand(CLI::App& parent)
{
    auto options = std::make_shared<RenderOptions>();
    CLI::App* app = parent.add_subcommand(
        "render",
        "Render a scene off-screen (OSMesa, no display needed) to DIR/frame_00000.png, "
        "frame_00001.png, ...: every K-th frame, frame 0 being the initial state.\n"
        "Shapes are filled and outlined, with a line from the centre showing the angle; "
        "static, kinematic and dynamic bodies in different colours. Each PNG is written whole "
        "or not at all.");
    app->add_option("scene", options->scenePath, "Scene file (JSON; see docs/scene-format.md)")
        ->required()
        ->type_name("SCENE.json");
    AddFormatOption(app);
    app->add_option("--out", options->outDirectory, "Directory for the frames (created if missing)")
        ->required()
        ->type_name("DIR");
    app->add_option("--frames", options->frames,
                    "Number of steps to run (default: the scene's world.frames)")
        ->type_name("N")
        ->check(CLI::Range(0, INT_MAX));
    app->add_option("--every", options->every, "Write every K-th frame (default 1)")
        ->type_name("K")
        ->check(CLI::Range(1, INT_MAX));
    app->add_option("--size", options->size, "Image size in pixels, each 1..8192 (default 640x480)")
        ->type_name("WxH");
    CLI::Option* cameraOption =
        app->add_option(
               "--camera", options->camera,
               "World point at the image centre and world height shown, in metres "
               "(default: the scene's render.camera, else fit to the bodies over the whole "
               "run)")
            ->type_name("x,y,height");
    CLI::Option* follow =
        app->add_option("--follow", options->follow,
                        "Follow the body of this name: the camera (of --camera's or the scene's "
                        "height, else frame 0's fit) eases after it and keeps it in the middle "
                        "80 % of the view")
            ->type_name("BODY");
    CLI::Option* fit = app->add_option("--fit-frames", options->fitFrames,
                                       "Fit the camera to the bodies over frames A to B "
                                       "(inclusive; default: the whole run)")
                           ->type_name("A:B");
    fit->excludes(follow);
    fit->excludes(cameraOption);
    app->add_flag("--no-caption", options->noCaption, "No caption (scene, frame, time) at the top");
    app->add_flag("--no-legend", options->noLegend,
                  "No colour legend, impulse legend or scale bar");
    app->add_flag("--transparent", options->transparent,
                  "Transparent background: RGBA PNGs (and SVGs without a background)");
    app->add_flag("--svg", options->svg,
                  "Also write each frame as SVG (frame_NNNNN.svg beside the PNG), for figures");
    app->add_flag("--contacts", options->contacts, "Draw contact points and normals");
    app->add_flag("--impulses", options->impulses,
                  "Draw arrows proportional to each contact's normal impulse and each joint's "
                  "reaction impulse (one scale for the run, shown in a legend)");
    app->add_flag("--joints", options->joints,
                  "Draw joints: their anchors and the lines linking them to their bodies");
    app->add_flag("--overlay-box2d", options->overlayBox2D,
                  "Draw Box2D 2.4.1's bodies of the same frame as blue outlines over meff's");
    CLI::Option* gif = app->add_option("--gif", options->gifPath,
                                       "Also assemble the frames into an animated GIF (ffmpeg)")
                           ->type_name("FILE");
    CLI::Option* mp4 = app->add_option("--mp4", options->mp4Path,
                                       "Also assemble the frames into an H.264 MP4 (ffmpeg)")
                           ->type_name("FILE");
    gif->excludes(mp4);
    app->add_option("--fps", options->fps,
                    "Frame rate of the GIF or MP4: each frame shows for 1/N s (default: "
                    "simulated time, 1/(dt·K) frames per second); at most 50 for a GIF")
        ->type_name("N")
        ->check(CLI::Range(1, 240));
    app->add_flag("--overwrite", options->overwrite,
                  "DIR may hold frames of an earlier render: remove them first (without it, "
                  "such a folder is refused)");
    AddJobsOption(app, options->jobs, "Draw and write frames");
    AddThreadsOption(*app, options->threads,
                     "Threads to step the world on (the frames are drawn on --jobs)");
    AddShardOption(app, options->shard,
                   "frames (frame k to shard k mod N + 1; each shard steps the whole run)");
    AddSolverOption(*app, options->solver,
                    "meff's solver back end instead of the scene's world.solver "
                    "(--overlay-box2d draws Box2D 2.4.1's own)");
    return {app, [options] { return Run(*options); }};
}

} // namespace meff::cli
