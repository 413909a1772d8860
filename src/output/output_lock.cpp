#include "output/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "core/errors.hpp"

namespace tunica {

OutputLock::OutputLock(const std::string& directory, bool create) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (create) {
    fs::create_directories(directory, ec);
    if (ec) throw std::runtime_error("cannot create the output directory '" + directory + "': " + ec.message());
  } else if (!fs::is_directory(directory, ec)) {
    throw InputError({directory, 0, 0, ""}, "there is no output folder here to continue a run from");
  }
  const std::string path = directory + "/" + kFileName;
  fd_ = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw std::runtime_error("cannot open the lock file '" + path + "': " + std::strerror(errno));
  int rc;
  do rc = flock(fd_, LOCK_EX | LOCK_NB);
  while (rc != 0 && errno == EINTR);
  if (rc != 0) {
    const int err = errno;
    close(fd_);
    fd_ = -1;
    if (err == EWOULDBLOCK)
      throw InputError({directory, 0, 0, ""}, "another Tunica run is writing into this output folder (it holds " +
                                                  std::string(kFileName) + "); wait for it to end or choose another folder");
    throw std::runtime_error("cannot lock '" + path + "': " + std::strerror(err));
  }
}

OutputLock::~OutputLock() {
  if (fd_ >= 0) close(fd_);  // releases the lock
}

}  // namespace tunica
