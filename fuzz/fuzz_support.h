#pragma once
// Shared helpers of the libFuzzer targets: the parsers' contract is that any input gives a
// valid result or throws parkloc::InputError. Anything else (another exception type, a
// crash, a sanitizer report, a result that breaks its invariants) aborts so that libFuzzer
// records the input.
#include <fcntl.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <typeinfo>

#include "common/error.h"

namespace parkloc::fuzz {

[[noreturn]] inline void violation(const std::string& what) {
  std::fprintf(stderr, "fuzz: contract violated: %s\n", what.c_str());
  std::abort();
}

inline void check(bool ok, const char* what) {
  if (!ok) violation(what);
}

// Runs `parse`; InputError (and its IoError) is the one accepted failure. Returns whether
// `parse` finished without throwing.
template <typename Parse>
bool acceptsOnlyInputError(Parse&& parse) {
  try {
    parse();
    return true;
  } catch (const InputError&) {
    return false;
  } catch (const std::exception& e) {
    violation(std::string("escaped exception ") + typeid(e).name() + ": " + e.what());
  } catch (...) {
    violation("escaped exception of unknown type");
  }
}

// Catches leaked file descriptors, which LeakSanitizer does not see (a FILE* that a decoder
// never closes stays reachable through libc's list of open files). The kernel hands out the
// lowest free descriptor, so a probe after the input that gets a higher number than a probe
// before it means that the input left a descriptor open. Measured around each input only:
// libFuzzer itself keeps pipes to the symbolizer open between inputs.
inline int lowestFreeDescriptor() {
  const int probe = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
  if (probe < 0) violation("cannot open /dev/null (descriptors exhausted?)");
  ::close(probe);
  return probe;
}

// Runs one input through `fuzz_one` and fails when it leaked a file descriptor.
template <typename FuzzOne>
void withoutDescriptorLeak(FuzzOne&& fuzz_one) {
  const int before = lowestFreeDescriptor();
  fuzz_one();
  if (lowestFreeDescriptor() > before) violation("a file descriptor leaked");
}

// A file under /dev/shm (memory, no disk wear) unique to this process, for APIs that only
// take a path. Removed when the process exits normally.
class ScratchFile {
 public:
  explicit ScratchFile(const std::string& name)
      : path_("/dev/shm/parkloc-fuzz-" + std::to_string(::getpid()) + "-" + name) {}
  ~ScratchFile() {
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  }
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;

  const std::string& write(const uint8_t* data, size_t size) const {
    std::ofstream out(path_, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    out.close();
    if (!out) violation("cannot write the scratch file " + path_);
    return path_;
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace parkloc::fuzz
