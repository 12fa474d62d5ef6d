// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// `meff validate --baseline DIR`'s files (baseline_files.h).
#include "baseline_files.h"

#include "output_file.h"

#include "meff_version.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace meff::cli
{

namespace
{

/// The tolerance --tolerance NAME sets, or nullptr.
double* ToleranceNamed(validation::Tolerances& tolerances, const std::string& name)
{
    return name == "position"           ? &tolerances.position
           : name == "angle"            ? &tolerances.angle
           : name == "velocity"         ? &tolerances.velocity
           : name == "impulse"          ? &tolerances.impulse
           : name == "impulse_relative" ? &tolerances.impulseRelative
                                        : nullptr;
}

/// NAME=VALUE split, VALUE read; nullopt when VALUE is not a number ≥ 0.
std::optional<std::pair<std::string, double>> ParseSetting(const std::string& setting)
{
    const std::size_t equals = setting.find('=');
    if (equals == std::string::npos)
    {
        return std::nullopt;
    }
    const std::string text = setting.substr(equals + 1);
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !(value >= 0) || value == HUGE_VAL)
    {
        return std::nullopt;
    }
    return std::pair{setting.substr(0, equals), value};
}

std::string ReadWholeFile(const std::string& file)
{
    std::error_code error;
    if (!std::filesystem::exists(file, error))
    {
        throw validation::BaselineError(file + ": no baseline recorded for this scene (record "
                                               "one with --record)");
    }
    std::ifstream in(file, std::ios::binary);
    std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (!in.is_open() || in.bad())
    {
        throw validation::BaselineError(file + ": cannot be read: " + std::strerror(errno));
    }
    return bytes;
}

} // namespace

std::string BaselineFile(const std::string& directory, const std::string& scenePath)
{
    std::error_code error;
    std::filesystem::path name = std::filesystem::proximate(scenePath, error).lexically_normal();
    if (error || name.empty() || *name.begin() == "..")
    {
        // Outside the working directory: its absolute path, below the root.
        name = std::filesystem::absolute(scenePath, error).lexically_normal().relative_path();
    }
    return (std::filesystem::path(directory) / name).string() + ".baseline.gz";
}

std::string CheckToleranceSetting(const std::string& setting)
{
    const auto parsed = ParseSetting(setting);
    validation::Tolerances tolerances;
    if (!parsed || ToleranceNamed(tolerances, parsed->first) == nullptr)
    {
        return "expected NAME=VALUE, NAME one of position, angle, velocity, impulse, "
               "impulse_relative and VALUE a number >= 0, got " +
               setting;
    }
    return {};
}

validation::Tolerances BaselineTolerances(const std::vector<std::string>& settings, bool bitExact)
{
    validation::Tolerances tolerances;
    if (bitExact)
    {
        return {0, 0, 0, 0, 0};
    }
    for (const std::string& setting : settings)
    {
        const auto parsed = ParseSetting(setting); // checked by CheckToleranceSetting
        *ToleranceNamed(tolerances, parsed->first) = parsed->second;
    }
    return tolerances;
}

std::string RecordBaselineFile(const Scene& scene, const validation::RunOptions& options,
                               const std::string& file)
{
    const validation::Baseline baseline = validation::RecordBaseline(scene, options, MEFF_VERSION);
    const std::string bytes = validation::EncodeBaseline(baseline);
    std::error_code error;
    const std::filesystem::path folder = std::filesystem::path(file).parent_path();
    std::filesystem::create_directories(folder, error);
    if (error)
    {
        throw std::runtime_error("cannot create " + folder.string() + ": " + error.message());
    }
    OutputFile out(file);
    std::fwrite(bytes.data(), 1, bytes.size(), out.Stream());
    out.Commit();
    return "RECORDED " + scene.sourcePath + ": " + std::to_string(baseline.header.frames) +
           " frames, back end " + baseline.header.backEnd + ", in " + file + " (" +
           std::to_string(bytes.size()) + " bytes)\n";
}

validation::ValidationResult CompareWithBaselineFile(const Scene& scene,
                                                     const validation::RunOptions& options,
                                                     const std::string& file,
                                                     const validation::Tolerances& tolerances,
                                                     bool acceptSceneChange)
{
    const validation::Baseline baseline = validation::DecodeBaseline(ReadWholeFile(file), file);
    const validation::BaselineHeader current = validation::HeaderFor(scene, options, MEFF_VERSION);
    validation::CheckBaseline(baseline.header, current, file, acceptSceneChange);
    validation::ValidationResult result =
        validation::CompareWithBaseline(scene, baseline, options, tolerances);
    if (baseline.header.sceneHash != current.sceneHash ||
        baseline.header.settings != current.settings)
    {
        result.notes.push_back("the scene file differs from the one recorded (" +
                               baseline.header.sceneHash + ", now " + current.sceneHash +
                               "): compared anyway (--accept-scene-change)");
    }
    return result;
}

} // namespace meff::cli
