// The photon map (renderer/photons/): POV-Ray's photon encoding, the C library's rand() POV-Ray samples the map with,
// the tree's gather against a brute-force search, the photon map files, and what the photon pass does in a scene:
// photons only at +Q9, the same map for any thread count, energy conserved through a clear pane (docs/issue20-photons.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <cstring>
#include <random>

#include "renderer/photons/photon_file.hpp"
#include "renderer/photons/photon_map.hpp"
#include "scene_kit.hpp"
#include "tests/common/scratch_folder.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::render::photons;
using namespace povtrace::render::test;

// POV-Ray never seeds rand(): glibc's sequence from seed 1, which srand(1) restarts.
TEST(PhotonRandom, IsTheCLibrarysRandFromSeedOne) {
  std::srand(1);
  CRandom ours;
  for (int i = 0; i < 2000; ++i) ASSERT_EQ(ours(), std::rand()) << "draw " << i;
}

// RGBE with exponent bias 250: at most one part in 128 low (the channels are truncated), never high.
TEST(PhotonEncoding, ColourIsTruncatedRgbe) {
  for (const Vec3 c : {Vec3{0.3, 0.2, 0.1}, Vec3{1e-6, 3e-6, 2e-6}, Vec3{7.5, 0.25, 0}}) {
    const Vec3 back = photon_colour(make_photon({0, 0, 0}, c, {0, 1, 0}));
    const double top = std::max({c.x, c.y, c.z});
    for (const auto& [a, b] : {std::pair{c.x, back.x}, std::pair{c.y, back.y}, std::pair{c.z, back.z}}) {
      EXPECT_LE(b, a * (1 + 1e-6));
      EXPECT_GE(b, a - top / 128.0);
    }
  }
  EXPECT_EQ(photon_colour(make_photon({0, 0, 0}, {0, 0, 0}, {0, 1, 0})), (Vec3{0, 0, 0}));
}

// Directions in two signed bytes: θ from the horizontal plane and φ around y, steps of π/127.
TEST(PhotonEncoding, DirectionWithinOneStep) {
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  for (int i = 0; i < 500; ++i) {
    const Vec3 d = normalize(Vec3{normal(random), normal(random), normal(random)});
    const Vec3 back = photon_direction(make_photon({1, 2, 3}, {1, 1, 1}, d * 3.0));
    EXPECT_LT(std::acos(std::clamp(dot(d, back), -1.0, 1.0)), 2.0 * M_PI / 127.0) << d.x << " " << d.y << " " << d.z;
  }
}

std::vector<Photon> cloud(int n, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Photon> p;
  for (int i = 0; i < n; ++i) p.push_back(make_photon({u(random), 0, u(random)}, {1e-3, 1e-3, 1e-3}, {0, 1, 0}));
  return p;
}

PhotonSettings settings_with_radius(double r) {
  PhotonSettings s;
  s.radius = r;
  return s;
}

// The gather finds photons within the radius only, at most gather_max of them, and (but for the photons POV-Ray's
// unsorted two-photon leaves hide) the nearest ones: a brute-force search agrees on nearly all of them.
TEST(PhotonGather, NearestWithinTheRadius) {
  const PhotonMap map(cloud(20000, 3), settings_with_radius(0.2));
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(-0.9, 0.9);
  std::size_t agreed = 0, total = 0;
  Gathered g;
  std::vector<double> scratch;
  for (int q = 0; q < 200; ++q) {
    const Vec3 at{u(random), 0, u(random)};
    const double r = map.gather(at, 0.2, 50, nullptr, g, scratch);
    ASSERT_LE(g.found.size(), 50u);
    std::vector<double> brute;
    for (const Photon& p : map.photons()) {
      const Vec3 v = Vec3{p.position[0], p.position[1], p.position[2]} - at;
      if (dot(v, v) < 0.04) brute.push_back(dot(v, v));
    }
    std::sort(brute.begin(), brute.end());
    if (brute.size() > 50) brute.resize(50);
    for (const auto& [d, p] : g.found) {
      EXPECT_LT(d, 0.04);
      EXPECT_LE(d, r * r * (1 + 1e-12));
      agreed += std::binary_search(brute.begin(), brute.end(), d) ? 1 : 0;
    }
    total += brute.size();
  }
  EXPECT_GT(static_cast<double>(agreed), 0.97 * static_cast<double>(total));
}

// Without a radius the map estimates one from its density: photons spread evenly over a sphere (a surface without
// edges) of density ρ give about √(gather_max / (π ρ)); the widening by 20 × the share of sparse samples stays
// small, since with 100 photons expected almost no sample finds fewer than 70.
TEST(PhotonGather, EstimatedRadiusFollowsTheDensity) {
  std::mt19937 random(9);
  std::normal_distribution<double> normal;
  std::vector<Photon> on_sphere;
  for (int i = 0; i < 40000; ++i)
    on_sphere.push_back(make_photon(normalize(Vec3{normal(random), normal(random), normal(random)}), {1e-3, 1e-3, 1e-3},
                                    {0, 1, 0}));
  const PhotonMap map(std::move(on_sphere), PhotonSettings{});
  const double density = 40000 / (4 * M_PI);
  const double expected = std::sqrt(100 / (M_PI * density));
  EXPECT_GT(map.gather_radius(), 0.95 * expected);
  EXPECT_LT(map.gather_radius(), 1.15 * expected);
}

TEST(PhotonFile, SavesAndLoadsTheTreeAsIs) {
  const povtrace::test::ScratchFolder folder;
  const PhotonMap map(cloud(1000, 4), settings_with_radius(0.1));
  const auto path = folder.path() / "map.ph";
  save_photon_file(path, map.photons());
  EXPECT_EQ(std::filesystem::file_size(path), 4u + 1000u * 20u + 4u);
  const std::vector<Photon> back = load_photon_file(path);
  ASSERT_EQ(back.size(), 1000u);
  for (std::size_t i = 0; i < back.size(); ++i) {
    EXPECT_EQ(back[i].position[0], map.photons()[i].position[0]);
    EXPECT_EQ(back[i].axis, map.photons()[i].axis);
    EXPECT_EQ(back[i].theta, map.photons()[i].theta);
  }
}

TEST(PhotonFile, RefusesShortAndMediaFiles) {
  const povtrace::test::ScratchFolder folder;
  const auto short_file = folder.path() / "short.ph";
  {
    std::ofstream out(short_file, std::ios::binary);
    const std::int32_t n = 10;
    out.write(reinterpret_cast<const char*>(&n), 4);
  }
  EXPECT_THROW(load_photon_file(short_file), std::runtime_error);
  const auto media_file = folder.path() / "media.ph";
  {
    std::ofstream out(media_file, std::ios::binary);
    const std::int32_t zero = 0, three = 3;
    out.write(reinterpret_cast<const char*>(&zero), 4);
    out.write(reinterpret_cast<const char*>(&three), 4);
  }
  try {
    load_photon_file(media_file);
    FAIL() << "a file with media photons loaded";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("media photons"), std::string::npos) << e.what();
  }
  EXPECT_THROW(load_photon_file(folder.path() / "missing.ph"), std::runtime_error);
}

// A glass sphere over a floor, lit by one light shooting photons at it.
SceneDescription caustic_scene() {
  SceneDescription s = base_scene();
  Finish glass;
  glass.ambient = rgb(0, 0, 0);
  glass.diffuse = 0;
  Object sphere = sphere_object({0, 1, 0}, 1, texture(rgbft(1, 1, 1, 0.95, 0), glass));
  sphere.interior = Interior{};
  sphere.interior->ior = 1.5;
  sphere.photons.target = 1;
  sphere.photons.refraction = true;
  s.objects.push_back(sphere);
  s.objects.push_back(plane_object({0, 1, 0}, -1, texture(rgb(0.8, 0.8, 0.8), finish_ambient_diffuse(0, 0.8))));
  Light l = point_light({0, 8, 0});
  l.photon_refraction = true;
  s.lights = {l};
  PhotonSettings p;
  p.spacing = 0.05;
  s.photons = p;
  return s;
}

TEST(PhotonPass, OnlyAtQualityNine) {
  BuildOptions q9, q8;
  q8.quality = 8;
  EXPECT_NE(build_render_scene(caustic_scene(), q9).photons, nullptr);
  EXPECT_EQ(build_render_scene(caustic_scene(), q8).photons, nullptr);
}

TEST(PhotonPass, SameMapForAnyThreadCount) {
  BuildOptions one, three;
  one.threads = 1;
  three.threads = 3;
  const auto a = build_render_scene(caustic_scene(), one).photons;
  const auto b = build_render_scene(caustic_scene(), three).photons;
  ASSERT_NE(a, nullptr);
  ASSERT_EQ(a->size(), b->size());
  EXPECT_EQ(0, std::memcmp(a->photons().data(), b->photons().data(), a->size() * sizeof(Photon)));
  EXPECT_EQ(a->gather_radius(), b->gather_radius());
}

// Every photon carries its light's colour times spread² · depth²: the area it stands for across its path (POV-Ray's
// lights do not fall off with distance). Through a clear pane of ior 1 (collect off) onto the floor, the photons'
// energies add up to the pane's shadow on the floor, times the cosine of incidence (≈ 0.995 here), within the
// jitter and the ring spacing at the shadow's edge.
TEST(PhotonPass, EnergyAddsUpToTheLitArea) {
  SceneDescription s = base_scene();
  Object pane = box_object({-0.5, 4.99, -0.5}, {0.5, 5.01, 0.5}, texture(rgbft(1, 1, 1, 1, 0)));
  pane.interior = Interior{};
  pane.photons.target = 1;
  pane.photons.refraction = true;
  pane.photons.collect = false;
  s.objects.push_back(pane);
  s.objects.push_back(plane_object({0, 1, 0}, 0, texture(rgb(0.8, 0.8, 0.8))));
  Light l = point_light({0, 10, 0});
  l.photon_refraction = true;
  s.lights = {l};
  PhotonSettings p;
  p.spacing = 0.01;
  s.photons = p;
  const RenderScene rs = build_render_scene(s, BuildOptions{});
  ASSERT_NE(rs.photons, nullptr);
  double floor_energy = 0;
  for (const Photon& ph : rs.photons->photons()) {
    ASSERT_LT(std::fabs(ph.position[1]), 1e-4) << "a photon off the floor";
    floor_energy += photon_colour(ph).x;
  }
  const double shadow_area = 2.0 * 2.0;   // the 1 × 1 pane halfway between the light and the floor
  EXPECT_NEAR(floor_energy, 0.995 * shadow_area, 0.04 * shadow_area);
}

}  // namespace

namespace {
// A spacing far too fine for its target is refused at the photons block before anything is shot (it would run for
// days and fill the memory), not attempted.
TEST(PhotonPass, RefusesASpacingThatWouldNeverEnd) {
  SceneDescription s = caustic_scene();
  s.photons->spacing = 1e-7;
  s.photons->loc = SourceLoc{};
  try {
    (void)build_render_scene(s, BuildOptions{});
    FAIL() << "a spacing of 1e-7 was shot";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("would shoot up to"), std::string::npos) << e.what();
  }
}
}  // namespace
