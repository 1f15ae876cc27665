// Options shared by `bezel glyph` and `bezel fill`.
#include <CLI/CLI.hpp>
#include <sstream>

#include "glyph_bitmap.hpp"

namespace bezel::cli {

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
