// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

namespace krp {

/// SHA-256 of a file's bytes, lowercase hex (what `sha256sum` prints and krp-train-map writes into
/// manifest.json). InputError naming the file when it cannot be read.
std::string fileSha256(const std::string& path);

}  // namespace krp
