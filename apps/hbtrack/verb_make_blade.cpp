// `hbtrack make-blade`: a fan blade as a full finite-element model, ready for `hbtrack reduce`:
// M.mtx, K.mtx, nodes.csv, boundary.txt and a summary with its lowest modes named (1B, 2B, 1T,
// ...). Either the parametric plate (hbtrack/model/blade_generator.hpp) or, with --geometry, a
// blade meshed from published stream-surface sections (data/rotor67/sections.csv: NASA rotor 67).
// With --calculix also the same mesh as a CalculiX deck, blade.inp; with --rotating also the
// matrices of rotation about X (Kg1.mtx, Mspin.mtx, G.mtx: hbtrack/model/rotating_matrices.hpp).
#include <chrono>
#include <csignal>
#include <cstdio>
#include <optional>

#include "cli_common.hpp"
#include "hbtrack/io/blade_sections_reader.hpp"
#include "hbtrack/io/matrix_market.hpp"
#include "hbtrack/model/blade_generator.hpp"
#include "hbtrack/model/blade_mode_classifier.hpp"
#include "hbtrack/model/calculix_deck.hpp"
#include "hbtrack/model/rotating_matrices.hpp"
#include "hbtrack/model/section_blade.hpp"
#include "hbtrack/model/sparse_modes.hpp"
#include "hbtrack/results/results_writer.hpp"
#include "node_table.hpp"
#include "result_folder.hpp"

namespace hbtrack::cli {

namespace {

using nlohmann::json;

// The paper's first bending, second bending and first torsion frequencies of rotor 67 (rad/s).
constexpr double kPaperFrequencies[] = {2039.78, 6343.69, 10745.26};

struct MakeBladeOptions {
  std::string out_dir;
  std::string geometry;  // a section table; empty: the parametric blade
  int refinement = 1;
  std::string rim_depth;  // m; empty: the section blade's default
  int modes = 6;
  bool calculix = false;  // also write blade.inp
  bool rotating = false;  // also write Kg1.mtx, Mspin.mtx, G.mtx
  bool quiet = false;
};

json material_json(const IsotropicMaterial& m) {
  return {{"youngs_modulus", m.youngs_modulus}, {"poisson_ratio", m.poisson_ratio}, {"density", m.density}};
}

json parametric_geometry_json(const BladeGeometry& g) {
  json j = {{"kind", "parametric"},
            {"hub_radius", g.hub_radius},
            {"tip_radius", g.tip_radius},
            {"root_chord", g.root_chord},
            {"tip_chord", g.tip_chord},
            {"root_thickness", g.root_thickness},
            {"tip_thickness", g.tip_thickness},
            {"root_stagger_deg", g.root_stagger_deg},
            {"tip_stagger_deg", g.tip_stagger_deg},
            {"camber", g.camber}};
  j.update(material_json(g.material));
  return j;
}

json section_geometry_json(const std::string& path, const SectionBladeOptions& o, const SectionBlade& blade) {
  json j = {{"kind", "sections"},
            {"sections", path},
            {"tip_clearance_m", o.shape.tip_clearance},
            {"minimum_thickness_m", o.shape.minimum_thickness},
            {"rim_depth_m", o.rim_depth},
            {"rim_layers", blade.rim_layers},
            // The blade moves towards +theta (sense +1) or -theta (-1) of the tip frames: the
            // case's tip_contact elements take engine_order = sense (eqs 47-48's rho * Omega).
            {"rotation_sense", blade.rotation.sense},
            {"leading_edge_lead_m", blade.rotation.leading_edge_lead},
            {"pressure_side", blade.rotation.pressure_side}};
  j.update(material_json(o.material));
  return j;
}

int run_make_blade(const MakeBladeOptions& o) {
  const auto t0 = Clock::now();
  // Nothing to save part-way (each file is written whole at the end): Ctrl-C or SIGTERM end the
  // meshing and the eigensolver at once instead of being noted for a continuation that never asks.
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  if (o.refinement < 1 || o.refinement > 16) throw CaseError("--refine: must be in 1..16");
  if (o.modes < 3) throw CaseError("--modes: must be >= 3");
  json geometry;
  // Held by value: BladeMesh has no virtual destructor, so neither blade is owned through it.
  std::optional<BladeModel> parametric_blade;
  std::optional<SectionBlade> section_blade;
  const BladeMesh* blade = nullptr;
  IsotropicMaterial material;
  if (o.geometry.empty()) {
    if (!o.rim_depth.empty()) throw CaseError("--rim-depth: only with --geometry (the parametric blade is clamped at its root)");
    const BladeGeometry parametric;
    parametric_blade.emplace(generate_blade(parametric, o.refinement));
    blade = &*parametric_blade;
    geometry = parametric_geometry_json(parametric);
    material = parametric.material;
  } else {
    SectionBladeOptions options;
    options.refinement = o.refinement;
    if (!o.rim_depth.empty()) {
      options.rim_depth = parse_number("--rim-depth", o.rim_depth);
      if (options.rim_depth < 0) throw CaseError("--rim-depth: must be >= 0 (m), got '" + o.rim_depth + "'");
    }
    const BladeSections sections = read_blade_sections(o.geometry);
    try {
      section_blade.emplace(generate_section_blade(sections, options));
    } catch (const std::invalid_argument& e) {
      throw CaseError(o.geometry + ": " + e.what());  // the table's geometry or the flags: bad input
    }
    blade = &*section_blade;
    geometry = section_geometry_json(o.geometry, options, *section_blade);
    material = options.material;
  }
  const AssembledMatrices matrices = assemble_blade(*blade);
  NormalModes modes;
  try {
    modes = lowest_sparse_modes(matrices.stiffness, matrices.mass, o.modes);
  } catch (const std::runtime_error& e) {
    throw RunFailed{std::string("make-blade: ") + e.what()};
  }

  // Node ids are mesh indices + 1; nodes.csv lists the free nodes in matrix row order.
  std::vector<NodeRecord> free_nodes;
  for (int node : blade->dofs.free_nodes()) free_nodes.push_back({node + 1, blade->grid.mesh().nodes[static_cast<size_t>(node)]});
  std::vector<int> boundary_ids;
  for (int node : blade->tip_nodes) boundary_ids.push_back(node + 1);

  ensure_directory(o.out_dir);
  write_matrix_market(o.out_dir + "/M.mtx", matrices.mass);
  write_matrix_market(o.out_dir + "/K.mtx", matrices.stiffness);
  write_node_table(o.out_dir + "/nodes.csv", free_nodes);
  write_node_list(o.out_dir + "/boundary.txt", boundary_ids, "tip nodes at mid-thickness, leading edge (n1) to trailing edge (n9)");
  json rotation = nullptr;
  if (o.rotating) {
    // The generated blades turn about X through the origin (blade_mesh.hpp), in the sense in which
    // their leading edge leads: G (the only matrix the sense changes) is built for it, so that a
    // positive [rotation] speed turns the blade the way it runs.
    const int sense = blade_rotation_sense(*blade);
    RotationAxis axis;
    axis.direction = Eigen::Vector3d(sense, 0.0, 0.0);
    RotatingMatrices r;
    try {
      r = assemble_rotating_hex20(blade->grid.mesh(), material, blade->dofs, matrices.stiffness, axis);
    } catch (const std::runtime_error& e) {
      throw RunFailed{std::string("make-blade: ") + e.what()};
    }
    write_matrix_market(o.out_dir + "/Kg1.mtx", r.geometric_stiffness);
    write_matrix_market(o.out_dir + "/Mspin.mtx", r.spin_softening);
    write_matrix_market(o.out_dir + "/G.mtx", r.gyroscopic);
    rotation = {
        {"axis_origin", {0.0, 0.0, 0.0}},
        {"axis_direction", {double(sense), 0.0, 0.0}},
        {"sense", "the blade's: its leading edge leads (rotation_sense); G is built for it"},
        {"files", {{"Kg1", "Kg1.mtx"}, {"Mspin", "Mspin.mtx"}, {"G", "G.mtx"}}},
        {"prestress", "linear: K(Omega) = K + Omega^2 (Kg1 - Mspin), Kg1 the stress stiffness of K u1 = f1 (centrifugal load at 1 rad/s)"},
        {"max_static_displacement_at_1_rad_s", r.static_displacement.cwiseAbs().maxCoeff()}};
  }
  if (o.calculix) {
    std::vector<int> clamped;
    for (int n = 0; n < blade->grid.mesh().node_count(); ++n)
      if (blade->dofs.dof(n, 0) < 0) clamped.push_back(n);
    write_file_atomically(o.out_dir + "/blade.inp", calculix_deck(blade->grid.mesh(), clamped, material, kCalculixMatrixStorageStep));
  }

  json frequencies = json::array(), types = json::array(), paper = json::array(), tip_radii = json::array();
  for (Eigen::Index r = 0; r < modes.frequencies.size(); ++r) {
    frequencies.push_back(modes.frequencies(r));
    types.push_back(classify_blade_mode(*blade, modes.shapes.col(r)).label());
  }
  for (int r = 0; r < 3; ++r) paper.push_back(modes.frequencies(r) / kPaperFrequencies[r] - 1.0);
  for (const auto& frame : blade->tip_frames) tip_radii.push_back(frame.radius);
  const auto& grid = blade->grid;
  json summary = {
      {"verb", "make-blade"},
      {"geometry", geometry},
      {"refinement", o.refinement},
      {"elements",
       {{"chord", grid.cells(0)}, {"thickness", grid.cells(1)}, {"span", grid.cells(2)}, {"total", grid.mesh().elements.size()}}},
      {"nodes", grid.mesh().node_count()},
      {"dofs", blade->dofs.free_dofs()},
      {"boundary_node_ids", boundary_ids},
      {"boundary_node_radii", tip_radii},
      {"natural_frequencies", frequencies},
      {"mode_types", types},
      {"rotation", rotation},
      {"paper_frequencies", kPaperFrequencies},
      {"relative_difference_to_paper", paper},
      {"timings", {{"wall_s", std::chrono::duration<double>(Clock::now() - t0).count()}}}};
  write_json_atomically(o.out_dir + "/summary.json", summary);
  if (!o.quiet) {
    std::fprintf(stderr, "make-blade: %d elements, %d dofs -> %s\n", static_cast<int>(grid.mesh().elements.size()), blade->dofs.free_dofs(),
                 o.out_dir.c_str());
    for (Eigen::Index r = 0; r < modes.frequencies.size(); ++r)
      std::fprintf(stderr, "  mode %lld %-3s %10.2f rad/s\n", static_cast<long long>(r + 1),
                   types[static_cast<size_t>(r)].get<std::string>().c_str(), modes.frequencies(r));
  }
  return 0;
}

void add_make_blade_verbs(CLI::App& app, VerbList& verbs) {
  static MakeBladeOptions options;
  CLI::App* make =
      app.add_subcommand("make-blade", "generate a fan blade's full FE model for `reduce` (the parametric plate, or --geometry sections)");
  make->add_option("-o,--output", options.out_dir, "output folder (created if missing)")->required();
  make->add_option("--geometry", options.geometry,
                   "blade section table (e.g. data/rotor67/sections.csv: NASA rotor 67); without it, the parametric plate");
  make->add_option("--refine", options.refinement, "multiply the element counts by R (default 1)");
  make->add_option("--rim-depth", options.rim_depth,
                   "with --geometry: depth (m) of the disk-rim sector under the hub, clamped at its bottom; 0 clamps the hub section");
  make->add_option("--modes", options.modes, "lowest modes computed and named (default 6)");
  make->add_flag("--calculix", options.calculix,
                 "also write the mesh as a CalculiX deck, blade.inp, whose step writes the matrices `reduce --calculix DIR/blade` reads");
  make->add_flag("--rotating", options.rotating,
                 "also write the matrices of rotation about X: Kg1.mtx (centrifugal stress stiffening at 1 rad/s), Mspin.mtx "
                 "(spin softening), G.mtx (gyroscopic); K(Omega) = K + Omega^2 (Kg1 - Mspin)");
  make->add_flag("-q,--quiet", options.quiet, "no closing report");
  verbs.push_back({make, [] { return run_make_blade(options); }});
}

const VerbRegistrar make_blade_registrar(add_make_blade_verbs);

}  // namespace

}  // namespace hbtrack::cli
