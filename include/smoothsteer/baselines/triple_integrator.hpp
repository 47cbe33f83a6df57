#pragma once
//! \file triple_integrator.hpp
//! Time-optimal feedback of the triple integrator x1''' = u, |u| <= U (Walther, Georgiou,
//! Tannenbaum, "On the computation of switching surfaces in optimal control: a Groebner basis
//! approach", IEEE TAC 2001). The paper's HOSM baseline (Sec. IV-B) prints the switching surface
//! s(sigma) without its bracket term; the complete surface is (paper_notes §7):
//!
//!   S2 = x2 + x3 |x3| / (2U);  nu = sign(S2)  (nu = -sign(x3) if S2 = 0)
//!   S3 = x1 + x3^3 / (3U^2) + nu ( x2 x3 / U + U^(-1/2) (nu x2 + x3^2 / (2U))^(3/2) )
//!   u  = -U sign(S3); if S3 = 0: -U sign(S2); if both are 0: -U sign(x3)

namespace smoothsteer {

struct TripleIntegratorSwitching {
  double second_order_surface = 0.0;  //!< S2
  double third_order_surface = 0.0;   //!< S3
  double control_sign = 0.0;          //!< u / U in {-1, 0, +1}
};

//! Evaluates S2, S3 and the sign of the time-optimal control. Requires U > 0; noexcept.
TripleIntegratorSwitching triple_integrator_switching(double x1, double x2, double x3,
                                                      double bound) noexcept;

}  // namespace smoothsteer
