#include "ocr/ctc.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "common/error.h"
#include "ocr/lexicon.h"

namespace parkloc::ocr {
namespace {

// Random softmax rows, [steps x classes].
std::vector<float> randomProbs(int steps, int classes, std::mt19937& rng) {
  std::normal_distribution<float> logit(0.f, 1.5f);
  std::vector<float> p(static_cast<size_t>(steps) * classes);
  for (int t = 0; t < steps; ++t) {
    float sum = 0.f;
    for (int c = 0; c < classes; ++c) sum += p[t * classes + c] = std::exp(logit(rng));
    for (int c = 0; c < classes; ++c) p[t * classes + c] /= sum;
  }
  return p;
}

std::vector<int> collapse(const std::vector<int>& path) {
  std::vector<int> out;
  int previous = -1;
  for (int c : path) {
    if (c != 0 && c != previous) out.push_back(c);
    previous = c;
  }
  return out;
}

// Sum over every path of `steps` classes that collapses to `labels`.
double bruteForce(const CtcMatrix& m, const std::vector<int>& labels) {
  double total = 0.0;
  std::vector<int> path(m.steps, 0);
  std::function<void(int, double)> walk = [&](int t, double p) {
    if (t == m.steps) {
      if (collapse(path) == labels) total += p;
      return;
    }
    for (int c = 0; c < m.classes; ++c) {
      path[t] = c;
      walk(t + 1, p * m.at(t, c));
    }
  };
  walk(0, 1.0);
  return total;
}

TEST(CtcForward, EqualsBruteForceSumOverAlignments) {
  std::mt19937 rng(42);
  const std::vector<std::vector<int>> label_sets = {{}, {1}, {2, 2}, {1, 2}, {1, 2, 1}, {2, 1, 1}};
  for (int steps = 1; steps <= 6; ++steps) {
    const auto probs = randomProbs(steps, 3, rng);
    const CtcMatrix m{probs.data(), steps, 3};
    for (const auto& labels : label_sets) {
      const double expected = bruteForce(m, labels);
      const double got = ctcLogProbability(m, labels);
      if (expected == 0.0) {
        EXPECT_TRUE(std::isinf(got) && got < 0) << "steps " << steps;
      } else {
        EXPECT_NEAR(got, std::log(expected), 1e-9)
            << "steps " << steps << " labels " << labels.size();
      }
    }
  }
}

TEST(CtcForward, ProbabilitiesOfAllStringsSumToOne) {
  // Every path collapses to exactly one string, so the strings' probabilities sum to one.
  std::mt19937 rng(3);
  const int steps = 4, classes = 3;
  const auto probs = randomProbs(steps, classes, rng);
  const CtcMatrix m{probs.data(), steps, classes};
  double sum = 0.0;
  std::function<void(std::vector<int>)> strings = [&](std::vector<int> s) {
    sum += std::exp(ctcLogProbability(m, s));
    if (s.size() == static_cast<size_t>(steps)) return;
    for (int c = 1; c < classes; ++c) {
      auto next = s;
      next.push_back(c);
      strings(next);
    }
  };
  strings({});
  EXPECT_NEAR(sum, 1.0, 1e-6);  // the rows are floats
}

TEST(CtcGreedy, MergesRepeatsAndDropsBlanks) {
  // Best path: a a blank a b b blank -> "a a b" as classes 1 1 2.
  const int best[] = {1, 1, 0, 1, 2, 2, 0};
  std::vector<float> probs(7 * 3, 0.1f);
  for (int t = 0; t < 7; ++t) probs[t * 3 + best[t]] = 0.8f;
  const GreedyResult r = ctcGreedyDecode({probs.data(), 7, 3});
  EXPECT_EQ(r.classes, (std::vector<int>{1, 1, 2}));
  EXPECT_NEAR(r.mean_confidence, 0.8f, 1e-6);
}

TEST(CtcGreedy, RestrictedToReadingClassesTakesTheBestOfThose) {
  // Step 0: class 3 ('o') is the most probable, class 2 ('0') the best of the reading classes.
  const Charset charset({"A", "0", "o"});
  const std::vector<float> probs = {0.1f, 0.1f, 0.3f, 0.5f,   // o over 0
                                    0.7f, 0.1f, 0.1f, 0.1f};  // blank
  const auto classes = charset.readingClasses("A0");
  EXPECT_EQ(classes, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(charset.decode(ctcGreedyDecode({probs.data(), 2, 4}).classes), "o");
  const GreedyResult r = ctcGreedyDecode({probs.data(), 2, 4}, classes);
  EXPECT_EQ(charset.decode(r.classes), "0");
  EXPECT_NEAR(r.mean_confidence, 0.3f, 1e-6);
}

TEST(Charset, ReadingClassesOfAnEmptyAlphabetAreAllAndAForeignCharacterIsAnError) {
  const Charset charset({"A", "0"});
  EXPECT_TRUE(charset.readingClasses("").empty());
  EXPECT_THROW(charset.readingClasses("A#"), InputError);
}

TEST(Charset, EncodesAndDecodesUtf8) {
  const Charset charset({"A", "B", "1", "-", "é"});
  EXPECT_EQ(charset.classCount(), 6);
  const auto code = charset.encode("B-1é");
  ASSERT_TRUE(code);
  EXPECT_EQ(*code, (std::vector<int>{2, 4, 3, 5}));
  EXPECT_EQ(charset.decode(*code), "B-1é");
  EXPECT_FALSE(charset.encode("C"));
}

// A sharp CTC output spelling `classes`, each symbol held two steps, blanks between.
std::vector<float> spelled(const std::vector<int>& classes, int n_classes, float peak, int* steps) {
  std::vector<int> path;
  for (int c : classes) path.insert(path.end(), {c, c, 0});
  *steps = static_cast<int>(path.size());
  std::vector<float> p(path.size() * n_classes, (1.f - peak) / (n_classes - 1));
  for (size_t t = 0; t < path.size(); ++t) p[t * n_classes + path[t]] = peak;
  return p;
}

TEST(Lexicon, PicksTheEntryTheCropSpellsWithHighPosterior) {
  const Charset charset({"1", "2", "7", "B", "-"});
  int steps = 0;
  const auto probs = spelled(*charset.encode("B2-117"), charset.classCount(), 0.9f, &steps);
  const LexiconDecoding d = decodeWithLexicon({probs.data(), steps, charset.classCount()}, charset,
                                              {"B2-112", "B2-117", "B1-117", "71"});
  EXPECT_TRUE(d.matched);
  EXPECT_EQ(d.best_index, 1);
  EXPECT_EQ(d.raw_text, "B2-117");
  EXPECT_GT(d.posterior, 0.9);
}

TEST(Lexicon, ReportsUnknownInsteadOfForcingTheNearestEntry) {
  const Charset charset({"1", "2", "7", "B", "-"});
  int steps = 0;
  const auto probs = spelled(*charset.encode("B2-771"), charset.classCount(), 0.9f, &steps);
  const LexiconDecoding d =
      decodeWithLexicon({probs.data(), steps, charset.classCount()}, charset, {"B2-117", "B2-711"});
  EXPECT_FALSE(d.matched);
  EXPECT_EQ(d.raw_text, "B2-771");
  EXPECT_LT(d.posterior, 0.5);
}

TEST(Lexicon, AmbiguousCharacterIsResolvedByTheLexicon) {
  // The third symbol is "1" or "7" about equally; only "B7" is in the lexicon.
  const Charset charset({"1", "7", "B"});
  const int C = charset.classCount();
  int steps = 0;
  auto probs = spelled({3, 1}, C, 0.9f, &steps);
  for (int t = 3; t < 5; ++t) {
    probs[t * C + 1] = 0.48f;
    probs[t * C + 2] = 0.46f;
  }
  const LexiconDecoding d = decodeWithLexicon({probs.data(), steps, C}, charset, {"B7", "A1"});
  EXPECT_EQ(d.raw_text, "B1");
  EXPECT_TRUE(d.matched);
  EXPECT_EQ(d.best_index, 0);
  // About equal likelihoods: the lexicon prior (open_world_weight) tips the balance.
  EXPECT_GT(d.posterior, 0.8);
  EXPECT_LT(d.posterior, 0.99);
}

TEST(Lexicon, LookAlikeMisreadIsTheEntry) {
  // An unseen font's "0" read confidently as "O": the free reading "BO7" is far more probable
  // than "B07", yet it differs only by a look-alike glyph, so the entry is accepted.
  const Charset charset({"0", "7", "B", "O", "A"});
  const int C = charset.classCount();
  int steps = 0;
  auto probs = spelled(*charset.encode("BO7"), C, 0.9f, &steps);
  for (int t = 3; t < 5; ++t) {  // the "O" steps: "0" second best
    probs[t * C + 4] = 0.8f;
    probs[t * C + 1] = 0.12f;
  }
  const LexiconDecoding d = decodeWithLexicon({probs.data(), steps, C}, charset, {"B07", "A07"});
  EXPECT_EQ(d.raw_text, "BO7");
  EXPECT_TRUE(d.matched);
  EXPECT_EQ(d.best_index, 0);

  LexiconOptions strict;
  strict.look_alikes_are_the_entry = false;
  EXPECT_FALSE(
      decodeWithLexicon({probs.data(), steps, C}, charset, {"B07", "A07"}, strict).matched);
}

TEST(Lexicon, LookAlikeGroupsDoNotMatchOtherCharacters) {
  EXPECT_TRUE(sameUpToLookAlikes("BO07", "B007"));
  EXPECT_TRUE(sameUpToLookAlikes("8U01", "B001"));
  EXPECT_FALSE(sameUpToLookAlikes("B007", "B017"));
  EXPECT_FALSE(sameUpToLookAlikes("B007", "B0071"));
  EXPECT_FALSE(sameUpToLookAlikes("A007", "B007"));
}

}  // namespace
}  // namespace parkloc::ocr
