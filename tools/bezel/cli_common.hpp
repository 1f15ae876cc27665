// tools/bezel/cli_common.hpp — what every bezel subcommand shares: exit codes, error lines,
// argument parsing helpers, output formats and writing the result to stdout or a file.
//
// Conventions (the same for every subcommand):
//   - exit 0 on success, 1 on a runtime failure (a font that does not open, a glyph id out of
//     range, an unwritable output file), 2 on a usage error (unknown option, missing or
//     conflicting options, malformed values);
//   - an error is one line on stderr, `bezel: <input>: <what is wrong>`; usage errors add a
//     second line pointing at --help;
//   - output is produced completely in memory before anything is written, and `-o FILE` goes
//     through a temporary file beside FILE that is renamed on success, so a failure never leaves
//     a partial or truncated FILE behind.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "bezel/expected.hpp"
#include "bezel/image.hpp"

namespace CLI {
class App;
}

namespace bezel::cli {

enum ExitCode : int {
    kExitOk = 0,
    kExitRuntime = 1,  // the input was well formed but the work failed
    kExitUsage = 2,    // the command line itself is wrong
};

// Prints `bezel: <message>` on stderr and returns kExitRuntime. `message` already names its input.
int fail_runtime(const std::string& message);
// Prints `bezel: <message>` and a hint to run `<command> --help`; returns kExitUsage.
// `command` is e.g. "bezel outline".
int fail_usage(const std::string& message, const std::string& command);

// The line `bezel --version` prints: "bezel 0.1.0".
std::string version_string();

// Longest --text accepted, in code points: each one becomes a glyph with its own outline listing,
// so this bounds the work and the output size of a single call.
inline constexpr std::size_t kMaxTextCodePoints = 1000;

// Decodes UTF-8 strictly (no overlong forms, no surrogates, nothing above U+10FFFF). The error
// names the byte offset of the first bad sequence.
Expected<std::u32string> decode_utf8(std::string_view text);
void append_utf8(std::string& out, char32_t code_point);

// Parses a --char argument: one UTF-8 encoded code point ("g", "é"), or "U+0067" / "u+67"
// (1 to 6 hex digits). The error quotes the argument and leaves naming the option to the caller
// (CLI11 prefixes a check's message with "--char: ").
Expected<char32_t> parse_code_point(std::string_view arg);
// "U+0067" (at least four hex digits, upper case).
std::string format_code_point(char32_t code_point);

// The whole of `text` read as one number (strtod's syntax, so also "nan", "inf" and hex floats:
// callers that want a finite value or a range test for it); nullopt when `text` is empty or has
// anything after the number.
std::optional<double> parse_number(const std::string& text);

// A number as people write it: the shortest decimal that reads back as the same double, with no
// exponent for magnitudes from 1e-6 to 1e15 ("10", "0.1", "-2.5", "32768"), and an exponent
// beyond them ("1e+20"); "nan", "inf" and "-inf" as such. For output and messages alike.
std::string plain_number(double v);

enum class OutputFormat { Text, Json, Svg };
// "text", "json", "svg".
const char* format_name(OutputFormat format);
// The format named by `-O`, or nullopt for an unknown name.
std::optional<OutputFormat> parse_format(std::string_view name);

// One -o file extension and the output format it selects.
struct FormatExtension {
    std::string extension;   // lower case, with the dot: ".png"
    std::string format;      // the -O name it stands for
    bool listed = true;      // named in the unknown-extension error (false: an alias, as .ansi)
};
// The extension of `file` with its dot, in lower case ("a/B.PNG" → ".png"; "" when it has none).
std::string lowercase_extension(const std::string& file);

// Every subcommand's rule for its output format: -O's value when given (the subcommand checks the
// name, mostly through CLI11), else the format the -o file's extension selects (compared
// case-insensitively), else `fallback` (stdout: no -o, or -o -). An extension not in `extensions`
// (or none) is an Error naming the file and the listed extensions, for fail_usage:
// "out.xyz: cannot tell the output format from the extension '.xyz' (use .png or .pgm, or give -O)".
Expected<std::string> pick_output_format(const std::string& format_option,
                                         const std::string& output_file,
                                         const std::vector<FormatExtension>& extensions,
                                         const std::string& fallback);

// pick_output_format for text, json and svg: the extensions .txt, .json, .svg. An unknown -O
// name is an Error.
Expected<OutputFormat> choose_format(const std::string& format_option,
                                     const std::string& output_file, OutputFormat fallback);

// --compression fast|default|small on a command that writes PNG, into `png` (bezel/image.hpp's
// PngCompression says what each level trades; the default is `default`). A value not among them
// is a usage error (exit 2) that lists them.
void add_compression_option(CLI::App& cmd, PngOptions& png);

// Writes `data` to stdout when `output_file` is empty or "-", else atomically to `output_file`
// (temporary file `<output_file>.tmp-XXXXXX` in the same directory, then rename). The error
// names the file and the system's reason; no temporary file survives a failure.
Status write_output(const std::string& output_file, std::string_view data);
// The last step of a subcommand: write_output, then kExitOk, or the write's error reported by
// fail_runtime.
int write_result(const std::string& output_file, std::string_view data);

}  // namespace bezel::cli
