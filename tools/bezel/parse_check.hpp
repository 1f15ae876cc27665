// tools/bezel/parse_check.hpp — CLI11 checks made from the CLI's own parsers and range tests, so
// that a value they refuse is a usage error (exit 2) with bezel's message, which CLI11 prefixes
// with the option's name ("--text: empty string", "--margin: -5 is not in 0 to 32768").
#pragma once

#include <CLI/CLI.hpp>
#include <cmath>
#include <string>

#include "cli_common.hpp"

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

// A number from `lo` to `hi`, both included. The message prints the value as typed and the
// bounds as plain numbers ("-5 is not in 0 to 32768"), where CLI::Range printed them with
// std::to_string ("Value -5 not in range 0.000000 to 32768.000000").
inline CLI::Validator in_range(double lo, double hi) {
    return CLI::Validator(
        [lo, hi](std::string& value) -> std::string {
            const std::optional<double> v = parse_number(value);
            if (!v) return "'" + value + "' is not a number";
            if (!(*v >= lo && *v <= hi))  // NaN fails too
                return value + " is not in " + plain_number(lo) + " to " + plain_number(hi);
            return {};
        },
        // --help shows it after the type name: "--margin PX:[0, 32768]".
        "[" + plain_number(lo) + ", " + plain_number(hi) + "]", "RANGE");
}

// A number above 0 (and finite).
inline CLI::Validator positive_number() {
    return CLI::Validator(
        [](std::string& value) -> std::string {
            const std::optional<double> v = parse_number(value);
            if (!v) return "'" + value + "' is not a number";
            if (!(*v > 0 && std::isfinite(*v))) return value + " is not a positive number";
            return {};
        },
        "POSITIVE", "POSITIVE");
}

// A number from 0 up (a count or an index: CLI11 then checks it is a whole number).
inline CLI::Validator non_negative_number() {
    return CLI::Validator(
        [](std::string& value) -> std::string {
            const std::optional<double> v = parse_number(value);
            if (!v) return "'" + value + "' is not a number";
            if (!(*v >= 0)) return value + " is negative (expected 0 or more)";
            return {};
        },
        "NONNEGATIVE", "NONNEGATIVE");
}

}  // namespace bezel::cli
