#pragma once
// C = A B for dense column-major matrices: the AFT's DFTs of many signals at once (the Fourier
// coefficients of the contact forces and of their derivatives, the time samples of the
// harmonics). Through OpenBLAS's dgemm when the build found it (one thread, as DenseLU): its
// kernels use the processor's vector units, Eigen's product compiled for baseline x86-64 does
// not (README Performance); Eigen's product otherwise.
#include <Eigen/Dense>

namespace hbtrack {

// c <- a b (c resized; no allocation when it has the size already). a and b must not alias c.
void multiply(const Eigen::Ref<const Eigen::MatrixXd>& a, const Eigen::Ref<const Eigen::MatrixXd>& b, Eigen::MatrixXd& c);

}  // namespace hbtrack
