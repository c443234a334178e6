// SPDX-License-Identifier: MIT
#include "datapath_config.hpp"

#include <fmt/format.h>

#include "errors.hpp"

namespace acore {

void DatapathConfig::validate() const {
  auto need = [](bool ok, const std::string& why) {
    if (!ok) throw InputError("datapath configuration: " + why);
  };
  need(in_w >= 8 && in_w <= 24, fmt::format("in_w={} must be 8..24", in_w));
  need(reg_w >= d_w() + 1 && reg_w <= 30,
       fmt::format("reg_w={} must hold an offset of d_w+1={} bits and be <= 30", reg_w, d_w() + 1));
  need(s_w >= s_f + 2 && s_w <= 30, fmt::format("s_w={} must be s_f+2..30 (s_f={})", s_w, s_f));
  need(r_shift >= 0 && scale_guard >= 0 && scale_guard <= r_shift,
       fmt::format("need 0 <= scale_guard={} <= r_shift={}", scale_guard, r_shift));
  need(degree >= 1 && degree <= 7, fmt::format("degree={} must be 1..7", degree));
  need(regions == 4 || regions == 8, fmt::format("regions={} must be 4 or 8", regions));
  need(coef_f >= 1 && coef_f < reg_w, fmt::format("coef_f={} must be 1..reg_w-1", coef_f));
  need(acc_f() >= s_f, fmt::format("coef_f+acc_guard={} must be >= s_f={}", acc_f(), s_f));
  need(acc_int >= reg_w - coef_f + 1, fmt::format("acc_int={} too small for the coefficients", acc_int));
  need(acc_w() <= 40, fmt::format("acc_w={} must be <= 40", acc_w()));
  need(iterations >= 4 && iterations <= 24, fmt::format("iterations={} must be 4..24", iterations));
  need(cordic_guard >= 0 && cordic_guard <= 8, fmt::format("cordic_guard={} must be 0..8", cordic_guard));
  need(z_w >= angle_w && z_w <= reg_w + 2,
       fmt::format("z_w={} must be angle_w={}..reg_w+2={} (atan(1) must fit a word)", z_w, angle_w,
                   reg_w + 2));
  need(angle_w >= 8 && angle_w <= 24, fmt::format("angle_w={} must be 8..24", angle_w));
  need(fourier_k >= 0 && fourier_k <= 31, fmt::format("fourier_k={} must be 0..31", fourier_k));
  if (fourier_k == 0) return;
  need(fourier_iterations >= 4 && fourier_iterations <= iterations,
       fmt::format("fourier_iterations={} must be 4..iterations={} (it uses the CORDIC's atan words)",
                   fourier_iterations, iterations));
  need(z_w > angle_w, fmt::format("the Fourier correction needs z_w={} > angle_w={}", z_w, angle_w));
  need(fourier_guard >= 0 && fourier_guard <= 8, fmt::format("fourier_guard={} must be 0..8", fourier_guard));
  need(fourier_f() > angle_w && fourier_f() <= 40,
       fmt::format("fourier_coef_f+fourier_guard={} must be angle_w+1={}..40", fourier_f(), angle_w + 1));
  need(fourier_coef_f >= reg_w - 1,
       fmt::format("fourier_coef_f={} must be >= reg_w-1={} (a coefficient is less than half a turn)",
                   fourier_coef_f, reg_w - 1));
}

std::string DatapathConfig::describe() const {
  std::string fourier;
  if (fourier_k > 0)
    fourier = fmt::format(" fourier_k={} fourier_iterations={} fourier_coef_f={} fourier_guard={}", fourier_k,
                          fourier_iterations, fourier_coef_f, fourier_guard);
  return fmt::format(
      "in_w={} reg_w={} s_w={} s_f={} r_shift={} scale_guard={} degree={} regions={} coef_f={} "
      "acc_guard={} acc_int={} iterations={} cordic_guard={} z_w={} angle_w={}{}",
      in_w, reg_w, s_w, s_f, r_shift, scale_guard, degree, regions, coef_f, acc_guard, acc_int,
      iterations, cordic_guard, z_w, angle_w, fourier);
}

}  // namespace acore
