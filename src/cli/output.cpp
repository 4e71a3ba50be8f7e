// Output files of every subcommand (spec/cli.md#output-files): missing parent folders are
// created, and a file that cannot be written is reported with the reason.
#include <fmt/core.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include "commands.hpp"
#include "pathref/core/error.hpp"
#include "pathref/core/version.hpp"

extern char** environ;  // POSIX, for posix_spawn

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

namespace {
/// The full path of `name` on $PATH, or "" (an executable regular file).
std::string find_on_path(const std::string& name) {
  namespace fs = std::filesystem;
  const char* env = std::getenv("PATH");
  std::string path = env != nullptr ? env : "";
  std::size_t i = 0;
  while (i <= path.size()) {
    const std::size_t j = std::min(path.find(':', i), path.size());
    const fs::path cand = fs::path(path.substr(i, j - i).empty() ? "." : path.substr(i, j - i)) / name;
    std::error_code ec;
    if (fs::is_regular_file(cand, ec) && ::access(cand.c_str(), X_OK) == 0) return cand.string();
    i = j + 1;
  }
  return "";
}
}  // namespace

void write_figure(const std::string& path, const std::string& svg) {
  namespace fs = std::filesystem;
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext != ".pdf") {
    write_output_file(path, svg);
    return;
  }
  const std::string rsvg = find_on_path("rsvg-convert");
  if (rsvg.empty())
    throw UsageError("cannot write '" + path +
                     "': PDF output needs rsvg-convert (Debian librsvg2-bin), which is not installed; write an .svg instead");
  const std::string tmp = path + ".tmp.svg";
  write_output_file(tmp, svg);
  std::vector<std::string> args{rsvg, "-f", "pdf", "-o", path, tmp};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  int status = 0;
  const int rc = posix_spawn(&pid, rsvg.c_str(), nullptr, nullptr, argv.data(), environ);
  if (rc == 0) waitpid(pid, &status, 0);
  std::error_code ec;
  fs::remove(tmp, ec);
  if (rc != 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw UsageError("cannot write '" + path + "': rsvg-convert failed" +
                     (rc != 0 ? std::string(" to start: ") + std::strerror(rc)
                              : fmt::format(" (exit {})", WIFEXITED(status) ? WEXITSTATUS(status) : -1)));
}

void stamp_version(nlohmann::json& doc) {
  doc["pathref_version"] = std::string(pathref::version());
  doc["golden_set_version"] = std::string(pathref::golden_set_version());
}

}  // namespace pathref::cli
