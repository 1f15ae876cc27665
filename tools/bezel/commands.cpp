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

std::vector<Command> add_all_commands(CLI::App& app, const char* only) {
    using AddCommand = Command (*)(CLI::App&);
    // The registry: one entry per subcommand file, with the name it gives its subcommand.
    struct Entry {
        std::string_view name;
        AddCommand add;
    };
    static constexpr Entry kCommands[] = {
        {"outline", add_outline_command},
        {"intersect", add_intersect_command},
        {"smooth", add_smooth_command},
        {"continuity", add_continuity_command},
        {"stroke", add_stroke_command},
        {"info", add_info_command},
        {"glyph", add_glyph_command},
        {"fill", add_fill_command},
        {"bench", add_bench_command},
        {"surface", add_surface_command},
        {"render", add_render_command},
        {"atlas", add_atlas_command},
    };
    std::vector<Command> commands;
    if (only != nullptr)
        for (const Entry& e : kCommands)
            if (e.name == only) {
                commands.push_back(e.add(app));
                return commands;
            }
    for (const Entry& e : kCommands) commands.push_back(e.add(app));
    return commands;
}

}  // namespace bezel::cli
