// bezel — the command-line face of the library: one subcommand per job (see commands.hpp).
//
// main() only parses and dispatches. It maps CLI11's outcomes onto bezel's exit codes: --help
// and --version exit 0, every parse error exits 2 with CLI11's message and a hint to use --help.
#include <CLI/CLI.hpp>
#include <iostream>

#include "cli_common.hpp"
#include "commands.hpp"
#include "suggest.hpp"

namespace {

// The deepest subcommand the parser entered.
const CLI::App* deepest_command(const CLI::App& app) {
    const CLI::App* at = &app;
    for (;;) {
        auto subs = at->get_subcommands();
        if (subs.empty()) return at;
        at = subs.front();
    }
}

// "bezel outline", for "Run 'bezel outline --help'" hints.
std::string command_path(const CLI::App& app) {
    std::string path = "bezel";
    for (const CLI::App* at = &app; at->get_subcommands().size() > 0;) {
        at = at->get_subcommands().front();
        path += " " + at->get_name();
    }
    return path;
}

// Every option name `command` takes, "--font-size" and "-o" alike, including those of its option
// groups (CLI11 keeps a group as an unnamed subcommand).
void option_names(const CLI::App& command, std::vector<std::string>& names) {
    for (const CLI::Option* option : command.get_options()) {
        for (const std::string& l : option->get_lnames()) names.push_back("--" + l);
        for (const std::string& s : option->get_snames()) names.push_back("-" + s);
    }
    for (const CLI::App* sub : command.get_subcommands([](const CLI::App* a) {
             return a->get_name().empty();
         }))
        option_names(*sub, names);
}

// An unknown option on the command line, as bezel says it, with the option meant when one is
// close: "unknown option --font-sise; did you mean --font-size?". Empty when every word was
// taken. CLI11 reports an unknown option as "The following argument was not expected", or, when
// a required option is missing too, only that ("--char" misspelled leaves the group without
// one); either way the unknown one is what the user needs to hear about first.
std::string unknown_option_message(const CLI::App& app) {
    const CLI::App* command = deepest_command(app);
    const std::vector<std::string> extras = command->remaining();
    if (extras.empty() || extras.front().size() < 2 || extras.front()[0] != '-') return {};
    const std::string typed = extras.front().substr(0, extras.front().find('='));
    std::vector<std::string> names;
    option_names(*command, names);
    std::string message = "unknown option " + typed;
    if (auto meant = bezel::cli::closest_name(typed, names)) message += "; did you mean " + *meant + "?";
    return message;
}

}  // namespace

namespace bezel::cli {

// The whole CLI as a function, so that tests/fuzz/fuzz_cli.cpp can run it in-process (main()
// is alone in entry.cpp).
int run_cli(int argc, char** argv) {
    CLI::App app{
        "bezel: a font and vector-outline engine.\n"
        "Inspect glyph outlines point by point, as text, JSON or an annotated SVG."};
    app.name("bezel");
    app.set_version_flag("--version", version_string(), "Print the version and exit");
    app.require_subcommand(1);
    app.footer(
        "Exit status: 0 success, 1 runtime error (unreadable font, bad glyph, unwritable "
        "output), 2 usage error.\nRun 'bezel <command> --help' for a command's options.");
    std::vector<Command> commands = add_all_commands(app, argc > 1 ? argv[1] : nullptr);

    // Every command gets a last, hidden positional that takes whatever arguments are left over,
    // reported below as a usage error. Besides naming the stray argument, it keeps an EMPTY
    // argument away from CLI11 2.1's subcommand lookup, where "" matches an option group (an
    // unnamed subcommand) and parsing loops forever (fuzz_cli findings: `bezel smooth "" --x`,
    // `bezel stroke x "" -l`). So no command keeps a positional inside an option group: CLI11
    // fills the command's own positionals first, and this catcher would take it.
    std::vector<std::vector<std::string>> strays(commands.size());
    for (std::size_t i = 0; i < commands.size(); ++i)
        commands[i].app->add_option("bezel-stray-arguments", strays[i])->group("");

    // CLI11 would report a mistyped command only as "A subcommand is required"; name it instead,
    // with the command meant when one is close ("rendr: not a bezel command; did you mean render?").
    if (argc > 1 && argv[1][0] != '-') {
        std::string names;
        std::vector<std::string> name_list;
        bool known = false;
        for (const Command& command : commands) {
            known |= command.app->get_name() == argv[1];
            names += (names.empty() ? "" : ", ") + command.app->get_name();
            name_list.push_back(command.app->get_name());
        }
        if (!known) {
            std::string message = std::string(argv[1]) + ": not a bezel command";
            if (auto meant = closest_name(argv[1], name_list)) message += "; did you mean " + *meant + "?";
            return fail_usage(message + " (commands: " + names + ")", "bezel");
        }
    }

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        if (std::string unknown = unknown_option_message(app); !unknown.empty())
            return fail_usage(unknown, command_path(app));
        return fail_usage(e.what(), command_path(app));
    }

    for (std::size_t i = 0; i < commands.size(); ++i) {
        if (!commands[i].app->parsed()) continue;
        if (!strays[i].empty())
            return fail_usage("unexpected argument '" + strays[i].front() + "'",
                              "bezel " + commands[i].app->get_name());
        return commands[i].run();
    }
    // require_subcommand(1) makes this unreachable; stay defined anyway.
    return fail_usage("no command given", "bezel");
}

}  // namespace bezel::cli
