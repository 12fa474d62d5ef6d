// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// What the scene loader says about a text: shared by the loader's tests.
#pragma once

#include "meff/scene.h"

#include <string>
#include <vector>

namespace meff::test
{

/// The messages ParseScene throws for `text`, or an empty list when it loads.
inline std::vector<std::string> ErrorsOf(const std::string& text)
{
    try
    {
        ParseScene(text, "x.json");
    }
    catch (const SceneError& error)
    {
        return error.messages();
    }
    return {};
}

} // namespace meff::test
