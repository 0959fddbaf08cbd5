#pragma once
// A result folder as one HDF5 file, for users who read results with h5py, MATLAB's h5read,
// Julia or ParaView: `hbtrack export DIR --format h5`. The same content as the .mat file
// (mat_export.hpp), laid out the HDF5 way.
#include <string>
#include <vector>

namespace hbtrack::cli {

// Writes every table of `dir` (branch.csv, states.csv, ... any *.csv) as a group named after the
// file holding one 1-D double dataset per column, named as the column ('/' becomes '_'), the
// columns x0, x1, ... of a state table gathered in one 2-D dataset `x` (rows x unknowns);
// `special_points` as a group with a string dataset `type` and one double dataset per number
// of summary.json's entries (NaN where one lacks it); and summary.json itself as the string
// dataset `summary_json`, with the root attributes `verb`, `stop_reason` and `points` where the
// summary has them. Written to a temporary file in the same folder, synced and renamed into
// place: `h5_path` is complete or absent. Returns the top-level names written.
std::vector<std::string> export_result_folder_h5(const std::string& dir, const std::string& h5_path);

}  // namespace hbtrack::cli
