#include "mat_export.hpp"

#include <matio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>

#include "cli_common.hpp"
#include "hbtrack/io/mat_header_check.hpp"
#include "hbtrack/results/results_writer.hpp"
#include "result_folder.hpp"

namespace hbtrack::cli {

namespace {

using nlohmann::json;

// libmatio frees a struct's fields with the struct; a variable not yet handed over is ours.
struct VarDeleter {
  void operator()(matvar_t* v) const { Mat_VarFree(v); }
};
using Var = std::unique_ptr<matvar_t, VarDeleter>;

// Both copied by libmatio (no MAT_F_DONT_COPY_DATA): the arguments may go. A field has no name.
Var double_matrix(const std::vector<double>& column_major, size_t rows, size_t cols) {
  size_t dims[2] = {rows, cols};
  return Var(Mat_VarCreate(nullptr, MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, const_cast<double*>(column_major.data()), 0));
}

Var char_row(const std::string& text, const char* name = nullptr) {
  size_t dims[2] = {1, text.size()};
  return Var(Mat_VarCreate(name, MAT_C_CHAR, MAT_T_UTF8, 2, dims, const_cast<char*>(text.data()), 0));
}

// The variables libmatio finds in a .mat file (-1 when it cannot open it).
int variables_in(const std::string& path) {
  mat_t* file = Mat_Open(path.c_str(), MAT_ACC_RDONLY);
  if (!file) return -1;
  int count = 0;
  for (matvar_t* v; (v = Mat_VarReadNextInfo(file)) != nullptr; ++count) Mat_VarFree(v);
  Mat_Close(file);
  return count;
}

// The .mat file being written, into a scratch file always removed at the end.
class PendingMatFile {
 public:
  PendingMatFile(std::string temporary, std::string final_path) : temporary_(std::move(temporary)), final_(std::move(final_path)) {
    file_ = Mat_CreateVer(temporary_.c_str(), nullptr, MAT_FT_MAT5);
    if (!file_) throw std::runtime_error("export: cannot create " + temporary_);
  }
  ~PendingMatFile() {
    if (file_) Mat_Close(file_);
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
  }
  PendingMatFile(const PendingMatFile&) = delete;
  PendingMatFile& operator=(const PendingMatFile&) = delete;
  void write(const Var& v, const std::string& name) {
    if (!v || Mat_VarWrite(file_, v.get(), MAT_COMPRESSION_NONE) != 0)
      throw std::runtime_error("export: could not write " + name + " into " + temporary_);
    ++written_;
  }
  void commit() {
    const int closed = Mat_Close(file_);
    file_ = nullptr;
    if (closed != 0) throw std::runtime_error("export: could not finish " + temporary_);
    // libmatio does not check its writes: a full disk or a file-size limit left a truncated file
    // that it reported written. Read back, every variable must be whole.
    try {
      check_mat_headers(temporary_);
    } catch (const std::runtime_error&) {
      throw std::runtime_error("export: " + temporary_ + " was not written whole (disk full or file-size limit?)");
    }
    if (variables_in(temporary_) != written_)
      throw std::runtime_error("export: " + temporary_ + " was not written whole (disk full or file-size limit?)");
    // libmatio writes through stdio without a check at each write: the finished bytes go into
    // place by the checked, synced write of every result file (a full disk fails here).
    std::ifstream in(temporary_, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    write_file_atomically(final_, bytes);
  }

 private:
  std::string temporary_, final_;
  mat_t* file_ = nullptr;
  int written_ = 0;
};

// A struct (1 x count) with these field names, each element's fields given by `field(i, name)`.
Var struct_of(const std::string& name, const std::vector<std::string>& fields, size_t count,
              const std::function<Var(size_t, const std::string&)>& field) {
  std::vector<const char*> names;
  for (const std::string& f : fields) names.push_back(f.c_str());
  size_t dims[2] = {1, count};
  Var s(Mat_VarCreateStruct(name.c_str(), 2, dims, names.data(), static_cast<unsigned>(names.size())));
  if (!s) throw std::runtime_error("export: libmatio could not create the struct " + name);
  for (size_t i = 0; i < count; ++i)
    for (const std::string& f : fields) {
      Var value = field(i, f);
      if (!value) throw std::runtime_error("export: libmatio could not create " + name + "." + f);
      Mat_VarSetStructFieldByName(s.get(), f.c_str(), i, value.release());  // the struct owns it now
    }
  return s;
}

// Field names for a table's columns, unique (a clash gets _2, _3, ...); x0, x1, ... of a state
// table become one field x.
struct TableLayout {
  std::vector<std::string> fields;
  std::vector<std::vector<int>> columns;  // of each field
};

TableLayout layout_of(const std::vector<std::string>& header) {
  TableLayout layout;
  std::set<std::string> used;
  std::vector<int> state_columns;
  for (size_t c = 0; c < header.size(); ++c) {
    const std::string& h = header[c];
    if (h == "x" + std::to_string(state_columns.size())) {
      state_columns.push_back(static_cast<int>(c));
      continue;
    }
    std::string name = matlab_name(h);
    for (int k = 2; used.count(name); ++k) name = matlab_name(h + "_" + std::to_string(k));
    used.insert(name);
    layout.fields.push_back(name);
    layout.columns.push_back({static_cast<int>(c)});
  }
  if (!state_columns.empty()) {
    std::string name = "x";
    for (int k = 2; used.count(name); ++k) name = "x_" + std::to_string(k);
    layout.fields.push_back(name);
    layout.columns.push_back(state_columns);
  }
  return layout;
}

Var table_struct(const std::string& name, const CsvTable& table) {
  const TableLayout layout = layout_of(table.header);
  const size_t rows = table.rows.size();
  return struct_of(name, layout.fields, 1, [&](size_t, const std::string& field) {
    const auto at = std::find(layout.fields.begin(), layout.fields.end(), field) - layout.fields.begin();
    const std::vector<int>& cols = layout.columns[static_cast<size_t>(at)];
    std::vector<double> data;
    data.reserve(rows * cols.size());
    for (int c : cols)
      for (const auto& row : table.rows) data.push_back(row[static_cast<size_t>(c)]);
    return double_matrix(data, rows, cols.size());
  });
}

Var special_points_struct(const json& points) {
  std::vector<std::string> numbers;  // every numeric key, in first-seen order
  for (const json& p : points)
    for (const auto& [key, value] : p.items())
      if ((value.is_number() || value.is_boolean()) && std::find(numbers.begin(), numbers.end(), key) == numbers.end())
        numbers.push_back(key);
  std::vector<std::string> fields{"type"};
  std::map<std::string, std::string> key_of;
  for (const std::string& k : numbers) {
    std::string name = matlab_name(k);
    while (std::find(fields.begin(), fields.end(), name) != fields.end()) name += "_";
    fields.push_back(name);
    key_of[name] = k;
  }
  return struct_of("special_points", fields, points.size(), [&](size_t i, const std::string& field) {
    const json& p = points[i];
    if (field == "type") return char_row(p.value("type", ""));
    const std::string& key = key_of[field];
    double v = std::numeric_limits<double>::quiet_NaN();
    if (p.contains(key) && p[key].is_boolean())
      v = p[key].get<bool>() ? 1.0 : 0.0;
    else if (p.contains(key) && p[key].is_number())
      v = p[key].get<double>();
    return double_matrix({v}, 1, 1);
  });
}

}  // namespace

std::string matlab_name(const std::string& column) {
  std::string name;
  for (char c : column) name += std::isalnum(static_cast<unsigned char>(c)) || c == '_' ? c : '_';
  if (name.empty() || !std::isalpha(static_cast<unsigned char>(name[0]))) name = "c_" + name;
  return name.substr(0, 63);
}

std::vector<std::string> export_result_folder(const std::string& dir, const std::string& mat_path) {
  const ResultFolderContents contents = list_result_folder(dir);
  const json& summary = contents.summary;

  PendingMatFile file(mat_path + ".matio", mat_path);
  std::vector<std::string> written;
  for (const std::string& table : contents.tables) {
    const std::string name = matlab_name(std::filesystem::path(table).stem().string());
    file.write(table_struct(name, read_csv_table(table)), name);
    written.push_back(name);
  }
  if (summary.contains("special_points") && summary["special_points"].is_array() && !summary["special_points"].empty()) {
    file.write(special_points_struct(summary["special_points"]), "special_points");
    written.push_back("special_points");
  }
  file.write(char_row(summary.dump(), "summary_json"), "summary_json");
  written.push_back("summary_json");
  file.commit();
  return written;
}

}  // namespace hbtrack::cli
