// tools/bezel/commands.hpp — the registry of bezel's subcommands.
//
// A subcommand lives in its own file, tools/bezel/<name>.cpp, which defines one function
// `Command add_<name>_command(CLI::App& app)`: it adds its CLI::App subcommand with all options
// bound to state it owns, and returns that subcommand together with the function that runs it
// once parsing has selected it. Adding a subcommand is that file plus its line in the registry in commands.cpp
// (a declaration and an entry in the list).
#pragma once

#include <functional>
#include <string_view>
#include <vector>

namespace CLI { class App; }

namespace bezel::cli {

struct Command {
    CLI::App* app = nullptr;     // the subcommand, owned by the parent CLI::App
    std::function<int()> run;    // returns the process exit code (see cli_common.hpp)
};

// Adds every subcommand to `app`, in the order `bezel --help` lists them; or, when `only` is the
// name of one, just that one: building every command's options is a quarter of a one-letter
// `bezel render`'s instructions, and a command line names its command first. The registry's
// names are those the commands give themselves (tested).
std::vector<Command> add_all_commands(CLI::App& app, const char* only = nullptr);

}  // namespace bezel::cli
