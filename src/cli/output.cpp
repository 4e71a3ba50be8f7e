// Output files of every subcommand (spec/cli.md#output-files): missing parent folders are
// created, and a file that cannot be written is reported with the reason.
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "commands.hpp"
#include "pathref/core/error.hpp"
#include "pathref/core/version.hpp"

namespace pathref::cli {

void write_output_file(const std::string& path, const std::string& text) {
  namespace fs = std::filesystem;
  const fs::path p(path);
  std::error_code ec;
  if (p.has_parent_path() && !fs::is_directory(p.parent_path(), ec)) {
    fs::create_directories(p.parent_path(), ec);
    if (ec)
      throw UsageError("cannot write '" + path + "': cannot create the folder '" + p.parent_path().string() +
                       "': " + ec.message());
  }
  if (fs::is_directory(p, ec)) throw UsageError("cannot write '" + path + "': it is a folder");
  errno = 0;
  std::ofstream out(path, std::ios::binary);
  if (!out) throw UsageError("cannot write '" + path + "': " + (errno != 0 ? std::strerror(errno) : "cannot open"));
  out << text;
  out.close();
  if (!out) throw UsageError("cannot write '" + path + "': " + (errno != 0 ? std::strerror(errno) : "write failed"));
}

void stamp_version(nlohmann::json& doc) {
  doc["pathref_version"] = std::string(pathref::version());
  doc["golden_set_version"] = std::string(pathref::golden_set_version());
}

}  // namespace pathref::cli
