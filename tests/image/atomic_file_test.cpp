// Atomic replacement: a failed write never leaves a temporary file and never touches an existing destination.
#include <unistd.h>

#include <filesystem>
#include <set>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "renderer/image/atomic_file.hpp"
#include "renderer/image/image.hpp"
#include "tests/common/scratch_folder.hpp"

namespace povtrace::image {
namespace {

namespace fs = std::filesystem;
using namespace std::string_literals;
using test::ScratchFolder;

const std::string old_content = "old content \x00\x01\x02 that must survive"s;

EncodeOptions png_options() {
  EncodeOptions options;
  options.format = FileFormat::png;
  return options;
}

// Runs `action`, which must throw ImageError, and returns the message.
template <class Action>
std::string error_message(Action action) {
  try {
    action();
  } catch (const ImageError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no ImageError thrown";
  return "";
}

TEST(AtomicFile, SuccessReplacesTheFileAndLeavesNoTemporary) {
  ScratchFolder folder;
  test::write_bytes(folder / "out.txt", old_content);
  write_file_atomically(folder / "out.txt", [](const fs::path& temp) { test::write_bytes(temp, "new"); });
  EXPECT_EQ(test::read_bytes(folder / "out.txt"), "new");
  EXPECT_EQ(folder.entries(), (std::set<std::string>{"out.txt"}));
}

TEST(AtomicFile, TemporaryFileIsInTheDestinationFolder) {
  ScratchFolder folder;
  fs::path seen;
  write_file_atomically(folder / "out.txt", [&](const fs::path& temp) {
    seen = temp;
    EXPECT_TRUE(fs::exists(temp));
  });
  EXPECT_EQ(seen.parent_path(), folder.path());
  EXPECT_FALSE(fs::exists(seen));
}

TEST(AtomicFile, FailingWriterLeavesTheDestinationByteIdentical) {
  ScratchFolder folder;
  test::write_bytes(folder / "out.png", old_content);
  const std::string message = error_message([&] {
    write_file_atomically(folder / "out.png", [](const fs::path& temp) {
      test::write_bytes(temp, "partial");
      throw std::runtime_error("disk on fire");
    });
  });
  EXPECT_NE(message.find((folder / "out.png").string()), std::string::npos) << message;
  EXPECT_NE(message.find("disk on fire"), std::string::npos) << message;
  EXPECT_EQ(test::read_bytes(folder / "out.png"), old_content);
  EXPECT_EQ(folder.entries(), (std::set<std::string>{"out.png"}));
}

TEST(AtomicFile, MissingFolderThrowsNamingThePath) {
  ScratchFolder folder;
  const fs::path destination = folder / "no_such_folder" / "out.png";
  const std::string message = error_message([&] { write_image(Image(2, 2), destination, png_options()); });
  EXPECT_NE(message.find(destination.string()), std::string::npos) << message;
  EXPECT_TRUE(folder.entries().empty());
}

TEST(AtomicFile, FolderThatIsAFileThrows) {
  ScratchFolder folder;
  test::write_bytes(folder / "plain_file", old_content);
  EXPECT_THROW(write_image(Image(2, 2), folder / "plain_file" / "out.png", png_options()), ImageError);
  EXPECT_EQ(folder.entries(), (std::set<std::string>{"plain_file"}));
  EXPECT_EQ(test::read_bytes(folder / "plain_file"), old_content);
}

TEST(AtomicFile, UnwritableFolderThrowsAndLeavesNoTemporary) {
  if (::geteuid() == 0) GTEST_SKIP() << "root can write into a read-only folder";
  ScratchFolder folder;
  const fs::path locked = folder / "locked";
  fs::create_directory(locked);
  test::write_bytes(locked / "out.png", old_content);
  fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
  EXPECT_THROW(write_image(Image(2, 2), locked / "out.png", png_options()), ImageError);
  fs::permissions(locked, fs::perms::owner_all);
  EXPECT_EQ(ScratchFolder::entries_of(locked), (std::set<std::string>{"out.png"}));
  EXPECT_EQ(test::read_bytes(locked / "out.png"), old_content);
}

TEST(AtomicFile, FailedRenameOverAFolderRemovesTheTemporary) {
  ScratchFolder folder;
  fs::create_directory(folder / "out.png");
  EXPECT_THROW(write_image(Image(2, 2), folder / "out.png", png_options()), ImageError);
  EXPECT_EQ(folder.entries(), (std::set<std::string>{"out.png"}));
  EXPECT_TRUE(fs::is_directory(folder / "out.png"));
}

TEST(AtomicFile, InvalidImageLeavesTheDestinationByteIdentical) {
  ScratchFolder folder;
  test::write_bytes(folder / "out.png", old_content);
  Image broken(2, 2);
  broken.rgba.resize(3);  // does not match 2×2
  EXPECT_THROW(write_image(broken, folder / "out.png", png_options()), ImageError);
  EXPECT_THROW(write_image(Image(), folder / "out.png", png_options()), ImageError);
  EXPECT_EQ(test::read_bytes(folder / "out.png"), old_content);
  EXPECT_EQ(folder.entries(), (std::set<std::string>{"out.png"}));
}

}  // namespace
}  // namespace povtrace::image
