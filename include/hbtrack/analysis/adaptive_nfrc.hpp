#pragma once
// An NFRC whose harmonic count H changes along the branch (case file `[harmonic_balance]
// adaptive`, hbm/adaptive_harmonics.hpp). The branch is followed in segments at a fixed H
// (compute_branch), each ended by its observer when a point asks for another H. A point that
// asks for more is not kept: the step that reached it had too few harmonics (a limit point in it
// would be located with them), so the last point kept is solved again at its omega with the H
// the dropped point needs, and the step is taken again from there. A point that asks for fewer
// is kept and solved again with them. The next segment leaves the junction along the old tangent
// mapped onto the new unknowns: the same direction of travel, across a fold too. Limit, branch
// and stability points are located inside the segments by the engine as on any branch; a change
// of H is put off (by a few points) when the fold test or the stability verdict at the junction
// differ between the two H, so that no special point is lost or found twice there.
#include <functional>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/hbm/adaptive_harmonics.hpp"

namespace hbtrack {

// The system balanced with H harmonics: built once per H by the caller and kept while the
// run lasts.
using SystemWithHarmonics = std::function<HarmonicBalance&(int harmonics)>;

// Where the adaptive branch starts: the NFRC from options.omega_start over its range (x empty:
// omega and window unused), or the branch through the solution x at omega (balanced with
// `harmonics`), within the window.
struct AdaptiveStart {
  int harmonics = 0;
  Eigen::VectorXd x;
  double omega = 0;
  ParameterWindow window;
};

// Points, special points and recorded outputs are padded with zeros to adaptive.max harmonics
// (so one table layout holds them all); each RecordedPoint's balanced_harmonics is the H it was
// solved with. A junction appears twice: the last point at the old H and the same omega at the
// new one. The observer sees the padded points with their index in the whole branch.
NfrcResult compute_adaptive_nfrc(const SystemWithHarmonics& system_with, const AdaptiveHarmonics& adaptive, const AdaptiveStart& start,
                                 const NfrcOptions& options, const std::vector<OutputDof>& outputs, const RecordedObserver& observer = {});

}  // namespace hbtrack
