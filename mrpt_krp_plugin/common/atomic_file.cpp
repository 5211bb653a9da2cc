// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/common/atomic_file.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {

AtomicFile::AtomicFile(std::string final_path)
    : final_path_(std::move(final_path)), temp_path_(final_path_ + ".tmp." + std::to_string(getpid())) {
  const auto parent = std::filesystem::path(final_path_).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
}

AtomicFile::~AtomicFile() {
  if (!committed_) std::remove(temp_path_.c_str());
}

void AtomicFile::commit() {
  if (committed_) return;
  if (std::rename(temp_path_.c_str(), final_path_.c_str()) != 0)
    throw InputError(final_path_, "cannot move the finished temporary file into place");
  committed_ = true;
}

void writeFileAtomically(const std::string& path, const std::string& content) {
  AtomicFile f(path);
  {
    std::ofstream out(f.tempPath(), std::ios::binary);
    out << content;
    if (!out) throw InputError(path, "write failed");
  }
  f.commit();
}

}  // namespace krp
