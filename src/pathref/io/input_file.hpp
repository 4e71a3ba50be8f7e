#pragma once
/// \file input_file.hpp
/// The one way pathref opens an input file (spec/formats.md#input-files): every reader of a file
/// named by the user — maps, scenes, scenarios, path and trace files, golden files, model files,
/// data files, reproduction documents — reads it through read_input_file.
#include <cstdint>
#include <string>
#include <string_view>

namespace pathref::io {

/// The whole content of the regular file `path`, read without ever blocking or growing past
/// `max_bytes`: the file is opened non-blocking and checked with fstat on the open descriptor, so
/// a FIFO, a character device (/dev/zero), a socket or a directory is refused before one byte is
/// read, and a file larger than `max_bytes` before any allocation. Throws UsageError
/// `cannot read WHAT 'PATH': REASON` (REASON: the operating system's message, or "a directory",
/// "a FIFO", "a character device", ... "not a regular file"), or `WHAT 'PATH' has N bytes, more
/// than the limit of M`. `what` names the file's role ("map file", "model file", ...).
[[nodiscard]] std::string read_input_file(const std::string& path, std::string_view what, std::uintmax_t max_bytes);

/// read_input_file for a caller that reports a refusal in its own words (a ROS map's image is
/// reported at the YAML line that names it): true with the content in `out`, or false with
/// `reason` ("No such file or directory", "it is a FIFO (named pipe), not a regular file", "it has
/// N bytes, more than the limit of M", ...). Never blocks; reads nothing from a non-regular file.
[[nodiscard]] bool try_read_input_file(const std::string& path, std::uintmax_t max_bytes, std::string& out,
                                       std::string& reason);

}  // namespace pathref::io
