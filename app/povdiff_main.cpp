// povdiff: compares two images (EXR, PNG or PPM) and says whether they match within a tolerance.
//
//   povdiff A B [--diff heat.png] [--threshold T] [--min-psnr DB] [--max-share S]
//
// Exit status: 0 within tolerance, 1 outside, 2 bad input (arguments, unreadable file, size mismatch).
// The last line of the output is a machine-readable summary:
//   povdiff: rmse=… psnr=… max=… over=… share=… verdict=pass|fail      (share is a fraction, not %)
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "renderer/image/compare.hpp"
#include "renderer/image/image.hpp"

namespace {

namespace fs = std::filesystem;
namespace img = povtrace::image;

constexpr int exit_pass = 0;
constexpr int exit_fail = 1;
constexpr int exit_bad_input = 2;

constexpr const char* usage_text =
    "usage: povdiff A B [--diff heat.png] [--threshold T] [--min-psnr DB] [--max-share S]\n"
    "\n"
    "Compares images A and B (EXR, PNG or binary PPM). Two files of the same kind are compared as stored;\n"
    "a PNG/PPM against an EXR is compared in linear light (the PNG/PPM is sRGB-decoded).\n"
    "\n"
    "  --diff FILE      write a false-colour difference map (black equal, blue <= T, green..red > T)\n"
    "  --threshold T    a pixel fails when its largest channel difference exceeds T (default 1/255)\n"
    "  --min-psnr DB    pass needs PSNR >= DB, peak 1.0 (default 50)\n"
    "  --max-share S    pass needs the share of failing pixels <= S, a fraction (default 0.001 = 0.1 %)\n"
    "  --help           print this text\n"
    "Numbers may be written as fractions, e.g. 1/255.\n"
    "Exit status: 0 within tolerance, 1 outside, 2 bad input.\n";

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Options {
  std::vector<fs::path> inputs;
  std::optional<fs::path> diff;
  double threshold = 1.0 / 255.0;
  double min_psnr = 50.0;
  double max_share = 0.001;
  bool help = false;
};

double parse_plain_number(std::string_view text, std::string_view option) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) {
    throw UsageError("bad number '" + std::string(text) + "' for " + std::string(option));
  }
  return value;
}

// "0.004", "1e-3" or a fraction "1/255".
double parse_number(std::string_view text, std::string_view option) {
  const std::size_t slash = text.find('/');
  if (slash == std::string_view::npos) return parse_plain_number(text, option);
  const double denominator = parse_plain_number(text.substr(slash + 1), option);
  if (denominator == 0.0) {
    throw UsageError("division by zero in '" + std::string(text) + "' for " + std::string(option));
  }
  return parse_plain_number(text.substr(0, slash), option) / denominator;
}

// Applies one "--name value" option; returns false for an unknown name.
bool apply_option(Options& options, std::string_view name, std::string_view value) {
  if (name == "--diff") {
    options.diff = fs::path(std::string(value));
  } else if (name == "--threshold") {
    options.threshold = parse_number(value, name);
  } else if (name == "--min-psnr") {
    options.min_psnr = parse_number(value, name);
  } else if (name == "--max-share") {
    options.max_share = parse_number(value, name);
  } else {
    return false;
  }
  return true;
}

// Accepts "--name value" and "--name=value". Returns how many arguments were used.
int parse_option(Options& options, int argc, char** argv, int i) {
  std::string_view arg = argv[i];
  if (arg == "--help" || arg == "-h") {
    options.help = true;
    return 1;
  }
  const std::size_t equals = arg.find('=');
  if (equals != std::string_view::npos) {
    if (!apply_option(options, arg.substr(0, equals), arg.substr(equals + 1))) {
      throw UsageError("unknown option '" + std::string(arg) + "'");
    }
    return 1;
  }
  if (i + 1 >= argc) throw UsageError("option '" + std::string(arg) + "' needs a value");
  if (!apply_option(options, arg, argv[i + 1])) throw UsageError("unknown option '" + std::string(arg) + "'");
  return 2;
}

Options parse_arguments(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc;) {
    const std::string_view arg = argv[i];
    if (arg.size() > 1 && arg[0] == '-') {
      i += parse_option(options, argc, argv, i);
    } else {
      options.inputs.emplace_back(std::string(arg));
      ++i;
    }
  }
  if (options.help) return options;
  if (options.inputs.size() != 2) {
    throw UsageError("expected two image files, got " + std::to_string(options.inputs.size()));
  }
  if (!(options.threshold >= 0.0)) throw UsageError("--threshold must be >= 0");
  if (options.diff && !img::format_from_extension(*options.diff)) {
    throw UsageError("--diff file needs a .png, .exr or .ppm extension: '" + options.diff->string() + "'");
  }
  return options;
}

std::string number(double value, const char* format = "%.6g") {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string describe(const img::Image& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height) + ", " +
         (image.encoding == img::Encoding::linear ? "linear" : "encoded") + (image.has_alpha ? ", RGBA" : ", RGB");
}

bool within_tolerance(const img::CompareReport& report, const Options& options) {
  return report.psnr >= options.min_psnr && report.share_over_threshold <= options.max_share;
}

void print_report(const img::CompareReport& report, const Options& options, bool pass) {
  const char* channel_names[] = {"R", "G", "B", "A"};
  std::cout << "RMSE:           " << number(report.rmse) << "\n"
            << "PSNR:           " << number(report.psnr, "%.3f") << " dB (peak 1.0; pass needs >= "
            << number(options.min_psnr) << ")\n"
            << "mean abs error: " << number(report.mean_abs_error) << "\n"
            << "max abs error:  " << number(report.max_abs_error) << " at (" << report.max_x << ", " << report.max_y
            << ") channel " << channel_names[report.max_channel] << "\n"
            << "over threshold: " << report.pixels_over_threshold << " of " << report.pixel_count << " pixels ("
            << number(100.0 * report.share_over_threshold, "%.4f") << " %; pass needs <= "
            << number(100.0 * options.max_share, "%.4g") << " %) with a channel difference > "
            << number(options.threshold) << "\n"
            << "verdict:        " << (pass ? "pass" : "fail") << "\n"
            << "povdiff: rmse=" << number(report.rmse) << " psnr=" << number(report.psnr, "%.3f")
            << " max=" << number(report.max_abs_error) << " over=" << report.pixels_over_threshold
            << " share=" << number(report.share_over_threshold) << " verdict=" << (pass ? "pass" : "fail")
            << std::endl;
}

void write_heat_map(const img::Image& a, const img::Image& b, const Options& options) {
  img::EncodeOptions encode;
  encode.format = *img::format_from_extension(*options.diff);
  img::write_image(img::difference_heat_map(a, b, options.threshold), *options.diff, encode);
  std::cout << "difference map: " << options.diff->string() << "\n";
}

int run(const Options& options) {
  const img::Image a = img::read_image(options.inputs[0]);
  const img::Image b = img::read_image(options.inputs[1]);
  std::cout << "A: " << options.inputs[0].string() << " (" << describe(a) << ")\n"
            << "B: " << options.inputs[1].string() << " (" << describe(b) << ")\n"
            << "compared "
            << (img::comparison_encoding(a, b) == img::Encoding::linear ? "in linear light" : "as encoded")
            << ", channels " << (a.has_alpha || b.has_alpha ? "RGBA" : "RGB") << "\n";
  const img::CompareReport report = img::compare_images(a, b, options.threshold);
  if (options.diff) write_heat_map(a, b, options);
  const bool pass = within_tolerance(report, options);
  print_report(report, options, pass);
  return pass ? exit_pass : exit_fail;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options options = parse_arguments(argc, argv);
    if (options.help) {
      std::cout << usage_text;
      return exit_pass;
    }
    return run(options);
  } catch (const UsageError& e) {
    std::cerr << "povdiff: " << e.what() << "\n"
              << "usage: povdiff A B [--diff heat.png] [--threshold T] [--min-psnr DB] [--max-share S] (--help)\n";
    return exit_bad_input;
  } catch (const std::exception& e) {
    std::cerr << "povdiff: " << e.what() << "\n";
    return exit_bad_input;
  }
}
