// tools/bezel/surface_input.hpp — `bezel surface`'s inputs: the patch JSON file and the x,y,z
// and WxH option values.
//
// Patch file (JSON; every point an [x, y, z] array of finite numbers):
//   {"basis": "bezier" | "hermite" | "bspline",          optional; default: --basis, else bezier
//    "patches": [[16 points], ...]}                      G[i][j] = point 4i + j (i along s)
// or, for "bspline" only, a control grid giving C2 patches (bezel::bspline_grid):
//   {"basis": "bspline", "grid": [[row 0 points], [row 1 points], ...]}   rows along s
// Hermite patches list their 16 entries in the same row-major order, with the layout of
// surface.hpp: rows Q(0,·), Q(1,·), Q_s(0,·), Q_s(1,·); columns value(0), value(1), ∂t(0), ∂t(1).
// Other keys (e.g. "comment") are ignored.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "bezel/surface.hpp"

namespace bezel::cli {

// Largest patch file read, in bytes: the teapot is 12 KiB; 16 MiB holds ~kMaxSurfacePatches
// patches of 17-digit points.
inline constexpr std::size_t kMaxSurfaceFileBytes = std::size_t{16} << 20;

// Parses the JSON above. `name` names the input in errors; `basis` is --basis when given (a file
// naming another basis is an error).
Expected<std::vector<Patch>> parse_surface_json(std::string_view text, const std::string& name,
                                                std::optional<SurfaceBasis> basis);
// Reads `file` ('-': stdin) and parses it.
Expected<std::vector<Patch>> read_surface_file(const std::string& file,
                                               std::optional<SurfaceBasis> basis);

// "x,y,z" (three finite numbers) for --eye, --target, --up; `what` names the option.
Expected<Vec3> parse_vec3(std::string_view text, const std::string& what);
// "WxH" for --size, each side 1 to kMaxSurfaceImageDim.
Expected<std::pair<int, int>> parse_size(std::string_view text);

}  // namespace bezel::cli
