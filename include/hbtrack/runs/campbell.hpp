#pragma once
// `modes --speeds LO:HI:N`: the Campbell diagram of a rotating case ([rotation] with [model] Kg1,
// Mspin and, when given, G): at each speed Omega the lowest frequencies of
//   (K + Omega^2 (Kg1 - Mspin)) phi + i w Omega G phi - w^2 M phi = 0
// (undamped; G couples the modes through the Coriolis force), each mode followed from speed to
// speed by the correlation (MAC) of its shape with the previous speed's, so that a column is one
// mode even where two cross. Table "campbell": speed, then one column per mode named as the
// caller names them (1B, 2B, ...; "mode K" otherwise) in the order of the modes at rest; the
// summary lists where each mode meets the engine-order lines w = k Omega.
#include <string>
#include <vector>

#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/result_sink.hpp"
#include "hbtrack/runs/run_report.hpp"

namespace hbtrack::runs {

struct CampbellOptions {
  std::vector<double> speeds;      // rad/s, >= 0, increasing
  int count = 6;                   // modes followed
  std::vector<std::string> names;  // of the modes at rest, in increasing frequency (may be shorter)
  int engine_orders = 8;           // crossings with k Omega, k = 1 .. engine_orders
};

// Throws a CaseError for a case without [rotation], speeds not increasing or negative, count < 1.
RunReport campbell(const CaseDefinition& c, const CampbellOptions& o, ResultSink& sink);

// The speeds of a "LO:HI:N" text (N evenly spaced, ends included); a CaseError naming `field`.
std::vector<double> parse_speeds(const std::string& text, const std::string& field);

}  // namespace hbtrack::runs
