#include "hbtrack/util/stop_reason.hpp"

#include <ostream>

namespace hbtrack {

std::ostream& operator<<(std::ostream& out, StopReason reason) { return out << to_string(reason); }

}  // namespace hbtrack
