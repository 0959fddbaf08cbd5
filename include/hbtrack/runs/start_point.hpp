#pragma once
// A periodic solution a run starts from: a point of an earlier result (a row of its states).
#include <Eigen/Dense>
#include <string>

namespace hbtrack::runs {

struct StartPoint {
  double omega = 0;    // rad/s
  Eigen::VectorXd x;   // the harmonic balance unknowns at omega
  std::string source;  // what holds it, for messages: "DIR/states.csv", "start"
  // Throws a CaseError when x does not hold the case's `unknowns` (a result of another case).
  void require_unknowns(int unknowns) const;
};

}  // namespace hbtrack::runs
