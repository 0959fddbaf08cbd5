// libFuzzer target: the CalculiX readers; the same input is read as a matrix (.sti/.mas), as a
// dof map (.dof) and as an input deck's nodes (.inp).
#include "fuzz_support.hpp"
#include "hbtrack/io/calculix_input_nodes.hpp"
#include "hbtrack/io/calculix_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = hbtrack::fuzz::write_input(data, size, ".sti");
  hbtrack::fuzz::read_or_refuse_in_one_line([&] { hbtrack::read_calculix_matrix(path); });
  hbtrack::fuzz::read_or_refuse_in_one_line([&] { hbtrack::read_calculix_dof_map(path); });
  hbtrack::fuzz::read_or_refuse_in_one_line([&] { hbtrack::read_calculix_input_nodes(path); });
  return 0;
}
