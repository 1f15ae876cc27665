#include <gtest/gtest.h>

#include "bezel/path.hpp"

using namespace bezel;

TEST(PathBuilder, DrawingAfterCloseStartsNewContourAtStart) {
    Path p;
    p.move_to({1, 2});
    p.line_to({5, 2});
    p.line_to({5, 6});
    p.close();
    p.line_to({0, 0});
    ASSERT_EQ(p.verbs().size(), 6u);
    EXPECT_EQ(p.verbs()[4], Verb::Move);
    EXPECT_EQ(p.points()[3], (Point{1, 2}));
}
