#pragma once
// Word recall on real photographs of scene text (street signs, storefronts, plates): the check
// that a model trained on the simulator's renders still reads the real world. A folder holds
// the photos and labels.tsv, one line per photo:
//   FILE <TAB> SOURCE_REPO <TAB> SOURCE_PATH <TAB> TOKEN|TOKEN|...
// The tokens are what a person reads there with confidence, so recall is scored, not
// precision. A token prefixed "[P]" is parking-related; the prefix is not part of it. Scored
// tokens are the ASCII ones of two characters or more (the plates' Chinese province glyphs
// and single characters are left out); a token is read when it occurs, ignoring case, inside
// some text the spotter reported for that photo.
#include <string>
#include <vector>

namespace parkloc::eval {

struct PhotoLabels {
  std::string file;                 // the photo, relative to the folder
  std::vector<std::string> tokens;  // as labelled, "[P]" removed
};

// Reads FOLDER/labels.tsv; throws InputError naming the file and line of a malformed line
// (fewer than four fields, no file name) or IoError when the file is missing.
std::vector<PhotoLabels> loadPhotoLabels(const std::string& folder);

// The tokens of `labels` that recall counts (ASCII, two characters or more).
std::vector<std::string> scoredTokens(const PhotoLabels& labels);

// The scored tokens of one photo that occur, ignoring case, inside some of `readings`.
int tokensRead(const std::vector<std::string>& tokens, const std::vector<std::string>& readings);

struct PhotoRecall {
  int photos = 0;
  int tokens = 0;  // scored tokens over the photos
  int read = 0;    // of them, read
  double recall() const { return tokens > 0 ? static_cast<double>(read) / tokens : 0.0; }
  void add(int photo_tokens, int photo_read) {
    ++photos;
    tokens += photo_tokens;
    read += photo_read;
  }
};

}  // namespace parkloc::eval
