// Surface pictures: camera projection and fitting, solid coverage and shading, hidden surfaces,
// wireframe placement. Golden images of whole renders are in surface_cli_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "bezel/surface.hpp"

namespace bezel {
namespace {

// A flat Bézier patch through the bilinear map of four corners (exact degree elevation).
Patch bilinear(Vec3 p00, Vec3 p01, Vec3 p10, Vec3 p11) {
    Patch p;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double s = i / 3.0, t = j / 3.0;
            p.g[i][j] = p00 * ((1 - s) * (1 - t)) + p01 * ((1 - s) * t) + p10 * (s * (1 - t)) + p11 * (s * t);
        }
    return p;
}

// Looking along +y from y = −10, z up, orthographic, 4 world units tall.
Camera front_camera() {
    Camera c;
    c.eye = {0, -10, 0};
    c.target = {0, 0, 0};
    c.up = {0, 0, 1};
    c.projection = Projection::Orthographic;
    c.ortho_height = 4;
    return c;
}

SolidStyle head_on_light(Shading shading) {
    SolidStyle s;
    s.shading = shading;
    s.light = {0, 0, 1};  // from the viewer
    s.ambient = 0.2;
    s.color = {200, 100, 50, 255};
    return s;
}

int channel_diff(Rgba8 a, Rgba8 b) {
    return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

TEST(SurfaceViewTest, ProjectionMapsTargetToCentreAndScales) {
    auto v = View::look_at(front_camera(), 100, 80);
    ASSERT_TRUE(v.ok());
    Vec3 c = v->project({0, 0, 0});
    EXPECT_DOUBLE_EQ(c.x, 50);
    EXPECT_DOUBLE_EQ(c.y, 40);
    EXPECT_DOUBLE_EQ(c.z, 10);  // depth: distance along the view direction
    Vec3 r = v->project({1, 3, 1});  // 1 right, 1 up; depth does not matter in orthographic
    EXPECT_DOUBLE_EQ(r.x, 50 + 20);
    EXPECT_DOUBLE_EQ(r.y, 40 - 20);

    Camera persp = front_camera();
    persp.projection = Projection::Perspective;
    persp.fov_y_deg = 90;
    auto p = View::look_at(persp, 100, 100);
    ASSERT_TRUE(p.ok());
    // tan(45°) = 1: a point at depth 10 and height 10 is on the top edge; twice as far, halfway.
    EXPECT_NEAR(p->project({0, 0, 10}).y, 0.0, 1e-12);
    EXPECT_NEAR(p->project({0, 10, 10}).y, 25.0, 1e-12);
    EXPECT_FALSE(p->in_front({0, -11, 0}));
}

TEST(SurfaceViewTest, FitKeepsTheSurfaceInsideTheMargin) {
    Patch saddle;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double x = -1 + 2 * i / 3.0, y = -1 + 2 * j / 3.0;
            saddle.g[i][j] = {x, y, x * y};
        }
    for (Projection proj : {Projection::Orthographic, Projection::Perspective}) {
        Camera cam = orbit_camera({0, 0, 0}, 30, 25, 6, proj);
        auto v = View::fit(cam, 200, 120, {saddle}, 10);
        ASSERT_TRUE(v.ok());
        double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
        for (int i = 0; i <= 20; ++i)
            for (int j = 0; j <= 20; ++j) {
                Vec3 q = v->project(saddle.eval(i / 20.0, j / 20.0));
                x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
            }
        EXPECT_GE(x0, 10 - 1e-9);
        EXPECT_LE(x1, 190 + 1e-9);
        EXPECT_GE(y0, 10 - 1e-9);
        EXPECT_LE(y1, 110 + 1e-9);
        // And it is not tiny: the surface spans most of the tighter direction.
        EXPECT_GT(std::max((x1 - x0) / 180, (y1 - y0) / 100), 0.8);
    }
}

TEST(SurfaceViewTest, RejectsBadCameras) {
    Camera c = front_camera();
    EXPECT_FALSE(View::look_at(c, 0, 10).ok());
    EXPECT_FALSE(View::look_at(c, 10, kMaxSurfaceImageDim + 1).ok());
    c.up = {0, 1, 0};  // along the view direction
    EXPECT_FALSE(View::look_at(c, 10, 10).ok());
    c = front_camera();
    c.target = c.eye;
    EXPECT_FALSE(View::look_at(c, 10, 10).ok());
    c = front_camera();
    c.projection = Projection::Perspective;
    c.fov_y_deg = 180;
    EXPECT_FALSE(View::look_at(c, 10, 10).ok());
}

TEST(SurfaceSolidTest, FacingSquareHasExactCoverageAndNoSeams) {
    // The square [−1, 1]² at y = 0 covers pixels 25..75 of a 100×100 picture exactly.
    std::vector<Patch> square = {bilinear({-1, 0, -1}, {-1, 0, 1}, {1, 0, -1}, {1, 0, 1})};
    auto mesh = tessellate(square, {8, 0});  // 128 triangles: many shared edges cross pixels
    ASSERT_TRUE(mesh.ok());
    auto v = View::look_at(front_camera(), 100, 100);
    ASSERT_TRUE(v.ok());
    for (Shading sh : {Shading::Flat, Shading::Smooth}) {
        SolidStyle style = head_on_light(sh);
        auto img = render_solid(*mesh, *v, style);
        ASSERT_TRUE(img.ok()) << img.error().message;
        // Lit head-on: ambient + (1 − ambient)·1 = the colour itself, on every covered pixel;
        // abutting triangles' partial coverages add to 1, so no lighter seam anywhere.
        for (int y = 0; y < 100; ++y)
            for (int x = 0; x < 100; ++x) {
                bool inside = x >= 25 && x < 75 && y >= 25 && y < 75;
                Rgba8 want = inside ? style.color : style.background;
                ASSERT_LE(channel_diff(img->at(x, y), want), 1) << x << "," << y;
            }
    }
}

TEST(SurfaceSolidTest, HalfCoveredEdgePixelsBlendInLinearLight) {
    // The square [−0.98, 0.98]²: its edges cut the border pixels in half.
    std::vector<Patch> square = {bilinear({-0.98, 0, -0.98}, {-0.98, 0, 0.98},
                                          {0.98, 0, -0.98}, {0.98, 0, 0.98})};
    auto mesh = tessellate(square, {3, 0});
    auto v = View::look_at(front_camera(), 100, 100);
    ASSERT_TRUE(mesh.ok() && v.ok());
    SolidStyle style = head_on_light(Shading::Flat);
    style.color = {0, 0, 0, 255};
    auto img = render_solid(*mesh, *v, style);
    ASSERT_TRUE(img.ok());
    // Half black over white in linear light is 0.5, sRGB-encoded 188.
    EXPECT_NEAR(img->at(25, 50).r, 188, 1);
    EXPECT_NEAR(img->at(50, 74).g, 188, 1);
    EXPECT_EQ(img->at(50, 50).r, 0);
}

TEST(SurfaceSolidTest, NearerSurfaceHidesFartherOne) {
    // A tilted plane whose triangles' centroids are NEARER than the small facing square in front
    // of its upper part: the depth sort draws the plane first; the square must still show.
    std::vector<Patch> scene = {
        bilinear({-2, -1, -2}, {2, -1, -2}, {-2, 5, 2}, {2, 5, 2}),          // tilted, far at the top
        bilinear({-0.5, 3.5, 1.0}, {0.5, 3.5, 1.0}, {-0.5, 3.5, 1.8}, {0.5, 3.5, 1.8}),  // facing
    };
    auto mesh = tessellate(scene, {1, 0});
    auto v = View::look_at(front_camera(), 100, 100);
    ASSERT_TRUE(mesh.ok() && v.ok());
    SolidStyle style = head_on_light(Shading::Flat);
    auto img = render_solid(*mesh, *v, style);
    ASSERT_TRUE(img.ok());
    // The square's centre (0, 3.5, 1.4) lands at pixel (50, 15); the plane is at y = 4.1 there.
    Vec3 q = v->project({0, 3.5, 1.4});
    Rgba8 square = img->at(static_cast<int>(q.x), static_cast<int>(q.y));
    EXPECT_LE(channel_diff(square, style.color), 1)  // facing: full brightness
        << int(square.r) << " " << int(square.g) << " " << int(square.b);
    // Beside the square the tilted plane shows, darker: n·l = 4/√52.
    Rgba8 plane = img->at(static_cast<int>(q.x) + 20, static_cast<int>(q.y));
    EXPECT_GT(channel_diff(plane, style.color), 20);
    EXPECT_LE(channel_diff(plane, style.background), 254);
}

TEST(SurfaceSolidTest, SmoothShadingHasNoFacetSteps) {
    // A dome: flat shading shows a step at every facet edge, smooth shading varies gently.
    Patch dome;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double x = -1 + 2 * i / 3.0, z = -1 + 2 * j / 3.0;
            dome.g[i][j] = {x, (i == 1 || i == 2) && (j == 1 || j == 2) ? -1.5 : 0.0, z};
        }
    auto mesh = tessellate({dome}, {6, 0});
    auto v = View::look_at(front_camera(), 100, 100);
    ASSERT_TRUE(mesh.ok() && v.ok());
    auto biggest_step = [&](Shading sh) {
        SolidStyle style = head_on_light(sh);
        style.light = {0.6, 0.3, 0.74};
        auto img = render_solid(*mesh, *v, style);
        EXPECT_TRUE(img.ok());
        // Largest second difference along rows: a facet edge is a step (a spike here), a smooth
        // gradient is not.
        int worst = 0;
        for (int y = 30; y < 70; ++y)
            for (int x = 30; x < 68; ++x) {
                int a = img->at(x, y).r, b = img->at(x + 1, y).r, c = img->at(x + 2, y).r;
                worst = std::max(worst, std::abs(a - 2 * b + c));
            }
        return worst;
    };
    int flat = biggest_step(Shading::Flat), smooth = biggest_step(Shading::Smooth);
    EXPECT_GE(flat, 20) << "smooth " << smooth;  // measured 50
    EXPECT_LE(smooth, 6) << "flat " << flat;  // measured 4: rounding and the curvature itself
}

TEST(SurfaceWireTest, IsoLinesLandWhereTheyShould) {
    // The square [−1, 1]² facing the camera, 3 iso-lines per direction: lines at x, z = −1, 0, 1,
    // i.e. pixel columns and rows 25, 50, 75.
    std::vector<Patch> square = {bilinear({-1, 0, -1}, {-1, 0, 1}, {1, 0, -1}, {1, 0, 1})};
    auto v = View::look_at(front_camera(), 100, 100);
    ASSERT_TRUE(v.ok());
    WireStyle style;
    style.iso_lines = 3;
    style.line_width_px = 2;
    style.color = {0, 0, 0, 255};
    auto img = render_wireframe(square, *v, style);
    ASSERT_TRUE(img.ok()) << img.error().message;
    for (int k : {25, 50, 75}) {
        // A 2 px line centred on pixel boundary k covers pixels k−1 and k fully.
        EXPECT_EQ(img->at(k - 1, 40).r, 0) << k;
        EXPECT_EQ(img->at(k, 40).r, 0) << k;
        EXPECT_EQ(img->at(40, k - 1).r, 0) << k;
        EXPECT_EQ(img->at(40, k).r, 0) << k;
    }
    EXPECT_EQ(img->at(37, 40).r, 255);  // between lines
    EXPECT_EQ(img->at(10, 10).r, 255);  // outside
    style.iso_lines = 1;
    EXPECT_FALSE(render_wireframe(square, *v, style).ok());
}

// A camera standing on a floor that runs far past it on every side: the floor crosses the near
// plane behind and below the eye. Looking level along +x from 1 unit up, the horizon is the middle
// row; the floor fills the lower half of the picture and nothing of it reaches the upper half.
Camera standing_camera() {
    Camera c;
    c.eye = {0, 0, 1};
    c.target = {10, 0, 1};
    c.up = {0, 0, 1};
    c.projection = Projection::Perspective;
    c.fov_y_deg = 60;
    return c;
}

std::vector<Patch> floor_around_the_camera() {
    return {bilinear({-100, -100, 0}, {-100, 100, 0}, {100, -100, 0}, {100, 100, 0})};
}

TEST(SurfaceNearPlaneTest, FloorCrossingTheNearPlaneFillsTheLowerHalfWithoutSpikes) {
    auto mesh = tessellate(floor_around_the_camera(), {16, 0});
    ASSERT_TRUE(mesh.ok());
    auto v = View::look_at(standing_camera(), 120, 80);
    ASSERT_TRUE(v.ok());
    SolidStyle style = head_on_light(Shading::Flat);
    auto img = render_solid(*mesh, *v, style);
    ASSERT_TRUE(img.ok()) << img.error().message;
    // Every triangle under the camera crosses the near plane: were it dropped, the rows near the
    // bottom would show the background through the hole.
    for (int y = 0; y < 80; ++y)
        for (int x = 0; x < 120; ++x) {
            const Rgba8 px = img->at(x, y);
            if (y < 39) {
                ASSERT_EQ(channel_diff(px, style.background), 0) << x << "," << y;
            } else if (y > 41) {
                ASSERT_GT(channel_diff(px, style.background), 100) << x << "," << y;
            }
        }
}

TEST(SurfaceNearPlaneTest, WireframeLinesEndAtTheNearPlane) {
    WireStyle style;
    auto v = View::look_at(standing_camera(), 120, 80);
    ASSERT_TRUE(v.ok());
    auto img = render_wireframe(floor_around_the_camera(), *v, style);
    ASSERT_TRUE(img.ok()) << img.error().message;
    int ink_below = 0;
    for (int y = 0; y < 80; ++y)
        for (int x = 0; x < 120; ++x) {
            const bool ink = channel_diff(img->at(x, y), style.background) > 0;
            if (y < 39) {
                ASSERT_FALSE(ink) << "a spike above the horizon at " << x << "," << y;
            }
            ink_below += ink && y > 41;
        }
    // The iso-line x = 0 runs under the eye to the bottom of the picture.
    EXPECT_GT(ink_below, 40);
    EXPECT_GT(channel_diff(img->at(60, 79), style.background), 0);
}

TEST(SurfaceNearPlaneTest, FitKeepsTheFieldOfViewWhenTheCameraIsAmongThePatches) {
    const Camera c = standing_camera();
    auto fitted = View::fit(c, 120, 80, floor_around_the_camera(), 4);
    auto plain = View::look_at(c, 120, 80);
    ASSERT_TRUE(fitted.ok() && plain.ok());
    for (Vec3 p : {Vec3{10, 0, 0}, Vec3{5, 3, 0}, Vec3{50, -20, 0}}) {
        EXPECT_EQ(fitted->project(p).x, plain->project(p).x);
        EXPECT_EQ(fitted->project(p).y, plain->project(p).y);
    }
    EXPECT_EQ(plain->near_depth(), 10.0 * kNearPlaneFraction);
    EXPECT_FALSE(plain->in_front({0.1, 0, 0}));
    EXPECT_TRUE(plain->in_front({0.2, 0, 0}));
}

}  // namespace
}  // namespace bezel
