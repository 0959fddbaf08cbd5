// The chord corrector's factorization in double (DenseLU, dgetrf) against single precision
// (SinglePrecisionLU, sgetrf with subnormals flushed): milliseconds per factorization of the
// bordered condensed systems' sizes (blade and rotor 67 at H = 10: 568; at H = 15: 838) on a
// well-conditioned random matrix. Both in this run, one thread: read the ratio.
//
//   build/bench/bench_single_precision_lu
#include <chrono>
#include <cstdio>

#include "hbtrack/util/dense_lu.hpp"
#include "hbtrack/util/single_precision_lu.hpp"

namespace {

template <class Factor>
double milliseconds_per_factorization(const Eigen::MatrixXd& a, Factor&& factor) {
  const int repeats = 40;
  factor(a);  // sizes the storage
  const auto start = std::chrono::steady_clock::now();
  for (int r = 0; r < repeats; ++r) factor(a);
  return 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / repeats;
}

}  // namespace

int main() {
  std::printf("| size | dgetrf [ms] | sgetrf [ms] | ratio |\n|---|---|---|---|\n");
  for (const int n : {568, 838}) {
    Eigen::MatrixXd random = Eigen::MatrixXd::Random(n, n);
    random.diagonal().array() += n;  // well conditioned: the ratio is the factorization's alone
    hbtrack::DenseLU dense;
    hbtrack::SinglePrecisionLU single;
    const double d = milliseconds_per_factorization(random, [&](const Eigen::MatrixXd& m) { dense.compute(m); });
    const double s = milliseconds_per_factorization(random, [&](const Eigen::MatrixXd& m) { single.compute(m); });
    std::printf("| %d | %.2f | %.2f | %.2f |\n", n, d, s, d / s);
  }
  return 0;
}
