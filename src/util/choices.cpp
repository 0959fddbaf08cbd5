#include "hbtrack/util/choices.hpp"

#include <stdexcept>

namespace hbtrack {

void throw_unknown_choice(std::string_view field, std::span<const std::string_view> names, const std::string& name) {
  std::string listed;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) listed += i + 1 == names.size() ? " or " : ", ";
    listed += names[i];
  }
  throw std::invalid_argument(std::string(field) + ": must be " + listed + ", got '" + name + "'");
}

}  // namespace hbtrack
