#include "app/assemble.hpp"

#include <cstdio>
#include <iostream>
#include <stdexcept>

#include "app/options.hpp"

namespace povtrace::app {
namespace {

std::string rect_text(const image::PixelRect& r) {
  char text[96];
  std::snprintf(text, sizeof text, "columns %d-%d, rows %d-%d", r.x0 + 1, r.x1 + 1, r.y0 + 1, r.y1 + 1);
  return text;
}

}  // namespace

image::Image assemble_parts(const std::vector<image::Image>& parts, const std::vector<std::string>& names) {
  if (parts.empty()) throw std::runtime_error("no parts to assemble");
  const image::Image& first = parts.front();
  image::Image out(first.width, first.height);
  out.has_alpha = first.has_alpha;
  out.encoding = first.encoding;
  std::vector<int> owner(static_cast<std::size_t>(first.width) * first.height, -1);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const image::Image& part = parts[i];
    const std::string& name = names.at(i);
    if (!part.region) throw std::runtime_error(name + " is not a region render (it records no povtrace:region)");
    if (part.width != first.width || part.height != first.height) {
      throw std::runtime_error(name + " is " + std::to_string(part.width) + "x" + std::to_string(part.height) +
                               " but " + names[0] + " is " + std::to_string(first.width) + "x" +
                               std::to_string(first.height));
    }
    if (part.has_alpha != first.has_alpha) {
      throw std::runtime_error(name + " and " + names[0] + " differ in alpha (render every part with or without +UA)");
    }
    if (part.encoding != first.encoding) {
      throw std::runtime_error(name + " and " + names[0] + " are of different kinds (EXR and PNG/PPM): use one format");
    }
    const image::PixelRect& r = *part.region;
    for (int y = r.y0; y <= r.y1; ++y) {
      for (int x = r.x0; x <= r.x1; ++x) {
        int& o = owner[static_cast<std::size_t>(y) * first.width + x];
        if (o >= 0) {
          throw std::runtime_error(name + " (" + rect_text(r) + ") overlaps " + names[static_cast<std::size_t>(o)] +
                                   " (" + rect_text(*parts[static_cast<std::size_t>(o)].region) + ") at column " +
                                   std::to_string(x + 1) + ", row " + std::to_string(y + 1));
        }
        o = static_cast<int>(i);
        const float* p = part.pixel(x, y);
        float* q = out.pixel(x, y);
        for (int c = 0; c < 4; ++c) q[c] = p[c];
      }
    }
  }
  for (int y = 0; y < first.height; ++y) {
    for (int x = 0; x < first.width; ++x) {
      if (owner[static_cast<std::size_t>(y) * first.width + x] < 0) {
        throw std::runtime_error("the parts leave a gap: column " + std::to_string(x + 1) + ", row " +
                                 std::to_string(y + 1) + " is in no part");
      }
    }
  }
  return out;
}

int run_assemble(const std::vector<std::string>& args) {
  if (args.empty()) throw UsageError("--assemble needs an output file and the part files");
  std::vector<std::string> argv_text{"povtrace"};
  std::vector<std::string> files;
  for (std::size_t i = 1; i < args.size(); ++i) {
    if (!args[i].empty() && (args[i][0] == '+' || args[i][0] == '-')) argv_text.push_back(args[i]);
    else files.push_back(args[i]);
  }
  if (files.empty()) throw UsageError("--assemble " + args[0] + ": no part files given");
  argv_text.push_back("+O" + args[0]);
  std::vector<const char*> argv;
  for (const auto& a : argv_text) argv.push_back(a.c_str());
  RenderOptions options = parse_command_line(static_cast<int>(argv.size()), argv.data());
  options.input = args[0];   // resolved_output_path wants a scene name; the output is given
  const std::filesystem::path out = resolved_output_path(options);
  std::vector<image::Image> parts;
  for (const auto& f : files) {
    try {
      parts.push_back(image::read_image(f));
    } catch (const image::ImageError& e) {
      throw std::runtime_error(f + ": " + e.what());
    }
  }
  const image::Image merged = assemble_parts(parts, files);
  image::write_image(merged, out, resolved_encoding(options));
  std::cerr << "povtrace: assembled " << files.size() << " parts -> " << out.string() << "\n";
  return 0;
}

}  // namespace povtrace::app
