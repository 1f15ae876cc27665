#include "commands.hpp"

#include <CLI/CLI.hpp>

namespace bezel::cli {

Command add_outline_command(CLI::App& app);
Command add_intersect_command(CLI::App& app);
Command add_smooth_command(CLI::App& app);
Command add_continuity_command(CLI::App& app);
Command add_stroke_command(CLI::App& app);
Command add_info_command(CLI::App& app);
Command add_glyph_command(CLI::App& app);
Command add_fill_command(CLI::App& app);
Command add_bench_command(CLI::App& app);
Command add_surface_command(CLI::App& app);
Command add_render_command(CLI::App& app);
Command add_atlas_command(CLI::App& app);

std::vector<Command> add_all_commands(CLI::App& app) {
    using AddCommand = Command (*)(CLI::App&);
    // The registry: one entry per subcommand file.
    static constexpr AddCommand kCommands[] = {
        add_outline_command,
        add_intersect_command,
        add_smooth_command,
        add_continuity_command,
        add_stroke_command,
        add_info_command,
        add_glyph_command,
        add_fill_command,
        add_bench_command,
        add_surface_command,
        add_render_command,
        add_atlas_command,
    };
    std::vector<Command> commands;
    for (AddCommand add : kCommands) commands.push_back(add(app));
    return commands;
}

}  // namespace bezel::cli
