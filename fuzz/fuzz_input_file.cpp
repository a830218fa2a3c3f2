#include "fuzz_input_file.hpp"

#include <cstdio>
#include <cstdlib>
#include <map>
#include <stdexcept>

#include <unistd.h>

namespace admitgen::fuzz {
namespace {

/// Scratch paths of this process by suffix, removed when the process exits normally.
struct ScratchFiles {
  std::map<std::string, std::string> paths;
  ~ScratchFiles() {
    for (const auto& [suffix, path] : paths) std::remove(path.c_str());
  }
};

ScratchFiles& scratch() {
  static ScratchFiles files;
  return files;
}

}  // namespace

const std::string& write_input_file(const std::uint8_t* data, std::size_t size, const char* suffix) {
  auto& path = scratch().paths[suffix];
  if (path.empty()) {
    const char* dir = std::getenv("TMPDIR");
    path = std::string(dir != nullptr && *dir != '\0' ? dir : "/tmp") + "/admitgen-fuzz-" +
           std::to_string(static_cast<long>(getpid())) + suffix;
  }
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) throw std::runtime_error("cannot write the fuzz scratch file " + path);
  const bool written = size == 0 || std::fwrite(data, 1, size, f) == size;
  if (std::fclose(f) != 0 || !written) throw std::runtime_error("cannot write the fuzz scratch file " + path);
  return path;
}

}  // namespace admitgen::fuzz
