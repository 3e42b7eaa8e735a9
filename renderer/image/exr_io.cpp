#include "renderer/image/exr_io.hpp"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>
#include <Imath/half.h>

#include <algorithm>
#include <cstdint>
#include <thread>
#include <exception>
#include <string>
#include <vector>

namespace povtrace::image {
namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t max_pixels = std::uint64_t(1) << 26;  // 1 GiB of floats: refuse larger files
constexpr const char* channel_names[4] = {"R", "G", "B", "A"};

// A slice over interleaved 4-channel pixels of type T starting at `first`; OpenEXR converts from the file's
// pixel type to T when reading.
template <class T>
Imf::Slice rgba_slice(Imf::PixelType type, const T* first, int width, const Imath::Box2i& window, double fill) {
  const std::size_t stride = 4 * sizeof(T);
  return Imf::Slice::Make(type, first, window, stride, stride * static_cast<std::size_t>(width), 1, 1, fill);
}

Imf::Slice float_slice(const Image& image, int channel, const Imath::Box2i& window, double fill) {
  return rgba_slice(Imf::FLOAT, &image.rgba[static_cast<std::size_t>(channel)], image.width, window, fill);
}

// OpenEXR does not convert pixel types when writing, so the values are first converted to the file's type
// (half: rounded to nearest, beyond ±65504 → ±inf).
template <class T>
void write_as(const Image& image, const fs::path& file, Imf::PixelType type) {
  const std::vector<T> values(image.rgba.begin(), image.rgba.end());
  Imf::Header header(image.width, image.height);
  header.compression() = Imf::ZIP_COMPRESSION;
  if (image.region) {
    header.insert(region_key, Imf::StringAttribute(region_text(*image.region, image.width, image.height)));
  }
  Imf::FrameBuffer frame;
  for (int c = 0; c < (image.has_alpha ? 4 : 3); ++c) {
    header.channels().insert(channel_names[c], Imf::Channel(type));
    frame.insert(channel_names[c], rgba_slice(type, &values[static_cast<std::size_t>(c)], image.width,
                                              header.dataWindow(), 0.0));
  }
  // Blocks of scanlines are compressed in parallel, on every core (the render's threads are idle by now).
  static const bool threads_set = [] {
    Imf::setGlobalThreadCount(static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
    return true;
  }();
  (void)threads_set;
  Imf::OutputFile out(file.c_str(), header, Imf::globalThreadCount());
  out.setFrameBuffer(frame);
  out.writePixels(image.height);
}

void write_pixels(const Image& image, const fs::path& file, bool full_float) {
  if (full_float) {
    write_as<float>(image, file, Imf::FLOAT);
  } else {
    write_as<half>(image, file, Imf::HALF);
  }
}

Image allocate_for(const Imath::Box2i& window) {
  const std::int64_t width = std::int64_t(window.max.x) - window.min.x + 1;
  const std::int64_t height = std::int64_t(window.max.y) - window.min.y + 1;
  if (width <= 0 || height <= 0 || std::uint64_t(width * height) > max_pixels) {
    throw ImageError("unsupported EXR data window size");
  }
  return Image(static_cast<int>(width), static_cast<int>(height));
}

// Luminance-only files: the Y channel is read into R and copied to G and B.
void spread_luminance(Image& image) {
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) image.rgba[i + 1] = image.rgba[i + 2] = image.rgba[i];
}

Image read_pixels(const fs::path& file) {
  Imf::InputFile in(file.c_str());
  const Imath::Box2i window = in.header().dataWindow();
  const Imf::ChannelList& channels = in.header().channels();
  const bool has_rgb = channels.findChannel("R") || channels.findChannel("G") || channels.findChannel("B");
  const bool luminance_only = !has_rgb && channels.findChannel("Y");
  if (!has_rgb && !luminance_only) throw ImageError("the EXR file has no R, G, B or Y channel");
  Image image = allocate_for(window);
  image.has_alpha = channels.findChannel("A") != nullptr;
  Imf::FrameBuffer frame;
  if (luminance_only) frame.insert("Y", float_slice(image, 0, window, 0.0));
  for (int c = 0; c < 3 && !luminance_only; ++c) frame.insert(channel_names[c], float_slice(image, c, window, 0.0));
  frame.insert("A", float_slice(image, 3, window, 1.0));
  in.setFrameBuffer(frame);
  in.readPixels(window.min.y, window.max.y);
  if (luminance_only) spread_luminance(image);
  if (const auto* region = in.header().findTypedAttribute<Imf::StringAttribute>(region_key)) {
    image.region = parse_region_text(region->value(), image.width, image.height);
  }
  return image;
}

}  // namespace

void write_exr(const Image& image, const fs::path& file, bool full_float) {
  try {
    write_pixels(image, file, full_float);
  } catch (const ImageError&) {
    throw;
  } catch (const std::exception& e) {
    throw ImageError(std::string("OpenEXR: ") + e.what());
  }
}

Image read_exr(const fs::path& file) {
  try {
    return read_pixels(file);
  } catch (const ImageError&) {
    throw;
  } catch (const std::exception& e) {
    throw ImageError(std::string("OpenEXR: ") + e.what());
  }
}

}  // namespace povtrace::image
