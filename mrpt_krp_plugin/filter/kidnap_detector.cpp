// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/filter/kidnap_detector.h"

namespace krp {

bool KidnapDetector::update(double fit_fraction) {
  if (!params_.enabled) return false;
  if (++since_reset_ <= params_.grace_updates) return false;
  suspicious_ = fit_fraction < params_.min_fit_fraction ? suspicious_ + 1 : 0;
  if (suspicious_ < params_.consecutive_updates) return false;
  reset();
  return true;
}

}  // namespace krp
