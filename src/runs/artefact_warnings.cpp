#include "hbtrack/runs/artefact_warnings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace hbtrack::runs {

namespace {
// Genuine folds and bifurcations of a resonance come in ones and twos, a few percent of the range
// apart; a sampling saw-tooth puts dozens within a fraction of a percent.
constexpr size_t kClusterSize = 4;
constexpr double kClusterSpacing = 1e-3;

std::string describe(const std::vector<const SpecialPoint*>& cluster) {
  std::map<std::string, int> by_type;
  for (const SpecialPoint* p : cluster) ++by_type[to_string(p->type)];  // by name: the message lists them alphabetically
  std::string types;
  for (const auto& [type, count] : by_type) types += (types.empty() ? "" : ", ") + std::to_string(count) + " " + type;
  char range[96];
  std::snprintf(range, sizeof range, "omega in [%.6g, %.6g]", cluster.front()->lambda, cluster.back()->lambda);
  return std::to_string(cluster.size()) + " special points (" + types + ") within " + range +
         ": closer together than the sampled contact law resolves, most likely artefacts of the time sampling. "
         "Raise harmonic_balance.samples, or use a regularised law whose width spans several samples "
         "(regularized_contact, law = \"sqrt\"), and check that they move or vanish";
}
}  // namespace

namespace {
// Whether the cluster's limit points stay put with more samples and shorter steps (see the header).
bool stays_when_recomputed(const std::vector<const SpecialPoint*>& cluster, const ClusterRecomputation& recompute) {
  double spacing = std::abs(cluster.back()->lambda - cluster.front()->lambda);
  for (size_t i = 1; i < cluster.size(); ++i) spacing = std::min(spacing, cluster[i]->lambda - cluster[i - 1]->lambda);
  for (const SpecialPoint* p : cluster)
    if (p->type != SpecialPointType::limit_point) return false;
  std::optional<std::vector<double>> found = recompute(cluster);
  if (!found || found->size() != cluster.size()) return false;
  std::sort(found->begin(), found->end());
  for (size_t i = 0; i < cluster.size(); ++i)  // both in increasing omega
    if (std::abs((*found)[i] - cluster[i]->lambda) > 0.1 * spacing) return false;
  return true;
}
}  // namespace

std::vector<std::string> special_point_clusters(const std::vector<SpecialPoint>& points, double omega_range,
                                                const ClusterRecomputation& recompute) {
  std::vector<const SpecialPoint*> sorted;
  for (const SpecialPoint& p : points)
    if (p.type != SpecialPointType::branch_point) sorted.push_back(&p);
  std::sort(sorted.begin(), sorted.end(), [](const SpecialPoint* a, const SpecialPoint* b) { return a->lambda < b->lambda; });
  std::vector<std::string> warnings;
  std::vector<const SpecialPoint*> cluster;
  auto flush = [&] {
    if (cluster.size() >= kClusterSize && !(recompute && stays_when_recomputed(cluster, recompute))) warnings.push_back(describe(cluster));
    cluster.clear();
  };
  for (const SpecialPoint* p : sorted) {
    if (!cluster.empty() && p->lambda - cluster.back()->lambda > kClusterSpacing * omega_range) flush();
    cluster.push_back(p);
  }
  flush();
  return warnings;
}

std::vector<std::string> extremum_pairs_below_resolution(const std::vector<FoldExtremum>& extrema, const std::string& parameter,
                                                         double parameter_range, double omega_span) {
  std::vector<const FoldExtremum*> along;
  for (const FoldExtremum& e : extrema)
    if (e.type == CurveExtremumType::parameter_min || e.type == CurveExtremumType::parameter_max)
      along.push_back(&e);  // not an NS curve's resonance ends
  std::sort(along.begin(), along.end(), [](const FoldExtremum* a, const FoldExtremum* b) { return a->index < b->index; });
  int pairs = 0;
  std::string listed;
  for (size_t i = 1; i < along.size(); ++i) {
    const FoldExtremum& a = *along[i - 1];
    const FoldExtremum& b = *along[i];
    if (a.type == b.type || std::abs(a.parameter - b.parameter) > kClusterSpacing * parameter_range ||
        std::abs(a.omega - b.omega) > kClusterSpacing * omega_span)
      continue;
    if (pairs < 4) {
      char at[96];
      std::snprintf(at, sizeof at, "%s%s = %.6g at omega = %.6g", pairs ? "; " : "", parameter.c_str(), a.parameter, a.omega);
      listed += at;
    }
    ++pairs;
    ++i;  // a pair uses both
  }
  if (pairs == 0) return {};
  return {std::to_string(pairs) + " min/max pair" + (pairs > 1 ? "s" : "") + " of " + parameter + " on the tracking curve (" + listed +
          (pairs > 4 ? "; ..." : "") +
          ") closer together than the sampled law resolves: most likely a wiggle of the time sampling, not a birth and a merge of "
          "branches. Raise harmonic_balance.samples, or use a regularised law whose width spans several samples, and check that they "
          "move or vanish"};
}

std::string first_nonsmooth_element(const CaseDefinition& c) {
  for (size_t i = 0; i < c.elements.size(); ++i)
    if (!c.elements[i]->smoothness_limit().empty()) return "elements[" + std::to_string(i) + "] (" + c.elements[i]->type() + ")";
  return "";
}

std::vector<std::string> unconfirmed_hill_bifurcations(const std::vector<SpecialPoint>& points, const std::string& nonsmooth_element,
                                                       int harmonics) {
  if (nonsmooth_element.empty()) return {};
  std::string listed;
  int count = 0;
  for (const SpecialPoint& p : points) {
    if (p.decided_by != "hill" || (p.type != SpecialPointType::period_doubling && p.type != SpecialPointType::neimark_sacker)) continue;
    char at[64];
    std::snprintf(at, sizeof at, "%s%s at omega = %.6g", count ? ", " : "", to_string(p.type).c_str(), p.lambda);
    listed += at;
    ++count;
  }
  if (count == 0) return {};
  return {std::to_string(count) + " bifurcation" + (count > 1 ? "s" : "") + " (" + listed + ") decided by Hill's method alone on " +
          nonsmooth_element + ", where its exponents converge slowly: confirm with harmonic_balance.harmonics = " +
          std::to_string(2 * harmonics) + " (a truncation artefact moves or vanishes) or stability.method = \"shooting\""};
}

}  // namespace hbtrack::runs
