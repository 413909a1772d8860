#include "core/bounded_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/errors.hpp"

namespace tunica {

namespace {

std::string size_text(std::size_t bytes) {
  if (bytes >= (1u << 20) && bytes % (1u << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " bytes";
}

/// Closes a descriptor on every exit.
struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string read_file_bounded(const std::string& path, std::size_t max_bytes, const std::string& what) {
  const auto fail = [&](const std::string& why) -> void {
    throw InputError(SourceLocation{path, 0, 0, ""}, "cannot read the " + what + ": " + why);
  };
  // O_NONBLOCK: opening a FIFO without a writer must not wait; it is refused below anyway.
  Fd f{::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY)};
  if (f.fd < 0) fail(errno == ENOENT ? "no such file" : std::strerror(errno));
  struct stat st {};
  if (::fstat(f.fd, &st) != 0) fail(std::strerror(errno));
  if (S_ISDIR(st.st_mode)) fail("it is a directory");
  if (!S_ISREG(st.st_mode)) fail("it is not a regular file (a device, pipe or socket)");
  if (static_cast<unsigned long long>(st.st_size) > max_bytes)
    throw InputError(SourceLocation{path, 0, 0, ""},
                     "the " + what + " is " + std::to_string(st.st_size) + " bytes, more than the " +
                         size_text(max_bytes) + " it may have");
  // Back to blocking reads for a regular file (O_NONBLOCK has no effect on them, but be plain).
  const int flags = ::fcntl(f.fd, F_GETFL);
  if (flags >= 0) ::fcntl(f.fd, F_SETFL, flags & ~O_NONBLOCK);
  std::string text;
  text.resize(static_cast<std::size_t>(st.st_size));
  std::size_t have = 0;
  // Read until end of file, never past max_bytes + 1: the file may have grown since fstat.
  for (;;) {
    if (have == text.size()) {
      if (text.size() > max_bytes) break;
      text.resize(std::min<std::size_t>(max_bytes + 1, text.size() + 65536));
    }
    const ssize_t n = ::read(f.fd, text.data() + have, text.size() - have);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail(std::strerror(errno));
    }
    if (n == 0) break;
    have += static_cast<std::size_t>(n);
  }
  text.resize(have);
  if (have > max_bytes)
    throw InputError(SourceLocation{path, 0, 0, ""},
                     "the " + what + " is larger than the " + size_text(max_bytes) + " it may have");
  return text;
}

}  // namespace tunica
