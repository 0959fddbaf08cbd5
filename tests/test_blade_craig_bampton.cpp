// Craig-Bampton reduction and the sparse eigensolver behind it, on a coarse blade.
#include <gtest/gtest.h>

#include "blade_boundary_support.hpp"
#include "hbtrack/model/blade_generator.hpp"
#include "hbtrack/model/craig_bampton.hpp"
#include "hbtrack/model/sparse_modes.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_blade_craig_bampton {

namespace {

using namespace hbtrack;

struct CoarseBlade {
  BladeModel blade;
  AssembledMatrices matrices;
  std::vector<CraigBamptonBoundaryNode> boundary;
};

// 4 x 2 x 6 elements (930 dofs): large enough for the sparse (Lanczos) path, solved in a blink.
const CoarseBlade& coarse_blade() {
  static const CoarseBlade model = [] {
    BladeGeometry g;
    g.span_elements = 6;
    CoarseBlade c{generate_blade(g), {}, {}};
    c.matrices = assemble_blade(c.blade);
    c.boundary = hbtrack::test::tip_boundary(c.blade);
    return c;
  }();
  return model;
}

TEST(SparseModes, LanczosMatchesTheDenseSolver) {
  BladeGeometry g;
  g.span_elements = 3;  // 474 dofs: the Lanczos path, and a quick dense reference
  const AssembledMatrices m = assemble_blade(generate_blade(g));
  ASSERT_GT(m.stiffness.rows(), 300);
  const NormalModes sparse = lowest_sparse_modes(m.stiffness, m.mass, 8);
  const NormalModes dense = normal_modes(Eigen::MatrixXd(m.mass), Eigen::MatrixXd(m.stiffness));
  // The dense solver's round-off grows with the spread of the spectrum (~1e6 here): 1e-8.
  for (int r = 0; r < 8; ++r) EXPECT_NEAR(sparse.frequencies(r) / dense.frequencies(r), 1.0, 1e-8) << "mode " << r + 1;
  const Eigen::MatrixXd orthogonality = sparse.shapes.transpose() * (m.mass * sparse.shapes);
  EXPECT_LT((orthogonality - Eigen::MatrixXd::Identity(8, 8)).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(CraigBampton, ReducedFrequenciesMatchTheFullModelWithinHalfAPercent) {
  const CoarseBlade& c = coarse_blade();
  const CraigBamptonModel rom = craig_bampton(c.matrices.mass, c.matrices.stiffness, c.boundary, 12);
  ASSERT_EQ(rom.mass.rows(), 39);
  const NormalModes full = lowest_sparse_modes(c.matrices.stiffness, c.matrices.mass, 6);
  const NormalModes reduced = normal_modes(rom.mass, rom.stiffness);
  for (int r = 0; r < 6; ++r) {
    EXPECT_GE(reduced.frequencies(r), full.frequencies(r) * (1 - 1e-9)) << "a Ritz reduction can only raise frequencies";
    EXPECT_NEAR(reduced.frequencies(r) / full.frequencies(r), 1.0, 0.005) << "mode " << r + 1;
  }
  EXPECT_EQ(rom.dof_names.front(), "n1_r");
  EXPECT_EQ(rom.dof_names[26], "n9_z");
  EXPECT_EQ(rom.dof_names.back(), "m12");
}

TEST(CraigBampton, BoundaryCoordinatesAreLocalDisplacementsAndModesAreDecoupled) {
  const CoarseBlade& c = coarse_blade();
  const CraigBamptonModel rom = craig_bampton(c.matrices.mass, c.matrices.stiffness, c.boundary, 12);
  // x_full = T q: reduced dof 3j + k moves boundary node j by one unit along its local axis k only.
  for (size_t j = 0; j < c.boundary.size(); ++j)
    for (size_t i = 0; i < c.boundary.size(); ++i) {
      Eigen::Matrix3d block;
      for (int d = 0; d < 3; ++d)
        block.row(d) = rom.transformation.row(c.boundary[i].dofs[static_cast<size_t>(d)]).segment<3>(static_cast<Eigen::Index>(3 * j));
      const Eigen::Matrix3d expected = i == j ? c.boundary[j].frame : Eigen::Matrix3d::Zero();
      EXPECT_LT((block - expected).cwiseAbs().maxCoeff(), 1e-14);
    }
  // Fixed-interface modes are M-orthonormal and K-orthogonal: the modal blocks are I and diag(w^2).
  const Eigen::MatrixXd mass_mm = rom.mass.bottomRightCorner(12, 12), stiffness_mm = rom.stiffness.bottomRightCorner(12, 12);
  EXPECT_LT((mass_mm - Eigen::MatrixXd::Identity(12, 12)).cwiseAbs().maxCoeff(), 1e-9);
  const Eigen::MatrixXd expected = rom.fixed_interface_frequencies.array().square().matrix().asDiagonal();
  EXPECT_LT((stiffness_mm - expected).cwiseAbs().maxCoeff(), 1e-8 * expected.maxCoeff());
  // Constraint modes are K-orthogonal to the fixed-interface modes.
  EXPECT_LT(rom.stiffness.topRightCorner(27, 12).cwiseAbs().maxCoeff(), 1e-8 * rom.stiffness.cwiseAbs().maxCoeff());
  EXPECT_EQ(rom.mass, rom.mass.transpose());
  EXPECT_EQ(rom.stiffness, rom.stiffness.transpose());
}

TEST(CraigBampton, RejectsBadInput) {
  const CoarseBlade& c = coarse_blade();
  auto twice = c.boundary;
  twice.push_back(twice.front());
  EXPECT_THROW(craig_bampton(c.matrices.mass, c.matrices.stiffness, twice, 4), std::invalid_argument);
  auto outside = c.boundary;
  outside[0].dofs[0] = static_cast<int>(c.matrices.mass.rows());
  EXPECT_THROW(craig_bampton(c.matrices.mass, c.matrices.stiffness, outside, 4), std::invalid_argument);
  EXPECT_THROW(craig_bampton(c.matrices.mass, c.matrices.stiffness, c.boundary, static_cast<int>(c.matrices.mass.rows())),
               std::invalid_argument);
  EXPECT_THROW(craig_bampton(c.matrices.mass, c.matrices.stiffness, {}, 4), std::invalid_argument);
}

}  // namespace

}  // namespace hbtrack_tests::file_blade_craig_bampton
