// SPDX-License-Identifier: MIT
#include "core/fixed_point.hpp"

#include <array>

namespace acore::fx {

const uint8_t* upper_partial_products8_table() {
  static const std::array<uint8_t, 1 << 16> table = [] {
    std::array<uint8_t, 1 << 16> t{};
    for (uint32_t rho = 0; rho < 256; ++rho)
      for (uint32_t beta = 0; beta < 256; ++beta)
        t[rho << 8 | beta] = static_cast<uint8_t>(upper_partial_products<uint32_t>(rho, beta, 8));
    return t;
  }();
  return table.data();
}

}  // namespace acore::fx
