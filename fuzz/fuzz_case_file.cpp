// libFuzzer target: the TOML case-file reader. Any input must load or be refused with CaseError
// (a std::runtime_error) in one line.
#include "fuzz_support.hpp"
#include "hbtrack/io/case_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = hbtrack::fuzz::write_input(data, size, ".toml");
  hbtrack::fuzz::read_or_refuse_in_one_line([&] { hbtrack::load_case(path); });
  return 0;
}
