// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// A game that loads its level from a meff scene (meff::scene of the installed package).
#include <meff/scene.h>

#include <cstdio>

int main()
{
    const char* level = R"({"meff_scene": 1,
        "bodies": [
            {"name": "ground", "type": "static",
             "shapes": [{"type": "box", "half_width": 10, "half_height": 1, "center": [0, -1]}]},
            {"name": "crate", "type": "dynamic", "position": [0, 3],
             "shapes": [{"type": "box", "half_width": 0.5, "half_height": 0.5}]}]})";
    try
    {
        meff::BuiltScene built = meff::BuildWorld(meff::ParseScene(level, "level.json"));
        for (int step = 0; step < 120; ++step)
        {
            built.world.Step(1.0f / 60.0f);
        }
        const float y = built.world.GetPosition(built.bodyByName.at("crate")).y;
        std::printf("crate at y = %.4f m after 2 s\n", y);
        // Resting polygons keep their skins (2 × 0.01 m) less the slop (0.005 m) apart.
        return y > 0.5f && y < 0.53f ? 0 : 1;
    }
    catch (const meff::SceneError& error)
    {
        std::fprintf(stderr, "%s\n", error.what());
        return 1;
    }
}
