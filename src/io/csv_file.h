#pragma once
// The small CSV files of a sequence (odometry, levels, video timestamps): one fixed header,
// then rows of comma-separated cells. Errors name the kind of file, its path and the line.
#include <fstream>
#include <string>

namespace parkloc::io {

// `s` without leading and trailing blanks, tabs and carriage returns.
std::string trimmed(const std::string& s);

// The file opened and its header line read and checked. Throws IoError ("<kind> <path>: cannot
// open file") or InputError ("<kind> <path>:1: expected the header '<header>'").
std::ifstream openCsvWithHeader(const std::string& kind, const std::string& path,
                                const std::string& header);

}  // namespace parkloc::io
