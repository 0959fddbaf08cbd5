#pragma once
// What a special point is: the `type` of summary.json's special_points and of the checkpoints,
// named once in a ChoiceTable each (util/choices.hpp gives to_string and parse_choice). Code
// compares the enums; the names appear only where a file is written or read. The names are a
// file format: add, never rename (tests/test_special_point_type.cpp lists them; so does
// python/hbtrack/special_points.py, the Python side's one table).
//
// Two enums because two kinds of curve carry special points: a branch in a continuation
// parameter (the engine's tests and its monitors' events), and a tracking curve of such a point
// in a second parameter, whose events are the extrema of that parameter and where it ends.
#include <iosfwd>
#include <string>
#include <string_view>

#include "hbtrack/util/choices.hpp"

namespace hbtrack {

// A special point of a branch.
enum class SpecialPointType {
  limit_point,      // LP: a fold in the continuation parameter (the engine's test)
  branch_point,     // BP: the bordered Jacobian singular off a fold (the engine's test)
  period_doubling,  // PD: a Floquet multiplier through -1 (the stability monitor)
  neimark_sacker,   // NS: a complex pair through the unit circle (the stability monitor)
  // Where an NS curve's frequency reaches 0 (1:1 resonance) or w/2 (1:2): the tracking's
  // resonance monitor ends the leg there; summary.json calls it a CurveExtremumType.
  resonance_1_1,  // R1
  resonance_1_2,  // R2
};

// A special point of a tracking curve (FoldExtremum, track's summary.json).
enum class CurveExtremumType {
  parameter_min,  // the tracked parameter is least: a pair of special points is born
  parameter_max,  // most: a pair disappears
  resonance_1_1,  // an NS curve ends on a fold curve
  resonance_1_2,  // an NS curve ends on a PD curve
};

template <>
struct ChoiceTable<SpecialPointType> {
  static constexpr std::string_view field = "special point type";
  static constexpr ChoiceName<SpecialPointType> names[] = {
      {SpecialPointType::limit_point, "LP"},    {SpecialPointType::branch_point, "BP"},  {SpecialPointType::period_doubling, "PD"},
      {SpecialPointType::neimark_sacker, "NS"}, {SpecialPointType::resonance_1_1, "R1"}, {SpecialPointType::resonance_1_2, "R2"}};
};

template <>
struct ChoiceTable<CurveExtremumType> {
  static constexpr std::string_view field = "tracking curve special point type";
  static constexpr ChoiceName<CurveExtremumType> names[] = {{CurveExtremumType::parameter_min, "min"},
                                                            {CurveExtremumType::parameter_max, "max"},
                                                            {CurveExtremumType::resonance_1_1, "resonance_1_1"},
                                                            {CurveExtremumType::resonance_1_2, "resonance_1_2"}};
};

// `field` names where the name was read (a file and its key) in the error.
inline SpecialPointType parse_special_point_type(const std::string& name, std::string_view field = ChoiceTable<SpecialPointType>::field) {
  return parse_choice<SpecialPointType>(name, field);
}
inline CurveExtremumType parse_curve_extremum_type(const std::string& name,
                                                   std::string_view field = ChoiceTable<CurveExtremumType>::field) {
  return parse_choice<CurveExtremumType>(name, field);
}

// Their names (test messages, logs).
std::ostream& operator<<(std::ostream& out, SpecialPointType type);
std::ostream& operator<<(std::ostream& out, CurveExtremumType type);

}  // namespace hbtrack
