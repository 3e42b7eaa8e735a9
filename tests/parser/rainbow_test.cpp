// rainbow { }: what POV-Ray's Parse_Rainbow leaves (angles into radians, the arc and falloff halved, its default 180
// kept in degrees, direction and up made square), the list order, and the errors it raises, at their positions.
#include <cmath>

#include <gtest/gtest.h>

#include "parse_helpers.hpp"

namespace povtrace::test {
namespace {

constexpr double kDegree = M_PI / 180.0;

TEST(Rainbow, ItemsAreStoredAsPovRayComputesThem) {
  const SceneDescription s = parse(
      "#version 3.7;\n"
      "rainbow { angle 42.5 width 5 distance 1e4 direction <0, 0, 2> jitter 0.01 up <0, 3, 1>\n"
      "  colour_map { [0 rgb 1] [1 rgb 0] } }\n"
      "rainbow { angle 30 width 2 direction z arc_angle 120 colour_map { [0 rgb 1] [1 rgb 0] } }\n"
      "rainbow { angle 30 width 2 direction z falloff_angle 90 }\n");
  ASSERT_EQ(s.rainbows.size(), 3u);
  const Rainbow& first = s.rainbows[2];   // the newest first, as POV-Ray lists them
  EXPECT_DOUBLE_EQ(first.angle, (42.5 - 2.5) * kDegree);
  EXPECT_DOUBLE_EQ(first.width, 5 * kDegree);
  EXPECT_EQ(first.distance, 1e4);
  EXPECT_EQ(first.jitter, 0.01);
  EXPECT_EQ(first.antisolar, (Vec3{0, 0, 1}));
  EXPECT_NEAR(dot(first.up, first.antisolar), 0.0, 1e-15);   // up made square to the direction
  EXPECT_NEAR(first.up.y, 1.0, 1e-15);
  EXPECT_NEAR(first.right.x, 1.0, 1e-15);                    // right = up × direction
  EXPECT_EQ(first.arc_angle, 180.0);                         // not written: POV-Ray's 180, in those units
  EXPECT_EQ(first.falloff_width, 0.0);
  ASSERT_TRUE(first.colour_map);
  EXPECT_EQ(first.colour_map->pattern, PatternKind::gradient);
  EXPECT_EQ(first.colour_map->entries.size(), 2u);
  const Rainbow& arc = s.rainbows[1];
  EXPECT_DOUBLE_EQ(arc.arc_angle, 120 * M_PI / 360);   // halved, in radians
  EXPECT_EQ(arc.falloff_angle, arc.arc_angle);         // arc_angle alone sets the falloff angle
  EXPECT_EQ(arc.falloff_width, 0.0);
  const Rainbow& falloff = s.rainbows[0];
  EXPECT_DOUBLE_EQ(falloff.falloff_angle, 90 * M_PI / 360);
  EXPECT_DOUBLE_EQ(falloff.falloff_width, 180 - 90 * M_PI / 360);   // POV-Ray's units, mixed as it mixes them
  EXPECT_FALSE(falloff.colour_map);                                  // no map: rendered as nothing
}

TEST(Rainbow, BadValuesAreErrorsAtTheirPosition) {
  struct Case {
    std::string text;
    int line, column;
    std::string fragment;
  };
  const Case cases[] = {
      {"rainbow { angle 40 width 2 }\n", 2, 1, "direction vector is zero"},
      {"rainbow { direction y up <0, 2, 0> }\n", 2, 1, "co-linear"},
      {"rainbow { direction z up 0 }\n", 2, 1, "up vector is zero"},
      {"rainbow { direction z\n  arc_angle 400 }\n", 3, 3, "arc_angle must be 0 to 360"},
      {"rainbow { direction z falloff_angle -1 }\n", 2, 23, "falloff_angle must be 0 to 360"},
      {"rainbow { direction z falloff_angle 90 arc_angle 60 }\n", 2, 40, "arc_angle is smaller than its falloff_angle"},
      {"rainbow { direction z colour rgb 1 }\n", 2, 23, "a rainbow item"},
  };
  for (const Case& c : cases) {
    const ParseError e = parse_error("#version 3.7;\n" + c.text);
    EXPECT_EQ(e.location().line, c.line) << c.text << e.what();
    EXPECT_EQ(e.location().column, c.column) << c.text << e.what();
    EXPECT_NE(e.bare_message().find(c.fragment), std::string::npos) << e.bare_message();
  }
}

}  // namespace
}  // namespace povtrace::test
