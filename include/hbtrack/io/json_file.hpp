#pragma once
// Bounded reading of the JSON files hbtrack reads back (summary.json, checkpoint.json,
// sweep.json): a size limit and a nesting limit checked on the text before it is parsed, because
// a JSON document nested 100 000 deep overflows the stack of the code that walks it.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace hbtrack {

// hbtrack writes at most 5 levels; a hand-edited file gets room to spare.
inline constexpr int kMaxJsonNesting = 64;
// A summary with thousands of special points is a few MB.
inline constexpr std::size_t kMaxJsonFileBytes = std::size_t{256} << 20;

// Throws CaseError "SOURCE:LINE: arrays or objects nested deeper than 64 levels" when `text`
// nests deeper than kMaxJsonNesting; brackets inside strings do not count.
void check_json_nesting(std::string_view text, const std::string& source);

// The parsed contents of a regular file of at most kMaxJsonFileBytes, nested at most
// kMaxJsonNesting deep; CaseError "PATH: ..." in one line otherwise (`what` names the file's role).
nlohmann::json read_json_file(const std::string& path, const std::string& what);

}  // namespace hbtrack
