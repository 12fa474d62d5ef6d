// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 the meff authors
// `meff`: runs scene files. One subcommand per file; add new ones to the list below.
#include "commands.h"
#include "output_file.h"

#include "meff_version.h"

#include <cstdio>
#include <exception>
#include <new>
#include <vector>

int main(int argc, char** argv)
{
    using namespace meff::cli;

    CLI::App app{"meff: a 2D rigid-body physics engine.\n"
                 "Scenes are JSON files (see docs/scene-format.md), or b2dJson levels "
                 "(R.U.B.E.'s export, docs/b2djson.md); samples are in samples/scenes/.\n"
                 "Three solver back ends, chosen by a scene's world.solver or by --solver (run, "
                 "validate, render, sweep and bench take it): box2d (the "
                 "default: Box2D 2.4.1's step, bit for bit), colour (the same rows solved by graph "
                 "colour in SIMD lanes: fastest), soft_step (sub-stepped soft constraints: far "
                 "more accurate for joints, pendulums and chains; see docs/soft-step.md).",
                 "meff"};
    app.set_version_flag("--version", std::string("meff ") + MEFF_VERSION,
                         "Print meff's version and exit");
    app.require_subcommand(1);
    app.footer("Exit status: 0 success, 1 the simulation failed or output could not be "
               "written, 2 bad input (scene file or command line).\n"
               "Run `meff COMMAND --help` for the options of a command.");

    const std::vector<Command> commands = {
        AddRunCommand(app),   AddValidateCommand(app), AddRenderCommand(app), AddBenchCommand(app),
        AddSweepCommand(app), AddImportCommand(app),   AddExportCommand(app), AddViewCommand(app),
    };

    try
    {
        app.parse(argc, argv);
    }
    catch (const CLI::ParseError& error)
    {
        // --help is a "parse error" with status 0; every real one is bad input.
        return app.exit(error) == 0 ? kExitOk : kExitBadInput;
    }
    // Ctrl-C or a kill leaves no half-written temporary file behind, nor does running out of
    // memory, which is said in one line.
    RemoveTemporariesOnSignal();
    EndOnOutOfMemory();
    for (const Command& command : commands)
    {
        if (!command.app->parsed())
        {
            continue;
        }
        // Each command reports its own failures; anything that still escapes is said in one
        // line rather than aborting the program.
        try
        {
            return command.run();
        }
        catch (const std::bad_alloc&)
        {
            std::fprintf(stderr, "meff %s: out of memory\n", command.app->get_name().c_str());
        }
        catch (const std::exception& error)
        {
            std::fprintf(stderr, "meff %s: %s\n", command.app->get_name().c_str(), error.what());
        }
        return kExitRunFailed;
    }
    return kExitBadInput;
}
