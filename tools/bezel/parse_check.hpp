// tools/bezel/parse_check.hpp — a CLI11 check made from one of the CLI's own parsers, so that a
// value the parser refuses is a usage error (exit 2) with the parser's message, which CLI11
// prefixes with the option's name ("--text: empty string").
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace bezel::cli {

// `parse(value)` returns an Expected; the check passes when it holds a value. The description
// is empty so that --help shows the option's type name alone ("LIST", not "LIST:LIST").
template <typename Parse>
CLI::Validator parse_check(Parse parse, const std::string& name) {
    return CLI::Validator(
        [parse](std::string& value) {
            auto parsed = parse(value);
            return parsed ? std::string() : parsed.error().message;
        },
        "", name);
}

}  // namespace bezel::cli
