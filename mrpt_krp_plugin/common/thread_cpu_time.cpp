// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/common/thread_cpu_time.h"

#include <time.h>

namespace krp {

double threadCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace krp
