// Regression tests for what fuzzing found (tests/fuzz/, `./dev fuzz`), each named after what
// broke, with the input inline (decoded from the fuzzer's bytes: the crash file is named).
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <string>
#include <vector>

#include "bezel/smooth.hpp"

namespace bezel {
namespace {

// fuzz_smooth crash-9f5b56b9e8eb20724d5d8ef13a8e19913d4c4986: a finite tension of DBL_MAX gave
// cardinal_tangents infinite tangents (lib/src/smooth/hermite.cpp, cardinal_tangents), which
// cardinal_spline then reported as hermite's error about tangents[0].
TEST(FuzzRegressions, CardinalTangentsWithTensionDblMaxAreAnErrorNotInfinite) {
    const std::vector<Point> points{{-39, 15},    {-30.5, -31}, {6.5, -31},   {-47, -49.5},
                                    {-47, -49.5}, {-20.5, -8.5}, {8.5, -55},  {-45.5, -5},
                                    {-45.5, -5},  {11.5, -47.5}, {-20.5, -8.5}};
    auto tangents = cardinal_tangents(points, DBL_MAX, false);
    ASSERT_FALSE(tangents.ok());
    EXPECT_NE(tangents.error().message.find("cardinal"), std::string::npos)
        << tangents.error().message;
    EXPECT_NE(tangents.error().message.find("overflows"), std::string::npos)
        << tangents.error().message;
    auto spline = cardinal_spline(points, DBL_MAX, false);
    ASSERT_FALSE(spline.ok());
    EXPECT_EQ(spline.error().message, tangents.error().message);
    // The largest tension that does not overflow still works, and stays finite.
    auto fine = cardinal_tangents(points, 1e300, false);
    ASSERT_TRUE(fine.ok());
    for (const Vec2& t : *fine) EXPECT_TRUE(std::isfinite(t.x) && std::isfinite(t.y));
}

}  // namespace
}  // namespace bezel
