// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

namespace krp {

/// Write-to-temporary-then-rename: write to `tempPath()`, then `commit()` renames it over
/// the final path. If `commit()` is never reached (an exception), the temporary is removed
/// and the final path is untouched, so a failed run never leaves a half-written output.
class AtomicFile {
 public:
  explicit AtomicFile(std::string final_path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::string& tempPath() const { return temp_path_; }
  const std::string& finalPath() const { return final_path_; }
  void commit();

 private:
  std::string final_path_;
  std::string temp_path_;
  bool committed_ = false;
};

/// Writes `content` to `path` atomically.
void writeFileAtomically(const std::string& path, const std::string& content);

}  // namespace krp
