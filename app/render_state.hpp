// +C / Continue_Trace: the render state file. While a frame renders to a file, every finished block is appended
// to `<output stem>.povtrace-state` next to the output (POV-Ray 3.7 keeps `<output stem>.pov-state` the same way);
// the file is removed once the image is written. After an interrupt it stays, and `+C` renders only the blocks
// it lacks and puts the saved ones back: blocks are independent, so the result is bit-identical to an
// uninterrupted render.
//
// povtrace's own format (POV-Ray's is not read or written): a text header, "povtrace render state 1\n", the byte
// count of the settings text on a line, then that text ("key=value" lines: image size, region, antialiasing, the
// frame, a digest of the scene file...: everything the pixels depend on); then one record per block: the tag
// "BLK1", x0 y0 x1 y1 (int32), the block's RGBA floats (linear, as the framebuffer holds them), and a 64-bit
// checksum of the record. Numbers are in the machine's byte order (the settings name it). The header is written to
// a temporary file and renamed into place; records are only appended, so a reader takes the records before the
// first incomplete or damaged one (a crash mid-write costs that block only) and a continued render appends after
// them.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "app/options.hpp"
#include "renderer/image/image.hpp"

namespace povtrace::app {

// `<dir>/<stem>.povtrace-state` for the output file `<dir>/<stem>.<ext>` (POV-Ray's rule for its .pov-state).
std::filesystem::path state_file_path(const std::filesystem::path& output);

// The settings text of a frame's state file: what its pixels depend on (not the thread count or the output
// format, which do not change them). `scene_text` is the scene's text (a file's or standard input's);
// `files_read` the names of the other files the parse read (SceneDescription::file_names: #include files…), each
// digested if it can be read (names that are not files are skipped).
std::string state_settings(const RenderOptions& options, const Frame& frame,
                           const std::optional<image::PixelRect>& region, int block_size,
                           const std::string& scene_text, const std::vector<std::string>& files_read = {});

struct SavedState {
  enum class Status {
    absent,          // no state file
    unreadable,      // not a povtrace state file, another format version, or a damaged header
    other_settings,  // written for other settings (`difference` says which)
    usable,
  };
  Status status = Status::absent;
  std::string difference;                // other_settings: "Width: 320 in the state file, 640 now" (first one)
  image::Image pixels;                   // usable: full frame size; the saved blocks' pixels, zero elsewhere
  std::vector<image::PixelRect> blocks;  // usable: the saved blocks, in the order they were written
  std::uintmax_t valid_bytes = 0;        // usable: the file's length up to the end of its last intact record
};

// Reads the state file at `path` for a render whose settings text is `settings` and whose frame is
// width × height.
SavedState read_state(const std::filesystem::path& path, const std::string& settings, int width, int height);

// The state file of a render in progress. Lazy, so that short renders cost nothing: blocks are only noted until
// the render has run for `delay_s` seconds; then the file is opened, the blocks so far are written from the
// framebuffer (final once finished), and each later block as it finishes. An interrupt writes whatever is still
// only noted (finish_interrupted). A kill -9 loses the blocks of the first `delay_s` seconds at most, and those
// of the last quarter second (written through to the system that often).
class StateWriter {
 public:
  // A new state file holding `settings` (an existing one is replaced whole: written beside `path` and renamed);
  // or, with `resume_after`, the existing file continued after its first *resume_after bytes (the intact
  // records; anything after is cut off).
  StateWriter(std::filesystem::path path, std::string settings, std::optional<std::uintmax_t> resume_after,
              double delay_s = 2.0);
  StateWriter(const StateWriter&) = delete;
  StateWriter& operator=(const StateWriter&) = delete;
  ~StateWriter();

  // Notes the finished block `block` of `image` (the render's full-size framebuffer, the same one every call);
  // may be called from several threads at once. Never throws: a write error is kept for finish_interrupted.
  void record(const image::Image& image, const image::PixelRect& block);
  // After an interrupt: writes the blocks not yet written, their pixels from `image` (the framebuffer), and closes
  // the file. Throws std::runtime_error naming the file if it could not be written (then +C may lack blocks).
  void finish_interrupted(const image::Image& image);
  // After the image was written: closes and deletes the state file (also an older one this render replaces).
  void discard();
  const std::filesystem::path& path() const { return path_; }
  long long blocks_recorded() const;

 private:
  void open_locked();                                            // creates or resumes the file
  void write_locked(const image::Image& image, const image::PixelRect& block);
  std::filesystem::path path_;
  std::string settings_;
  std::optional<std::uintmax_t> resume_after_;
  long long open_at_ns_ = 0;            // when to open the file if it is not open yet
  std::FILE* file_ = nullptr;
  mutable std::mutex mutex_;
  std::vector<image::PixelRect> pending_;   // recorded, not yet written
  long long last_flush_ns_ = 0;
  long long recorded_ = 0;
  std::string error_;                   // the first write error
};

}  // namespace povtrace::app
