// Replay driver for the fuzz targets when libFuzzer is not available (g++, or PATHREF_FUZZ=OFF).
// Usage: <target>_fuzzer FILE_OR_DIR...
// Every regular file given, or found (recursively, in sorted order) in a directory given, is read
// and passed once to LLVMFuzzerTestOneInput. A target reports a broken invariant by trapping
// (__builtin_trap) or by a sanitizer error, both of which end the process abnormally, so a
// replay that returns exit status 0 means every input held its invariant. Exit status 2: bad
// usage, an unreadable file, no input found, or a target that returned non-zero.
// Modelled on simdjson's fuzz/main.cpp (spec: docs/fuzzing.md).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

bool replay(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "replay: cannot read %s\n", file.string().c_str());
    return false;
  }
  const std::vector<char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  // A copy in a buffer of exactly the input's size, so that ASan catches reads past the end.
  std::vector<std::uint8_t> exact(bytes.begin(), bytes.end());
  const int rc = LLVMFuzzerTestOneInput(exact.empty() ? nullptr : exact.data(), exact.size());
  if (rc != 0) {
    std::fprintf(stderr, "replay: %s: the target returned %d\n", file.string().c_str(), rc);
    return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s FILE_OR_DIR...\n", argv[0]);
    return 2;
  }
  std::vector<fs::path> files;
  for (int i = 1; i < argc; ++i) {
    const fs::path arg(argv[i]);
    std::error_code ec;
    if (fs::is_directory(arg, ec)) {
      std::vector<fs::path> found;
      for (const auto& entry : fs::recursive_directory_iterator(arg, ec))
        if (entry.is_regular_file()) found.push_back(entry.path());
      std::sort(found.begin(), found.end());
      files.insert(files.end(), found.begin(), found.end());
    } else if (fs::is_regular_file(arg, ec)) {
      files.push_back(arg);
    } else {
      std::fprintf(stderr, "replay: %s is neither a file nor a directory\n", argv[i]);
      return 2;
    }
  }
  if (files.empty()) {
    std::fprintf(stderr, "replay: no input files found\n");
    return 2;
  }
  bool ok = true;
  for (const auto& f : files) {
    std::fprintf(stderr, "replay: %s\n", f.string().c_str());
    ok = replay(f) && ok;
  }
  std::fprintf(stderr, "replay: %zu input%s %s\n", files.size(), files.size() == 1 ? "" : "s",
               ok ? "passed" : "had errors");
  return ok ? 0 : 2;
}
