// The blade chain through the command-line tool: make-blade -> reduce (Matrix Market, .mat and
// CalculiX inputs give the same reduced model) -> modes and frc on the shipped blade case.
#include <gtest/gtest.h>
#include <matio.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "cli_support.hpp"
#include "hbtrack/io/matrix_market.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_blade_cli {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using hbtrack::test::CliRun;

class BladeCli : public hbtrack::test::ScratchFolderTest {
 protected:
  BladeCli() : ScratchFolderTest("hbtrack_blade_cli") {}
  static CliRun run(const std::string& args) { return hbtrack::test::run_cli(args); }
};

using hbtrack::test::read_json;

// Writes M and K as sparse variables of a MATLAB v5 file (libmatio).
void write_mat(const std::string& path, const Eigen::SparseMatrix<double>& m, const Eigen::SparseMatrix<double>& k) {
  mat_t* file = Mat_CreateVer(path.c_str(), nullptr, MAT_FT_MAT5);
  ASSERT_NE(file, nullptr);
  for (const auto& [name, matrix] : {std::pair<const char*, const Eigen::SparseMatrix<double>*>{"M", &m}, {"K", &k}}) {
    Eigen::SparseMatrix<double> a = *matrix;
    a.makeCompressed();
    std::vector<mat_uint32_t> rows(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros());
    std::vector<mat_uint32_t> columns(a.outerIndexPtr(), a.outerIndexPtr() + a.cols() + 1);
    std::vector<double> values(a.valuePtr(), a.valuePtr() + a.nonZeros());
    mat_sparse_t csc{};
    csc.nzmax = static_cast<mat_uint32_t>(values.size());
    csc.ir = rows.data();
    csc.nir = static_cast<mat_uint32_t>(rows.size());
    csc.jc = columns.data();
    csc.njc = static_cast<mat_uint32_t>(columns.size());
    csc.ndata = static_cast<mat_uint32_t>(values.size());
    csc.data = values.data();
    size_t dims[2] = {static_cast<size_t>(a.rows()), static_cast<size_t>(a.cols())};
    matvar_t* variable = Mat_VarCreate(name, MAT_C_SPARSE, MAT_T_DOUBLE, 2, dims, &csc, MAT_F_DONT_COPY_DATA);
    ASSERT_NE(variable, nullptr);
    EXPECT_EQ(Mat_VarWrite(file, variable, MAT_COMPRESSION_NONE), 0);
    Mat_VarFree(variable);
  }
  Mat_Close(file);
}

// Upper triangle `row col value` and `node.direction` rows, as CalculiX writes them.
void write_calculix(const std::string& jobname, const Eigen::SparseMatrix<double>& m, const Eigen::SparseMatrix<double>& k,
                    const std::vector<int>& node_ids) {
  for (const auto& [extension, matrix] : {std::pair<const char*, const Eigen::SparseMatrix<double>*>{".mas", &m}, {".sti", &k}}) {
    std::ofstream out(jobname + extension);
    out.precision(17);
    for (int c = 0; c < matrix->outerSize(); ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator it(*matrix, c); it; ++it)
        if (it.row() <= it.col()) out << it.row() + 1 << " " << it.col() + 1 << " " << it.value() << "\n";
  }
  std::ofstream dof(jobname + ".dof");
  for (int id : node_ids)
    for (int d = 1; d <= 3; ++d) dof << id << "." << d << "\n";
}

std::vector<int> node_ids_of(const std::string& nodes_csv) {
  std::ifstream in(nodes_csv);
  std::string line;
  std::getline(in, line);  // header
  std::vector<int> ids;
  while (std::getline(in, line)) ids.push_back(std::stoi(line.substr(0, line.find(','))));
  return ids;
}

TEST_F(BladeCli, MakeBladeThenReduceFromMatrixMarketMatAndCalculixGiveTheSameModel) {
  CliRun r = run("make-blade -q -o " + path("fe"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json blade = read_json(path("fe/summary.json"));
  EXPECT_EQ(blade["mode_types"][0], "1B");
  EXPECT_EQ(blade["mode_types"][1], "2B");
  EXPECT_EQ(blade["mode_types"][2], "1T");

  const std::string common = " --nodes " + path("fe/nodes.csv") + " --boundary-file " + path("fe/boundary.txt") + " --modes 12 -q -o ";
  r = run("reduce --mass " + path("fe/M.mtx") + " --stiffness " + path("fe/K.mtx") + common + path("rom_mtx"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto m = hbtrack::read_matrix_market_sparse(path("fe/M.mtx")), k = hbtrack::read_matrix_market_sparse(path("fe/K.mtx"));
  write_mat(path("fe/model.mat"), m, k);
  r = run("reduce --mass " + path("fe/model.mat") + ":M --stiffness " + path("fe/model.mat") + ":K" + common + path("rom_mat"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  write_calculix(path("fe/job"), m, k, node_ids_of(path("fe/nodes.csv")));
  r = run("reduce --calculix " + path("fe/job") + common + path("rom_ccx"));
  ASSERT_EQ(r.exit_code, 0) << r.err;

  for (const char* matrix : {"M.mtx", "K.mtx", "T.mtx"}) {
    const Eigen::MatrixXd reference(hbtrack::read_matrix_market_sparse(path(std::string("rom_mtx/") + matrix)));
    EXPECT_EQ(Eigen::MatrixXd(hbtrack::read_matrix_market_sparse(path(std::string("rom_mat/") + matrix))), reference) << matrix;
    // The CalculiX text carries 17 significant digits: equal to round-off.
    const Eigen::MatrixXd from_ccx(hbtrack::read_matrix_market_sparse(path(std::string("rom_ccx/") + matrix)));
    EXPECT_LT((from_ccx - reference).cwiseAbs().maxCoeff(), 1e-9 * reference.cwiseAbs().maxCoeff()) << matrix;
  }
  const json s = read_json(path("rom_mtx/summary.json"));
  EXPECT_EQ(s["sizes"]["reduced_dofs"], 39);
  EXPECT_EQ(s["dof_names"][0], "n1_r");
  EXPECT_GT(s["timings"]["wall_s"].get<double>(), 0.0);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(s["natural_frequencies"][i].get<double>() / s["full_model"]["natural_frequencies"][i].get<double>(), 1.0, 0.005);
  // make-blade's summary beside the matrices: its mode names kept for `hbtrack modes`.
  EXPECT_EQ(s["full_model"]["mode_types"], json({"1B", "2B", "1T", "3B", "1E", "2T"}));
  std::ifstream boundary(path("rom_mtx/boundary_nodes.csv"));
  std::string header;
  std::getline(boundary, header);
  EXPECT_EQ(header.rfind("node,x,y,z,radius,radial_x", 0), 0u) << header;
}

// Reading coordinates from JOB.inp (no node table) gives the node table's model exactly; the
// global frame is the cylindrical model turned back node by node: K_cyl = Q^T K_global Q with
// Q the boundary nodes' frames (boundary_nodes.csv) and the identity on the modal dofs.
TEST_F(BladeCli, ReduceTakesCalculixNodesFromTheDeckAndFramesInGlobalAxes) {
  ASSERT_EQ(run("make-blade -q -o " + path("fe")).exit_code, 0);
  const auto m = hbtrack::read_matrix_market_sparse(path("fe/M.mtx")), k = hbtrack::read_matrix_market_sparse(path("fe/K.mtx"));
  write_calculix(path("fe/job"), m, k, node_ids_of(path("fe/nodes.csv")));
  {
    std::ifstream table(path("fe/nodes.csv"));
    std::ofstream deck(path("fe/job.inp"));
    std::string line;
    std::getline(table, line);  // header
    deck << "** written by the test from nodes.csv\n*NODE, NSET=NALL\n";
    while (std::getline(table, line)) deck << line << "\n";  // node,x,y,z rows are *NODE lines as they stand
  }
  const std::string boundary = " --boundary-file " + path("fe/boundary.txt") + " --modes 6 -q -o ";
  CliRun r = run("reduce --calculix " + path("fe/job") + " --nodes " + path("fe/nodes.csv") + boundary + path("rom_table"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run("reduce --calculix " + path("fe/job") + boundary + path("rom_deck"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run("reduce --calculix " + path("fe/job") + " --frame global" + boundary + path("rom_global"));
  ASSERT_EQ(r.exit_code, 0) << r.err;

  const auto matrix = [&](const std::string& name) { return Eigen::MatrixXd(hbtrack::read_matrix_market_sparse(path(name))); };
  EXPECT_EQ(matrix("rom_deck/K.mtx"), matrix("rom_table/K.mtx"));
  EXPECT_EQ(matrix("rom_deck/M.mtx"), matrix("rom_table/M.mtx"));
  EXPECT_EQ(read_json(path("rom_deck/summary.json"))["inputs"]["nodes"], path("fe/job.inp"));
  const json global = read_json(path("rom_global/summary.json"));
  EXPECT_EQ(global["dof_names"][0], "n1_x");
  EXPECT_EQ(global["dof_names"][2], "n1_z");
  EXPECT_TRUE(global["rotation_axis"].is_null());

  const Eigen::MatrixXd k_cyl = matrix("rom_table/K.mtx"), k_global = matrix("rom_global/K.mtx");
  Eigen::MatrixXd q = Eigen::MatrixXd::Identity(k_cyl.rows(), k_cyl.cols());
  std::ifstream frames(path("rom_table/boundary_nodes.csv"));
  std::string line;
  std::getline(frames, line);  // header: node,x,y,z,radius, then radial, circumferential, axial (x, y, z each)
  for (Eigen::Index j = 0; std::getline(frames, line); ++j) {
    std::stringstream cells(line);
    std::vector<double> v;
    for (std::string cell; std::getline(cells, cell, ',');) v.push_back(std::stod(cell));
    ASSERT_EQ(v.size(), 14u);
    for (int axis = 0; axis < 3; ++axis)
      for (int c = 0; c < 3; ++c) q(3 * j + c, 3 * j + axis) = v[static_cast<size_t>(5 + 3 * axis + c)];
  }
  // Round-off of one change of basis on entries of size max|K|.
  EXPECT_LT((q.transpose() * k_global * q - k_cyl).cwiseAbs().maxCoeff(), 1e-11 * k_cyl.cwiseAbs().maxCoeff());
}

// The CalculiX round trip a user makes: make-blade --calculix writes the deck, ccx writes the
// matrices, reduce reads them and the deck's coordinates. Same reduced model as from hbtrack's own
// matrices up to ccx's 14 significant digits (matrices equal to 1e-10 of their largest entry, see
// the reader test), which move the reduced frequencies by 3e-9 to 8e-9 here, the bending modes
// most (their modal stiffness is far below the largest entry). 1e-6 keeps that apart from a wrong
// dof map, frame or coordinate, which moves them by percents.
TEST_F(BladeCli, ReduceFromCalculixOwnOutputOfTheMakeBladeDeck) {
  if (std::system("command -v ccx > /dev/null 2>&1") != 0) GTEST_SKIP() << "ccx (calculix-ccx) not installed";
  ASSERT_EQ(run("make-blade -q --calculix -o " + path("fe")).exit_code, 0);
  ASSERT_EQ(std::system(("cd " + path("fe") + " && ccx blade > ccx.log 2>&1").c_str()), 0) << "ccx failed, see " << path("fe/ccx.log");
  const std::string boundary = " --boundary-file " + path("fe/boundary.txt") + " --modes 6 -q -o ";
  CliRun r = run("reduce --calculix " + path("fe/blade") + boundary + path("rom_ccx"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run("reduce --mass " + path("fe/M.mtx") + " --stiffness " + path("fe/K.mtx") + " --nodes " + path("fe/nodes.csv") + boundary +
          path("rom_own"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json ccx = read_json(path("rom_ccx/summary.json")), own = read_json(path("rom_own/summary.json"));
  EXPECT_EQ(ccx["inputs"]["nodes"], path("fe/blade.inp"));
  ASSERT_EQ(ccx["natural_frequencies"].size(), own["natural_frequencies"].size());
  for (size_t k = 0; k < own["natural_frequencies"].size(); ++k)
    EXPECT_NEAR(ccx["natural_frequencies"][k].get<double>() / own["natural_frequencies"][k].get<double>(), 1.0, 1e-6) << "mode " << k + 1;
}

TEST_F(BladeCli, ReduceRejectsBadInputWithOneLineErrors) {
  ASSERT_EQ(run("make-blade -q -o " + path("fe")).exit_code, 0);
  std::ifstream boundary_list(path("fe/boundary.txt"));
  std::string tip;
  while (std::getline(boundary_list, tip) && tip.rfind('#', 0) == 0) {
  }
  const std::string matrices = " --mass " + path("fe/M.mtx") + " --stiffness " + path("fe/K.mtx") + " --nodes " + path("fe/nodes.csv");
  struct Case {
    std::string args, phrase;
  };
  const Case cases[] = {
      {matrices + " --boundary 1,2", "boundary node 1 is not in the node table"},
      {matrices + " --boundary " + tip + "," + tip, "is on the boundary twice"},
      {matrices + " --boundary " + tip + " --modes 100000", "fixed-interface modes asked"},
      {" --mass " + path("fe/M.mtx") + " --nodes " + path("fe/nodes.csv") + " --boundary " + tip, "go together"},
      {" --mass " + path("fe/nodes.csv") + " --stiffness " + path("fe/K.mtx") + " --nodes " + path("fe/nodes.csv") + " --boundary " + tip,
       "--mass: "},
      {" --mass x.mat --stiffness " + path("fe/K.mtx") + " --nodes " + path("fe/nodes.csv") + " --boundary " + tip, "name the variable"},
      {matrices + " --boundary " + tip + " --axis 0,0", "--axis: '0,0' must be x, y, z or a nonzero direction AX,AY,AZ"},
      {matrices + " --boundary " + tip + " --axis 0,0,0", "must be x, y, z or a nonzero direction"},
      {matrices + " --boundary " + tip + " --axis x --axis-origin 0,0", "--axis-origin"},
      {matrices + " --boundary " + tip + " --frame polar", "--frame: 'polar' must be cylindrical or global"},
      {" --mass " + path("fe/M.mtx") + " --stiffness " + path("fe/K.mtx") + " --boundary " + tip, "--nodes is required"},
      {" --calculix " + path("fe/nojob") + " --boundary " + tip, "nojob.inp not found"},
  };
  for (const Case& c : cases) {
    const CliRun r = run("reduce" + c.args + " -o " + path("rom"));
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.phrase), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

TEST_F(BladeCli, ModesOfTheShippedBladeCase) {
  const CliRun r = run("modes " + hbtrack::test::source_path("examples/blade/nominal.toml") + " --count 3 -q -o " + path("modes"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json s = read_json(path("modes/summary.json"));
  ASSERT_EQ(s["natural_frequencies"].size(), 3u);
  const double paper[] = {2039.78, 6343.69, 10745.26};
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(s["natural_frequencies"][i].get<double>() / paper[i], 1.0, 0.05);
  EXPECT_EQ(s["dofs"], 39);
  // Without -q: each mode named from the full model's summary, with the full model's frequency.
  const CliRun shown = run("modes " + hbtrack::test::source_path("examples/blade/nominal.toml") + " --count 4 -o " + path("modes_shown"));
  ASSERT_EQ(shown.exit_code, 0) << shown.err;
  for (const char* line : {"  mode 1 1B: 2035.", "  mode 2 2B: 6331.", "  mode 3 1T: 10735.", "  mode 4 3B: "})
    EXPECT_NE(shown.err.find(line), std::string::npos) << line << "\n" << shown.err;
  EXPECT_NE(shown.err.find(", full model 2035.2124 (+0.003 %)"), std::string::npos) << shown.err;
  EXPECT_NE(shown.err.find("the full model's, which the docs quote ("), std::string::npos) << shown.err;
  EXPECT_NE(shown.err.find("data/blade/summary.json: full_model), differ by the percentages shown"), std::string::npos) << shown.err;
}

// The nominal contact study end to end, coarsened to keep the suite quick: H = 5 and N = 256
// follow the same curve as the shipped H = 10, N = 1024 (peak within 0.2 %), and the per-point
// stability (Hill's method, which would triple the time) is not what this test is about.
TEST_F(BladeCli, NominalContactCaseRunsEndToEndBelowTheLinearResonance) {
  if (hbtrack::test::kSanitizedBuild) GTEST_SKIP() << "minutes under the sanitizers; run by the Release pass";
  const std::string coarser = " --set harmonic_balance.harmonics=5 --set harmonic_balance.samples=256 --set stability.method=none";
  const CliRun r = run("frc " + hbtrack::test::source_path("examples/blade/nominal.toml") + coarser + " -q -o " + path("nominal"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json s = read_json(path("nominal/summary.json"));
  EXPECT_EQ(s["stop_reason"], "reached_end");
  EXPECT_EQ(s["failed_steps"], 0);
  const double linear_1b = read_json(hbtrack::test::source_path("data/blade/summary.json"))["natural_frequencies"][0].get<double>();
  int limit_points = 0;
  for (const json& p : s["special_points"])
    if (p["type"] == "LP") ++limit_points;
  EXPECT_GE(limit_points, 2);
  // The resonance peak of the leading edge, in contact, lies below the linear 1B frequency: the
  // friction of a blade turning with its leading edge ahead pushes that edge into the casing and
  // softens the response (the fold at 0.90 x 1B at H = 10).
  std::ifstream branch(path("nominal/branch.csv"));
  std::string line, cell;
  std::getline(branch, line);
  std::vector<std::string> header;
  for (std::stringstream ss(line); std::getline(ss, cell, ',');) header.push_back(cell);
  const auto column = static_cast<size_t>(std::find(header.begin(), header.end(), "max_le") - header.begin());
  ASSERT_LT(column, header.size());
  double peak = 0, peak_omega = 0;
  while (std::getline(branch, line)) {
    std::vector<double> row;
    for (std::stringstream ss(line); std::getline(ss, cell, ',');) row.push_back(std::stod(cell));
    if (row[column] > peak) peak = row[column], peak_omega = row[0];
  }
  EXPECT_GT(peak, 4e-4) << "the leading edge reaches the casing";
  EXPECT_LT(peak_omega, 0.95 * linear_1b);
}

}  // namespace

}  // namespace hbtrack_tests::file_blade_cli
