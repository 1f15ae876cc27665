// Reading point lists for `bezel smooth`: the "x,y x,y" text of --points/--tangents, and the JSON
// the tool itself writes, so its output can be fed back in.
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "smooth_output.hpp"

namespace bezel::cli {

Expected<std::vector<Vec2>> parse_vec2_list(std::string_view text, const std::string& what) {
    std::vector<double> numbers;
    std::size_t i = 0;
    auto separator = [](char c) { return c == ',' || std::isspace(static_cast<unsigned char>(c)); };
    while (i < text.size()) {
        if (separator(text[i])) {
            ++i;
            continue;
        }
        std::size_t start = i;
        while (i < text.size() && !separator(text[i])) ++i;
        std::string token(text.substr(start, i - start));
        char* end = nullptr;
        errno = 0;
        double v = std::strtod(token.c_str(), &end);
        // strtod also reads "nan", "inf" and hex floats; only finite values are coordinates.
        if (end != token.c_str() + token.size() || !std::isfinite(v) || errno == ERANGE)
            return Error{what + ": '" + token + "' at offset " + std::to_string(start) +
                         " is not a finite number"};
        numbers.push_back(v);
        if (numbers.size() / 2 > kMaxSmoothPoints)
            return Error{what + ": more than " + std::to_string(kMaxSmoothPoints) + " points"};
    }
    if (numbers.size() % 2 != 0)
        return Error{what + ": " + std::to_string(numbers.size()) +
                     " numbers, expected x,y pairs (the last one has no y)"};
    std::vector<Vec2> out(numbers.size() / 2);
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = {numbers[2 * k], numbers[2 * k + 1]};
    return out;
}

Expected<std::vector<Vec2>> parse_points_json(std::string_view text, const std::string& what) {
    nlohmann::json doc = nlohmann::json::parse(text.begin(), text.end(), nullptr, false);
    if (doc.is_discarded()) return Error{what + ": not valid JSON"};
    const nlohmann::json* list = &doc;
    if (doc.is_object()) {
        auto it = doc.find("points");
        if (it == doc.end()) return Error{what + ": JSON object without a \"points\" array"};
        list = &*it;
    }
    if (!list->is_array()) return Error{what + ": \"points\" is not an array"};
    if (list->size() > kMaxSmoothPoints)
        return Error{what + ": more than " + std::to_string(kMaxSmoothPoints) + " points"};
    std::vector<Vec2> out;
    out.reserve(list->size());
    for (std::size_t k = 0; k < list->size(); ++k) {
        const nlohmann::json& p = (*list)[k];
        if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
            return Error{what + ": points[" + std::to_string(k) + "] is not an [x, y] pair"};
        Vec2 v{p[0].get<double>(), p[1].get<double>()};
        if (!v.is_finite())
            return Error{what + ": points[" + std::to_string(k) + "] is not finite"};
        out.push_back(v);
    }
    return out;
}

Expected<std::vector<Vec2>> read_points_file(const std::string& file) {
    std::string data;
    const std::string name = file == "-" ? "<stdin>" : file;
    auto read_from = [&](std::istream& in) -> Status {
        char buf[65536];
        while (in.read(buf, sizeof buf) || in.gcount() > 0) {
            data.append(buf, static_cast<std::size_t>(in.gcount()));
            if (data.size() > kMaxPointsFileBytes)
                return Error{name + ": larger than " + std::to_string(kMaxPointsFileBytes >> 20) +
                             " MiB"};
        }
        if (in.bad()) return Error{name + ": read error"};
        return ok_status();
    };
    Status st = ok_status();
    if (file == "-") {
        st = read_from(std::cin);
    } else {
        if (std::filesystem::is_directory(file)) return Error{file + ": is a directory"};
        std::ifstream in(file, std::ios::binary);
        if (!in) return Error{file + ": cannot open file"};
        st = read_from(in);
    }
    if (!st) return st.error();
    std::size_t first = data.find_first_not_of(" \t\r\n");
    if (first != std::string::npos && (data[first] == '{' || data[first] == '['))
        return parse_points_json(data, name);
    return parse_vec2_list(data, name);
}

}  // namespace bezel::cli
