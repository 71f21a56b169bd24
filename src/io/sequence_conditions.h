#pragma once
// The conditions a dataset sequence was recorded under, from its meta.json: the sequence-level
// subsets of the paper's Table 8 (bright, weak_light, blur).
#include <string>
#include <vector>

namespace parkloc::io {

// From the text of meta.json: its "condition" (or "conditions") entry as a string
// ("weak_light", "bright+blur"), a list of strings, or an object such as
// {"light": "weak", "blur": true}. Names are normalised (weak / dim / dark -> weak_light,
// fuzzy / motion_blur -> blur), sorted, each once. A rendered drive's look, meta.json's
// {"appearance": {"subset": "realistic"}}, adds its subset name as it is. Throws InputError
// for malformed JSON.
std::vector<std::string> sequenceConditions(const std::string& meta_json,
                                            const std::string& source_name = "meta.json");

}  // namespace parkloc::io
