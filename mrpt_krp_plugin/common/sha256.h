// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

namespace krp {

/// SHA-256 of `bytes`, lowercase hex: what `sha256sum` prints for a file holding them, and what
/// krp-train-map writes into manifest.json for each model file.
std::string sha256Hex(const std::vector<char>& bytes);

}  // namespace krp
