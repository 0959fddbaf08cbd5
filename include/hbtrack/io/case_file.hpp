#pragma once
// A study described in a TOML case file (format documented in docs/case-file.md): the model,
// damping, forcing, nonlinear elements, named parameters, harmonic and continuation settings,
// and the output dofs to record.
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/elements/nonlinear_element.hpp"
#include "hbtrack/hbm/harmonic_balance.hpp"
#include "hbtrack/hbm/recorded_outputs.hpp"
#include "hbtrack/model/base_motion.hpp"
#include "hbtrack/model/parameters.hpp"
#include "hbtrack/model/structural_model.hpp"

namespace hbtrack {

// A bad case file or override: the message is one line "<file>:<line>: <field>: <rule>".
class CaseError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The [study] section: what `hbtrack study` varies. Each tracked parameter gets every limit point
// of the nominal NFRC followed over [min, max] (the parameter's case value lies inside).
struct StudyTrack {
  std::string parameter;
  double min = 0, max = 0;
  std::vector<double> validate;  // extra validation NFRCs at these values (e.g. a paper's)
};
// A nonlinear mode the study computes beside the NFRC (`hbtrack backbone --mode K --range LO:HI`).
struct StudyBackbone {
  int mode = 1;
  double min = 0, max = 0;  // the modal amplitude's range
};
// The quasi-periodic response the study computes past the nominal NFRC's NS points (`hbtrack
// torus --harmonics H1,H2 --samples N1,N2`; 0: the torus' defaults).
struct StudyTorus {
  bool enabled = false;
  int h1 = 0, h2 = 0, n1 = 0, n2 = 0;
};
struct StudySettings {
  std::vector<StudyTrack> track;
  std::vector<StudyBackbone> backbones;
  bool switch_branches = false;  // follow the branches born at the nominal NFRC's BP and PD points
  int max_points = 400;          // per leg of a tracking curve
  int simulate_periods = 60;     // periods of the time-integration check, 0 for none
  // Its HHT steps per period of the elements' fastest rate (`simulate --element-steps`; 0: the
  // steps per period, the elements resolved as finely as the forcing).
  int simulate_element_steps = 0;
  // A validation NFRC's limit point on no tracking curve starts one of its own: at most this many
  // such curves per tracked parameter (0: none).
  int max_added_curves = 4;
  // Follow every NS and PD point of the nominal NFRC in each tracked parameter too (`track --ns K`,
  // `--pd K`): their curves are drawn and listed with the limit points', but no validation NFRC
  // or isola search starts from them.
  bool track_ns_pd = false;
  // From the lower NS point of every band of the nominal NFRC between two NS points where the
  // periodic branch is unstable, the torus born there (`torus_nsK/`).
  StudyTorus torus;
  // The convergence check: the nominal NFRC and the tracking curves recomputed with these
  // harmonics and samples (0: no check), their limit points and extrema compared.
  int convergence_harmonics = 0, convergence_samples = 0;
};

// [rotation]: the model turns at `speed` (rad/s) about the axis its rotating matrices were built
// for; [model] Kg1, Mspin and G. model.stiffness then holds K(Omega) = K + Omega^2 (Kg1 - Mspin)
// and model.damping C + Omega G (model/rotating_matrices.hpp).
struct RotationSettings {
  double speed = 0;
  std::string speed_parameter;                                                         // the named parameter it reads, "" for a number
  Eigen::MatrixXd stiffness_at_rest, geometric_stiffness, spin_softening, gyroscopic;  // gyroscopic: empty when not given
};

struct CaseDefinition {
  std::string path;
  // The file `[model] dofs = { file = ... }` names, resolved ("" for a list or a count): a
  // reduce summary.json there leads to the full model's modes (`hbtrack modes`).
  std::string dofs_file;
  StructuralModel model;
  // [base_motion] as the case gave it; model.forcing and model.forcing_growth then hold its
  // equivalent forcing (model/base_motion.hpp).
  std::optional<BaseMotion> base_motion;
  std::optional<RotationSettings> rotation;
  ElementList elements;
  ParameterSet parameters;
  HarmonicBalanceOptions harmonic_balance;
  NfrcOptions nfrc;
  std::vector<OutputDof> outputs;
  StudySettings study;
};

// `overrides` are "NAME=VALUE": a named parameter (`amplitude=2`) or a dotted case key
// (`harmonic_balance.harmonics=10`), applied before the case is read.
CaseDefinition load_case(const std::string& path, const std::vector<std::string>& overrides = {});

// A copy of `c` with "NAME=VALUE" overrides of its settings: named parameters and the
// [harmonic_balance], [continuation] and [stability] keys, read by the case file's own reader
// (same keys, defaults and errors as `--set`); `c` itself, and its model, are unchanged. An
// override of another section (model, elements, ...) is refused: load_case changes those.
CaseDefinition with_overrides(const CaseDefinition& c, const std::vector<std::string>& overrides);

// The index of the parameter a user named in `field` (a flag, a keyword argument); a CaseError
// "FIELD: unknown parameter 'NAME' (the case has: ...)" when the case has none of that name.
int parameter_index(const ParameterSet& parameters, const std::string& name, const std::string& field);

}  // namespace hbtrack
