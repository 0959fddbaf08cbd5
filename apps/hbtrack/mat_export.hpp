#pragma once
// A result folder as one MATLAB .mat file (v5, readable by MATLAB, Octave and scipy.io.loadmat),
// for users who read results in MATLAB: `hbtrack export DIR`.
#include <string>
#include <vector>

namespace hbtrack::cli {

// A MATLAB identifier from a column name: letters, digits and '_' (others become '_'), a
// letter first ("c_" is put before anything else), at most 63 characters.
std::string matlab_name(const std::string& column);

// Writes every table of `dir` (branch.csv, states.csv, stability.csv, special_states.csv and
// any other *.csv) as a struct named after the file, one field per column (a column vector),
// the columns x0, x1, ... of a state table gathered in one matrix field `x`; `special_points`
// as a struct array (type, and every number of summary.json's entries, NaN where one lacks
// it); and summary.json itself as the string `summary_json`. Written to a temporary file and
// renamed into place: `mat_path` is complete or absent. Returns the variable names.
std::vector<std::string> export_result_folder(const std::string& dir, const std::string& mat_path);

}  // namespace hbtrack::cli
