// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// meff_strip: puts PNG frames side by side into one PNG, for documentation (docs/rendering.md's
// strip of frames made by `meff render`). The frames are copied pixel for pixel, never redrawn.
//
//   meff_strip OUT.png FRAME.png... [--gap N]
#include "meff/render.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
    using namespace meff::render;
    std::vector<std::string> paths;
    int gap = 4;
    for (int i = 1; i < argc; ++i)
    {
        const std::string argument = argv[i];
        if (argument == "--gap" && i + 1 < argc)
        {
            gap = std::atoi(argv[++i]);
        }
        else
        {
            paths.push_back(argument);
        }
    }
    if (paths.size() < 2 || gap < 0)
    {
        std::fprintf(stderr, "usage: meff_strip OUT.png FRAME.png... [--gap N]\n");
        return 2;
    }
    try
    {
        std::vector<Image> frames;
        for (std::size_t i = 1; i < paths.size(); ++i)
        {
            frames.push_back(ReadPng(paths[i]));
        }
        WritePng(paths[0], StitchHorizontally(frames, gap));
    }
    catch (const RenderError& error)
    {
        std::fprintf(stderr, "meff_strip: %s\n", error.what());
        return 2;
    }
    return 0;
}
