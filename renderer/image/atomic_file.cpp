#include "renderer/image/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <exception>
#include <random>
#include <string>
#include <system_error>

#include "renderer/image/image.hpp"

namespace povtrace::image {
namespace {

namespace fs = std::filesystem;

constexpr int max_name_attempts = 100;  // O_EXCL collisions with other writers before giving up

std::string failure_message(const fs::path& destination, const std::string& cause) {
  return "cannot write '" + destination.string() + "': " + cause;
}

fs::path folder_of(const fs::path& destination) {
  const fs::path folder = destination.parent_path();
  return folder.empty() ? fs::path(".") : folder;
}

// A hidden name next to the destination, unique per process and call: ".name.tmp-<pid>-<random>".
fs::path candidate_temp_name(const fs::path& destination, std::mt19937_64& random) {
  // Appended piece by piece: GCC 12 gives a false -Wrestrict for "literal" + std::string&& (a known false positive).
  std::string name = ".";
  name += destination.filename().string();
  name += ".tmp-";
  name += std::to_string(::getpid());
  name += "-";
  name += std::to_string(random() % 1000000000ULL);
  return folder_of(destination) / name;
}

// Creates the temporary file exclusively (O_EXCL), so it never clobbers anything. Mode 0666 minus the umask,
// the same as a plain fopen would give the destination.
fs::path create_temp_file(const fs::path& destination) {
  std::mt19937_64 random(std::random_device{}());
  for (int attempt = 0; attempt < max_name_attempts; ++attempt) {
    const fs::path temp = candidate_temp_name(destination, random);
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      return temp;
    }
    if (errno != EEXIST) {
      throw ImageError(failure_message(destination, "cannot create a temporary file in '" +
                                                        folder_of(destination).string() + "': " +
                                                        std::strerror(errno)));
    }
  }
  throw ImageError(failure_message(destination, "no free temporary file name in '" +
                                                    folder_of(destination).string() + "'"));
}

void discard(const fs::path& temp) {
  std::error_code ignored;
  fs::remove(temp, ignored);
}

}  // namespace

void write_file_atomically(const fs::path& destination,
                           const std::function<void(const fs::path& temp)>& write_temp) {
  const fs::path temp = create_temp_file(destination);
  try {
    write_temp(temp);
  } catch (const std::exception& e) {
    discard(temp);
    throw ImageError(failure_message(destination, e.what()));
  } catch (...) {
    discard(temp);
    throw ImageError(failure_message(destination, "unknown error"));
  }
  std::error_code error;
  fs::rename(temp, destination, error);
  if (error) {
    discard(temp);
    throw ImageError(failure_message(destination, "cannot rename the temporary file over it: " + error.message()));
  }
}

}  // namespace povtrace::image
