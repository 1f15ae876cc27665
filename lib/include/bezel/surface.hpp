// bezel/surface.hpp — bicubic surface patches: evaluation, subdivision, tessellation to triangles,
// OBJ/STL export, and pictures (wireframe and shaded) drawn with bezel's own rasterizer.
//
// A patch is the course notes' matrix form, one coordinate at a time:
//     Q(s,t) = S·M·G·Mᵀ·Tᵀ,   S = [s³ s² s 1],  T = [t³ t² t 1],  s, t ∈ [0, 1],
// M one of the geometry core's basis matrices (bezel::basis, bezier.hpp) and G a 4×4 grid of 3D
// points (or points and derivatives, for Hermite). G[i][j]: i runs along s, j along t. S·M is the
// row of blending functions in s, T·M the one in t, so Q = Σᵢⱼ (S·M)ᵢ·(T·M)ⱼ·G[i][j].
//
// Geometry layouts:
//   Bézier:  G[i][j] = control point bᵢⱼ; the patch interpolates its four corners b00, b03, b30, b33.
//   Hermite: with Q_s = ∂Q/∂s, Q_t = ∂Q/∂t, Q_st = ∂²Q/∂s∂t (the twist),
//              G = [ Q(0,0)    Q(0,1)    Q_t(0,0)   Q_t(0,1)  ]
//                  [ Q(1,0)    Q(1,1)    Q_t(1,0)   Q_t(1,1)  ]
//                  [ Q_s(0,0)  Q_s(0,1)  Q_st(0,0)  Q_st(0,1) ]
//                  [ Q_s(1,0)  Q_s(1,1)  Q_st(1,0)  Q_st(1,1) ]
//            (basis::kHermite's [P0 P1 T0 T1] in each direction).
//   B-spline: G[i][j] = de Boor point; the patch is the uniform bicubic B-spline piece over the
//            middle of the 4×4 grid and passes through none of its points.
// Continuity between patches that share data (patch meshes): Bézier patches sharing an edge row of
// control points are C0; G1/C1 needs the rows either side collinear (and equally spaced) — the
// data's business (the Utah teapot is G1 nearly everywhere). Hermite patches sharing corner points,
// tangents and twists along an edge are C1. Uniform B-spline patches cut from one control grid
// (bspline_grid) are C2 by construction.
//
// Coordinates: world units, right-handed, any axis may be "up" (Camera::up). Images: pixels, y DOWN.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "bezel/bezier.hpp"
#include "bezel/expected.hpp"
#include "bezel/image.hpp"
#include "bezel/limits.hpp"

#pragma GCC visibility push(default)  // the public API of libbezel.so (docs/architecture.md)
namespace bezel {

// A 3D point or vector (surfaces only; 2D geometry uses Vec2).
struct Vec3 {
    double x = 0.0, y = 0.0, z = 0.0;

    constexpr Vec3() = default;
    constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
    constexpr Vec3 operator+(Vec3 o) const { return {x + o.x, y + o.y, z + o.z}; }
    constexpr Vec3 operator-(Vec3 o) const { return {x - o.x, y - o.y, z - o.z}; }
    constexpr Vec3 operator-() const { return {-x, -y, -z}; }
    constexpr Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
    constexpr Vec3 operator/(double s) const { return {x / s, y / s, z / s}; }
    constexpr Vec3& operator+=(Vec3 o) { x += o.x; y += o.y; z += o.z; return *this; }
    constexpr bool operator==(Vec3 o) const { return x == o.x && y == o.y && z == o.z; }
    constexpr bool operator!=(Vec3 o) const { return !(*this == o); }
    constexpr double dot(Vec3 o) const { return x * o.x + y * o.y + z * o.z; }
    constexpr Vec3 cross(Vec3 o) const {
        return {y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x};
    }
    double length() const { return std::sqrt(dot(*this)); }
    // Unit vector; the zero vector stays zero.
    Vec3 normalized() const {
        double l = length();
        return l > 0.0 ? *this / l : Vec3{};
    }
    bool is_finite() const { return std::isfinite(x) && std::isfinite(y) && std::isfinite(z); }
};
constexpr Vec3 operator*(double s, Vec3 v) { return v * s; }

enum class SurfaceBasis : std::uint8_t { Bezier, Hermite, BSpline };

// "bezier", "hermite", "bspline".
const char* basis_name(SurfaceBasis basis);
// The basis matrix M (basis::kBezier, kHermite, kBSpline).
const basis::Mat4& basis_matrix(SurfaceBasis basis);
// The matrix C = M_bez⁻¹·M that maps this basis's geometry to Bézier control points along one
// direction (identity for Bézier; basis::kBSplineToBezier for B-spline, computed, not typed).
// A patch's Bézier control net is C·G·Cᵀ.
basis::Mat4 to_bezier_matrix(SurfaceBasis basis);
// The blending functions U·M for U = [u³ u² u 1]: weight of geometry row/column k at u. Bézier
// and B-spline weights sum to 1 for every u (partition of unity); Hermite's two position
// weights sum to 1 (the tangent weights carry no position).
std::array<double, 4> blend(SurfaceBasis basis, double u);
// Their derivatives d/du (U′·M with U′ = [3u² 2u 1 0]) and second derivatives (U″ = [6u 2 0 0]).
std::array<double, 4> blend_deriv(SurfaceBasis basis, double u);
std::array<double, 4> blend_deriv2(SurfaceBasis basis, double u);

struct Patch {
    SurfaceBasis basis = SurfaceBasis::Bezier;
    Vec3 g[4][4] = {};  // G[i][j], i along s, j along t (layouts above)

    // Q(s,t) by the matrix form.
    Vec3 eval(double s, double t) const;
    // ∂Q/∂s and ∂Q/∂t (matrix form with S′ or T′).
    Vec3 deriv_s(double s, double t) const;
    Vec3 deriv_t(double s, double t) const;
    // The unit normal (∂Q/∂s × ∂Q/∂t)/|…|. Where that cross product vanishes (a collapsed edge,
    // like the teapot lid's pole: |∂s × ∂t| ≤ 1e-12·size² of the net) the limit direction is
    // taken from a point 1e-5 towards the patch centre in parameter space; zero only if the
    // patch is degenerate there too.
    Vec3 normal(double s, double t) const;
    // The same surface as a Bézier patch, control net C·G·Cᵀ (to rounding).
    Patch to_bezier() const;
    bool is_finite() const;
};

// --- Bézier-only operations (any patch is converted by to_bezier() first) ---------------------

// Evaluation by de Casteljau along t on each row, then along s: the stable reference the matrix
// form is tested against.
Vec3 eval_de_casteljau(const Patch& bezier, double s, double t);
// de Casteljau at s (resp. t) on every column (row) of the net: the two halves, meeting exactly
// along the iso-curve. The results are Bézier patches.
std::pair<Patch, Patch> split_s(const Patch& patch, double s);
std::pair<Patch, Patch> split_t(const Patch& patch, double t);
// The piece over [s0, s1] × [t0, t1], reparametrised to [0, 1]², as a Bézier patch (blossoms).
Patch subpatch(const Patch& patch, double s0, double s1, double t0, double t1);

// --- Patch meshes ------------------------------------------------------------------------------

// The uniform bicubic B-spline surface of a rows × cols grid of de Boor points (row-major,
// points[r·cols + c]; r along s, c along t): (rows − 3)·(cols − 3) patches, C2 across every
// shared edge. Errors: rows or cols < 4 or > kMaxBSplineGridSide, a point count ≠ rows·cols,
// a non-finite point.
Expected<std::vector<Patch>> bspline_grid(const std::vector<Vec3>& points, int rows, int cols);

// Checks a patch list: not empty, at most kMaxSurfacePatches, finite points. `what` names the
// input in the message.
Status validate_patches(const std::vector<Patch>& patches, const std::string& what);

// --- Tessellation --------------------------------------------------------------------------------

struct TessellateOptions {
    // > 0: exactly steps × steps grid cells per patch. 0: the count from `tolerance`.
    int steps = 0;
    // Largest distance, in world units, between a point of the mesh and the surface point with the
    // same parameters (so the Hausdorff distance is at most this too). > 0.
    double tolerance = 1e-3;
};

// A triangle mesh. Vertex k has position, unit normal (from the surface, not the facets) and
// the (s,t) it came from; triangle m came from patch `patch_of[m]`. Triangles are wound so that
// (b − a) × (c − a) points along +∂Q/∂s × ∂Q/∂t.
struct TriangleMesh {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;
    std::vector<Vec2> params;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<std::uint32_t> patch_of;
};

// The grid steps per direction one Bézier patch needs for `tolerance`. A uniform grid of step h
// cut into triangles interpolates a C2 map within
//     (h²/8)·(M_ss + 2·M_st + M_tt),  M_xy = max |∂²Q/∂x∂y|
// (Filip, Magedson & Markot, "Surface algorithms using bounds on derivatives", CAGD 1986), and
// for a Bézier net M_ss ≤ 6·max|Δ²_s b|, M_st ≤ 9·max|Δ_sΔ_t b|, M_tt ≤ 6·max|Δ²_t b| (the second
// derivative is a Bézier patch of those differences). So n = ⌈√((M_ss + 2M_st + M_tt)/(8·tol))⌉,
// at least 1. May exceed kMaxTessellationSteps (the caller decides).
int steps_for_tolerance(const Patch& patch, double tolerance);

// Every patch as an n × n grid of 2n² triangles, n = options.steps or the largest
// steps_for_tolerance over all patches: one n for all keeps shared edges sampled at the same
// parameters, so a mesh of patches that share edges has no cracks. Vertices are not shared
// between patches. Errors: invalid patches (validate_patches), tolerance ≤ 0 or not finite,
// steps < 0, n > kMaxTessellationSteps, more than kMaxMeshTriangles triangles.
Expected<TriangleMesh> tessellate(const std::vector<Patch>& patches,
                                  const TessellateOptions& options);

// Wavefront OBJ text: "v x y z", "vn x y z", "f a//a b//b c//c" (1-based), 17 significant digits.
std::string to_obj(const TriangleMesh& mesh);
// STL: binary (80-byte header, uint32 count, 50 bytes per triangle, little-endian float32) or
// ASCII ("solid bezel" … "endsolid bezel"). Facet normals are the triangles' own; degenerate
// triangles get a zero normal.
std::string to_stl_binary(const TriangleMesh& mesh);
std::string to_stl_ascii(const TriangleMesh& mesh);

// --- Camera and pictures ------------------------------------------------------------------------

enum class Projection : std::uint8_t { Orthographic, Perspective };

struct Camera {
    Vec3 eye{0, -5, 2};
    Vec3 target{0, 0, 0};
    Vec3 up{0, 0, 1};         // need not be perpendicular to the view direction, only not parallel
    Projection projection = Projection::Perspective;
    double fov_y_deg = 30.0;  // perspective: vertical field of view, (0, 180)
    double ortho_height = 2.0;  // orthographic: world units visible from top to bottom
};

// The camera looking at `target` from azimuth/elevation in degrees (z up: azimuth 0 looks along
// +y from −y, increasing counter-clockwise seen from above; elevation 90 looks straight down),
// from `distance` away.
Camera orbit_camera(Vec3 target, double azimuth_deg, double elevation_deg, double distance,
                    Projection projection);

// The perspective near plane, as a fraction of the eye–target distance. Geometry nearer to the eye
// than this is clipped: it bounds projected coordinates to 1/kNearPlaneFraction times the picture
// scale at the target (so an edge running past the eye stays a finite line, not a spike), while
// clipping only what is far closer than what the camera looks at.
inline constexpr double kNearPlaneFraction = 1.0 / 64;

// World → picture. View space: x right, y up, z the distance along the view direction. Pixel
// x = cx + k·X, y = cy − k·Y with (X, Y) = (x, y) (orthographic) or (x/z, y/z) (perspective).
class View {
public:
    // k and (cx, cy) from the camera's field of view (or ortho_height), centred on the target.
    static Expected<View> look_at(const Camera& camera, int width, int height);
    // The same camera and direction, but k and the centre chosen so that the Bézier control nets
    // of `patches` (hence, by the convex hull property, which projection preserves, the
    // surfaces) fill the picture less `margin_px` on each side. When a control point lies behind
    // the near plane (a perspective camera on or inside the surfaces' hull) no scale makes them
    // fit, and the view is look_at's: the camera's own field of view.
    static Expected<View> fit(const Camera& camera, int width, int height,
                              const std::vector<Patch>& patches, double margin_px);

    // (pixel x, pixel y, view depth). Depth is meaningful for every point; pixel x, y only where
    // in_front().
    Vec3 project(Vec3 world) const;
    // The view depth of `world` alone: its distance along the view direction from the eye.
    double depth(Vec3 world) const;
    // For perspective: depth ≥ near_depth(). Always true for orthographic. The renderers clip
    // what crosses the near plane at the plane itself, so a camera on or inside a surface sees
    // it cut there.
    bool in_front(Vec3 world) const;
    // Perspective: kNearPlaneFraction of the eye–target distance; orthographic: −∞.
    double near_depth() const;
    // Unit vector from `world` towards the viewer (constant for orthographic).
    Vec3 to_viewer(Vec3 world) const;
    // View-space basis in world coordinates: right, up, forward.
    Vec3 right() const { return right_; }
    Vec3 up() const { return up_; }
    Vec3 forward() const { return forward_; }
    int width() const { return width_; }
    int height() const { return height_; }
    Projection projection() const { return projection_; }

private:
    Vec3 to_view(Vec3 world) const;
    Vec3 eye_, right_, up_, forward_;
    Projection projection_ = Projection::Perspective;
    double k_ = 1.0, cx_ = 0.0, cy_ = 0.0, near_ = 0.0;
    int width_ = 0, height_ = 0;
};

struct WireStyle {
    int iso_lines = 5;             // iso-curves per patch per direction, ≥ 2 (2 = the edges only)
    double line_width_px = 1.0;
    double flatten_tolerance_px = 0.05;  // projected polyline vs. the projected curve (estimate)
    Rgba8 background{255, 255, 255, 255};
    Rgba8 color{20, 30, 60, 255};
};

// Iso-curves of constant s and t, flattened in 3D, projected, stroked with stroke() (round joins
// and caps) and filled with Rasterizer::fill_path (NonZero). Hidden lines are NOT removed: the
// wireframe is see-through. Parts behind a perspective camera's near plane are cut away.
// Errors: too many patches (validate_patches), iso_lines < 2 or > 64, width not in (0, 64],
// tolerance ≤ 0, a stroke or fill error.
Expected<Image> render_wireframe(const std::vector<Patch>& patches, const View& view,
                                 const WireStyle& style);

enum class Shading : std::uint8_t { Flat, Smooth };

struct SolidStyle {
    Shading shading = Shading::Smooth;
    // Lambert: colour·(ambient + (1 − ambient)·max(0, n·l)), l the unit direction towards the
    // light in VIEW space (x right, y up, z towards the viewer): default upper left, in front.
    Vec3 light{-0.4, 0.5, 0.77};
    double ambient = 0.18;
    Rgba8 background{255, 255, 255, 255};
    Rgba8 color{200, 120, 60, 255};
};

// The mesh's triangles filled with the Rasterizer's exact-area coverage and shaded per
// triangle (Flat, the facet normal) or per pixel (Smooth: Gouraud's idea on normals — the vertex
// normals interpolated perspective-correctly at the pixel centre, then Lambert). Both sides of
// the surface are lit (the normal is turned towards the viewer).
// Hidden surfaces: depth sort (painter's order, front to back) composited by SATURATING coverage
// — each triangle adds min(coverage, 1 − coverage already there), OpenGL's polygon antialiasing
// (GL_SRC_ALPHA_SATURATE). Why this rather than a z-buffer: the edges keep the rasterizer's exact
// anti-aliasing, and triangles sharing an edge add up to full coverage (plain "over" would leave
// a faint seam along every mesh edge). Known failures, as every depth sort: triangles that
// interpenetrate or overlap cyclically, and long triangles whose centroid order differs from
// their true order, can show the farther one in front; fine tessellations make this rare.
// Triangles with a vertex behind a perspective near plane are dropped.
Expected<Image> render_solid(const TriangleMesh& mesh, const View& view, const SolidStyle& style);

}  // namespace bezel
#pragma GCC visibility pop
