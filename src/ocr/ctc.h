#pragma once
// CTC decoding of the recognizer's per-step class probabilities: the character set,
// greedy (best path) decoding, and the CTC forward probability of a given string, i.e. the
// sum over every alignment that collapses to it (Graves et al. 2006), computed in log space.
#include <optional>
#include <string>
#include <vector>

namespace parkloc::ocr {

// Class 0 is the CTC blank; classes 1..n are the characters of the dictionary file, in
// order; PaddleOCR appends a space as the last class.
class Charset {
 public:
  Charset() = default;
  // `characters`: one UTF-8 character each, without the blank.
  explicit Charset(std::vector<std::string> characters);
  // Reads a PaddleOCR dictionary (one character a line) and appends the space class.
  // Throws InputError naming the path when the file is missing or empty.
  static Charset fromDictionaryFile(const std::string& path);

  int classCount() const { return static_cast<int>(characters_.size()) + 1; }
  const std::string& character(int class_index) const { return characters_[class_index - 1]; }
  // The class sequence of a UTF-8 string; empty when a character is not in the set.
  std::optional<std::vector<int>> encode(const std::string& text) const;
  std::string decode(const std::vector<int>& classes) const;
  // The classes a reading restricted to `alphabet` may use: the blank and each of its
  // characters that the set has, in class order. An empty alphabet: every class.
  // Throws InputError naming a character of `alphabet` that the set lacks.
  std::vector<int> readingClasses(const std::string& alphabet) const;

 private:
  std::vector<std::string> characters_;
  std::vector<std::pair<std::string, int>> sorted_;  // character -> class, for encode
};

// Splits a UTF-8 string into characters (invalid bytes become single-byte characters).
std::vector<std::string> splitUtf8(const std::string& text);

// Row-major [steps x classes] probabilities of one sequence (softmax output).
struct CtcMatrix {
  const float* data = nullptr;
  int steps = 0;
  int classes = 0;
  float at(int t, int c) const { return data[static_cast<size_t>(t) * classes + c]; }
};

struct GreedyResult {
  std::vector<int> classes;
  // Mean of the kept steps' probabilities (PaddleOCR's confidence); 0 when empty.
  float mean_confidence = 0.f;
};

// Best path: the most probable class per step, repeats merged, blanks dropped. With
// `classes` (Charset::readingClasses, the blank included), the most probable of those only:
// a garage's texts use a few dozen of the recognizer's 6625 classes, and a glyph the
// renderer or a worn paint blurs is then read as the nearest of those, not as a Chinese
// character or a lower-case look-alike.
GreedyResult ctcGreedyDecode(const CtcMatrix& probs, const std::vector<int>& classes = {});

// log P(labels | probs): the CTC forward algorithm over the blank-extended label sequence.
// -infinity when no alignment fits (more labels than steps allow).
double ctcLogProbability(const CtcMatrix& probs, const std::vector<int>& labels);

}  // namespace parkloc::ocr
