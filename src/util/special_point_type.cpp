#include "hbtrack/util/special_point_type.hpp"

#include <ostream>

namespace hbtrack {

std::ostream& operator<<(std::ostream& out, SpecialPointType type) { return out << to_string(type); }
std::ostream& operator<<(std::ostream& out, CurveExtremumType type) { return out << to_string(type); }

}  // namespace hbtrack
