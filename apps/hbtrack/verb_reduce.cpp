// `hbtrack reduce`: Craig-Bampton reduction of a full model (Matrix Market, .mat or CalculiX
// matrices) onto the translations of boundary nodes in their local cylindrical frames, plus
// fixed-interface modes. Formats and outputs: docs/reduction.md.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <cmath>
#include <map>
#include <optional>

#include "cli_common.hpp"
#include "hbtrack/io/calculix_input_nodes.hpp"
#include "hbtrack/io/calculix_reader.hpp"
#include "hbtrack/io/mat_file.hpp"
#include "hbtrack/io/matrix_market.hpp"
#include "hbtrack/model/craig_bampton.hpp"
#include "hbtrack/model/sparse_modes.hpp"
#include "hbtrack/results/results_writer.hpp"
#include "node_table.hpp"

namespace hbtrack::cli {

namespace {

using nlohmann::json;
using SparseMatrix = Eigen::SparseMatrix<double>;

struct ReduceOptions {
  std::string mass, stiffness, calculix, nodes, boundary_file, out_dir;
  std::vector<int> boundary;
  std::string axis = "x";             // x, y, z or "AX,AY,AZ": the rotation axis of the model
  std::string frame = "cylindrical";  // the boundary dofs' directions: cylindrical (r, t, z) or global (x, y, z)
  std::vector<double> axis_origin{0.0, 0.0, 0.0};
  int modes = 12;
  int compare = 6;
  bool rotating = false;    // also reduce Kg1.mtx, Mspin.mtx, G.mtx found beside --mass
  std::string check_speed;  // rad/s: compare the reduced and full models' frequencies at this speed
  bool quiet = false;
};

// The full model: matrices and, per row, the node and direction (0 x, 1 y, 2 z) it moves.
struct FullModel {
  SparseMatrix mass, stiffness;
  std::map<std::pair<int, int>, int> row_of;  // (node id, direction) -> row
};

// "file.mtx", or "file.mat:VARIABLE" for a variable of a MATLAB file.
SparseMatrix read_matrix_argument(const std::string& spec, const char* option) {
  const auto colon = spec.rfind(':');
  const bool mat_variable = colon != std::string::npos && colon > 4 && spec.compare(colon - 4, 4, ".mat") == 0;
  if (!mat_variable && spec.size() > 4 && spec.compare(spec.size() - 4, 4, ".mat") == 0)
    throw CaseError(std::string(option) + ": " + spec + ": name the variable, e.g. " + spec + ":K");
  try {
    if (mat_variable) return read_mat_variable_sparse(spec.substr(0, colon), spec.substr(colon + 1));
    return read_matrix_market_sparse(spec);
  } catch (const std::runtime_error& e) {
    throw CaseError(std::string(option) + ": " + e.what());
  }
}

// The rotating blade's matrices of `make-blade --rotating`, beside M.mtx.
struct RotatingFullModel {
  SparseMatrix geometric_stiffness, spin_softening, gyroscopic;
};

RotatingFullModel read_rotating_matrices(const ReduceOptions& o, Eigen::Index rows) {
  namespace fs = std::filesystem;
  if (!o.calculix.empty() || o.mass.find(".mat:") != std::string::npos)
    throw CaseError("--rotating: reads Kg1.mtx, Mspin.mtx and G.mtx beside --mass M.mtx (as make-blade --rotating writes them)");
  const fs::path folder = fs::path(o.mass).parent_path();
  auto read = [&](const char* name) {
    const std::string path = (folder / name).string();
    if (!fs::exists(path)) throw CaseError("--rotating: " + path + " not found (write it with make-blade --rotating)");
    SparseMatrix a = read_matrix_argument(path, "--rotating");
    if (a.rows() != rows || a.cols() != rows)
      throw CaseError("--rotating: " + path + " is " + std::to_string(a.rows()) + "x" + std::to_string(a.cols()) + ", K is " +
                      std::to_string(rows) + "x" + std::to_string(rows));
    return a;
  };
  return {read("Kg1.mtx"), read("Mspin.mtx"), read("G.mtx")};
}

FullModel read_full_model(const ReduceOptions& o, const std::vector<NodeRecord>& nodes) {
  FullModel model;
  if (!o.calculix.empty()) {
    CalculixMatrices c;
    try {
      c = read_calculix_matrices(o.calculix);
    } catch (const std::runtime_error& e) {
      throw CaseError(std::string("--calculix: ") + e.what());
    }
    model.mass = std::move(c.mass);
    model.stiffness = std::move(c.stiffness);
    for (size_t row = 0; row < c.dofs.size(); ++row)
      if (c.dofs[row].direction >= 1 && c.dofs[row].direction <= 3)
        model.row_of[{c.dofs[row].node, c.dofs[row].direction - 1}] = static_cast<int>(row);
    return model;
  }
  model.mass = read_matrix_argument(o.mass, "--mass");
  model.stiffness = read_matrix_argument(o.stiffness, "--stiffness");
  // Matrix files carry no dof names: rows follow nodes.csv, three translations per node.
  if (model.stiffness.rows() != 3 * static_cast<Eigen::Index>(nodes.size()))
    throw CaseError(o.nodes + ": lists " + std::to_string(nodes.size()) + " nodes, the matrices have " +
                    std::to_string(model.stiffness.rows()) + " rows (expected 3 per node, in the table's order)");
  for (size_t k = 0; k < nodes.size(); ++k)
    for (int d = 0; d < 3; ++d) model.row_of[{nodes[k].id, d}] = static_cast<int>(3 * k) + d;
  return model;
}

void check_square_pair(const FullModel& m) {
  const Eigen::Index n = m.stiffness.rows();
  if (m.stiffness.cols() != n || m.mass.rows() != n || m.mass.cols() != n)
    throw CaseError("reduce: M (" + std::to_string(m.mass.rows()) + "x" + std::to_string(m.mass.cols()) + ") and K (" + std::to_string(n) +
                    "x" + std::to_string(m.stiffness.cols()) + ") must be square and of the same size");
}

// "x", "y", "z" (either case) or three comma-separated numbers.
Eigen::Vector3d parse_axis(const std::string& text) {
  if (text == "x" || text == "X") return Eigen::Vector3d::UnitX();
  if (text == "y" || text == "Y") return Eigen::Vector3d::UnitY();
  if (text == "z" || text == "Z") return Eigen::Vector3d::UnitZ();
  Eigen::Vector3d v;
  char c1 = 0, c2 = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%lf %c %lf %c %lf %c", &v(0), &c1, &v(1), &c2, &v(2), &extra) != 5 || c1 != ',' || c2 != ',' ||
      !v.allFinite() || !(v.norm() > 0))
    throw CaseError("--axis: '" + text + "' must be x, y, z or a nonzero direction AX,AY,AZ");
  return v;
}

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The node coordinates: a node table, or the *NODE blocks of a CalculiX deck (--nodes JOB.inp,
// or JOB.inp found beside --calculix JOB's matrices).
std::vector<NodeRecord> read_nodes(const ReduceOptions& o) {
  std::string inp = ends_with(o.nodes, ".inp") ? o.nodes : "";
  if (o.nodes.empty()) {
    if (o.calculix.empty())
      throw CaseError("reduce: --nodes is required with --mass and --stiffness (a node table node,x,y,z or a CalculiX .inp)");
    inp = o.calculix + ".inp";
    if (!std::filesystem::exists(inp))
      throw CaseError("reduce: --nodes not given and " + inp + " not found: give the node table or the CalculiX deck with --nodes");
  }
  if (inp.empty()) return read_node_table(o.nodes);
  std::vector<CalculixNode> deck;
  try {
    deck = read_calculix_input_nodes(inp);
  } catch (const std::runtime_error& e) {
    throw CaseError(std::string("--nodes: ") + e.what());
  }
  std::vector<NodeRecord> nodes(deck.size());
  for (size_t k = 0; k < deck.size(); ++k) nodes[k] = {deck[k].id, deck[k].position};
  return nodes;
}

json to_json(const Eigen::VectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); }

// The names (1B, 2B, 1T) of the full model's lowest `count` modes when `make-blade` wrote its
// matrices: its summary.json beside them. `hbtrack modes` shows them beside the reduced model's.
json full_model_mode_types(const ReduceOptions& o, int count) {
  namespace fs = std::filesystem;
  const std::string matrices = o.calculix.empty() ? o.mass : o.calculix;
  std::ifstream in(fs::path(matrices).parent_path() / "summary.json");
  if (!in) return nullptr;
  const json blade = json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (!blade.is_object() || blade.value("verb", "") != "make-blade" || !blade.contains("mode_types") || !blade["mode_types"].is_array())
    return nullptr;
  json types = json::array();
  for (const json& t : blade["mode_types"])
    if (static_cast<int>(types.size()) < count) types.push_back(t);
  return types;
}

int run_reduce(const ReduceOptions& o) {
  const auto t0 = Clock::now();
  if (o.calculix.empty() == (o.mass.empty() && o.stiffness.empty()))
    throw CaseError("reduce: give either --mass and --stiffness, or --calculix JOBNAME");
  if (o.calculix.empty() && (o.mass.empty() || o.stiffness.empty())) throw CaseError("reduce: --mass and --stiffness go together");
  if (o.boundary.empty() == o.boundary_file.empty()) throw CaseError("reduce: give exactly one of --boundary and --boundary-file");
  if (o.modes < 0) throw CaseError("--modes: must be >= 0");
  const Eigen::Vector3d axis = parse_axis(o.axis);
  if (o.axis_origin.size() != 3) throw CaseError("--axis-origin: give three numbers X,Y,Z");
  const Eigen::Vector3d axis_origin(o.axis_origin[0], o.axis_origin[1], o.axis_origin[2]);
  if (!axis_origin.allFinite()) throw CaseError("--axis-origin: must be finite");

  if (o.frame != "cylindrical" && o.frame != "global") throw CaseError("--frame: '" + o.frame + "' must be cylindrical or global");
  const bool global_frame = o.frame == "global";
  const std::vector<NodeRecord> nodes = read_nodes(o);
  const std::string node_source = o.nodes.empty() ? o.calculix + ".inp" : o.nodes;
  const std::vector<int> boundary_ids = o.boundary.empty() ? read_node_list(o.boundary_file) : o.boundary;
  const FullModel full = read_full_model(o, nodes);
  check_square_pair(full);
  if (!o.check_speed.empty() && !o.rotating) throw CaseError("--check-speed: needs --rotating");
  const double check_speed = o.check_speed.empty() ? 0.0 : parse_number("--check-speed", o.check_speed);
  if (!(check_speed >= 0) || !std::isfinite(check_speed))
    throw CaseError("--check-speed: must be >= 0 (rad/s), got '" + o.check_speed + "'");
  std::optional<RotatingFullModel> rotating;
  if (o.rotating) rotating = read_rotating_matrices(o, full.stiffness.rows());
  const double read_s = seconds_since(t0);

  std::map<int, const NodeRecord*> node_by_id;
  for (const NodeRecord& n : nodes) node_by_id[n.id] = &n;
  std::vector<CraigBamptonBoundaryNode> boundary;
  std::vector<NodeRecord> boundary_records;
  std::vector<CylindricalFrame> frames;
  for (int id : boundary_ids) {
    const auto found = node_by_id.find(id);
    if (found == node_by_id.end()) throw CaseError(node_source + ": boundary node " + std::to_string(id) + " is not in the node table");
    CraigBamptonBoundaryNode b;
    for (int d = 0; d < 3; ++d) {
      const auto row = full.row_of.find({id, d});
      if (row == full.row_of.end())
        throw CaseError("reduce: boundary node " + std::to_string(id) + " has no free " + "xyz"[d] + " translation in the matrices");
      b.dofs[static_cast<size_t>(d)] = row->second;
    }
    if (!global_frame) {
      try {
        frames.push_back(cylindrical_frame(found->second->position, axis_origin, axis));
      } catch (const std::invalid_argument& e) {
        throw CaseError("reduce: boundary node " + std::to_string(id) + ": " + e.what());
      }
      b.frame = frames.back().directions;
    }
    boundary.push_back(b);
    boundary_records.push_back(*found->second);
  }

  const auto t_reduce = Clock::now();
  CraigBamptonModel rom;
  try {
    rom = craig_bampton(full.mass, full.stiffness, boundary, o.modes);
  } catch (const std::invalid_argument& e) {
    throw CaseError(std::string("reduce: ") + e.what());
  } catch (const std::runtime_error& e) {
    throw RunFailed{std::string("reduce: ") + e.what()};
  }
  const double reduce_s = seconds_since(t_reduce);
  if (global_frame) rom.dof_names = craig_bampton_dof_names(static_cast<int>(boundary.size()), o.modes, {"_x", "_y", "_z"});

  const NormalModes reduced_modes = normal_modes(rom.mass, rom.stiffness);
  const auto t_full = Clock::now();
  const int compare =
      static_cast<int>(std::min<Eigen::Index>({Eigen::Index{o.compare}, reduced_modes.frequencies.size(), full.stiffness.rows()}));
  Eigen::VectorXd full_frequencies;
  if (compare > 0) {
    try {
      full_frequencies = lowest_sparse_modes(full.stiffness, full.mass, compare).frequencies;
    } catch (const std::runtime_error& e) {
      throw RunFailed{std::string("reduce: full-model modes: ") + e.what()};
    }
  }
  const double full_modes_s = seconds_since(t_full);

  // The rotating matrices on the basis at rest; with --check-speed, the reduced model's modes at
  // that speed against the full model's (K(Omega) without G: what the basis must hold).
  json at_speed = nullptr;
  Eigen::MatrixXd rom_geometric, rom_spin, rom_gyroscopic;
  if (rotating) {
    rom_geometric = craig_bampton_project(rom, rotating->geometric_stiffness);
    rom_spin = craig_bampton_project(rom, rotating->spin_softening);
    rom_gyroscopic = craig_bampton_project(rom, rotating->gyroscopic);
    if (!o.check_speed.empty() && compare > 0) {
      const double s2 = check_speed * check_speed;
      Eigen::VectorXd full_at_speed, reduced_at_speed;
      try {
        full_at_speed = lowest_sparse_modes(SparseMatrix(full.stiffness + s2 * (rotating->geometric_stiffness - rotating->spin_softening)),
                                            full.mass, compare)
                            .frequencies;
        reduced_at_speed = normal_modes(rom.mass, rom.stiffness + s2 * (rom_geometric - rom_spin)).frequencies.head(compare);
      } catch (const std::exception& e) {
        throw RunFailed{std::string("reduce: modes at --check-speed: ") + e.what()};
      }
      json difference = json::array();
      for (int r = 0; r < compare; ++r) difference.push_back(reduced_at_speed(r) / full_at_speed(r) - 1.0);
      at_speed = {{"speed", check_speed},
                  {"full_model_frequencies", to_json(full_at_speed)},
                  {"reduced_frequencies", to_json(reduced_at_speed)},
                  {"relative_difference_of_reduced", difference}};
    }
  }

  ensure_directory(o.out_dir);
  if (rotating) {
    write_matrix_market(o.out_dir + "/Kg1.mtx", rom_geometric.sparseView());
    write_matrix_market(o.out_dir + "/Mspin.mtx", rom_spin.sparseView());
    write_matrix_market(o.out_dir + "/G.mtx", rom_gyroscopic.sparseView());
  }
  write_matrix_market(o.out_dir + "/M.mtx", rom.mass.sparseView());
  write_matrix_market(o.out_dir + "/K.mtx", rom.stiffness.sparseView());
  write_matrix_market(o.out_dir + "/T.mtx", rom.transformation.sparseView());
  if (global_frame)
    write_node_table(o.out_dir + "/boundary_nodes.csv", boundary_records);
  else
    write_boundary_nodes(o.out_dir + "/boundary_nodes.csv", boundary_records, frames);

  json errors = json::array();
  for (int r = 0; r < compare; ++r) errors.push_back(reduced_modes.frequencies(r) / full_frequencies(r) - 1.0);
  json summary = {
      {"verb", "reduce"},
      {"inputs", o.calculix.empty() ? json{{"mass", o.mass}, {"stiffness", o.stiffness}, {"nodes", node_source}}
                                    : json{{"calculix", o.calculix}, {"nodes", node_source}}},
      {"frame", o.frame},
      {"sizes",
       {{"full_dofs", full.stiffness.rows()},
        {"boundary_nodes", boundary.size()},
        {"boundary_dofs", 3 * boundary.size()},
        {"fixed_interface_modes", o.modes},
        {"reduced_dofs", rom.mass.rows()}}},
      {"boundary_node_ids", boundary_ids},
      {"rotation_axis",
       global_frame ? json(nullptr)
                    : json{{"origin", {axis_origin.x(), axis_origin.y(), axis_origin.z()}}, {"direction", {axis.x(), axis.y(), axis.z()}}}},
      {"dof_names", rom.dof_names},
      {"natural_frequencies", to_json(reduced_modes.frequencies)},
      {"fixed_interface_frequencies", to_json(rom.fixed_interface_frequencies)},
      {"full_model",
       {{"natural_frequencies", to_json(full_frequencies)},
        {"relative_difference_of_reduced", errors},
        {"mode_types", full_model_mode_types(o, compare)}}},
      {"rotation", rotating ? json{{"files", {{"Kg1", "Kg1.mtx"}, {"Mspin", "Mspin.mtx"}, {"G", "G.mtx"}}},
                                   {"basis", "the Craig-Bampton basis at rest"},
                                   {"check_at_speed", at_speed}}
                            : json(nullptr)},
      {"timings", {{"wall_s", seconds_since(t0)}, {"read_s", read_s}, {"reduction_s", reduce_s}, {"full_modes_s", full_modes_s}}}};
  write_json_atomically(o.out_dir + "/summary.json", summary);
  if (!o.quiet) {
    std::fprintf(stderr, "reduce: %lld -> %lld dofs (%zu boundary nodes, %d modes) in %.2f s -> %s\n",
                 static_cast<long long>(full.stiffness.rows()), static_cast<long long>(rom.mass.rows()), boundary.size(), o.modes,
                 seconds_since(t0), o.out_dir.c_str());
    for (int r = 0; r < compare; ++r)
      std::fprintf(stderr, "  mode %d: full %.2f rad/s, reduced %.2f rad/s (%+.3f %%)\n", r + 1, full_frequencies(r),
                   reduced_modes.frequencies(r), 100.0 * errors[static_cast<size_t>(r)].get<double>());
    if (!at_speed.is_null())
      for (int r = 0; r < compare; ++r)
        std::fprintf(stderr, "  at %.1f rad/s, mode %d: full %.2f rad/s, reduced %.2f rad/s (%+.3f %%)\n", check_speed, r + 1,
                     at_speed["full_model_frequencies"][static_cast<size_t>(r)].get<double>(),
                     at_speed["reduced_frequencies"][static_cast<size_t>(r)].get<double>(),
                     100.0 * at_speed["relative_difference_of_reduced"][static_cast<size_t>(r)].get<double>());
  }
  return 0;
}

void add_reduce_verbs(CLI::App& app, VerbList& verbs) {
  static ReduceOptions options;
  CLI::App* reduce = app.add_subcommand("reduce", "Craig-Bampton reduction onto boundary nodes (local r, t, z) and fixed-interface modes");
  reduce->add_option("--mass", options.mass, "mass matrix: M.mtx (Matrix Market) or model.mat:M (MATLAB variable)");
  reduce->add_option("--stiffness", options.stiffness, "stiffness matrix: K.mtx or model.mat:K");
  reduce->add_option("--calculix", options.calculix, "CalculiX matrix storage: reads JOBNAME.sti, JOBNAME.mas, JOBNAME.dof");
  reduce->add_option("--nodes", options.nodes,
                     "node table node,x,y,z (for matrix files: rows 3k..3k+2 are node k's x, y, z) or a CalculiX deck FILE.inp "
                     "(its *NODE blocks); with --calculix JOB, JOB.inp when omitted");
  reduce->add_option("--boundary", options.boundary, "boundary node ids, in order (n1, n2, ...)")->delimiter(',');
  reduce->add_option("--boundary-file", options.boundary_file, "file of boundary node ids, in order");
  reduce->add_option("--axis", options.axis,
                     "rotation axis of the model, for the boundary nodes' (r, t, z) frames: x, y, z or AX,AY,AZ (default x)");
  reduce->add_option(
      "--frame", options.frame,
      "directions of the boundary dofs: cylindrical (n1_r, n1_t, n1_z about --axis, the default) or global (n1_x, n1_y, n1_z)");
  reduce->add_option("--axis-origin", options.axis_origin, "a point of the rotation axis X,Y,Z (default 0,0,0)")
      ->delimiter(',')
      ->expected(3);
  reduce->add_option("--modes", options.modes, "fixed-interface modes kept (default 12)");
  reduce->add_option("--compare", options.compare, "full-model modes computed to check the reduced model (default 6)");
  reduce->add_option("-o,--output", options.out_dir, "output folder (created if missing)")->required();
  reduce->add_flag("--rotating", options.rotating,
                   "also reduce the rotating blade's Kg1.mtx, Mspin.mtx and G.mtx (make-blade --rotating) found beside --mass, on the "
                   "same basis");
  reduce->add_option("--check-speed", options.check_speed,
                     "with --rotating: compare the reduced and full models' frequencies at this speed (rad/s), K + W^2 (Kg1 - Mspin)");
  reduce->add_flag("-q,--quiet", options.quiet, "no closing report");
  verbs.push_back({reduce, [] { return run_reduce(options); }});
}

const VerbRegistrar reduce_registrar(add_reduce_verbs);

}  // namespace

}  // namespace hbtrack::cli
