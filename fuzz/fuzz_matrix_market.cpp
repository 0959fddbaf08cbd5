// libFuzzer target: the Matrix Market reader, sparse and dense.
#include "fuzz_support.hpp"
#include "hbtrack/io/matrix_market.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = hbtrack::fuzz::write_input(data, size, ".mtx");
  hbtrack::fuzz::read_or_refuse_in_one_line([&] { hbtrack::read_matrix_market_sparse(path); });
  hbtrack::fuzz::read_or_refuse_in_one_line([&] { hbtrack::read_matrix_market(path); });
  return 0;
}
