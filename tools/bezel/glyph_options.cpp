// Options and format choice shared by `bezel glyph` and `bezel fill`.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sstream>

#include "glyph_bitmap.hpp"

namespace bezel::cli {

Expected<std::string> pick_picture_format(
    const std::string& format_option, const std::string& output_file,
    const std::vector<std::pair<std::string, std::string>>& extensions, const std::string& fallback) {
    if (!format_option.empty()) return format_option;
    if (output_file.empty() || output_file == "-") return fallback;
    std::string ext = std::filesystem::path(output_file).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    std::string known;
    for (const auto& [e, format] : extensions) {
        if (e == ext) return format;
        known += (known.empty() ? "" : ", ") + e;
    }
    return Error{output_file + ": cannot tell the format from the extension '" + ext + "' (" +
                 known + "); use -O"};
}

void add_picture_options(CLI::App& cmd, std::string& output_file, std::string& fill,
                         double& tolerance_px) {
    cmd.add_option("-o,--output-file", output_file,
                   "Write here instead of stdout (atomically: no partial file on failure)")
        ->type_name("FILE");
    cmd.add_option("--fill", fill, "Fill rule: nonzero or evenodd")
        ->capture_default_str()
        ->check(CLI::IsMember({"nonzero", "evenodd"}));
    cmd.add_option("--tolerance", tolerance_px, "Flattening tolerance in pixels")
        ->capture_default_str()
        ->type_name("PX");
}

Status check_tolerance(double tolerance_px) {
    if (tolerance_px >= kMinFlattenTolerancePx && tolerance_px <= 100.0) return ok_status();
    std::ostringstream msg;  // the value as given ("0", "1e-12"), not std::to_string's "0.000000"
    msg << "--tolerance " << tolerance_px << ": expected a number of pixels in [1e-9, 100]";
    return Error{msg.str()};
}

}  // namespace bezel::cli
