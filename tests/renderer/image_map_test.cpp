// image_map lookups against hand-computed values (POV-Ray 3.7 support/imageutil.cpp map_pos, the mappers and the
// interpolations) and the decoding of PNG samples into working-space texels (base/image/png.cpp, image.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "scene/source.hpp"
#include "renderer/pattern/image_map.hpp"

namespace povtrace::render {
namespace {

constexpr double kEps = 1e-10;   // added to every image position

ImageMapping mapping(int map_type, int columns, int rows, bool once = false, int interpolate = 0) {
  ImageMapping m;
  m.map_type = map_type;
  m.interpolate = interpolate;
  m.once = once;
  m.columns = columns;
  m.rows = rows;
  m.width = columns;
  m.height = rows;
  return m;
}

// A w × h image whose pixel (x, y) has red x, green y (and blue, filter, transmit 0).
MapImage coordinates_image(int w, int h) {
  MapImage image;
  image.width = w;
  image.height = h;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) image.texels.push_back(Texel{float(x), float(y), 0, 0, 0});
  return image;
}

void expect_position(const std::optional<std::array<double, 2>>& at, double column, double row) {
  ASSERT_TRUE(at.has_value());
  EXPECT_NEAR((*at)[0], column, 1e-9);
  EXPECT_NEAR((*at)[1], row, 1e-9);
}

TEST(ImageMapPosition, PlanarTakesXAsColumnAndYUpwardsFromTheBottomRow) {
  const ImageMapping m = mapping(0, 4, 4);
  // x 0.3 → column 1.2; y 0.3 → 1.2 rows up from the bottom edge, i.e. row 4 − 1.2 = 2.8 from the top.
  expect_position(image_position(m, {0.3, 0.3, 7.0}), 1.2 + kEps, 2.8 - kEps);
  // Outside [0, 1) the image repeats: x −0.1 → column 4 − 0.4, y 1.25 → 0.25 of the image → row 3.
  expect_position(image_position(m, {-0.1, 1.25, 0.0}), 3.6 + kEps, 3.0 - kEps);
  // x and y exactly 0: the 1e-10 nudge keeps column 0 and puts the row just inside the bottom one.
  expect_position(image_position(m, {0.0, 0.0, 0.0}), kEps, 4.0 - kEps);
}

TEST(ImageMapPosition, OnceLeavesTheImageOutsideTheUnitSquare) {
  const ImageMapping m = mapping(0, 4, 4, true);
  EXPECT_FALSE(image_position(m, {1.2, 0.5, 0}).has_value());
  EXPECT_FALSE(image_position(m, {0.5, -0.01, 0}).has_value());
  // x exactly 1 is inside the square, and fmod(1 · 4, 4) wraps it to column 0.
  expect_position(image_position(m, {1.0, 0.5, 0}), kEps, 2 - kEps);
  expect_position(image_position(m, {0.5, 0.5, 0}), 2 + kEps, 2 - kEps);
  const MapImage image = coordinates_image(4, 4);
  EXPECT_FALSE(image_map_colour(image, m, {1.5, 0.5, 0}).has_value());
  EXPECT_EQ(kOffImageColour, (Colour{1, 1, 1, 0, 1}));   // clear white off the image
}

TEST(ImageMapPosition, RepeatAndOffsetScaleAndShiftTheImage) {
  ImageMapping m = mapping(0, 4, 2);
  m.width = 8;            // repeat <2, 1>: two images per unit
  m.offset_u = -0.5 * 4;  // offset <0.5, 0>
  // x 0.3 → 0.3 · 8 = 2.4 (fmod 8), then −2 → 0.4.
  expect_position(image_position(m, {0.3, 0.25, 0}), 0.4 + kEps, 1.5 - kEps);
}

TEST(ImageMapPosition, SphericalTakesLongitudeAndLatitude) {
  const ImageMapping m = mapping(1, 8, 4);
  // On +x: longitude 0, latitude 0 (v = half the height, counted up from the bottom).
  expect_position(image_position(m, {2, 0, 0}), kEps, 2 - kEps);
  // On +z: a quarter turn; on −z three quarters; the length of the point does not matter.
  expect_position(image_position(m, {0, 0, 0.5}), 2 + kEps, 2 - kEps);
  expect_position(image_position(m, {0, 0, -3}), 6 + kEps, 2 - kEps);
  // 30° up at −x: latitude 0.5 + 1/6, longitude half a turn.
  expect_position(image_position(m, {-std::sqrt(3.0), 1, 0}), 4 + kEps, 4 - 4 * (0.5 + 1.0 / 6.0) - kEps);
  EXPECT_FALSE(image_position(m, {0, 0, 0}).has_value());   // the centre is off the image
}

TEST(ImageMapPosition, CylindricalTakesTheAngleAroundYAndYItself) {
  const ImageMapping m = mapping(2, 8, 4);
  expect_position(image_position(m, {0, 0.25, 3}), 2 + kEps, 3 - kEps);
  expect_position(image_position(m, {-1, 1.5, 0}), 4 + kEps, 2 - kEps);   // y repeats
  EXPECT_FALSE(image_position(mapping(2, 8, 4, true), {-1, 1.5, 0}).has_value());
  EXPECT_FALSE(image_position(m, {0, 0.5, 0}).has_value());   // on the axis
}

TEST(ImageMapPosition, TorusTakesTheAngleAroundYAndAroundTheTube) {
  const ImageMapping m = mapping(5, 8, 4);
  // On the outer equator at +x: both angles 0 (the tube angle starts at the inner side: acos(−x) = π → half).
  expect_position(image_position(m, {1.5, 0, 0}), kEps, 4 - 2 - kEps);
  // Above the tube centre at +z: a quarter turn around y, the tube angle 2π − π/2 (y > 0) → 3/4.
  expect_position(image_position(m, {0, 0.5, 1}), 2 + kEps, 4 - 3 - kEps);
}

TEST(ImageMapColour, NearestPixelWrapsOrClampsWithOnce) {
  const MapImage image = coordinates_image(4, 3);
  const ImageMapping m = mapping(0, 4, 3);
  Texel t = image_colour_at(image, m, 2.7, 1.2);
  EXPECT_EQ(t.r, 2.0f);
  EXPECT_EQ(t.g, 1.0f);
  t = image_colour_at(image, m, -0.5, 3.5);   // wrapped: column 3, row 0
  EXPECT_EQ(t.r, 3.0f);
  EXPECT_EQ(t.g, 0.0f);
  t = image_colour_at(image, mapping(0, 4, 3, true), -0.5, 3.5);   // clamped: column 0, row 2
  EXPECT_EQ(t.r, 0.0f);
  EXPECT_EQ(t.g, 2.0f);
}

TEST(ImageMapColour, BilinearWeighsTheFourPixelCentresAround) {
  const MapImage image = coordinates_image(4, 4);
  const ImageMapping m = mapping(0, 4, 4, false, 2);
  // Position (1.2, 2.9): pixel centres at 0.5 and 1.5 → 30 % of column 0, 70 % of column 1; rows 2 (60 %), 3 (40 %).
  const Texel t = image_colour_at(image, m, 1.2, 2.9);
  EXPECT_NEAR(t.r, 0.7, 1e-6);
  EXPECT_NEAR(t.g, 0.6 * 2 + 0.4 * 3, 1e-6);
  // Near the left edge the neighbour wraps around to the last column.
  EXPECT_NEAR(image_colour_at(image, m, 0.25, 1.5).r, 0.75 * 0 + 0.25 * 3, 1e-6);
}

TEST(ImageMapColour, NormalisedDistanceWeighsByInverseSquaredDistance) {
  MapImage image;
  image.width = image.height = 2;
  image.texels = {Texel{1, 0, 0, 0, 0}, Texel{0, 0, 0, 0, 0}, Texel{0, 0, 0, 0, 0}, Texel{0, 0, 0, 0, 0}};
  const ImageMapping m = mapping(0, 2, 2, false, 4);
  // Position (0.75, 0.75): distances² to the centres of pixels (0,0), (1,0), (0,1), (1,1): 0.125, 0.125+0.5 …
  const double w00 = 1 / 0.125, w10 = 1 / 0.625, w01 = 1 / 0.625, w11 = 1 / 1.125;
  EXPECT_NEAR(image_colour_at(image, m, 0.75, 0.75).r, w00 / (w00 + w10 + w01 + w11), 1e-6);
}

TEST(ImageMapColour, BicubicIsExactOnALinearRampAndKeepsSixteenWeightsSummingToOne) {
  const MapImage image = coordinates_image(8, 8);
  const ImageMapping m = mapping(0, 8, 8, false, 3);
  // Inside the image, away from the wrap, Catmull-Rom weights reproduce a linear ramp: the value at position x is
  // x − 0.5 (pixel centres at i + 0.5).
  const Texel t = image_colour_at(image, m, 3.3, 4.6);
  EXPECT_NEAR(t.r, 2.8, 1e-6);
  EXPECT_NEAR(t.g, 4.1, 1e-6);
  // The weights at p = 0.25: −0.5·p·q², 0.5·q·(q(3p+1)+1), 0.5·p·(p(3q+1)+1), −0.5·q·p².
  const double p = 0.25, q = 0.75;
  const double w[4] = {-0.5 * p * q * q, 0.5 * q * (q * (3 * p + 1) + 1), 0.5 * p * (p * (3 * q + 1) + 1),
                       -0.5 * q * p * p};
  EXPECT_NEAR(w[0] + w[1] + w[2] + w[3], 1.0, 1e-15);
  MapImage spike = coordinates_image(8, 8);
  for (auto& texel : spike.texels) texel = Texel{};
  spike.texels[3 * 8 + 3].r = 1;   // pixel (3, 3)
  // Position (3.75, 3.75) + 0.5 → index 4, fraction 0.25: pixel 3 is the second sample of each axis.
  EXPECT_NEAR(image_colour_at(spike, m, 3.75, 3.75).r, w[1] * w[1], 1e-7);
}

image::PngSamples png_of(int colour_type, int bit_depth) {
  image::PngSamples png;
  png.width = 2;
  png.height = 1;
  png.colour_type = colour_type;
  png.bit_depth = bit_depth;
  png.channels = colour_type == 2 ? 3 : colour_type == 6 ? 4 : colour_type == 4 ? 2 : 1;
  png.samples.assign(static_cast<std::size_t>(2 * png.channels), 0);
  return png;
}

ImageGamma gamma_mode(ImageGammaMode mode, double working = 1.0) {
  ImageGamma g;
  g.mode = mode;
  g.working = working;
  return g;
}

TEST(ImageDecoding, GammaFollowsTheSceneModeTheChunksAndTheOverride) {
  image::PngSamples png = png_of(2, 8);
  const float raw = 128.0f / 255.0f;
  EXPECT_EQ(decode_sample(png, gamma_mode(ImageGammaMode::none), 128, 255), raw);
  // 3.7 scenes take a file without chunks as sRGB: ((v + 0.055) / 1.055)^2.4.
  EXPECT_NEAR(decode_sample(png, gamma_mode(ImageGammaMode::file_or_srgb), 128, 255), 0.2158605, 1e-6);
  // Older scenes with assumed_gamma leave it as it is.
  EXPECT_EQ(decode_sample(png, gamma_mode(ImageGammaMode::file_or_working, 2.2), 128, 255), raw);
  // assumed_gamma 2.2: decoded from sRGB, then encoded with the power 1/2.2.
  EXPECT_NEAR(decode_sample(png, gamma_mode(ImageGammaMode::file_or_srgb, 2.2), 128, 255),
              std::pow(0.2158605, 1 / 2.2), 1e-6);
  png.file_gamma = 1.0;   // a gAMA chunk of 1: linear values
  EXPECT_NEAR(decode_sample(png, gamma_mode(ImageGammaMode::file_or_srgb), 128, 255), raw, 1e-7);
  png.srgb_chunk = true;   // the sRGB chunk wins over gAMA
  EXPECT_NEAR(decode_sample(png, gamma_mode(ImageGammaMode::file_or_working), 128, 255), 0.2158605, 1e-6);
  ImageGamma given = gamma_mode(ImageGammaMode::none);
  given.given = true;
  given.given_gamma = 2.0;   // `gamma 2` decodes with x², whatever the file says
  EXPECT_NEAR(decode_sample(png, given, 128, 255), raw * raw, 1e-7);
}

TEST(ImageDecoding, AlphaBecomesTransmitAndLowDepthGreysAreStoredAsEightBits) {
  image::PngSamples rgba = png_of(6, 8);
  rgba.samples = {255, 0, 0, 51, 0, 255, 0, 255};
  const MapImage a = decode_map_image(rgba, gamma_mode(ImageGammaMode::none));
  EXPECT_EQ(a.texels[0].r, 1.0f);
  EXPECT_FLOAT_EQ(a.texels[0].t, 0.8f);   // alpha 51/255 = 0.2
  EXPECT_EQ(a.texels[0].f, 0.0f);
  EXPECT_EQ(a.texels[1].t, 0.0f);
  image::PngSamples grey = png_of(0, 4);
  grey.samples = {5, 15};
  const MapImage g = decode_map_image(grey, gamma_mode(ImageGammaMode::none));
  const float stored = g.texels[0].r * 255.0f;
  EXPECT_EQ(stored, std::floor(stored));                 // a whole number of 255ths
  EXPECT_NEAR(g.texels[0].r, 5.0f / 15.0f, 1.0 / 255);   // of the value 5/15
  EXPECT_EQ(g.texels[0].g, g.texels[0].r);
}

TEST(ImageDecoding, PaletteEntriesTakeTheirSettingsInWrittenOrder) {
  image::PngSamples png = png_of(3, 8);
  png.palette = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}};
  png.palette_alpha = {255, 0};   // entry 1 fully clear; entry 2 beyond the tRNS values: opaque
  png.samples = {1, 2};
  MapImage image = decode_map_image(png, gamma_mode(ImageGammaMode::none));
  EXPECT_TRUE(image.indexed);
  EXPECT_EQ(image.texels[0].t, 1.0f);
  EXPECT_EQ(image.texels[1].t, 0.0f);
  std::vector<ImageChannelSetting> settings(2);
  settings[0] = {true, -1, 0.5, {}};    // transmit all 0.5
  settings[1] = {false, 2, 0.25, {}};   // filter 2, 0.25
  apply_channel_settings(image, settings);
  EXPECT_EQ(image.texels[0].t, 0.5f);
  EXPECT_EQ(image.texels[1].t, 0.5f);
  EXPECT_EQ(image.texels[1].f, 0.25f);
  EXPECT_EQ(image.texels[0].f, 0.0f);
  EXPECT_TRUE(image.transparent);
  EXPECT_THROW(apply_channel_settings(image, {{false, 3, 0.1, {}}}), ParseError);   // beyond the palette
}

TEST(ImageDecoding, OtherImagesAddTheLastAllValueAndRefuseEntries) {
  MapImage image = decode_map_image(png_of(2, 8), gamma_mode(ImageGammaMode::none));
  EXPECT_THROW(apply_channel_settings(image, {{true, 0, 0.5, {}}}), ParseError);
  apply_channel_settings(image, {{true, -1, 0.5, {}}, {true, -1, 0.25, {}}, {false, -1, 0.125, {}}});
  EXPECT_EQ(image.texels[0].t, 0.25f);
  EXPECT_EQ(image.texels[0].f, 0.125f);
  EXPECT_FALSE(image.indexed);
}

}  // namespace
}  // namespace povtrace::render
