#pragma once
// UTF-8 well-formedness (RFC 3629: no overlong forms, no surrogates, nothing above U+10FFFF).
#include <cstddef>
#include <string_view>

namespace hbtrack {

// The offset of the first byte that starts no well-formed UTF-8 sequence, or npos.
std::size_t first_invalid_utf8(std::string_view text);

}  // namespace hbtrack
