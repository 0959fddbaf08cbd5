// libFuzzer target: the MATLAB .mat reader (libmatio opens the file itself), sparse and dense,
// variable K (the name the seeds use).
#include "fuzz_support.hpp"
#include "hbtrack/io/mat_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = hbtrack::fuzz::write_input(data, size, ".mat");
  hbtrack::fuzz::read_or_refuse_in_one_line([&] { hbtrack::read_mat_variable_sparse(path, "K"); });
  hbtrack::fuzz::read_or_refuse_in_one_line([&] { hbtrack::read_mat_variable(path, "K"); });
  return 0;
}
