#pragma once
// FNV-1a, 64 bits: the fingerprints by which a resumed run or study recognises the case or model
// it continues (not a cryptographic hash: it tells an edit from none, not an attack).
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace hbtrack {

class Fnv1a {
 public:
  void bytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) hash_ = (hash_ ^ p[i]) * 1099511628211ull;
  }
  void bytes(std::string_view text) { bytes(text.data(), text.size()); }
  std::uint64_t value() const { return hash_; }
  // 16 lowercase hex digits, as summary.json and the checkpoints write it.
  std::string hex() const {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash_));
    return text;
  }

 private:
  std::uint64_t hash_ = 14695981039346656037ull;
};

}  // namespace hbtrack
