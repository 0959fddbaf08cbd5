#pragma once
// `modes`: the undamped natural frequencies of a case's (reduced) model, each with the dof that
// moves most in its mass-normalised shape (a quick way to tell modes apart). Writes the summary
// alone (natural_frequencies, dominant_dofs).
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/result_sink.hpp"
#include "hbtrack/runs/run_report.hpp"

namespace hbtrack::runs {

// The lowest `count` modes (fewer when the model has fewer dofs). Throws a CaseError for
// count < 1; a mass matrix that is not positive definite is a failure of the run.
RunReport modes(const CaseDefinition& c, int count, ResultSink& sink);

}  // namespace hbtrack::runs
