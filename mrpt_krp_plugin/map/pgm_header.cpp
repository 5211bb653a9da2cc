// SPDX-License-Identifier: BSD-3-Clause
#include "mrpt_krp_plugin/map/pgm_header.h"

#include <cctype>
#include <filesystem>
#include <fstream>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp {
namespace {
// Reads the next header integer, skipping whitespace and '#' comments.
bool readHeaderInt(std::istream& in, long long& v) {
  int c;
  while ((c = in.peek()) != EOF) {
    if (std::isspace(c)) in.get();
    else if (c == '#') { std::string line; std::getline(in, line); }
    else break;
  }
  if (c == EOF || !std::isdigit(c)) return false;
  v = 0;
  int digits = 0;
  while (std::isdigit(in.peek()) && digits < 12) { v = v * 10 + (in.get() - '0'); ++digits; }
  return digits > 0 && digits < 12;
}
}  // namespace

void checkPgmFile(const std::string& path, double max_cells) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open the image file");
  char magic[2] = {0, 0};
  in.read(magic, 2);
  if (in.gcount() != 2 || magic[0] != 'P' || (magic[1] != '5' && magic[1] != '2'))
    throw InputError(path, "not a PGM file (missing 'P5'/'P2' magic)");
  long long w = 0, h = 0, maxval = 0;
  if (!readHeaderInt(in, w) || !readHeaderInt(in, h) || !readHeaderInt(in, maxval))
    throw InputError(path, "malformed PGM header (width, height, maxval)");
  if (w <= 0 || h <= 0) throw InputError(path, "PGM width and height must be positive");
  if (static_cast<double>(w) * static_cast<double>(h) > max_cells)
    throw InputError(path, "PGM is " + std::to_string(w) + " x " + std::to_string(h) + ", larger than the limit");
  if (maxval <= 0 || maxval > 65535) throw InputError(path, "PGM maxval must be in 1..65535");
  if (magic[1] == '2') return;  // ASCII: OpenCV reports a short file itself
  in.get();  // the single whitespace byte after maxval
  const auto header = static_cast<long long>(in.tellg());
  const long long bytes_per_px = maxval > 255 ? 2 : 1;
  const auto size = static_cast<long long>(std::filesystem::file_size(path));
  if (size - header < w * h * bytes_per_px)
    throw InputError(path, "PGM is truncated: expected " + std::to_string(w * h * bytes_per_px) + " pixel bytes, found " +
                               std::to_string(size - header));
}

}  // namespace krp
