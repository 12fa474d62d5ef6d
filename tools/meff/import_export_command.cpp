// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// `meff import` and `meff export`: b2dJson levels (R.U.B.E.'s export) to meff scene files and
// back (docs/b2djson.md). Each output file appears whole or not at all.
#include "commands.h"
#include "output_file.h"

#include <cstdio>
#include <memory>
#include <stdexcept>

namespace meff::cli
{

namespace
{

struct ConvertOptions
{
    std::string inputPath;
    std::string outputPath;
    bool hexFloats = false;
};

void PrintErrors(const SceneError& error)
{
    for (const std::string& message : error.messages())
    {
        std::fprintf(stderr, "%s\n", message.c_str());
    }
}

int WriteOutput(const char* command, const std::string& path, const std::string& text)
{
    try
    {
        OutputFile file(path);
        std::fputs(text.c_str(), file.Stream());
        file.Commit();
    }
    catch (const std::runtime_error& error)
    {
        std::fprintf(stderr, "meff %s: %s\n", command, error.what());
        return kExitRunFailed;
    }
    return kExitOk;
}

int Import(const ConvertOptions& options)
{
    LoadedScene loaded;
    try
    {
        loaded = LoadSceneFile(options.inputPath, SceneFormat::B2dJson, SceneLimitsOfOptions(),
                               ImportOptions());
    }
    catch (const SceneError& error)
    {
        PrintErrors(error);
        return kExitBadInput;
    }
    for (const std::string& warning : loaded.warnings)
    {
        std::fprintf(stderr, "%s\n", warning.c_str());
    }
    const int status = WriteOutput("import", options.outputPath, loaded.meffText);
    if (status == kExitOk)
    {
        std::printf("%s: %zu bodies, %zu joints -> %s\n", options.inputPath.c_str(),
                    loaded.scene.bodies.size(), loaded.scene.joints.size(),
                    options.outputPath.c_str());
    }
    return status;
}

int Export(const ConvertOptions& options)
{
    std::string text;
    std::size_t bodies = 0;
    std::size_t joints = 0;
    try
    {
        const Scene scene = LoadScene(options.inputPath, SceneLimitsOfOptions());
        text = ExportB2dJson(scene, B2dJsonExportOptions{.hexFloats = options.hexFloats});
        bodies = scene.bodies.size();
        joints = scene.joints.size();
    }
    catch (const SceneError& error)
    {
        PrintErrors(error);
        return kExitBadInput;
    }
    const int status = WriteOutput("export", options.outputPath, text);
    if (status == kExitOk)
    {
        std::printf("%s: %zu bodies, %zu joints -> %s\n", options.inputPath.c_str(), bodies, joints,
                    options.outputPath.c_str());
    }
    return status;
}

} // namespace

Command AddImportCommand(CLI::App& parent)
{
    auto options = std::make_shared<ConvertOptions>();
    CLI::App* app = parent.add_subcommand(
        "import", "Convert a b2dJson level (R.U.B.E.'s export) to a meff scene file.\n"
                  "What meff does not model (custom properties, images, ...) is left out with "
                  "one warning line each on stderr; docs/b2djson.md has the mapping.");
    app->add_option("level", options->inputPath, "b2dJson file")
        ->required()
        ->type_name("LEVEL.json");
    app->add_option("-o,--out", options->outputPath, "The meff scene file to write")
        ->required()
        ->type_name("SCENE.json");
    AddLimitOptions(app);
    AddImportOptions(app);
    return {app, [options] { return Import(*options); }};
}

Command AddExportCommand(CLI::App& parent)
{
    auto options = std::make_shared<ConvertOptions>();
    CLI::App* app = parent.add_subcommand(
        "export", "Convert a meff scene file to a b2dJson level (opens in R.U.B.E.).\n"
                  "What b2dJson has no field for travels in \"meff.*\" custom properties, so "
                  "that `meff import` gives the same scene back.");
    app->add_option("scene", options->inputPath, "meff scene file")
        ->required()
        ->type_name("SCENE.json");
    app->add_option("-o,--out", options->outputPath, "The b2dJson file to write")
        ->required()
        ->type_name("LEVEL.json");
    app->add_flag("--hex-floats", options->hexFloats,
                  "Write numbers that are exact floats as b2dJson's hex strings of their bits "
                  "(default: decimal, exact)");
    AddLimitOptions(app);
    return {app, [options] { return Export(*options); }};
}

} // namespace meff::cli
