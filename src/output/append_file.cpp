#include "output/append_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace tunica {

AppendFile::~AppendFile() {
  if (fd_ >= 0) close(fd_);
}

void AppendFile::open_file(const std::string& path, int flags) {
  if (fd_ >= 0) close(fd_);
  path_ = path;
  fd_ = open(path.c_str(), O_WRONLY | O_CLOEXEC | flags, 0644);
  if (fd_ < 0) throw std::runtime_error("cannot write '" + path + "': " + std::strerror(errno));
}

void AppendFile::create(const std::string& directory, const std::string& name, const std::string& initial,
                        const std::string& tail) {
  name_ = name;
  tail_ = tail;
  size_bytes_ = 0;
  crc_ = 0;
  open_file(directory + "/" + name, O_CREAT | O_TRUNC);
  append(initial);
}

void AppendFile::resume(const std::string& directory, const FileRecord& record, const std::string& tail) {
  name_ = record.name;
  tail_ = tail;
  size_bytes_ = record.size_bytes;
  crc_ = record.crc32;
  open_file(directory + "/" + record.name, 0);
  if (!tail_.empty()) append("");
}

void AppendFile::append(const std::string& text) {
  const std::string data = text + tail_;
  std::size_t done = 0;
  while (done < data.size()) {
    const ssize_t n = pwrite(fd_, data.data() + done, data.size() - done, static_cast<off_t>(size_bytes_ + done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error("cannot write '" + path_ + "': " + std::strerror(n < 0 ? errno : EIO));
    done += static_cast<std::size_t>(n);
  }
  size_bytes_ += text.size();
  crc_ = crc32_of(text, crc_);
}

void AppendFile::sync() {
  if (fd_ >= 0 && fdatasync(fd_) != 0) throw std::runtime_error("cannot sync '" + path_ + "': " + std::strerror(errno));
}

}  // namespace tunica
