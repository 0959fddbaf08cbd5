#pragma once
// Opt-in wall-time accounting of the phases that dominate a continuation, so that a benchmark
// can print where a Newton iteration's time goes:
//   aft            time-domain force evaluation and the DFTs of forces and their derivatives;
//   jacobian       assembly of the Jacobian blocks (element blocks, condensed linear part);
//   factorization  dense LU factorizations and the solves with their factors.
// Off by default: a ScopedPhase then costs one branch on a global flag. On, it costs two
// steady_clock reads (tens of nanoseconds against milliseconds per phase). Phases must not
// nest. Process-wide and not thread-safe: the library evaluates on one thread.
#include <array>
#include <chrono>

namespace hbtrack {

enum class Phase { aft, jacobian, factorization };
inline constexpr int kPhaseCount = 3;

class PhaseTimes {
 public:
  static void enable(bool on) { enabled_ = on; }
  static bool enabled() { return enabled_; }
  static void reset() {
    seconds_.fill(0.0);
    calls_.fill(0);
  }
  static double seconds(Phase p) { return seconds_[static_cast<size_t>(p)]; }
  static long calls(Phase p) { return calls_[static_cast<size_t>(p)]; }
  static void add(Phase p, double s) {
    seconds_[static_cast<size_t>(p)] += s;
    ++calls_[static_cast<size_t>(p)];
  }

 private:
  static inline bool enabled_ = false;
  static inline std::array<double, kPhaseCount> seconds_{};
  static inline std::array<long, kPhaseCount> calls_{};
};

// Adds the time from construction to destruction to its phase when timing is enabled.
class ScopedPhase {
 public:
  explicit ScopedPhase(Phase p) : phase_(p), running_(PhaseTimes::enabled()) {
    if (running_) start_ = std::chrono::steady_clock::now();
  }
  ~ScopedPhase() {
    if (running_) PhaseTimes::add(phase_, std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
  }
  ScopedPhase(const ScopedPhase&) = delete;
  ScopedPhase& operator=(const ScopedPhase&) = delete;

 private:
  Phase phase_;
  bool running_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace hbtrack
