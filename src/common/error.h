#pragma once
// Typed errors for bad input from outside (files, images, options). The library throws
// them at the edge with the file, field and value in the message; the CLI prints the
// message as one line on stderr and exits non-zero.
#include <stdexcept>
#include <string>

namespace parkloc {

// Malformed or inconsistent input data (a file, an image, a command-line option).
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A file that cannot be opened, read or written.
class IoError : public InputError {
 public:
  using InputError::InputError;
};

}  // namespace parkloc
