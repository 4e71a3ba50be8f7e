// The one way to open an input file (spec/formats.md#input-files).
#include "pathref/io/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

#include "pathref/core/error.hpp"
#include "pathref/io/json_text.hpp"

namespace pathref::io {

namespace {

/// What a non-regular file is, for the message.
const char* file_kind(mode_t m) {
  if (S_ISDIR(m)) return "it is a directory, not a regular file";
  if (S_ISFIFO(m)) return "it is a FIFO (named pipe), not a regular file";
  if (S_ISCHR(m)) return "it is a character device, not a regular file";
  if (S_ISBLK(m)) return "it is a block device, not a regular file";
  if (S_ISSOCK(m)) return "it is a socket, not a regular file";
  return "not a regular file";
}

/// Closes the descriptor on every path out.
class Fd {
 public:
  explicit Fd(int fd) noexcept : fd_(fd) {}
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  [[nodiscard]] int get() const noexcept { return fd_; }

 private:
  int fd_;
};

}  // namespace

namespace {

enum class Refusal { none, unreadable, too_large };

/// The shared body: the content, or the refusal and its reason (and the size when too large).
Refusal read_bounded(const std::string& path, std::uintmax_t max_bytes, std::string& out, std::string& reason,
                     std::uintmax_t& size) {
  if (path.empty()) {
    reason = "the file name is empty";
    return Refusal::unreadable;
  }
  if (path.find('\0') != std::string::npos) {
    reason = "the file name contains a NUL byte";
    return Refusal::unreadable;
  }
  // O_NONBLOCK: opening a FIFO with no writer must not wait; the descriptor is only read after
  // fstat says it is a regular file, for which O_NONBLOCK changes nothing.
  const Fd fd(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY));
  if (fd.get() < 0) {
    reason = std::strerror(errno);
    return Refusal::unreadable;
  }
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0) {
    reason = std::strerror(errno);
    return Refusal::unreadable;
  }
  if (!S_ISREG(st.st_mode)) {
    reason = file_kind(st.st_mode);
    return Refusal::unreadable;
  }
  size = static_cast<std::uintmax_t>(st.st_size);
  if (size > max_bytes) {
    reason = fmt::format("it has {} bytes, more than the limit of {}", size, max_bytes);
    return Refusal::too_large;
  }
  out.assign(static_cast<std::size_t>(size), '\0');
  std::size_t got = 0;
  while (got < out.size()) {
    const ssize_t n = ::read(fd.get(), out.data() + got, out.size() - got);
    if (n < 0) {
      if (errno == EINTR) continue;
      reason = std::strerror(errno);
      return Refusal::unreadable;
    }
    if (n == 0) break;  // the file shrank while read: what is there is the content
    got += static_cast<std::size_t>(n);
  }
  out.resize(got);  // a file that grew while read is read up to the size fstat gave
  return Refusal::none;
}

}  // namespace

bool try_read_input_file(const std::string& path, std::uintmax_t max_bytes, std::string& out, std::string& reason) {
  std::uintmax_t size = 0;
  return read_bounded(path, max_bytes, out, reason, size) == Refusal::none;
}

std::string read_input_file(const std::string& path, std::string_view what, std::uintmax_t max_bytes) {
  std::string out, reason;
  std::uintmax_t size = 0;
  switch (read_bounded(path, max_bytes, out, reason, size)) {
    case Refusal::none: return out;
    case Refusal::too_large:
      throw UsageError(
          fmt::format("{} '{}' has {} bytes, more than the limit of {}", what, printable(path, 300), size, max_bytes));
    case Refusal::unreadable: break;
  }
  throw UsageError(fmt::format("cannot read {} '{}': {}", what, printable(path, 300), reason));
}

}  // namespace pathref::io
