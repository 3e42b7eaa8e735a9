// Regions (+SR +ER +SC +EC, issue 18 step 5) and `--assemble` (step 10): POV-Ray 3.7's rules for the values, the
// pixels of a region equal to the same pixels of a full render (the block grid stays anchored at (0,0)), the
// black opaque fill outside, the region recorded in EXR and PNG files, and the merging of parts.
#include <gtest/gtest.h>

#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <mutex>
#include <string>
#include <vector>

#include "app/assemble.hpp"
#include "app/options.hpp"
#include "app/region.hpp"
#include "app/render_job.hpp"
#ifdef POVTRACE_HAVE_MPI
#include "app/mpi_render.hpp"
#endif

namespace {

using namespace povtrace;
using app::RegionOptions;
using image::PixelRect;
namespace fs = std::filesystem;

// ---- resolve_region: POV-Ray 3.7's rules ------------------------------------------------------------------------

struct RegionCase {
  std::optional<double> sc, ec, sr, er;
  PixelRect expected;
};

TEST(ResolveRegion, NoValuesMeansNoRegion) {
  EXPECT_FALSE(app::resolve_region(RegionOptions{}, 64, 48).has_value());
}

TEST(ResolveRegion, FractionsAndPixels) {
  const std::vector<RegionCase> cases = {
      // fractions: start int(size × v), end int(size × v) − 1
      {0.25, 0.5, 0.25, 0.5, {16, 12, 31, 23}},
      {0.0, 1.0, 0.0, 1.0, {0, 0, 63, 47}},
      {0.5, std::nullopt, std::nullopt, std::nullopt, {32, 0, 63, 47}},
      {std::nullopt, std::nullopt, 0.999, std::nullopt, {0, 47, 63, 47}},
      // +ER1 / +EC1 is a fraction (the last row/column), +SR1 / +SC1 a pixel (the first)
      {1.0, 1.0, 1.0, 1.0, {0, 0, 63, 47}},
      // 1-based pixels: int(v) − 1
      {2.0, 10.0, 3.0, 48.0, {1, 2, 9, 47}},
      {64.0, 64.0, 48.0, 48.0, {63, 47, 63, 47}},
      {10.7, 20.2, 5.9, 6.1, {9, 4, 19, 5}},
      // an end fraction that rounds down to the pixel before the start fraction's: int(64 × 0.3) − 1 = 18
      {0.25, 0.3, std::nullopt, std::nullopt, {16, 0, 18, 47}},
  };
  for (const RegionCase& c : cases) {
    RegionOptions o;
    o.start_column = c.sc;
    o.end_column = c.ec;
    o.start_row = c.sr;
    o.end_row = c.er;
    const auto r = app::resolve_region(o, 64, 48);
    ASSERT_TRUE(r.has_value());
    EXPECT_EQ(*r, c.expected) << "SC " << c.sc.value_or(-1) << " EC " << c.ec.value_or(-1) << " SR "
                              << c.sr.value_or(-1) << " ER " << c.er.value_or(-1) << " gave " << r->x0 << " "
                              << r->y0 << " " << r->x1 << " " << r->y1;
  }
}

TEST(ResolveRegion, OutOfRangeIsAUsageError) {
  auto fails = [](std::optional<double> sc, std::optional<double> ec, std::optional<double> sr,
                  std::optional<double> er, const char* words) {
    RegionOptions o;
    o.start_column = sc;
    o.end_column = ec;
    o.start_row = sr;
    o.end_row = er;
    try {
      (void)app::resolve_region(o, 64, 48);
      ADD_FAILURE() << "no error for " << words;
    } catch (const app::UsageError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  fails(65.0, std::nullopt, std::nullopt, std::nullopt, "invalid start column or row");
  fails(std::nullopt, std::nullopt, 49.0, std::nullopt, "invalid start column or row");
  fails(std::nullopt, 65.0, std::nullopt, std::nullopt, "invalid end column or row");
  fails(std::nullopt, std::nullopt, std::nullopt, 49.0, "invalid end column or row");
  fails(-2.0, std::nullopt, std::nullopt, std::nullopt, "invalid start column or row");
  fails(std::nullopt, 0.0, std::nullopt, std::nullopt, "invalid end column or row");   // int(0) − 1 = −1
  fails(30.0, 20.0, std::nullopt, std::nullopt, "before the start");
  fails(std::nullopt, std::nullopt, 0.5, 0.25, "before the start");
}

// ---- renders ------------------------------------------------------------------------------------------------------

fs::path source_dir() {
  const char* dir = std::getenv("POVTRACE_SOURCE_DIR");
  return dir ? fs::path(dir) : fs::path(".");
}

class Scratch {
 public:
  Scratch() {
    std::string pattern = (fs::temp_directory_path() / "povtrace_region_XXXXXX").string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~Scratch() { fs::remove_all(path_); }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

struct AaCase {
  const char* name;
  bool antialias;
  int method;
};
const AaCase kAaCases[] = {{"no AA", false, 1}, {"+AM1 +A0.05", true, 1}, {"+AM2 +A0.05 +J", true, 2}};

app::RenderOptions options_for(const AaCase& aa, const char* scene) {
  app::RenderOptions o;
  o.input = source_dir() / "scenes" / scene;
  o.width = 64;
  o.height = 48;
  o.antialias = aa.antialias;
  o.antialias_threshold = 0.05;
  o.sampling_method = aa.method;
  o.jitter = true;
  o.output_alpha = true;
  o.write_file = false;
  return o;
}

image::Image render(const app::RenderOptions& o) {
  std::atomic<bool> never{false};
  app::JobResult r = app::run_render(o, never);
  EXPECT_EQ(r.exit_status, 0);
  return std::move(r.image);
}

// A 3 × 3 grid of regions whose edges are not on the 32-pixel block grid, in 1-based pixels as +SC/+EC/+SR/+ER take
// them; every cell's pixels equal the full render's bit for bit, and every pixel outside is black and opaque (what
// Debian's povray 3.7.0.10 writes there, +UA or not).
TEST(RegionRender, EveryCellOfAGridEqualsTheFullRender) {
  const double columns[4] = {1, 22, 46, 65}, rows[4] = {1, 17, 34, 49};
  for (const char* scene : {"checker_sphere.pov", "csg_union.pov"}) {
    for (const AaCase& aa : kAaCases) {
      app::RenderOptions full_options = options_for(aa, scene);
      full_options.threads = 1;
      const image::Image full = render(full_options);
      ASSERT_EQ(full.width, 64);
      EXPECT_FALSE(full.region.has_value());
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          app::RenderOptions o = options_for(aa, scene);
          o.threads = 2;
          o.region.start_column = columns[i];
          o.region.end_column = columns[i + 1] - 1;
          o.region.start_row = rows[j];
          o.region.end_row = rows[j + 1] - 1;
          const image::Image part = render(o);
          const PixelRect cell{int(columns[i]) - 1, int(rows[j]) - 1, int(columns[i + 1]) - 2, int(rows[j + 1]) - 2};
          ASSERT_TRUE(part.region.has_value());
          EXPECT_EQ(*part.region, cell);
          int differing = 0, bad_fill = 0;
          for (int y = 0; y < 48; ++y) {
            for (int x = 0; x < 64; ++x) {
              const float* p = part.pixel(x, y);
              if (cell.contains(x, y)) {
                differing += std::memcmp(p, full.pixel(x, y), 4 * sizeof(float)) != 0;
              } else {
                bad_fill += !(p[0] == 0 && p[1] == 0 && p[2] == 0 && p[3] == 1);
              }
            }
          }
          EXPECT_EQ(differing, 0) << scene << " " << aa.name << " cell " << i << "," << j;
          EXPECT_EQ(bad_fill, 0) << scene << " " << aa.name << " cell " << i << "," << j;
        }
      }
    }
  }
}

// block_done reports every block once, from the worker threads, clipped to the region: the rectangles are disjoint
// and cover the region exactly (what a +C state file and MPI rely on).
TEST(RegionRender, BlockDoneCoversTheRegionOnce) {
  app::RenderOptions o = options_for(kAaCases[1], "checker_sphere.pov");
  o.width = 150;
  o.height = 100;
  const SceneDescription description = parse_scene(o.input, app::parse_options_from(o));
  const render::RenderScene scene = render::build_render_scene(description, {o.output_alpha, false, {}});
  for (const std::optional<PixelRect>& region : {std::optional<PixelRect>{}, std::optional<PixelRect>{{20, 7, 99, 70}}}) {
    render::RenderSettings s = app::render_settings_from(o);
    s.threads = 3;
    s.region = region;
    std::mutex m;
    std::vector<int> hits(static_cast<std::size_t>(o.width * o.height), 0);
    int calls = 0;
    s.block_done = [&](const image::Image&, const PixelRect& r) {
      std::lock_guard lock(m);
      ++calls;
      for (int y = r.y0; y <= r.y1; ++y)
        for (int x = r.x0; x <= r.x1; ++x) ++hits[static_cast<std::size_t>(y * o.width + x)];
    };
    (void)render::render(scene, s);
    const PixelRect area = region.value_or(PixelRect{0, 0, o.width - 1, o.height - 1});
    int wrong = 0;
    for (int y = 0; y < o.height; ++y)
      for (int x = 0; x < o.width; ++x) wrong += hits[static_cast<std::size_t>(y * o.width + x)] != (area.contains(x, y) ? 1 : 0);
    EXPECT_EQ(wrong, 0);
    EXPECT_EQ(calls, region ? 4 * 3 : 5 * 4);   // blocks of the (0,0) grid meeting the area
  }
}

TEST(RegionRender, ARegionOutsideTheImageStopsBeforeParsing) {
  app::RenderOptions o = options_for(kAaCases[0], "no_such_scene.pov");
  o.region.start_row = 100;
  std::atomic<bool> never{false};
  EXPECT_THROW(app::run_render(o, never), app::UsageError);
}

// ---- files and --assemble ---------------------------------------------------------------------------------------

std::string file_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(RegionFiles, ExrAndPngKeepTheRegion) {
  Scratch dir;
  image::Image im(8, 6);
  im.region = PixelRect{1, 2, 5, 4};
  for (const char* name : {"a.exr", "a.png"}) {
    image::EncodeOptions e;
    e.format = *image::format_from_extension(name);
    image::write_image(im, dir.path() / name, e);
    const image::Image back = image::read_image(dir.path() / name);
    ASSERT_TRUE(back.region.has_value()) << name;
    EXPECT_EQ(*back.region, *im.region) << name;
  }
  im.region.reset();
  image::write_image(im, dir.path() / "b.png", image::EncodeOptions{});
  EXPECT_FALSE(image::read_image(dir.path() / "b.png").region.has_value());
}

TEST(RegionFiles, ParseRejectsASizeMismatch) {
  EXPECT_THROW(image::parse_region_text("0 0 3 3 8 8", 8, 6), image::ImageError);
  EXPECT_THROW(image::parse_region_text("0 0 9 3 8 6", 8, 6), image::ImageError);
  EXPECT_THROW(image::parse_region_text("0 0 3", 8, 6), image::ImageError);
  EXPECT_EQ(image::parse_region_text("0 1 3 4 8 6", 8, 6), (PixelRect{0, 1, 3, 4}));
}

// Four region renders written as files (rows and columns split off the block grid) and merged with --assemble give
// the full render's file byte for byte, in EXR and in PNG.
TEST(Assemble, FourRegionRendersGiveTheFullRenderFile) {
  Scratch dir;
  for (const char* ext : {".exr", ".png"}) {
    for (const AaCase& aa : {kAaCases[0], kAaCases[1]}) {
      app::RenderOptions full = options_for(aa, "checker_sphere.pov");
      full.write_file = true;
      full.output = dir.path() / (std::string("full") + ext);
      render(full);
      std::vector<std::string> args{(dir.path() / (std::string("merged") + ext)).string()};
      const double sc[2][2] = {{1, 0.45}, {0.45, 1}}, sr[2][2] = {{1, 20}, {21, 1}};
      for (int i = 0; i < 2; ++i) {
        for (int j = 0; j < 2; ++j) {
          app::RenderOptions o = options_for(aa, "checker_sphere.pov");
          o.write_file = true;
          o.region.start_column = sc[i][0];
          o.region.end_column = sc[i][1];
          o.region.start_row = sr[j][0];
          o.region.end_row = sr[j][1];
          o.output = dir.path() / ("part" + std::to_string(i) + std::to_string(j) + ext);
          render(o);
          args.push_back(o.output->string());
        }
      }
      EXPECT_EQ(app::run_assemble(args), 0);
      EXPECT_EQ(file_bytes(dir.path() / (std::string("merged") + ext)), file_bytes(*full.output)) << ext << " "
                                                                                                   << aa.name;
    }
  }
}

void expect_assemble_error(const std::vector<image::Image>& parts, const char* words) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < parts.size(); ++i) names.push_back("part" + std::to_string(i));
  try {
    (void)app::assemble_parts(parts, names);
    ADD_FAILURE() << "no error, expected '" << words << "'";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

image::Image part(int w, int h, PixelRect r) {
  image::Image im(w, h);
  im.region = r;
  return im;
}

TEST(Assemble, RefusesOverlapsGapsAndMismatches) {
  expect_assemble_error({part(8, 6, {0, 0, 4, 5}), part(8, 6, {4, 0, 7, 5})}, "overlaps part0");
  expect_assemble_error({part(8, 6, {0, 0, 3, 5}), part(8, 6, {5, 0, 7, 5})}, "gap: column 5, row 1");
  expect_assemble_error({part(8, 6, {0, 0, 3, 5}), part(8, 5, {4, 0, 7, 4})}, "part1 is 8x5 but part0 is 8x6");
  image::Image plain(8, 6);
  expect_assemble_error({part(8, 6, {0, 0, 3, 5}), plain}, "not a region render");
  image::Image with_alpha = part(8, 6, {4, 0, 7, 5});
  with_alpha.has_alpha = true;
  expect_assemble_error({part(8, 6, {0, 0, 3, 5}), with_alpha}, "differ in alpha");
  const image::Image ok = app::assemble_parts({part(8, 6, {0, 0, 3, 5}), part(8, 6, {4, 0, 7, 5})}, {"a", "b"});
  EXPECT_FALSE(ok.region.has_value());
}

#ifdef POVTRACE_HAVE_MPI
// MPI starts only under a launcher that reports more than one rank; a plain run (or mpirun -np 1) never calls
// MPI_Init and renders as without MPI.
TEST(MpiLaunch, OnlyWithMoreThanOneRank) {
  ::unsetenv("OMPI_COMM_WORLD_SIZE");
  ::unsetenv("PMI_SIZE");
  EXPECT_FALSE(app::mpi_launched());
  ::setenv("OMPI_COMM_WORLD_SIZE", "1", 1);
  EXPECT_FALSE(app::mpi_launched());
  ::setenv("OMPI_COMM_WORLD_SIZE", "3", 1);
  EXPECT_TRUE(app::mpi_launched());
  ::unsetenv("OMPI_COMM_WORLD_SIZE");
  ::setenv("PMI_SIZE", "2", 1);
  EXPECT_TRUE(app::mpi_launched());
  ::unsetenv("PMI_SIZE");
}
#endif

}  // namespace
