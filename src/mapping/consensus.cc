#include "mapping/consensus.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <utility>

#include "map/numbering.h"

namespace parkloc::mapping {
namespace {

// Sightings near one another on the floor, whatever they read.
struct Place {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  std::vector<size_t> members;
  Eigen::Vector2d centre() const { return sum / static_cast<double>(members.size()); }
};

using FrameKey = std::pair<size_t, size_t>;  // (drive, frame set)

std::set<FrameKey> frameSetsOf(const std::vector<Sighting>& sightings,
                               const std::vector<size_t>& members) {
  std::set<FrameKey> frames;
  for (size_t i : members) frames.insert({sightings[i].drive, sightings[i].frame});
  return frames;
}

int distinctFrameSets(const std::vector<Sighting>& sightings, const std::vector<size_t>& members) {
  return static_cast<int>(frameSetsOf(sightings, members).size());
}

std::vector<Place> groupByPlace(const std::vector<std::optional<CastSighting>>& cast,
                                const std::vector<size_t>& placed, double radius) {
  std::vector<Place> places;
  for (size_t i : placed) {
    const Eigen::Vector2d& c = cast[i]->centre;
    Place* nearest = nullptr;
    double best = radius;
    for (Place& p : places) {
      const double d = (p.centre() - c).norm();
      if (d <= best) {
        best = d;
        nearest = &p;
      }
    }
    if (!nearest) nearest = &places.emplace_back();
    nearest->sum += c;
    nearest->members.push_back(i);
  }
  return places;
}

// The frame sets that read both tracks: one text is at one place in a frame set, so two places
// read together are two texts, however near.
int seenTogether(const std::vector<Sighting>& sightings, const std::vector<size_t>& a,
                 const std::vector<size_t>& b) {
  const std::set<FrameKey> in_a = frameSetsOf(sightings, a);
  const std::set<FrameKey> in_b = frameSetsOf(sightings, b);
  return static_cast<int>(std::count_if(in_b.begin(), in_b.end(),
                                        [&](const FrameKey& k) { return in_a.count(k) > 0; }));
}

// One reading of a place as a track, and whether it was confirmed.
struct Reading {
  TextTrack track;
  bool confirmed = false;
};

// A place left out for a close runner-up or too little agreement: each of its readings, the
// most seen first.
struct Contest {
  size_t undecided;  // index into Consensus::undecided
  std::vector<Reading> readings;
};

// Whether `text` is one number from a landmark within `radius` of `place`.
bool inSequence(const std::string& text, const Eigen::Vector2d& place,
                const std::vector<TextTrack>& tracks, double radius) {
  return std::any_of(tracks.begin(), tracks.end(), [&](const TextTrack& t) {
    const auto apart = map::numbersApart(text, t.text);
    return apart && *apart == 1 && (t.place - place).norm() <= radius;
  });
}

// The rows' numbering as the landmarks show it; no row segment when off.
RowSequence rowsOf(const std::vector<TextTrack>& tracks, const ConsensusOptions& options) {
  std::vector<PlacedNumber> placed;
  if (options.row_sequence)
    for (const TextTrack& t : tracks) placed.push_back({t.text, t.place});
  return RowSequence(placed, options.row);
}

}  // namespace

Consensus formConsensus(const std::vector<Sighting>& sightings,
                        const std::vector<std::optional<CastSighting>>& cast,
                        const ConsensusOptions& options) {
  Consensus out;
  std::vector<size_t> placed;
  for (size_t i = 0; i < sightings.size(); ++i) {
    if (i < cast.size() && cast[i] && cast[i]->range_m <= options.max_range_m)
      placed.push_back(i);
    else
      ++out.unplaced;
  }
  std::vector<TextTrack> candidates;
  std::vector<Contest> contests;
  for (const Place& place : groupByPlace(cast, placed, options.place_radius_m)) {
    std::map<std::string, std::vector<size_t>> by_text;
    for (size_t i : place.members) by_text[sightings[i].text].push_back(i);
    // The reading of the most frame sets; ties to the more confident reading.
    const std::vector<size_t>* winner = nullptr;
    std::pair<int, double> best{-1, 0.0};
    for (const auto& [text, members] : by_text) {
      double score = 0.0;
      for (size_t i : members) score += sightings[i].recognition_score;
      const std::pair<int, double> key{distinctFrameSets(sightings, members), score};
      if (key > best) {
        best = key;
        winner = &members;
      }
    }
    // A reading that is part of the winner ("28" of "286") is the same text cut by the
    // image's border: it neither competes with the winner nor counts against its agreement.
    const std::string& winning_text = sightings[winner->front()].text;
    int runner_up = 0;
    std::vector<size_t> competing = *winner;
    for (const auto& [text, members] : by_text) {
      if (&members == winner || winning_text.find(text) != std::string::npos) continue;
      runner_up = std::max(runner_up, distinctFrameSets(sightings, members));
      competing.insert(competing.end(), members.begin(), members.end());
    }
    const int all_frames = distinctFrameSets(sightings, competing);
    const int misreads = static_cast<int>(place.members.size() - winner->size());
    out.misreads += static_cast<size_t>(misreads);
    // A place legible enough to be a landmark that the rules leave out, with what it read.
    const auto undecided = [&](const char* why) {
      if (best.first < options.min_frame_sets) return;
      UndecidedPlace u;
      u.place = place.centre();
      u.why = why;
      for (const auto& [text, members] : by_text)
        u.readings.emplace_back(text, distinctFrameSets(sightings, members));
      std::sort(u.readings.begin(), u.readings.end(),
                [](const auto& a, const auto& b) { return a.second > b.second; });
      out.undecided.push_back(std::move(u));
    };
    const bool contested = best.first < options.min_agreement * static_cast<double>(all_frames) ||
                           best.first < options.min_margin * runner_up;
    if (best.first < options.min_frame_sets || contested) {
      ++out.weak_places;
      undecided(best.first < options.min_margin * runner_up ? "close runner-up" : "disagreement");
      if (best.first < options.min_frame_sets) continue;
    }
    // A reading of the place as a track, and whether it was confirmed.
    const auto readingOf = [&](const std::vector<size_t>& members) {
      TextTrack track;
      track.text = sightings[members.front()].text;
      track.cls = sightings[members.front()].cls;
      track.sightings = members;
      track.frame_sets = distinctFrameSets(sightings, members);
      track.misreads = static_cast<int>(place.members.size() - members.size());
      for (size_t i : members) track.place += cast[i]->centre;
      track.place /= static_cast<double>(members.size());
      std::vector<size_t> confirmed;
      for (size_t i : members)
        if (!sightings[i].second_opinion && !sightings[i].off_numbering) confirmed.push_back(i);
      return Reading{std::move(track),
                     distinctFrameSets(sightings, confirmed) >= options.min_confirmed_frame_sets};
    };
    Reading won = readingOf(*winner);
    if (contested) {
      Contest c{out.undecided.size() - 1, {std::move(won)}};
      for (const auto& [text, members] : by_text)
        if (&members != winner && winning_text.find(text) == std::string::npos)
          c.readings.push_back(readingOf(members));
      contests.push_back(std::move(c));
      continue;
    }
    if (!won.confirmed) {
      ++out.unconfirmed_places;
      undecided("unconfirmed");
      continue;
    }
    candidates.push_back(std::move(won.track));
  }

  // One reading at several places: a loop when they are near. Far apart, it is a number
  // painted twice or a misread that won another number's place; the place that has it in at
  // least min_margin times the frame sets of every other keeps it (as a place keeps its
  // reading against a runner-up), else no place does.
  std::map<std::string, std::vector<size_t>> by_text;
  for (size_t t = 0; t < candidates.size(); ++t) by_text[candidates[t].text].push_back(t);
  for (auto& [text, indices] : by_text) {
    std::vector<TextTrack> places;  // the candidates merged into places loop_radius_m apart
    for (size_t index : indices) {
      const TextTrack& other = candidates[index];
      auto near = std::find_if(places.begin(), places.end(), [&](const TextTrack& p) {
        return (other.place - p.place).norm() <= options.loop_radius_m &&
               (options.min_frame_sets_seen_apart <= 0 ||
                seenTogether(sightings, p.sightings, other.sightings) <
                    options.min_frame_sets_seen_apart);
      });
      if (near == places.end()) {
        places.push_back(other);
        continue;
      }
      const double n = static_cast<double>(near->sightings.size());
      const double m = static_cast<double>(other.sightings.size());
      near->place = (n * near->place + m * other.place) / (n + m);
      near->sightings.insert(near->sightings.end(), other.sightings.begin(), other.sightings.end());
      near->misreads += other.misreads;
      ++out.loops;
    }
    for (TextTrack& p : places) p.frame_sets = distinctFrameSets(sightings, p.sightings);
    std::sort(places.begin(), places.end(),
              [](const TextTrack& a, const TextTrack& b) { return a.frame_sets > b.frame_sets; });
    if (places.size() > 1) {
      if (places[0].frame_sets < options.min_margin * places[1].frame_sets) {
        out.duplicates.push_back(text);
        continue;
      }
      out.outweighed_duplicates.push_back(text);
    }
    out.tracks.push_back(std::move(places.front()));
  }

  // Two landmarks of one format side by side whose numbers are not consecutive: one of them
  // is a misread that won its place. The one the rows' numbering allows stays; when the rows
  // allow both or neither, the one seen in more frame sets.
  if (options.sequence_radius_m > 0.0) {
    const RowSequence rows = rowsOf(out.tracks, options);
    std::vector<bool> allowed;
    for (const TextTrack& t : out.tracks) allowed.push_back(rows.allows(t.text, t.place));
    std::vector<TextTrack> kept;
    for (size_t i = 0; i < out.tracks.size(); ++i) {
      const TextTrack& t = out.tracks[i];
      bool outvoted = false;
      for (size_t j = 0; j < out.tracks.size() && !outvoted; ++j) {
        const TextTrack& u = out.tracks[j];
        const auto apart = map::numbersApart(t.text, u.text);
        if (j == i || !apart || *apart == 1 ||
            (u.place - t.place).norm() > options.sequence_radius_m)
          continue;
        outvoted = allowed[i] != allowed[j] ? allowed[j] : u.frame_sets > t.frame_sets;
      }
      if (outvoted)
        out.out_of_sequence.push_back(t.text);
      else
        kept.push_back(t);
    }
    out.tracks = std::move(kept);
  }

  // Contested places decided by the sequence, against the landmarks decided so far.
  if (options.sequence_decides_contests && options.sequence_radius_m > 0.0) {
    const std::vector<TextTrack> decided = out.tracks;
    const RowSequence rows = rowsOf(decided, options);
    std::vector<size_t> settled;
    for (Contest& c : contests) {
      const double radius = options.sequence_radius_m;
      // The one reading of the place, of those seen in min_frame_sets, that is consecutive
      // to a landmark nearby or that the rows allow, if only one is.
      std::vector<size_t> in_sequence;
      for (size_t r = 0; r < c.readings.size(); ++r) {
        const TextTrack& reading = c.readings[r].track;
        if (reading.frame_sets < options.min_frame_sets) continue;
        if (inSequence(reading.text, reading.place, decided, radius) ||
            rows.allows(reading.text, reading.place))
          in_sequence.push_back(r);
      }
      if (in_sequence.size() != 1) continue;
      const size_t r = in_sequence.front();
      if (r != 0 && !options.sequence_decides_for_any_reading) continue;
      TextTrack& reading = c.readings[r].track;
      // Against the tracks as they grow: two contests won by one reading make one landmark.
      const bool elsewhere =
          std::any_of(out.tracks.begin(), out.tracks.end(),
                      [&](const TextTrack& t) { return t.text == reading.text; });
      if (!c.readings[r].confirmed || elsewhere) continue;
      out.decided_by_sequence.push_back(reading.text);
      out.tracks.push_back(std::move(reading));
      settled.push_back(c.undecided);
      --out.weak_places;
    }
    std::vector<UndecidedPlace> left;
    for (size_t u = 0; u < out.undecided.size(); ++u)
      if (std::find(settled.begin(), settled.end(), u) == settled.end())
        left.push_back(std::move(out.undecided[u]));
    out.undecided = std::move(left);
  }
  return out;
}

}  // namespace parkloc::mapping
