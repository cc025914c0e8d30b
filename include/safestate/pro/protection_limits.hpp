// The hazard thresholds of PRO-01 (docs/design/protection.md §3). Every comparison is
// strict: a value equal to a limit is not a hazard.
#pragma once

#include <cstdint>

namespace safestate::pro {

struct ProtectionLimits {
  std::int16_t temp_limit_c{85};
  std::uint16_t volt_min_dv{180};
  std::uint16_t volt_max_dv{300};

  [[nodiscard]] constexpr bool valid() const noexcept { return volt_min_dv <= volt_max_dv; }
};

}  // namespace safestate::pro
