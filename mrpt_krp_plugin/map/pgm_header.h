// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

namespace krp {

/// Validates a binary (P5) or ASCII (P2) PGM: magic, width, height, maxval, and for P5 that
/// the file holds every pixel byte. OpenCV decodes a truncated PGM without complaint,
/// which would turn a damaged map into a silently wrong one. Throws InputError.
void checkPgmFile(const std::string& path, double max_cells);

}  // namespace krp
