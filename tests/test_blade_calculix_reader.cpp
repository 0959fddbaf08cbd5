// The CalculiX matrix-storage reader (.sti/.mas/.dof): small handwritten files, malformed files
// with their one-line errors, and, when ccx is installed, real CalculiX output of a blade mesh
// against hbtrack's own hex20 assembly; the node coordinates of an input deck (*NODE, *INCLUDE).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "hbtrack/io/calculix_input_nodes.hpp"
#include "hbtrack/io/calculix_reader.hpp"
#include "hbtrack/model/blade_generator.hpp"
#include "hbtrack/model/calculix_deck.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_blade_calculix_reader {

namespace {

namespace fs = std::filesystem;
using namespace hbtrack;

class CalculixReader : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device entropy;
    dir_ = fs::temp_directory_path() / ("hbtrack_calculix_" + std::to_string(entropy()) + std::to_string(entropy()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }
  std::string write(const std::string& name, const std::string& text) const {
    const std::string path = (dir_ / name).string();
    std::ofstream(path) << text;
    return path;
  }
  fs::path dir_;
};

// The error is one line "<path>: line N: <rule>".
template <class Action>
void expect_error(Action&& action, const std::string& path, int line, const std::string& phrase) {
  try {
    action();
    ADD_FAILURE() << "expected an error containing '" << phrase << "'";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.rfind(path + ": line " + std::to_string(line) + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(phrase), std::string::npos) << message;
  }
}

TEST_F(CalculixReader, ReadsUpperTriangleAndDofMap) {
  // Node 5 keeps only y and z (x constrained), node 6 all three: 5 rows, as ccx writes them.
  write("job.dof", "5.2\n5.3\n6.1\n6.2\n6.3\n");
  write("job.sti", "1 1  4.0e+00\n1 2 -1.0e+00\n2 2  4.0e+00\n2 3 -1.0e+00\n3 3  4.0e+00\n1 5  5.0e-01\n4 4 2.0\n5 5 3.0\n");
  write("job.mas", "1 1 2.0\n2 2 2.0\n3 3 2.0\n4 4 2.0\n5 5 2.0\n1 2 0.0\n");
  const CalculixMatrices m = read_calculix_matrices((dir_ / "job").string());
  ASSERT_EQ(m.dofs.size(), 5u);
  EXPECT_EQ(m.dofs[0].node, 5);
  EXPECT_EQ(m.dofs[0].direction, 2);
  EXPECT_EQ(m.dofs[4].node, 6);
  EXPECT_EQ(m.dofs[4].direction, 3);
  Eigen::MatrixXd k(5, 5);
  k << 4, -1, 0, 0, 0.5,  //
      -1, 4, -1, 0, 0,    //
      0, -1, 4, 0, 0,     //
      0, 0, 0, 2, 0,      //
      0.5, 0, 0, 0, 3;
  EXPECT_EQ(Eigen::MatrixXd(m.stiffness), k);
  EXPECT_EQ(Eigen::MatrixXd(m.mass), 2.0 * Eigen::MatrixXd::Identity(5, 5));
  // A lower triangle is read the same way.
  const std::string lower = write("lower.sti", "1 1 4\n2 1 -1\n2 2 4\n");
  Eigen::Matrix2d expected;
  expected << 4, -1, -1, 4;
  EXPECT_EQ(Eigen::MatrixXd(read_calculix_matrix(lower)), expected);
}

TEST_F(CalculixReader, MalformedFilesGiveOneLineErrors) {
  struct Case {
    const char* text;
    int line;
    const char* phrase;
  };
  const Case matrices[] = {
      {"1 1 4.0\n1 2\n", 2, "expected 'row column value'"},
      {"1 1 4.0\n0 2 1.0\n", 2, "integers >= 1"},
      {"1 1 4.0\nx 2 1.0\n", 2, "integers >= 1"},
      {"1 1 nan\n", 1, "finite number"},
      {"1 1 1e999\n", 1, "finite number"},
      {"1 1 4.0\n1 2 1.0\n3 2 1.0\n", 3, "both sides of the diagonal"},
      {"1 1 4.0\n1 2 1.0\n1 2 1.0\n", 3, "duplicate entry (1, 2), first on line 2"},
      {"1 1 4.0\n1 9 1.0\n", 2, "exceeds the 3 dofs"},
      {"\n\n", 1, "no matrix entries"},
      // Fuzzing findings: sized by its largest index, this one line took 36 s (and 3.5e6 up to
      // 29 s) under the sanitizers.
      {"1 1 4.0\n16716466 1 6\n", 2, "exceeds the limit of 1000000 dofs"},
  };
  for (const Case& c : matrices) {
    const std::string path = write("bad.sti", c.text);
    expect_error([&] { read_calculix_matrix(path, 3); }, path, c.line, c.phrase);
  }
  const Case dof_maps[] = {
      {"1.1\n1.2\n12\n", 3, "node.direction"},
      {"1.1\n1.x\n", 2, "node.direction"},
      {"1.1\n0.2\n", 2, "node number must be >= 1"},
      {"1.1\n2.7\n", 2, "direction must be 0 to 6"},
      {"1.1\n2.1\n1.1\n", 3, "already listed on line 1"},
      {"", 1, "no dofs"},
  };
  for (const Case& c : dof_maps) {
    const std::string path = write("bad.dof", c.text);
    expect_error([&] { read_calculix_dof_map(path); }, path, c.line, c.phrase);
  }
  expect_error([&] { read_calculix_dof_map((dir_ / "missing.dof").string()); }, (dir_ / "missing.dof").string(), 0, "cannot open");
}

// A deck as meshers write it: comments, keywords in any case, NSET parameters, a trailing comma,
// a coordinate left out (0 for ccx), other keywords' data lines (elements, *NODE PRINT) skipped,
// and an included mesh file, read from beside the including deck.
TEST_F(CalculixReader, ReadsTheNodesOfAnInputDeckAndItsIncludes) {
  write("mesh.msh", "** nodes of the tip\n*node, nset=TIP\n 7, 1.5, -2.0e-1, +3\n8, 4.0, 5.0,\n");
  const std::string deck = write("job.inp",
                                 "*HEADING\nblade\n*NODE, NSET=Nall\n1, 0.0, 0.0, 0.0\n2, 1.0, 2.0\n"
                                 "*ELEMENT, TYPE=C3D8, ELSET=E\n1, 1, 2, 7, 8, 1, 2, 7, 8\n"
                                 "*INCLUDE, INPUT=mesh.msh\n*STEP\n*NODE PRINT, NSET=Nall\nU\n*END STEP\n");
  const std::vector<CalculixNode> nodes = read_calculix_input_nodes(deck);
  ASSERT_EQ(nodes.size(), 4u);
  const std::pair<int, Eigen::Vector3d> expected[] = {
      {1, {0.0, 0.0, 0.0}}, {2, {1.0, 2.0, 0.0}}, {7, {1.5, -0.2, 3.0}}, {8, {4.0, 5.0, 0.0}}};
  for (size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(nodes[k].id, expected[k].first);
    EXPECT_EQ(nodes[k].position, expected[k].second) << "node " << nodes[k].id;  // exact: the text's nearest doubles
  }
}

TEST_F(CalculixReader, InputDeckErrorsNameTheFileTheLineAndTheRule) {
  struct Bad {
    std::string text;
    int line;
    std::string phrase;
  };
  const Bad cases[] = {
      {"*NODE\n1, 0, 0, 0\n1, 1, 1, 1\n", 3, "node 1 is already defined at"},
      {"*NODE\n0, 0, 0, 0\n", 2, "node id '0' must be an integer >= 1"},
      {"*NODE\nA, 0, 0, 0\n", 2, "must be an integer >= 1"},
      {"*NODE\n1, 0, nan, 0\n", 2, "coordinate y of node 1 must be a finite number"},
      {"*NODE\n1, 0, 0, 0, 9\n", 2, "a *NODE line is 'id, x, y, z', got 5 fields"},
      {"*NODE, SYSTEM=C\n1, 1, 0, 0\n", 1, "only rectangular coordinates"},
      {"*NODE\n1, 1, 0, 0\n*TRANSFORM, NSET=N, TYPE=C\n0,0,0,1,0,0\n", 3, "*TRANSFORM"},
      {"*INCLUDE\n", 1, "*INCLUDE needs INPUT=FILE"},
      {"*HEADING\nno nodes\n", 0, "no *NODE block"},
  };
  for (const Bad& c : cases) {
    const std::string path = write("bad.inp", c.text);
    expect_error([&] { read_calculix_input_nodes(path); }, path, c.line, c.phrase);
  }
  const std::string self = write("self.inp", "*INCLUDE, INPUT=self.inp\n");
  expect_error([&] { read_calculix_input_nodes(self); }, self, 1, "nested more than");
  const std::string missing = (dir_ / "missing.inp").string();
  expect_error([&] { read_calculix_input_nodes(missing); }, missing, 0, "cannot open");
}

// CalculiX's C3D20 (full integration) and hbtrack's hex20 share node order and quadrature: on the
// same mesh, material and clamp their matrices agree to round-off.
TEST_F(CalculixReader, RealCalculixOutputMatchesHbtrackAssembly) {
  if (std::system("command -v ccx > /dev/null 2>&1") != 0) GTEST_SKIP() << "ccx (calculix-ccx) not installed";
  BladeGeometry g;
  g.span_elements = 2;
  const BladeModel blade = generate_blade(g);
  const SolidMesh& mesh = blade.grid.mesh();
  std::vector<int> clamped;
  for (int n = 0; n < mesh.node_count(); ++n)
    if (blade.dofs.dof(n, 0) < 0) clamped.push_back(n);
  std::ofstream(dir_ / "blade.inp") << calculix_deck(mesh, clamped, g.material, kCalculixMatrixStorageStep);
  // The deck's nodes read back are the mesh's, to the 14 digits written.
  const std::vector<CalculixNode> deck_nodes = read_calculix_input_nodes((dir_ / "blade.inp").string());
  ASSERT_EQ(static_cast<int>(deck_nodes.size()), mesh.node_count());
  for (int n = 0; n < mesh.node_count(); ++n)
    EXPECT_LT((deck_nodes[static_cast<size_t>(n)].position - mesh.nodes[static_cast<size_t>(n)]).norm(), 1e-13) << "node " << n + 1;
  const std::string command = "cd " + dir_.string() + " && ccx blade > ccx.log 2>&1";
  if (std::system(command.c_str()) != 0) {
    std::stringstream log;
    log << std::ifstream(dir_ / "ccx.log").rdbuf();
    FAIL() << "ccx failed:\n" << log.str();
  }
  const CalculixMatrices ccx = read_calculix_matrices((dir_ / "blade").string());
  const AssembledMatrices own = assemble_blade(blade);
  ASSERT_EQ(static_cast<int>(ccx.dofs.size()), blade.dofs.free_dofs());
  // Permutation from ccx rows to hbtrack's free dofs.
  Eigen::VectorXi to_own(static_cast<Eigen::Index>(ccx.dofs.size()));
  for (size_t r = 0; r < ccx.dofs.size(); ++r)
    to_own(static_cast<Eigen::Index>(r)) = blade.dofs.dof(ccx.dofs[r].node - 1, ccx.dofs[r].direction - 1);
  const Eigen::PermutationMatrix<Eigen::Dynamic> permutation(to_own);
  const Eigen::MatrixXd k_ccx = permutation * Eigen::MatrixXd(ccx.stiffness) * permutation.transpose();
  const Eigen::MatrixXd m_ccx = permutation * Eigen::MatrixXd(ccx.mass) * permutation.transpose();
  const Eigen::MatrixXd k_own(own.stiffness), m_own(own.mass);
  // ccx writes 14 significant digits.
  EXPECT_LT((k_ccx - k_own).cwiseAbs().maxCoeff(), 1e-10 * k_own.cwiseAbs().maxCoeff());
  EXPECT_LT((m_ccx - m_own).cwiseAbs().maxCoeff(), 1e-10 * m_own.cwiseAbs().maxCoeff());
}

}  // namespace

}  // namespace hbtrack_tests::file_blade_calculix_reader
