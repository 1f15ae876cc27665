// Reading `bezel surface`'s patch files and option values (formats in surface_input.hpp).
#include "surface_input.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

namespace bezel::cli {
namespace {

using nlohmann::json;

std::optional<SurfaceBasis> basis_from_name(std::string_view name) {
    for (SurfaceBasis b : {SurfaceBasis::Bezier, SurfaceBasis::Hermite, SurfaceBasis::BSpline})
        if (name == basis_name(b)) return b;
    return std::nullopt;
}

Expected<Vec3> point_from_json(const json& p, const std::string& where) {
    if (!p.is_array() || p.size() != 3 || !p[0].is_number() || !p[1].is_number() ||
        !p[2].is_number())
        return Error{where + " is not an [x, y, z] array of numbers"};
    Vec3 v{p[0].get<double>(), p[1].get<double>(), p[2].get<double>()};
    if (!v.is_finite()) return Error{where + " is not finite"};
    return v;
}

Expected<std::vector<Patch>> patches_from_json(const json& list, SurfaceBasis basis,
                                               const std::string& name) {
    if (!list.is_array()) return Error{name + ": \"patches\" is not an array"};
    if (list.size() > kMaxSurfacePatches)
        return Error{name + ": " + std::to_string(list.size()) + " patches, more than " +
                     std::to_string(kMaxSurfacePatches)};
    std::vector<Patch> out;
    out.reserve(list.size());
    for (std::size_t k = 0; k < list.size(); ++k) {
        const json& pts = list[k];
        const std::string where = name + ": patches[" + std::to_string(k) + "]";
        if (!pts.is_array() || pts.size() != 16)
            return Error{where + " has " + (pts.is_array() ? std::to_string(pts.size()) : "no") +
                         " points, expected 16"};
        Patch p;
        p.basis = basis;
        for (std::size_t i = 0; i < 16; ++i) {
            auto v = point_from_json(pts[i], where + "[" + std::to_string(i) + "]");
            if (!v) return v.error();
            p.g[i / 4][i % 4] = *v;
        }
        out.push_back(p);
    }
    return out;
}

Expected<std::vector<Patch>> grid_from_json(const json& rows, const std::string& name) {
    if (!rows.is_array()) return Error{name + ": \"grid\" is not an array of rows"};
    const std::size_t r = rows.size();
    const std::size_t c = r > 0 && rows[0].is_array() ? rows[0].size() : 0;
    const auto max_side = static_cast<std::size_t>(kMaxBSplineGridSide);
    if (r < 4 || c < 4 || r > max_side || c > max_side)
        return Error{name + ": grid " + std::to_string(r) + "x" + std::to_string(c) +
                     ", each side must be 4 to " + std::to_string(kMaxBSplineGridSide)};
    std::vector<Vec3> points;
    points.reserve(r * c);
    for (std::size_t i = 0; i < r; ++i) {
        const std::string where = name + ": grid[" + std::to_string(i) + "]";
        if (!rows[i].is_array() || rows[i].size() != c)
            return Error{where + " does not have " + std::to_string(c) + " points like row 0"};
        for (std::size_t j = 0; j < c; ++j) {
            auto v = point_from_json(rows[i][j], where + "[" + std::to_string(j) + "]");
            if (!v) return v.error();
            points.push_back(*v);
        }
    }
    auto patches = bspline_grid(points, static_cast<int>(r), static_cast<int>(c));
    if (!patches) return Error{name + ": " + patches.error().message};
    return patches;
}

}  // namespace

Expected<std::vector<Patch>> parse_surface_json(std::string_view text, const std::string& name,
                                                std::optional<SurfaceBasis> basis) {
    json doc = json::parse(text.begin(), text.end(), nullptr, false);
    if (doc.is_discarded()) return Error{name + ": not valid JSON"};
    if (!doc.is_object()) return Error{name + ": expected a JSON object with \"patches\" or \"grid\""};
    if (auto it = doc.find("basis"); it != doc.end()) {
        auto named = it->is_string() ? basis_from_name(it->get<std::string>()) : std::nullopt;
        if (!named) return Error{name + ": \"basis\" must be \"bezier\", \"hermite\" or \"bspline\""};
        if (basis && *basis != *named)
            return Error{name + ": the file's basis is " + basis_name(*named) + ", not --basis " +
                         basis_name(*basis)};
        basis = named;
    }
    const SurfaceBasis b = basis.value_or(SurfaceBasis::Bezier);
    auto patches_it = doc.find("patches");
    auto grid_it = doc.find("grid");
    if ((patches_it == doc.end()) == (grid_it == doc.end()))
        return Error{name + ": expected exactly one of \"patches\" and \"grid\""};
    Expected<std::vector<Patch>> out = Error{""};
    if (grid_it != doc.end()) {
        if (b != SurfaceBasis::BSpline) return Error{name + ": \"grid\" needs basis bspline"};
        out = grid_from_json(*grid_it, name);
    } else {
        out = patches_from_json(*patches_it, b, name);
    }
    if (!out) return out;
    if (auto ok = validate_patches(*out, name); !ok) return ok.error();
    return out;
}

Expected<std::vector<Patch>> read_surface_file(const std::string& file,
                                               std::optional<SurfaceBasis> basis) {
    const std::string name = file == "-" ? "<stdin>" : file;
    std::ifstream in_file;
    std::istream* in = &std::cin;
    if (file != "-") {
        std::error_code ec;
        if (std::filesystem::is_directory(file, ec)) return Error{file + ": is a directory"};
        in_file.open(file, std::ios::binary);
        if (!in_file) return Error{file + ": cannot open file"};
        in = &in_file;
    }
    std::string data;
    char buf[65536];
    while (in->read(buf, sizeof buf) || in->gcount() > 0) {
        data.append(buf, static_cast<std::size_t>(in->gcount()));
        if (data.size() > kMaxSurfaceFileBytes)
            return Error{name + ": larger than " + std::to_string(kMaxSurfaceFileBytes >> 20) + " MiB"};
    }
    if (in->bad()) return Error{name + ": read error"};
    return parse_surface_json(data, name, basis);
}

Expected<Vec3> parse_vec3(std::string_view text, const std::string& what) {
    double v[3];
    std::size_t pos = 0;
    for (int k = 0; k < 3; ++k) {
        std::size_t end = k < 2 ? text.find(',', pos) : text.size();
        if (end == std::string_view::npos) end = text.size();
        std::string token(text.substr(pos, end - pos));
        char* stop = nullptr;
        errno = 0;
        v[k] = std::strtod(token.c_str(), &stop);
        if (token.empty() || stop != token.c_str() + token.size() || !std::isfinite(v[k]) ||
            errno == ERANGE || (k < 2 && end == text.size()))
            return Error{what + " '" + std::string(text) + "': expected x,y,z (three finite numbers)"};
        pos = end + 1;
    }
    return Vec3{v[0], v[1], v[2]};
}

Expected<std::pair<int, int>> parse_size(std::string_view text) {
    std::string s(text);
    char* stop = nullptr;
    errno = 0;
    long w = std::strtol(s.c_str(), &stop, 10);
    long h = -1;
    if (stop != s.c_str() && (*stop == 'x' || *stop == 'X')) {
        const char* hs = stop + 1;
        h = std::strtol(hs, &stop, 10);
        if (stop == hs || *stop != '\0') h = -1;
    } else if (stop != s.c_str() && *stop == '\0') {
        h = w;  // "N" is N×N
    }
    if (h < 1 || w < 1 || w > kMaxSurfaceImageDim || h > kMaxSurfaceImageDim || errno == ERANGE)
        return Error{"--size '" + s + "': expected WxH (or N), each 1 to " +
                     std::to_string(kMaxSurfaceImageDim)};
    return std::pair<int, int>{static_cast<int>(w), static_cast<int>(h)};
}

}  // namespace bezel::cli
