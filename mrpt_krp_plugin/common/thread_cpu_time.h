// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace krp {

/// CPU time of the calling thread [s]: what a stage costs on one core, unaffected by other
/// processes sharing the machine (wall time is not).
double threadCpuSeconds();

}  // namespace krp
