// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <string>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp::test {

/// The message of the InputError `f` throws; empty when it throws none (other exceptions pass).
inline std::string inputErrorMessage(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace krp::test
