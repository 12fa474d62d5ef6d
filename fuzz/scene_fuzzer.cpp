// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// libFuzzer target for the scene loader (issue 7): any bytes given to meff::ParseScene either
// load or are refused with a SceneError whose every message is a clear "FILE: ..." line; a
// scene that loads is built into a World (which must accept it: the loader and the engine
// share one set of rules) and stepped a few times, where the only failure allowed is a
// SimulationError (the engine's documented stop on a non-finite state). Anything
// else — a crash, a sanitizer report, another exception, a message without its file name —
// is a finding. Built only with -DMEFF_FUZZ=ON and clang (fuzz/CMakeLists.txt).
#include "fuzz_checks.h"
#include "meff/scene.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace
{

constexpr const char* kSource = "fuzz.json";
/// Steps per loaded scene: enough to collide and solve the fuzzed geometry once or twice,
/// few enough that a 200-body sample still runs thousands of inputs per second.
constexpr int kMaxSteps = 3;

constexpr const char* kTarget = "scene_fuzzer";

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    meff::Scene scene;
    try
    {
        scene = meff::ParseScene(text, kSource);
    }
    catch (const meff::SceneError& error)
    {
        meff::fuzz::CheckRejection(kTarget, error, kSource);
        return 0;
    }
    try
    {
        meff::BuiltScene built = meff::BuildWorld(scene);
        const int steps = scene.world.frames < kMaxSteps ? scene.world.frames : kMaxSteps;
        for (int i = 0; i < steps; ++i)
        {
            built.Step(meff::Real(scene.world.dt));
        }
    }
    catch (const meff::SceneError& error)
    {
        // The loader applies the engine's own rules (meff/validity.h): a scene it accepts is
        // one the engine builds. A refusal here means the two disagree.
        meff::fuzz::Finding(kTarget, "the engine refused a scene the loader accepted: " +
                                         std::string(error.what()));
    }
    catch (const meff::SimulationError&)
    {
        // A valid scene may still blow up (huge velocities, extreme masses): the documented
        // stop, not a finding.
    }
    return 0;
}
