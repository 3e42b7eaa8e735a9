// julia_fractal and bicubic_patch as POV-Ray 3.7's parser reads them (parser/objects/fractal_patch.cpp).
#include <cmath>

#include <gtest/gtest.h>

#include "parse_helpers.hpp"

namespace povtrace::test {
namespace {

const Object& only_object(const SceneDescription& s) {
  EXPECT_EQ(s.objects.size(), 1u);
  return s.objects.at(0);
}

TEST(JuliaFractal, ItemsDefaultsAndClamps) {
  auto s = parse("#version 3.7;\njulia_fractal { 0.2 hypercomplex sin max_iteration 7.9 precision 0.5 "
                 "slice <1, 0, 0, 1>, 0.5 }\n");
  auto j = std::get<JuliaFractal>(only_object(s).shape);
  for (double c : j.julia) EXPECT_EQ(c, 0.2);   // a float fills all four
  EXPECT_EQ(j.algebra, JuliaAlgebra::hypercomplex);
  EXPECT_EQ(j.function, JuliaFunction::sin);
  EXPECT_EQ(j.max_iteration, 7);                // floored
  EXPECT_EQ(j.precision, 1.0);                  // precision below 1 is 1: the step is 1/1
  EXPECT_DOUBLE_EQ(j.slice[0], std::sqrt(0.5));
  EXPECT_DOUBLE_EQ(j.slice[3], std::sqrt(0.5));
  EXPECT_EQ(j.slice_distance, 0.5);
  s = parse("#version 3.7;\njulia_fractal { <1, 2> hypercomplex pwr(2, 0.5) max_iteration -3 }\n");
  j = std::get<JuliaFractal>(only_object(s).shape);
  EXPECT_EQ(j.julia, (std::array<double, 4>{1, 2, 0, 0}));   // padded with zeros
  EXPECT_EQ(j.function, JuliaFunction::pwr);
  EXPECT_EQ(j.exponent, (std::array<double, 2>{2, 0.5}));
  EXPECT_EQ(j.max_iteration, 1);
  s = parse("#version 3.7;\njulia_fractal { <-0.083, 0, -0.83, -0.025> }\n");
  j = std::get<JuliaFractal>(only_object(s).shape);
  EXPECT_EQ(j.algebra, JuliaAlgebra::quaternion);
  EXPECT_EQ(j.function, JuliaFunction::sqr);
  EXPECT_EQ(j.max_iteration, 20);
  EXPECT_EQ(j.precision, 1.0 / 20.0);
}

TEST(JuliaFractal, PovRaysErrors) {
  auto message = [](const std::string& text) { return std::string(parse_error("#version 3.7;\n" + text).what()); };
  EXPECT_NE(message("julia_fractal { <1, 0, 0, 0> quaternion exp }\n").find("supports only sqr and cube"),
            std::string::npos);
  EXPECT_NE(message("julia_fractal { 1 slice <1, 0, 0, 1e-11>, 0 }\n").find("4th component is zero"),
            std::string::npos);
  EXPECT_NE(message("julia_fractal { 1 slice <0, 0, 0, 0>, 0 }\n").find("slice vector is zero"), std::string::npos);
  EXPECT_NE(message("julia_fractal { 1 hypercomplex log }\n").find("a julia_fractal item"), std::string::npos);
  EXPECT_NE(message("julia_fractal { 1 hypercomplex pwr 2, 0 }\n").find("after 'pwr'"), std::string::npos);
  EXPECT_NE(message("julia_fractal { rgb 1 }\n").find("expected a 4-D vector"), std::string::npos);
}

// SetUp_Fractal and every transform clear the fractal's inversion (POV-Ray 3.7's Compute_BBox).
TEST(JuliaFractal, TransformsClearInverse) {
  auto s = parse("#version 3.7;\n#declare J = julia_fractal { 1 inverse }\nobject { J }\nobject { J inverse }\n"
                 "object { J inverse translate x }\n");
  ASSERT_EQ(s.objects.size(), 3u);
  EXPECT_FALSE(s.objects[0].inverse);
  EXPECT_TRUE(s.objects[1].inverse);
  EXPECT_FALSE(s.objects[2].inverse);
}

constexpr const char* kFlatNet =
    "<0,0,0>,<1,0,0>,<2,0,0>,<3,0,0>,<0,1,0>,<1,1,0>,<2,1,0>,<3,1,0>,"
    "<0,2,0>,<1,2,0>,<2,2,0>,<3,2,0>,<0,3,0>,<1,3,0>,<2,3,0>,<3,3,0>";

TEST(BicubicPatch, ItemsPointsAndTransforms) {
  auto s = parse(std::string("#version 3.7;\nbicubic_patch { type 0 flatness 0.1 u_steps 3 v_steps 4 accuracy 0.5 "
                             "uv_vectors <0, 0> <2, 0>, <2, 2> 1, ") +
                 kFlatNet + " translate z scale 2 }\n");
  const auto b = std::get<BicubicPatch>(only_object(s).shape);
  EXPECT_EQ(b.type, 0);
  EXPECT_EQ(b.flatness, 0.1);
  EXPECT_EQ(b.u_steps, 3);
  EXPECT_EQ(b.v_steps, 4);
  EXPECT_EQ(b.uv_vectors[1], (std::array<double, 2>{2, 0}));
  EXPECT_EQ(b.uv_vectors[3], (std::array<double, 2>{1, 1}));   // a float stands for both
  EXPECT_EQ(b.points[5], (Vec3{2, 2, 2}));                      // <1,1,0> moved by the transforms
  EXPECT_EQ(only_object(s).world_from_object, Matrix{});         // the patch keeps no matrix
}

TEST(BicubicPatch, OldSyntaxTypeChecksAndInverse) {
  Messages m;
  auto s = parse(std::string("#version 3.7;\nbicubic_patch { 1 3 2 ") + kFlatNet + " inverse }\n", &m);
  auto b = std::get<BicubicPatch>(only_object(s).shape);
  EXPECT_EQ(b.type, 1);
  EXPECT_EQ(b.flatness, 0.1);   // the old syntax's default
  EXPECT_EQ(b.u_steps, 3);
  EXPECT_EQ(b.v_steps, 2);
  EXPECT_FALSE(only_object(s).inverse);
  EXPECT_NE(m.joined().find("should use keywords"), std::string::npos) << m.joined();
  EXPECT_NE(m.joined().find("cannot invert a patch"), std::string::npos) << m.joined();
  s = parse(std::string("#version 3.7;\nbicubic_patch { type 3 ") + kFlatNet + " }\n", &m);
  EXPECT_EQ(std::get<BicubicPatch>(only_object(s).shape).type, 1);
  EXPECT_NE(m.joined().find("no longer supported"), std::string::npos) << m.joined();
  const ParseError e = parse_error(std::string("#version 3.7;\nbicubic_patch { flatness 0 ") + kFlatNet + " }\n");
  EXPECT_NE(e.bare_message().find("needs 'type 0' or 'type 1'"), std::string::npos) << e.bare_message();
  EXPECT_EQ(e.location().line, 2);
  const ParseError big =
      parse_error(std::string("#version 3.7;\nbicubic_patch { type 1 u_steps 11 v_steps 10 ") + kFlatNet + " }\n");
  EXPECT_NE(big.bare_message().find("is not rendered"), std::string::npos) << big.bare_message();
}

}  // namespace
}  // namespace povtrace::test
