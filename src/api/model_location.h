#pragma once
// Where an installed parkloc keeps its models: <prefix>/share/parkloc/models beside the
// <prefix>/lib that holds this library. Found from the library's own file at run time, so an
// installation moved to another prefix (or installed with `cmake --install --prefix`) still
// finds them.
#include <string>

namespace parkloc::api {

// The installed model folder, or "" when this library is not in an installation that has one
// (a build tree).
std::string installedModelDir();

}  // namespace parkloc::api
