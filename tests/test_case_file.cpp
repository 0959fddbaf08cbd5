// Case files: a valid file loads as written; each malformed one fails with a one-line error that
// names the file, the field and the rule.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "hbtrack/io/case_file.hpp"
#include "hbtrack/results/result_tables.hpp"
#include "hbtrack/model/damping.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_case_file {

using namespace hbtrack;
namespace fs = std::filesystem;

namespace {

const char* kValid = R"(
[model]
dofs = ["a", "b"]
M = [[1.0, 0.0], [0.0, 2.0]]
K = [[3.0, -1.0], [-1.0, 1.0]]
[damping]
rayleigh = [0.0, 0.01]
[[forcing]]
dof = "a"
cos = 0.5
[parameters]
amplitude = 2.0
clearance = 0.1
mu = 0.2
[[elements]]
type = "regularized_contact"
dofs = ["b"]
stiffness = 10.0
gap = "clearance"
width = 0.1
lanczos = 1
[harmonic_balance]
harmonics = 3
[continuation]
omega_start = 0.1
omega_end = 2.0
[[outputs]]
name = "tip"
dof = "b"
)";

// Per-process folder: ctest runs the tests of this file in parallel processes.
fs::path test_dir() { return fs::temp_directory_path() / ("hbtrack_case_tests_" + std::to_string(getpid())); }

fs::path write_case(const std::string& name, const std::string& text) {
  const fs::path dir = test_dir();
  fs::create_directories(dir);
  const fs::path p = dir / (name + ".toml");
  std::ofstream(p) << text;
  return p;
}

// kValid with one line replaced (or appended when `from` is empty).
std::string variant(const std::string& from, const std::string& to) {
  std::string s = kValid;
  if (from.empty()) return s + to + "\n";
  const size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

struct BadCase {
  const char* name;
  std::string text;
  const char* expected;  // substring of the error message
};

// Each case fails to load with one line that starts with its file and holds `expected`.
void expect_one_line_errors(const std::vector<BadCase>& cases) {
  for (const BadCase& bad : cases) {
    const fs::path p = write_case(bad.name, bad.text);
    try {
      load_case(p.string());
      ADD_FAILURE() << bad.name << ": no error";
    } catch (const CaseError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find(bad.expected), std::string::npos) << bad.name << ": got '" << msg << "'";
      EXPECT_EQ(msg.find('\n'), std::string::npos) << bad.name << ": not one line: " << msg;
      EXPECT_EQ(msg.rfind(p.string(), 0), 0u) << bad.name << ": does not start with the file name: " << msg;
    }
  }
}

}  // namespace

TEST(CaseFile, ValidCaseLoadsAsWritten) {
  const CaseDefinition c = load_case(write_case("valid", kValid).string());
  EXPECT_EQ(c.model.dofs(), 2);
  EXPECT_DOUBLE_EQ(c.model.mass(1, 1), 2.0);
  EXPECT_DOUBLE_EQ(c.model.damping(0, 1), -0.01);
  EXPECT_DOUBLE_EQ(c.parameters.value("amplitude"), 2.0);
  ASSERT_EQ(c.elements.size(), 1u);
  EXPECT_EQ(c.elements[0]->type(), "regularized_contact");
  EXPECT_DOUBLE_EQ(c.elements[0]->property_values(c.parameters)[1], 0.1);
  EXPECT_DOUBLE_EQ(c.elements[0]->lanczos_exponent, 1.0);
  EXPECT_EQ(c.harmonic_balance.harmonics, 3);
  EXPECT_EQ(c.outputs[0].name, "tip");
  EXPECT_EQ(c.outputs[0].dof, 1);
}

// Multi-byte UTF-8 (2, 3 and 4 bytes) is text like any other: only malformed sequences are refused.
TEST(CaseFile, OutputDescriptionsAreReadAndWrittenToTheSummary) {
  const CaseDefinition c =
      load_case(write_case("described", variant("dof = \"b\"\n", "dof = \"b\"\ndescription = \"tip, radial\"\n")).string());
  ASSERT_EQ(c.outputs.size(), 1u);
  EXPECT_EQ(c.outputs[0].description, "tip, radial");
  EXPECT_EQ(outputs_json(c)[0].value("description", ""), "tip, radial");
  // Without one, summary.json has no description key (figures fall back to name and dof).
  EXPECT_FALSE(outputs_json(load_case(write_case("valid", kValid).string()))[0].contains("description"));
}

TEST(CaseFile, NonAsciiUtf8TextIsAccepted) {
  const CaseDefinition c = load_case(
      write_case("utf8", "# clearance in \u00b5m \u2192 0.1, \U0001F600\n" + variant("name = \"tip\"", "name = \"tip_\u00b5\"")).string());
  EXPECT_EQ(c.outputs[0].name, "tip_\u00b5");
}

TEST(CaseFile, OverridesSetParametersAndKeys) {
  const CaseDefinition c =
      load_case(write_case("valid", kValid).string(), {"clearance=0.3", "harmonic_balance.harmonics=6", "continuation.step=0.01"});
  EXPECT_DOUBLE_EQ(c.elements[0]->property_values(c.parameters)[1], 0.3);
  EXPECT_EQ(c.harmonic_balance.harmonics, 6);
  EXPECT_DOUBLE_EQ(c.nfrc.continuation.step, 0.01);
  EXPECT_THROW(load_case(write_case("valid", kValid).string(), {"clearence=0.3"}), CaseError);
  try {
    load_case(write_case("valid", kValid).string(), {"clearence=0.3"});
  } catch (const CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'clearance'"), std::string::npos) << e.what();
  }
}

TEST(CaseFile, MassModeForcingExcitesOnlyThatMode) {
  const CaseDefinition c =
      load_case(write_case("mass_mode", variant("dof = \"a\"\ncos = 0.5", "shape = \"mass_mode\"\nmode = 1\nscale = 2.0")).string());
  ASSERT_EQ(c.model.forcing.size(), 1u);
  const NormalModes modes = normal_modes(c.model.mass, c.model.stiffness);
  const Eigen::VectorXd& f = c.model.forcing[0].cos_part;
  // phi_1^T (2 M phi_1) = 2 for a mass-normalised mode; M-orthogonality leaves mode 2 unforced.
  EXPECT_NEAR(std::abs(modes.shapes.col(0).dot(f)), 2.0, 1e-12);
  EXPECT_NEAR(modes.shapes.col(1).dot(f), 0.0, 1e-12);
  EXPECT_TRUE(c.model.forcing[0].sin_part.isZero());
}

TEST(CaseFile, MatrixFromMatrixMarketFile) {
  const fs::path dir = test_dir();
  fs::create_directories(dir);
  std::ofstream(dir / "K2.mtx") << "%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n1 1 3.0\n2 1 -1.0\n2 2 1.0\n";
  const CaseDefinition c = load_case(write_case("mtx", variant("K = [[3.0, -1.0], [-1.0, 1.0]]", "K = { file = \"K2.mtx\" }")).string());
  EXPECT_DOUBLE_EQ(c.model.stiffness(0, 1), -1.0);
  EXPECT_DOUBLE_EQ(c.model.stiffness(1, 0), -1.0);
  EXPECT_DOUBLE_EQ(c.model.stiffness(0, 0), 3.0);
}

TEST(CaseFile, MalformedCasesGiveOneLineErrorsNamingTheField) {
  const std::vector<BadCase> cases = {
      {"missing_model", "[continuation]\nomega_start = 0.1\nomega_end = 1.0\n", "model: missing"},
      {"syntax", variant("amplitude = 2.0", "amplitude = = 2.0"), "TOML syntax error"},
      {"unknown_section", variant("", "[contiuation]\nx = 1"), "did you mean 'continuation'"},
      {"missing_K", variant("K = [[3.0, -1.0], [-1.0, 1.0]]", ""), "model.K: missing"},
      {"wrong_size", variant("K = [[3.0, -1.0], [-1.0, 1.0]]", "K = [[3.0]]"), "model.K: expected 2x2"},
      {"ragged", variant("K = [[3.0, -1.0], [-1.0, 1.0]]", "K = [[3.0, -1.0], [-1.0]]"), "row 1 has 1 entries"},
      {"text_in_matrix", variant("K = [[3.0, -1.0], [-1.0, 1.0]]", "K = [[3.0, \"x\"], [-1.0, 1.0]]"), "model.K[0][1]: expected a number"},
      {"nonsymmetric", variant("K = [[3.0, -1.0], [-1.0, 1.0]]", "K = [[3.0, -1.0], [-2.0, 1.0]]"), "model.K: must be symmetric"},
      {"indefinite_mass", variant("M = [[1.0, 0.0], [0.0, 2.0]]", "M = [[1.0, 0.0], [0.0, -2.0]]"), "model.M: must be positive definite"},
      {"unknown_element", variant("type = \"regularized_contact\"", "type = \"regularised_contact\""),
       "unknown element type 'regularised_contact' (did you mean 'regularized_contact'?)"},
      {"unknown_dof", variant("dofs = [\"b\"]", "dofs = [\"c\"]"), "elements[0].dofs[0]: unknown dof 'c'"},
      {"unknown_parameter", variant("gap = \"clearance\"", "gap = \"clearence\""), "elements[0].gap: unknown parameter 'clearence'"},
      {"missing_property", variant("stiffness = 10.0", ""), "elements[0].stiffness: missing"},
      {"negative_stiffness", variant("stiffness = 10.0", "stiffness = -10.0"), "elements[0].stiffness: must be > 0"},
      {"unknown_key", variant("width = 0.1", "widht = 0.1"), "did you mean 'width'"},
      {"wrong_type_harmonics", variant("harmonics = 3", "harmonics = \"three\""), "harmonic_balance.harmonics: expected an integer"},
      {"zero_harmonics", variant("harmonics = 3", "harmonics = 0"), "harmonic_balance.harmonics: must be >= 1"},
      {"few_samples", variant("harmonics = 3", "harmonics = 3\nsamples = 4"), "harmonic_balance.samples: must be >= 2*harmonics+1"},
      {"no_omega_end", variant("omega_end = 2.0", ""), "continuation.omega_end: missing"},
      {"equal_range", variant("omega_end = 2.0", "omega_end = 0.1"), "continuation.omega_end: must differ"},
      {"bad_predictor", variant("omega_end = 2.0", "omega_end = 2.0\npredictor = \"euler\""),
       "continuation.predictor: must be tangent or secant"},
      {"two_dampings", variant("rayleigh = [0.0, 0.01]", "rayleigh = [0.0, 0.01]\nmodal_ratios = [0.01]"), "damping: give exactly one"},
      {"forcing_dof", variant("dof = \"a\"", "dof = \"z\""), "forcing[0].dof: unknown dof 'z'"},
      {"matrix_file_missing", variant("K = [[3.0, -1.0], [-1.0, 1.0]]", "K = { file = \"nope.mtx\" }"), "model.K.file: file"},
      {"output_dof", variant("dof = \"b\"\n", "dof = \"q\"\n"), "outputs[0].dof: unknown dof 'q'"},
      {"duplicate_dof", variant("dofs = [\"a\", \"b\"]", "dofs = [\"a\", \"a\"]"), "dof name 'a' appears twice"},
      {"negative_lanczos", variant("lanczos = 1", "lanczos = -1"), "elements[0].lanczos: must be >= 0"},
      // Issue 24: 1e9 was accepted (and removed every harmonic of the force but the mean).
      {"huge_lanczos", variant("lanczos = 1", "lanczos = 1e9"), "elements[0].lanczos: must be <= 10"},
      {"forcing_above_truncation", variant("cos = 0.5", "cos = 0.5\nharmonic = 4"),
       "forcing[0].harmonic: must be <= harmonic_balance.harmonics = 3"},
      // Continuation settings: positive, finite, ordered.
      {"zero_tolerance", variant("omega_end = 2.0", "omega_end = 2.0\ntolerance = 0.0"), "continuation.tolerance: must be > 0 and finite"},
      {"nan_tolerance", variant("omega_end = 2.0", "omega_end = 2.0\ntolerance = nan"), "continuation.tolerance: must be finite"},
      {"tolerance_one", variant("omega_end = 2.0", "omega_end = 2.0\ntolerance = 1.0"), "continuation.tolerance: must be < 1"},
      {"step_min_above_step", variant("omega_end = 2.0", "omega_end = 2.0\nstep = 0.01\nstep_min = 0.1"),
       "continuation.step_min: must be <= step"},
      {"step_above_step_max", variant("omega_end = 2.0", "omega_end = 2.0\nstep = 0.5\nstep_max = 0.1"),
       "continuation.step: must be <= step_max"},
      {"zero_max_points", variant("omega_end = 2.0", "omega_end = 2.0\nmax_points = 0"), "continuation.max_points: must be >= 1"},
      {"zero_max_iterations", variant("omega_end = 2.0", "omega_end = 2.0\nmax_iterations = 0"),
       "continuation.max_iterations: must be in [1, 1000]"},
      {"negative_omega", variant("omega_start = 0.1", "omega_start = -0.1"), "continuation.omega_start: must be finite and >= 0"},
      {"infinite_omega", variant("omega_end = 2.0", "omega_end = inf"), "continuation.omega_end: must be finite"},
      {"negative_time_limit", variant("omega_end = 2.0", "omega_end = 2.0\nwall_time_limit = -1"),
       "continuation.wall_time_limit: must be >= 0"},
      {"bad_corrector", variant("omega_end = 2.0", "omega_end = 2.0\ncorrector = \"newton\""),
       "continuation.corrector: must be pseudo_arclength or hypersphere"},
      {"locate_not_boolean", variant("omega_end = 2.0", "omega_end = 2.0\nlocate = 1"), "continuation.locate: expected true or false"},
      {"bad_stability_method", variant("", "[stability]\nmethod = \"floquet\""),
       "stability.method: must be hill, monodromy, shooting or none"},
      {"bad_condensation", variant("harmonics = 3", "harmonics = 3\ncondensation = \"guyan\""),
       "harmonic_balance.condensation: must be auto, schur, modal or none"},
      // Model, damping, forcing, elements, outputs.
      {"nan_in_matrix", variant("K = [[3.0, -1.0], [-1.0, 1.0]]", "K = [[3.0, nan], [nan, 1.0]]"), "model.K[0][1]: must be finite"},
      {"huge_chain",
       variant("dofs = [\"a\", \"b\"]\nM = [[1.0, 0.0], [0.0, 2.0]]\nK = [[3.0, -1.0], [-1.0, 1.0]]", "chain = { count = 100000 }"),
       "model.chain.count: must be in [1, 4000]"},
      // Issue 39: `dofs = N` had no upper bound; a model beyond it exhausts memory (kMaxModelDofs).
      {"huge_dof_count", variant("dofs = [\"a\", \"b\"]", "dofs = 4001"),
       "model.dofs: must be in [1, 4000] (the number of dofs, named x1 .. xN): the model's matrices are dense"},
      {"too_many_dof_names", variant("dofs = [\"a\", \"b\"]", "dofs = { file = \"4001_names.txt\" }"),
       "model.dofs: 4001 names, at most 4000: the model's matrices are dense"},
      // Sized before the dense copy: this one took 3.2 GB, then was refused.
      {"matrix_file_far_larger_than_the_model", variant("K = [[3.0, -1.0], [-1.0, 1.0]]", "K = { file = \"K20000.mtx\" }"),
       "model.K: expected 2x2 (one row per dof), got 20000x20000"},
      {"matrix_file_is_directory", variant("K = [[3.0, -1.0], [-1.0, 1.0]]", "K = { file = \".\" }"), "model.K.file: '"},
      {"matrix_file_wrong_shape", variant("K = [[3.0, -1.0], [-1.0, 1.0]]", "K = { file = \"K3.mtx\" }"),
       "model.K: expected 2x2 (one row per dof), got 3x3"},
      {"matrix_file_malformed", variant("K = [[3.0, -1.0], [-1.0, 1.0]]", "K = { file = \"garbage.mtx\" }"),
       "missing '%%MatrixMarket' banner"},
      {"mat_file_without_variable", variant("K = [[3.0, -1.0], [-1.0, 1.0]]", "K = { file = \"empty.mat\" }"),
       "model.K.variable: missing (required for a .mat file)"},
      {"rayleigh_one_number", variant("rayleigh = [0.0, 0.01]", "rayleigh = [0.01]"), "damping.rayleigh: expected [alpha, beta]"},
      {"forcing_vector_length", variant("dof = \"a\"\ncos = 0.5", "cos = [0.5]"),
       "forcing[0].cos: expected 2 entries (one per dof), got 1"},
      {"zero_weights", variant("lanczos = 1", "lanczos = 1\nweights = [0.0]"), "elements[0].weights: must not all be zero"},
      {"negative_friction",
       variant("", "[[elements]]\ntype = \"tanh_friction\"\ndofs = [\"a\"]\nmu = -0.2\nnormal_load = 1.0\nregularization_velocity = 0.01"),
       "elements[1].mu: must be >= 0"},
      {"output_name_with_comma", variant("name = \"tip\"", "name = \"tip,x\""), "outputs[0].name: must be non-empty without commas"},
      // Fuzzing finding: toml11 3.7 read out of bounds reporting this (a literal string with 0xE0).
      {"invalid_utf8_in_string", variant("name = \"tip\"", "name = 'tip\xe0'"), "not valid UTF-8 (byte"},
      {"overlong_utf8_in_comment", variant("", "# \xc0\xaf"), "not valid UTF-8 (byte"},
      {"long_description", variant("dof = \"b\"\n", "dof = \"b\"\ndescription = \"" + std::string(81, 'x') + "\"\n"),
       "outputs[0].description: at most 80 characters on one line"},
      {"description_not_text", variant("dof = \"b\"\n", "dof = \"b\"\ndescription = 3\n"), "outputs[0].description"},
  };
  // Side files the matrix rows refer to (relative paths resolve next to the case file).
  fs::create_directories(test_dir());
  std::ofstream(test_dir() / "K3.mtx") << "%%MatrixMarket matrix coordinate real general\n3 3 3\n1 1 1\n2 2 1\n3 3 1\n";
  std::ofstream(test_dir() / "garbage.mtx") << "not a matrix\n";
  std::ofstream(test_dir() / "K20000.mtx") << "%%MatrixMarket matrix coordinate real general\n20000 20000 1\n1 1 1\n";
  {
    std::ofstream names(test_dir() / "4001_names.txt");
    for (int i = 0; i < 4001; ++i) names << "n" << i << "\n";
  }
  std::ofstream(test_dir() / "empty.mat") << "";
  expect_one_line_errors(cases);
}

TEST(CaseFile, ForcingGrowthAndBaseMotionLoadAsWritten) {
  const CaseDefinition grown =
      load_case(write_case("growth", variant("", "[forcing_growth]\nexponent = 2\nreference_frequency = 1.5")).string());
  EXPECT_EQ(grown.model.forcing_growth.exponent, 2.0);
  EXPECT_EQ(grown.model.forcing_growth.reference_frequency, 1.5);
  const CaseDefinition based =
      load_case(write_case("base", variant("[[forcing]]\ndof = \"a\"\ncos = 0.5\n",
                                           "[base_motion]\nkind = \"velocity\"\ndofs = [\"a\", \"b\"]\ncos = 0.1\n"))
                    .string());
  ASSERT_TRUE(based.base_motion.has_value());
  EXPECT_EQ(based.base_motion->kind, BaseMotionKind::velocity);
  EXPECT_EQ(based.base_motion->dofs, (std::vector<int>{0, 1}));
  // Its equivalent forcing -M r u_b'': a velocity's grows as omega^1.
  ASSERT_EQ(based.model.forcing.size(), 1u);
  EXPECT_EQ(based.model.forcing_growth.exponent, 1.0);
}

TEST(CaseFile, BadForcingGrowthOrBaseMotionGivesOneLineErrorsNamingTheField) {
  const std::string no_forcing = variant("[[forcing]]\ndof = \"a\"\ncos = 0.5\n", "");
  auto with_base = [&](const std::string& body) { return no_forcing + "[base_motion]\n" + body + "\n"; };
  const std::vector<BadCase> cases = {
      {"growth_negative", variant("", "[forcing_growth]\nexponent = -1\nreference_frequency = 1.0"),
       "forcing_growth.exponent: must be >= 0"},
      {"growth_no_reference", variant("", "[forcing_growth]\nexponent = 2"), "forcing_growth.reference_frequency: missing"},
      {"growth_zero_reference", variant("", "[forcing_growth]\nexponent = 2\nreference_frequency = 0"),
       "forcing_growth.reference_frequency: must be > 0"},
      {"growth_unknown_key", variant("", "[forcing_growth]\nexponnent = 2"), "did you mean 'exponent'"},
      {"growth_without_forcing", no_forcing + "[forcing_growth]\nexponent = 2\nreference_frequency = 1.0\n",
       "forcing_growth: there is no [[forcing]]"},
      {"base_with_forcing", variant("", "[base_motion]\nkind = \"displacement\"\ndofs = [\"a\"]\ncos = 0.1"),
       "base_motion: cannot be combined with [[forcing]]"},
      {"base_with_growth", with_base("kind = \"displacement\"\ndofs = [\"a\"]\ncos = 0.1\n[forcing_growth]\nexponent = 2"),
       "forcing_growth: cannot be combined with [base_motion]"},
      {"base_unknown_dof", with_base("kind = \"displacement\"\ndofs = [\"c\"]\ncos = 0.1"), "base_motion.dofs[0]: unknown dof 'c'"},
      {"base_dof_twice", with_base("kind = \"displacement\"\ndofs = [\"a\", \"a\"]\ncos = 0.1"), "base_motion.dofs[1]: dof listed twice"},
      {"base_no_dofs", with_base("kind = \"displacement\"\ndofs = []\ncos = 0.1"), "base_motion.dofs: expected a non-empty array"},
      {"base_bad_kind", with_base("kind = \"position\"\ndofs = [\"a\"]\ncos = 0.1"),
       "base_motion.kind: must be displacement, velocity or acceleration, got 'position'"},
      {"base_no_kind", with_base("dofs = [\"a\"]\ncos = 0.1"), "base_motion.kind: missing"},
      {"base_static", with_base("kind = \"displacement\"\ndofs = [\"a\"]\nharmonic = 0\ncos = 0.1"), "base_motion.harmonic: must be >= 1"},
      {"base_above_truncation", with_base("kind = \"displacement\"\ndofs = [\"a\"]\nharmonic = 5\ncos = 0.1"),
       "base_motion.harmonic: harmonic 5 is not among the harmonics balanced"},
      {"base_no_amplitude", with_base("kind = \"displacement\"\ndofs = [\"a\"]"), "base_motion: needs cos and/or sin"},
  };
  expect_one_line_errors(cases);
}

TEST(CaseFile, BadDirectionsGiveOneLineErrorsNamingTheField) {
  // Elements along a direction over several dofs (`weights`) and the planar slider's two rows.
  const auto scalar = [](const std::string& keys) {
    return variant("", "[[elements]]\ntype = \"cubic_spring\"\ncubic_stiffness = 1.0\n" + keys);
  };
  const auto planar = [](const std::string& keys) { return variant("", "[[elements]]\ntype = \"elastic_dry_friction_2d\"\n" + keys); };
  const std::vector<BadCase> cases = {
      {"direction_wrong_count", scalar("dofs = [\"a\", \"b\"]\nweights = [0.6, 0.8, -1.0]"),
       "elements[1].weights: expected one weight per dof (2)"},
      {"direction_zero", scalar("dofs = [\"a\", \"b\"]\nweights = [0.0, 0.0]"), "elements[1].weights: must not all be zero"},
      {"direction_unknown_dof", scalar("dofs = [\"a\", \"c\"]\nweights = [0.6, 0.8]"), "elements[1].dofs[1]: unknown dof 'c'"},
      {"planar_one_row", planar("stiffness = 5.0\nlimit_force = 0.1\ndofs = [\"a\", \"b\"]\nweights = [1.0, 0.0]"),
       "elements[1].weights: expected two rows"},
      {"planar_row_length", planar("stiffness = 5.0\nlimit_force = 0.1\ndofs = [\"a\", \"b\"]\nweights = [[1.0, 0.0], [0.0, 1.0, 0.0]]"),
       "elements[1].weights[1]: expected one weight per dof (2)"},
      {"planar_zero_row", planar("stiffness = 5.0\nlimit_force = 0.1\ndofs = [\"a\", \"b\"]\nweights = [[1.0, 0.0], [0.0, 0.0]]"),
       "elements[1].weights[1]: must not all be zero"},
      {"planar_parallel_rows", planar("stiffness = 5.0\nlimit_force = 0.1\ndofs = [\"a\", \"b\"]\nweights = [[1.0, 2.0], [-0.5, -1.0]]"),
       "elements[1].weights: the two rows must not be parallel"},
      {"planar_one_dof", planar("stiffness = 5.0\nlimit_force = 0.1\ndofs = [\"a\"]"),
       "elements[1].weights: required unless the dofs are [x, y] (2)"},
      {"planar_negative_stiffness", planar("stiffness = -5.0\nlimit_force = 0.1\ndofs = [\"a\", \"b\"]"),
       "elements[1].stiffness: must be > 0"},
      {"planar_negative_limit", planar("stiffness = 5.0\nlimit_force = -0.1\ndofs = [\"a\", \"b\"]"), "elements[1].limit_force"},
      {"planar_unknown_dof", planar("stiffness = 5.0\nlimit_force = 0.1\ndofs = [\"a\", \"bb\"]"), "elements[1].dofs[1]: unknown dof 'bb'"},
  };
  expect_one_line_errors(cases);
}

}  // namespace hbtrack_tests::file_case_file
