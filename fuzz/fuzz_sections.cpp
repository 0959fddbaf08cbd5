// libFuzzer target: the blade section table reader (make-blade --geometry), and the blade built
// from a table it accepts, as make-blade builds it: the geometry's checks (the rotation sense, the
// splines, the mesh) refuse with std::invalid_argument, which make-blade reports in one line as
// bad input, so it must be one line too. The meshing is bounded by the table (at most 100
// surfaces; max_len 4096 keeps inputs to a few hundred rows).
#include <stdexcept>

#include "fuzz_support.hpp"
#include "hbtrack/io/blade_sections_reader.hpp"
#include "hbtrack/model/section_blade.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = hbtrack::fuzz::write_input(data, size, ".csv");
  hbtrack::fuzz::read_or_refuse_in_one_line([&] {
    const hbtrack::BladeSections sections = hbtrack::read_blade_sections(path);
    try {
      hbtrack::generate_section_blade(sections, hbtrack::SectionBladeOptions{});
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(e.what());
    }
  });
  return 0;
}
