#include "h5_export.hpp"

#include <fcntl.h>
#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>

#include "cli_common.hpp"
#include "result_folder.hpp"

namespace hbtrack::cli {

namespace {

using nlohmann::json;

// An HDF5 identifier, closed by its own function when it goes.
class Handle {
 public:
  Handle(hid_t id, herr_t (*closer)(hid_t), const std::string& what) : id_(id), close_(closer) {
    if (id_ < 0) throw std::runtime_error("export: HDF5 could not create " + what);
  }
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(Handle&& other) noexcept : id_(other.id_), close_(other.close_) { other.id_ = -1; }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t get() const { return id_; }
  // Closes now; false when HDF5 reports a failure (closing the file flushes it: a full disk).
  bool close() {
    const herr_t closed = close_(id_);
    id_ = -1;
    return closed >= 0;
  }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("export: HDF5 could not write " + what);
}

// A dataset name from a column name: HDF5 takes any text but '/' (a path separator) and ".".
std::string dataset_name(const std::string& column) {
  std::string name = column;
  std::replace(name.begin(), name.end(), '/', '_');
  return name.empty() || name == "." ? "c_" + name : name;
}

// A unique name among `used` (a clash gets _2, _3, ...).
std::string unique_name(const std::string& wanted, std::set<std::string>& used) {
  std::string name = wanted;
  for (int k = 2; used.count(name); ++k) name = wanted + "_" + std::to_string(k);
  used.insert(name);
  return name;
}

// Doubles as a dataset of `rows` (1-D) or `rows` x `cols` (2-D, row-major) under `parent`.
void write_doubles(hid_t parent, const std::string& name, const std::vector<double>& data, hsize_t rows, hsize_t cols = 0) {
  const hsize_t dims[2] = {rows, cols};
  Handle space(H5Screate_simple(cols ? 2 : 1, dims, nullptr), H5Sclose, "the dataspace of " + name);
  Handle set(H5Dcreate2(parent, name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose, name);
  if (!data.empty()) check(H5Dwrite(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), name);
}

// A UTF-8 string type of fixed length, padded with NULs (readers strip them).
Handle string_type(size_t length) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "a string type");
  check(H5Tset_size(type.get(), std::max<size_t>(length, 1)), "a string type");
  check(H5Tset_strpad(type.get(), H5T_STR_NULLPAD), "a string type");
  check(H5Tset_cset(type.get(), H5T_CSET_UTF8), "a string type");
  return type;
}

// Strings as a dataset: a scalar for one, 1-D for `as_array`.
void write_strings(hid_t parent, const std::string& name, const std::vector<std::string>& texts, bool as_array) {
  size_t width = 1;
  for (const std::string& t : texts) width = std::max(width, t.size());
  std::string packed(width * texts.size(), '\0');
  for (size_t i = 0; i < texts.size(); ++i) std::copy(texts[i].begin(), texts[i].end(), packed.begin() + static_cast<long>(i * width));
  const Handle type = string_type(width);
  const hsize_t dims[1] = {texts.size()};
  Handle space(as_array ? H5Screate_simple(1, dims, nullptr) : H5Screate(H5S_SCALAR), H5Sclose, "the dataspace of " + name);
  Handle set(H5Dcreate2(parent, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose, name);
  if (!packed.empty()) check(H5Dwrite(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, packed.data()), name);
}

void string_attribute(hid_t object, const std::string& name, const std::string& text) {
  const Handle type = string_type(text.size());
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "the dataspace of " + name);
  Handle attribute(H5Acreate2(object, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose, "the attribute " + name);
  std::string padded = text;
  padded.resize(std::max<size_t>(text.size(), 1), '\0');
  check(H5Awrite(attribute.get(), type.get(), padded.data()), "the attribute " + name);
}

void integer_attribute(hid_t object, const std::string& name, long long value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "the dataspace of " + name);
  Handle attribute(H5Acreate2(object, name.c_str(), H5T_STD_I64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
                   "the attribute " + name);
  check(H5Awrite(attribute.get(), H5T_NATIVE_LLONG, &value), "the attribute " + name);
}

// One group per table: a dataset per column, the state columns x0, x1, ... as one matrix `x`.
void write_table(hid_t file, const std::string& name, const CsvTable& table) {
  Handle group(H5Gcreate2(file, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "the group " + name);
  const hsize_t rows = table.rows.size();
  std::set<std::string> used;
  std::vector<size_t> state_columns;
  for (size_t c = 0; c < table.header.size(); ++c) {
    if (table.header[c] == "x" + std::to_string(state_columns.size())) {
      state_columns.push_back(c);
      continue;
    }
    std::vector<double> column;
    column.reserve(rows);
    for (const auto& row : table.rows) column.push_back(row[c]);
    write_doubles(group.get(), unique_name(dataset_name(table.header[c]), used), column, rows);
  }
  if (state_columns.empty()) return;
  std::vector<double> x;
  x.reserve(rows * state_columns.size());
  for (const auto& row : table.rows)
    for (size_t c : state_columns) x.push_back(row[c]);
  write_doubles(group.get(), unique_name("x", used), x, rows, state_columns.size());
}

// The special points as columns: `type`, then every number of any entry (NaN where one lacks it).
void write_special_points(hid_t file, const json& points) {
  Handle group(H5Gcreate2(file, "special_points", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "the group special_points");
  std::vector<std::string> types, keys;
  for (const json& p : points) {
    types.push_back(p.value("type", ""));
    for (const auto& [key, value] : p.items())
      if ((value.is_number() || value.is_boolean()) && std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
  }
  std::set<std::string> used{"type"};
  write_strings(group.get(), "type", types, true);
  for (const std::string& key : keys) {
    std::vector<double> values;
    for (const json& p : points) {
      double v = std::numeric_limits<double>::quiet_NaN();
      if (p.contains(key) && p[key].is_boolean())
        v = p[key].get<bool>() ? 1.0 : 0.0;
      else if (p.contains(key) && p[key].is_number())
        v = p[key].get<double>();
      values.push_back(v);
    }
    write_doubles(group.get(), unique_name(dataset_name(key), used), values, values.size());
  }
}

// The HDF5 file being written, into a scratch file in the same folder removed unless committed.
class PendingH5File {
 public:
  PendingH5File(std::string temporary, std::string final_path)
      : temporary_(std::move(temporary)),
        final_(std::move(final_path)),
        file_(H5Fcreate(temporary_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose, temporary_) {}
  ~PendingH5File() {
    if (!committed_) {
      if (file_.get() >= 0) file_.close();
      std::error_code ignored;
      std::filesystem::remove(temporary_, ignored);
    }
  }
  PendingH5File(const PendingH5File&) = delete;
  PendingH5File& operator=(const PendingH5File&) = delete;
  hid_t get() const { return file_.get(); }
  // Closed (HDF5 flushes and reports a write that failed), synced, then renamed over the target:
  // a crash leaves the old file or the whole new one, never a partial one.
  void commit() {
    if (!file_.close()) throw std::runtime_error("export: could not finish " + temporary_ + " (disk full?)");
    const int fd = ::open(temporary_.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0 || (::fsync(fd) != 0 && errno != EINVAL)) {
      const int error = errno;
      if (fd >= 0) ::close(fd);
      throw std::runtime_error("export: " + temporary_ + ": fsync failed: " + std::strerror(error));
    }
    ::close(fd);
    if (::rename(temporary_.c_str(), final_.c_str()) != 0)
      throw std::runtime_error("export: " + temporary_ + ": cannot rename to " + final_ + ": " + std::strerror(errno));
    committed_ = true;
  }

 private:
  std::string temporary_, final_;
  Handle file_;
  bool committed_ = false;
};

}  // namespace

std::vector<std::string> export_result_folder_h5(const std::string& dir, const std::string& h5_path) {
  const ResultFolderContents contents = list_result_folder(dir);
  const json& summary = contents.summary;

  // HDF5's exit handler flushes files a failed write left open, and segfaulted doing so after a
  // full disk; the process is ending anyway. Must precede every other HDF5 call.
  H5dont_atexit();
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // our one-line errors, not HDF5's stack on stderr
  PendingH5File file(h5_path + ".tmp", h5_path);
  std::vector<std::string> written;
  for (const std::string& table : contents.tables) {
    const std::string name = dataset_name(std::filesystem::path(table).stem().string());
    write_table(file.get(), name, read_csv_table(table));
    written.push_back(name);
  }
  if (summary.contains("special_points") && summary["special_points"].is_array() && !summary["special_points"].empty()) {
    write_special_points(file.get(), summary["special_points"]);
    written.push_back("special_points");
  }
  write_strings(file.get(), "summary_json", {summary.dump()}, false);
  written.push_back("summary_json");
  for (const char* key : {"verb", "stop_reason"})
    if (summary.contains(key) && summary[key].is_string()) string_attribute(file.get(), key, summary[key].get<std::string>());
  if (summary.contains("points") && summary["points"].is_number_integer())
    integer_attribute(file.get(), "points", summary["points"].get<long long>());
  file.commit();
  return written;
}

}  // namespace hbtrack::cli
