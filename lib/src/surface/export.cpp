// Triangle meshes as Wavefront OBJ and STL (binary and ASCII).
#include <cstdio>
#include <cstring>

#include "bezel/surface.hpp"

namespace bezel {
namespace {

void append_vec(std::string& out, const char* tag, Vec3 v) {
    char buf[96];
    int len = std::snprintf(buf, sizeof buf, "%s %.17g %.17g %.17g\n", tag, v.x, v.y, v.z);
    out.append(buf, static_cast<std::size_t>(len));
}

Vec3 facet_normal(const TriangleMesh& mesh, const std::array<std::uint32_t, 3>& tri) {
    Vec3 a = mesh.positions[tri[0]], b = mesh.positions[tri[1]], c = mesh.positions[tri[2]];
    return (b - a).cross(c - a).normalized();
}

void put_u32(std::string& out, std::uint32_t v) {
    for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xFF));
}
void put_f32(std::string& out, double v) {
    float f = static_cast<float>(v);
    std::uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    put_u32(out, bits);
}

}  // namespace

std::string to_obj(const TriangleMesh& mesh) {
    std::string out = "# bezel surface mesh: " + std::to_string(mesh.positions.size()) +
                      " vertices, " + std::to_string(mesh.triangles.size()) + " triangles\n";
    for (Vec3 p : mesh.positions) append_vec(out, "v", p);
    for (Vec3 n : mesh.normals) append_vec(out, "vn", n);
    char buf[96];
    for (const auto& t : mesh.triangles) {
        unsigned long a = t[0] + 1ul, b = t[1] + 1ul, c = t[2] + 1ul;
        int len = std::snprintf(buf, sizeof buf, "f %lu//%lu %lu//%lu %lu//%lu\n", a, a, b, b, c, c);
        out.append(buf, static_cast<std::size_t>(len));
    }
    return out;
}

std::string to_stl_binary(const TriangleMesh& mesh) {
    std::string out(80, '\0');
    const char kHeader[] = "bezel surface mesh (binary STL)";
    std::memcpy(&out[0], kHeader, sizeof kHeader - 1);
    out.reserve(84 + 50 * mesh.triangles.size());
    put_u32(out, static_cast<std::uint32_t>(mesh.triangles.size()));
    for (const auto& t : mesh.triangles) {
        Vec3 n = facet_normal(mesh, t);
        put_f32(out, n.x), put_f32(out, n.y), put_f32(out, n.z);
        for (std::uint32_t v : t) {
            Vec3 p = mesh.positions[v];
            put_f32(out, p.x), put_f32(out, p.y), put_f32(out, p.z);
        }
        out.append(2, '\0');  // attribute byte count
    }
    return out;
}

std::string to_stl_ascii(const TriangleMesh& mesh) {
    std::string out = "solid bezel\n";
    char buf[128];
    for (const auto& t : mesh.triangles) {
        Vec3 n = facet_normal(mesh, t);
        int len = std::snprintf(buf, sizeof buf, "  facet normal %.9g %.9g %.9g\n    outer loop\n",
                                n.x, n.y, n.z);
        out.append(buf, static_cast<std::size_t>(len));
        for (std::uint32_t v : t) {
            Vec3 p = mesh.positions[v];
            len = std::snprintf(buf, sizeof buf, "      vertex %.9g %.9g %.9g\n", p.x, p.y, p.z);
            out.append(buf, static_cast<std::size_t>(len));
        }
        out += "    endloop\n  endfacet\n";
    }
    out += "endsolid bezel\n";
    return out;
}

}  // namespace bezel
