// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// The bundled sample scenes, for tests that go over all of them.
#pragma once

#include <algorithm>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

/// The .json files of the given folders of the source tree ("samples/scenes", ...), sorted.
inline std::vector<std::string> SampleScenes(std::initializer_list<const char*> folders)
{
    std::vector<std::string> paths;
    for (const char* folder : folders)
    {
        for (const auto& entry :
             std::filesystem::directory_iterator(std::string(MEFF_SOURCE_DIR) + "/" + folder))
        {
            if (entry.path().extension() == ".json")
            {
                paths.push_back(entry.path().string());
            }
        }
    }
    std::sort(paths.begin(), paths.end());
    return paths;
}
