// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The `meff view` window: GLFW, OpenGL 3.3 and Dear ImGui over viewer_core.h's logic.
#pragma once

#include <string>

namespace meff::view
{

struct ViewerOptions
{
    std::string scenePath;
    std::string scriptPath; ///< empty: interactive
    int width = 1280;       ///< the window's size (pixels)
    int height = 800;
};

/// Opens the window and runs until it is closed (or the script ends). Returns the exit status:
/// 0, 1 (a script's step failed or a check did not hold), 2 (bad scene, script or no display).
int RunViewer(const ViewerOptions& options);

} // namespace meff::view
