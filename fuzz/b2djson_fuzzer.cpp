// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// libFuzzer targets for the b2dJson importer (issue 36), built from this one file:
//
// * b2djson_fuzzer: any bytes given to meff::ImportB2dJson either import or are refused with a
//   SceneError whose every message is a "FILE: ..." line; a level that imports is built into a
//   World and stepped a few times, where the only failure allowed is a SimulationError.
// * b2djson_roundtrip_fuzzer (MEFF_FUZZ_ROUND_TRIP): a level that imports is exported again
//   (meff::ExportB2dJson) and imported once more; the second import must succeed and build the
//   same world, bit for bit (the state hash of both worlds, before and after a step).
//
// Anything else (a crash, a sanitizer report, another exception, a message without its file
// name, a round trip that changes the world) is a finding. Built only with -DMEFF_FUZZ=ON and
// clang (fuzz/CMakeLists.txt).
#include "fuzz_checks.h"
#include "meff/b2djson.h"
#include "meff/scene.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace
{

constexpr const char* kSource = "fuzz.json";
/// Steps per imported level: as the scene fuzzer's, enough to collide the fuzzed geometry once
/// or twice, few enough to run thousands of inputs per second.
constexpr int kMaxSteps = 3;

#ifdef MEFF_FUZZ_ROUND_TRIP
constexpr const char* kTarget = "b2djson_roundtrip_fuzzer";
#else
constexpr const char* kTarget = "b2djson_fuzzer";
#endif

[[noreturn]] void Finding(const std::string& what)
{
    meff::fuzz::Finding(kTarget, what);
}

/// The state hash of `scene`'s world as built and after each of up to kMaxSteps steps; empty
/// when a step stops on a non-finite state (the documented stop, not a finding).
std::string Hashes(const meff::Scene& scene)
{
    std::string hashes;
    try
    {
        meff::BuiltScene built = meff::BuildWorld(scene);
        hashes += std::to_string(built.world.GetStateHash());
        const int steps = scene.world.frames < kMaxSteps ? scene.world.frames : kMaxSteps;
        for (int i = 0; i < steps; ++i)
        {
            built.Step(meff::Real(scene.world.dt));
            hashes += " " + std::to_string(built.world.GetStateHash());
        }
    }
    catch (const meff::SceneError& error)
    {
        // The importer ends with the scene loader, which applies the engine's own rules.
        Finding("the engine refused a level the importer accepted: " + std::string(error.what()));
    }
    catch (const meff::SimulationError&)
    {
        hashes += " (stopped)";
    }
    return hashes;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    meff::LoadedScene level;
    try
    {
        level = meff::ImportB2dJson(text, kSource);
    }
    catch (const meff::SceneError& error)
    {
        meff::fuzz::CheckRejection(kTarget, error, kSource);
        return 0;
    }
    const std::string hashes = Hashes(level.scene);
#ifdef MEFF_FUZZ_ROUND_TRIP
    meff::LoadedScene again;
    try
    {
        again = meff::ImportB2dJson(meff::ExportB2dJson(level.scene), kSource);
    }
    catch (const meff::SceneError& error)
    {
        Finding("the exported level does not import: " + std::string(error.what()));
    }
    const std::string hashesAgain = Hashes(again.scene);
    if (hashesAgain != hashes)
    {
        Finding("import -> export -> import built another world: state hashes " + hashes +
                " then " + hashesAgain);
    }
#else
    (void)hashes;
#endif
    return 0;
}
