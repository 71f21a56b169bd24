#include "api/model_location.h"

#include <dlfcn.h>

#include <filesystem>

// The model folder relative to the library's folder, from the install layout
// (GNUInstallDirs: lib/ and share/ by default; cmake/ParklocInstall.cmake).
#ifndef PARKLOC_MODELS_FROM_LIBDIR
#define PARKLOC_MODELS_FROM_LIBDIR "../share/parkloc/models"
#endif

namespace parkloc::api {

std::string installedModelDir() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&installedModelDir), &info) == 0 || info.dli_fname == nullptr)
    return "";
  std::error_code ec;
  const auto library = std::filesystem::canonical(info.dli_fname, ec);
  if (ec) return "";
  const auto dir = (library.parent_path() / PARKLOC_MODELS_FROM_LIBDIR).lexically_normal();
  return std::filesystem::is_directory(dir, ec) ? dir.string() : "";
}

}  // namespace parkloc::api
