// fuzz_svg_path — SVG path data: parse_svg_path never crashes, and whatever it accepts is finite
// and survives the round trip to_svg_path → parse_svg_path bit for bit (path.hpp's promise for
// precision 17), with the written form stable under a second round.
#include <cstddef>
#include <cstdint>
#include <string>

#include "bezel/path.hpp"
#include "fuzz_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    auto parsed = bezel::parse_svg_path(text);
    if (!parsed) {
        BEZEL_FUZZ_CHECK(!parsed.error().message.empty());
        return 0;
    }
    BEZEL_FUZZ_CHECK(parsed->is_finite());
    const std::string written = bezel::to_svg_path(*parsed);
    auto again = bezel::parse_svg_path(written);
    BEZEL_FUZZ_CHECK(again.ok());
    BEZEL_FUZZ_CHECK(*again == *parsed);
    BEZEL_FUZZ_CHECK(bezel::to_svg_path(*again) == written);
    // Fewer digits must still read back (not equal: rounded), and stay finite.
    auto rounded = bezel::parse_svg_path(bezel::to_svg_path(*parsed, 3));
    BEZEL_FUZZ_CHECK(rounded.ok() && rounded->verbs() == parsed->verbs());
    return 0;
}
