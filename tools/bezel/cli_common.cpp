#include "cli_common.hpp"

#include "bezel/text.hpp"

#include <CLI/CLI.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>

namespace bezel::cli {

int fail_runtime(const std::string& message) {
    std::cerr << "bezel: " << message << '\n';
    return kExitRuntime;
}

int fail_usage(const std::string& message, const std::string& command) {
    std::cerr << "bezel: " << message << '\n'
              << "Run '" << command << " --help' for the list of options.\n";
    return kExitUsage;
}

std::string version_string() { return std::string("bezel ") + BEZEL_VERSION; }

// One UTF-8 implementation for the library and the CLI: bezel/text.hpp's.
Expected<std::u32string> decode_utf8(std::string_view text) { return bezel::decode_utf8(text); }

void append_utf8(std::string& out, char32_t cp) { bezel::append_utf8(out, cp); }

std::optional<double> parse_number(const std::string& text) {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size()) return std::nullopt;
    return v;
}

std::string plain_number(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    if (v == 0) return "0";  // also -0: a sign on zero only puzzles a reader
    char buf[400];  // fixed notation of up to 1e15 with 17 significant digits fits easily
    const double a = std::fabs(v);
    const std::chars_format format =
        a >= 1e-6 && a < 1e15 ? std::chars_format::fixed : std::chars_format::general;
    // Without a precision, to_chars gives the shortest form that round-trips.
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, format);
    return ec == std::errc() ? std::string(buf, end) : std::to_string(v);
}

Expected<char32_t> parse_code_point(std::string_view arg) {
    const std::string quoted = "'" + std::string(arg) + "'";
    if (arg.size() > 2 && (arg[0] == 'U' || arg[0] == 'u') && arg[1] == '+') {
        std::string_view hex = arg.substr(2);
        if (hex.size() > 6)
            return Error{quoted + ": more than 6 hex digits"};
        char32_t cp = 0;
        for (char c : hex) {
            if (!std::isxdigit(static_cast<unsigned char>(c)))
                return Error{quoted + ": expected hex digits after U+"};
            int digit = std::isdigit(static_cast<unsigned char>(c))
                            ? c - '0'
                            : std::tolower(static_cast<unsigned char>(c)) - 'a' + 10;
            cp = cp * 16 + static_cast<char32_t>(digit);
        }
        if (cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))
            return Error{quoted + ": not a Unicode scalar value"};
        return cp;
    }
    auto decoded = decode_utf8(arg);
    if (!decoded) return Error{quoted + ": " + decoded.error().message};
    if (decoded->size() != 1)
        return Error{quoted + ": expected one character or U+XXXX, got " +
                     std::to_string(decoded->size()) + " characters"};
    return (*decoded)[0];
}

std::string format_code_point(char32_t cp) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "U+%04X", static_cast<unsigned>(cp));
    return buf;
}

const char* format_name(OutputFormat format) {
    switch (format) {
        case OutputFormat::Text: return "text";
        case OutputFormat::Json: return "json";
        case OutputFormat::Svg: return "svg";
    }
    return "text";
}

std::optional<OutputFormat> parse_format(std::string_view name) {
    if (name == "text" || name == "txt") return OutputFormat::Text;
    if (name == "json") return OutputFormat::Json;
    if (name == "svg") return OutputFormat::Svg;
    return std::nullopt;
}

std::string lowercase_extension(const std::string& file) {
    std::string ext = std::filesystem::path(file).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

Expected<std::string> pick_output_format(const std::string& format_option,
                                         const std::string& output_file,
                                         const std::vector<FormatExtension>& extensions,
                                         const std::string& fallback) {
    if (!format_option.empty()) return format_option;
    if (output_file.empty() || output_file == "-") return fallback;
    const std::string ext = lowercase_extension(output_file);
    std::vector<const std::string*> listed;
    for (const FormatExtension& e : extensions) {
        if (e.extension == ext) return e.format;
        if (e.listed) listed.push_back(&e.extension);
    }
    // ".a, .b or .c"
    std::string known;
    for (std::size_t i = 0; i < listed.size(); ++i)
        known += (i == 0 ? "" : i + 1 == listed.size() ? " or " : ", ") + *listed[i];
    return Error{output_file + ": cannot tell the output format from the extension '" + ext +
                 "' (use " + known + ", or give -O)"};
}

Expected<OutputFormat> choose_format(const std::string& format_option,
                                     const std::string& output_file, OutputFormat fallback) {
    auto name = pick_output_format(format_option, output_file,
                                   {{".txt", "text"}, {".json", "json"}, {".svg", "svg"}},
                                   format_name(fallback));
    if (!name) return name.error();
    if (auto f = parse_format(*name)) return *f;
    return Error{"-O '" + format_option + "': unknown output format (expected text, json or svg)"};
}

namespace {

std::string errno_text(int err) { return std::strerror(err); }

// Writes all of `data` to `fd`, retrying short writes and EINTR.
bool write_all(int fd, std::string_view data) {
    while (!data.empty()) {
        ssize_t n = ::write(fd, data.data(), data.size());
        if (n < 0) {
            if (errno == EINTR) continue;
            return false;
        }
        data.remove_prefix(static_cast<std::size_t>(n));
    }
    return true;
}

}  // namespace

Status write_output(const std::string& output_file, std::string_view data) {
    if (output_file.empty() || output_file == "-") {
        std::cout.write(data.data(), static_cast<std::streamsize>(data.size()));
        std::cout.flush();
        if (!std::cout) return Error{"<stdout>: write failed"};
        return ok_status();
    }
    if (std::filesystem::is_directory(output_file))
        return Error{output_file + ": is a directory"};

    // mkstemp creates the temporary beside the target, so rename() stays within one file system
    // and is atomic: readers see either the old file or the complete new one.
    std::string tmp = output_file + ".tmp-XXXXXX";
    int fd = ::mkstemp(tmp.data());
    if (fd < 0) return Error{output_file + ": cannot create file (" + errno_text(errno) + ")"};
    // mkstemp makes the file 0600; give it the mode a plain open() would: 0666 minus the umask.
    mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);

    bool ok = write_all(fd, data);
    int err = errno;
    if (::close(fd) != 0 && ok) {
        ok = false;
        err = errno;
    }
    if (ok && ::rename(tmp.c_str(), output_file.c_str()) != 0) {
        ok = false;
        err = errno;
    }
    if (!ok) {
        ::unlink(tmp.c_str());
        return Error{output_file + ": cannot write file (" + errno_text(err) + ")"};
    }
    return ok_status();
}

int write_result(const std::string& output_file, std::string_view data) {
    auto written = write_output(output_file, data);
    return written ? kExitOk : fail_runtime(written.error().message);
}

void add_compression_option(CLI::App& cmd, PngOptions& png) {
    cmd.add_option_function<std::string>(
           "--compression",
           [&png](const std::string& level) {
               png.compression = level == "fast"    ? PngCompression::Fast
                                 : level == "small" ? PngCompression::Small
                                                    : PngCompression::Default;
           },
           "How hard to deflate PNG: same pixels, time against file size (default: default)")
        ->type_name("LEVEL")
        ->check(CLI::IsMember({"fast", "default", "small"}));
}

}  // namespace bezel::cli
