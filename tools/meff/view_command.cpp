// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// `meff view`: the scene in a window (tools/view), live: play, step, drag bodies, switch the
// back end and watch the error readouts; or a script of the same actions, for tests and
// screenshots.
#include "commands.h"

#ifdef MEFF_HAS_VIEWER
#include "view_app.h"
#endif

#include <cstdio>
#include <memory>

namespace meff::cli
{

namespace
{

struct ViewOptions
{
    std::string scenePath;
    std::string scriptPath;
    std::string size = "1280x800";
};

int Run(const ViewOptions& options)
{
    int width = 0, height = 0;
    char x = 0, rest = 0;
    if (std::sscanf(options.size.c_str(), "%d%c%d%c", &width, &x, &height, &rest) != 3 ||
        x != 'x' || width < 16 || height < 16 || width > 8192 || height > 8192)
    {
        std::fprintf(stderr,
                     "meff view: --size must be WxH with each between 16 and 8192, got %s\n",
                     options.size.c_str());
        return kExitBadInput;
    }
#ifdef MEFF_HAS_VIEWER
    return view::RunViewer({options.scenePath, options.scriptPath, width, height});
#else
    std::fprintf(stderr, "meff view: this meff was built without the viewer (it needs GLFW and "
                         "Dear ImGui: apt-get install libglfw3-dev libimgui-dev, then rebuild)\n");
    return kExitBadInput;
#endif
}

} // namespace

Command AddViewCommand(CLI::App& parent)
{
    auto options = std::make_shared<ViewOptions>();
    CLI::App* app = parent.add_subcommand(
        "view",
        "Open a scene in a window (GLFW, OpenGL 3.3, Dear ImGui): play, pause, step, restart; "
        "pan (right or middle drag) and zoom (wheel); drag a body with the mouse and throw it; "
        "select a body to read its state, contacts and joint reactions; switch the back end and "
        "its settings live and watch energy, joint gaps and penetration; the Box2D 2.4.1 ghost "
        "(stepped in lockstep, drawn as outlines, the first divergent frame marked); the scene "
        "reloads when its file changes; save frames as meff render draws them. See "
        "docs/viewer.md.");
    app->add_option("scene", options->scenePath, "Scene file or b2dJson level")
        ->required()
        ->type_name("SCENE.json");
    app->add_option(
           "--script", options->scriptPath,
           "Run the commands of FILE (size, camera, step, grab, move, release, drag, "
           "solver, iterations, substeps, restart, screenshot, screenshot_window, ghost, expect; "
           "docs/viewer.md) "
           "instead of waiting for input, then close")
        ->type_name("FILE");
    app->add_option("--size", options->size, "Window size in pixels (default 1280x800)")
        ->type_name("WxH");
    return {app, [options] { return Run(*options); }};
}

} // namespace meff::cli
