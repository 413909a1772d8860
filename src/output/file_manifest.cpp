#include "output/file_manifest.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace tunica {

std::uint32_t crc32_of(const std::string& text, std::uint32_t crc) {
  const auto* p = reinterpret_cast<const Bytef*>(text.data());
  std::size_t left = text.size();
  uLong c = crc;
  while (left > 0) {  // zlib takes a uInt length
    const uInt n = static_cast<uInt>(std::min<std::size_t>(left, 1u << 30));
    c = crc32(c, p, n);
    p += n;
    left -= n;
  }
  return static_cast<std::uint32_t>(c);
}

void verify_file(const std::string& directory, const FileRecord& r, Tail tail) {
  const std::string path = directory + "/" + r.name;
  const auto refuse = [&](const std::string& what) {
    throw InputError({path, 0, 0, ""}, "the run cannot continue from this folder: " + what);
  };
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) refuse(std::string("the file the restart file records is unreadable: ") + std::strerror(errno));
  struct stat st {};
  if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    close(fd);
    refuse("not a regular file");
  }
  const auto size = static_cast<std::uint64_t>(st.st_size);
  if (size < r.size_bytes) {
    close(fd);
    refuse(fmt::format("it holds {} bytes, fewer than the {} the restart file records (truncated)", size, r.size_bytes));
  }
  if (size > r.size_bytes && tail == Tail::refuse) {
    close(fd);
    refuse(fmt::format("it holds {} bytes, not the {} the restart file records (changed)", size, r.size_bytes));
  }
  std::vector<char> block(1 << 20);
  uLong crc = crc32(0, nullptr, 0);
  for (std::uint64_t left = r.size_bytes; left > 0;) {
    const ssize_t n = read(fd, block.data(), static_cast<std::size_t>(std::min<std::uint64_t>(left, block.size())));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      close(fd);
      refuse("it could not be read to its recorded length");
    }
    crc = crc32(crc, reinterpret_cast<const Bytef*>(block.data()), static_cast<uInt>(n));
    left -= static_cast<std::uint64_t>(n);
  }
  close(fd);
  if (static_cast<std::uint32_t>(crc) != r.crc32)
    refuse(fmt::format("its first {} bytes differ from what the restart file records (CRC-32 {:08x}, recorded {:08x}): "
                       "it was changed after the checkpoint",
                       r.size_bytes, static_cast<std::uint32_t>(crc), r.crc32));
  if (size > r.size_bytes && truncate(path.c_str(), static_cast<off_t>(r.size_bytes)) != 0)
    throw std::runtime_error("cannot cut '" + path + "' back to its recorded length: " + std::strerror(errno));
}

}  // namespace tunica
