// SPDX-License-Identifier: BSD-3-Clause
#include "bag_framing.h"

#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include <bzlib.h>
#include <roslz4/lz4s.h>

#include "mrpt_krp_plugin/common/input_error.h"

namespace krp::ros1 {
namespace {
// The ROS bag 2.0 format (wiki.ros.org/Bags/Format/2.0): the magic line, then records of
// <header_len><header><data_len><data>; a header is a list of <field_len><name>=<value>.
constexpr std::string_view kMagic = "#ROSBAG V2.0\n";
constexpr uint8_t kOpMessageData = 0x02, kOpBagHeader = 0x03, kOpIndexData = 0x04, kOpChunk = 0x05,
                  kOpChunkInfo = 0x06, kOpConnection = 0x07;
constexpr size_t kIndexEntryBytes = 12;  // time (sec, nsec) and offset, each uint32
constexpr uint32_t kIndexVersion = 1;
/// The largest uncompressed chunk accepted: rosbag writes chunks of 768 KiB by default
/// (`rosbag record --chunksize` in KiB); far above that, a size field is corrupt, not a choice.
constexpr uint32_t kMaxChunkBytes = 256u << 20;

using Fields = std::map<std::string, std::string>;

template <typename T>
T readLe(const char* p) {
  T v;
  std::memcpy(&v, p, sizeof(T));  // bags are little-endian, as is x86
  return v;
}

class Checker {
 public:
  explicit Checker(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void fail(uint64_t at, const std::string& problem) const {
    std::ostringstream s;
    s << "corrupt bag at byte " << at << ": " << problem;
    throw InputError(path_, s.str());
  }

  /// The fields of a header held in `bytes` (a record header or a connection header).
  Fields parseFields(const std::string& bytes, uint64_t at) const {
    Fields f;
    size_t pos = 0;
    while (pos < bytes.size()) {
      if (bytes.size() - pos < sizeof(uint32_t)) fail(at + pos, "a header field's length is cut off");
      const uint32_t len = readLe<uint32_t>(bytes.data() + pos);
      pos += sizeof(uint32_t);
      if (len > bytes.size() - pos) fail(at + pos, "a header field runs past its header");
      const std::string field = bytes.substr(pos, len);
      const auto eq = field.find('=');
      if (eq == std::string::npos) fail(at + pos, "a header field has no '='");
      f[field.substr(0, eq)] = field.substr(eq + 1);
      pos += len;
    }
    return f;
  }

  uint8_t op(const Fields& f, uint64_t at) const {
    const auto it = f.find("op");
    if (it == f.end() || it->second.size() != 1) fail(at, "a record without a one-byte 'op' field");
    return static_cast<uint8_t>(it->second[0]);
  }

  template <typename T>
  T number(const Fields& f, const char* name, uint64_t at) const {
    const auto it = f.find(name);
    if (it == f.end() || it->second.size() != sizeof(T)) fail(at, std::string("field '") + name + "' is missing or mis-sized");
    return readLe<T>(it->second.data());
  }

  struct Record {
    uint64_t pos = 0;
    uint8_t op = 0;
    Fields fields;
    std::string data;  ///< kept only for chunks, connections and index records
  };

  /// Walks the records in `bytes` (the inside of an uncompressed chunk); returns their offsets.
  std::set<uint64_t> innerRecords(const std::string& bytes, uint64_t chunk_data_at) const {
    std::set<uint64_t> offsets;
    size_t pos = 0;
    while (pos < bytes.size()) {
      offsets.insert(pos);
      const auto header = take(bytes, pos, chunk_data_at, "inner record header");
      const auto fields = parseFields(header, chunk_data_at + pos);
      const uint8_t kind = op(fields, chunk_data_at + pos);
      const auto data = take(bytes, pos, chunk_data_at, "inner record data");
      if (kind == kOpConnection) parseFields(data, chunk_data_at + pos);
      else if (kind != kOpMessageData) fail(chunk_data_at + pos, "a chunk holds a record that is neither a message nor a connection");
    }
    return offsets;
  }

  void check() {
    std::ifstream in(path_, std::ios::binary);
    if (!in) throw InputError(path_, "cannot open the bag");
    in.seekg(0, std::ios::end);
    const uint64_t size = static_cast<uint64_t>(in.tellg());
    in.seekg(0);
    std::string magic(kMagic.size(), '\0');
    in.read(magic.data(), static_cast<std::streamsize>(magic.size()));
    if (!in || magic != kMagic) throw InputError(path_, "not a ROS bag in format 2.0 (no '#ROSBAG V2.0' line)");

    std::vector<Record> records;
    std::map<uint64_t, uint8_t> op_at;
    uint64_t pos = kMagic.size();
    while (pos < size) {
      Record r;
      r.pos = pos;
      const auto header = readBlock(in, pos, size, "record header");
      r.fields = parseFields(header, r.pos + sizeof(uint32_t));
      r.op = op(r.fields, r.pos);
      const uint64_t data_at = pos + sizeof(uint32_t);
      const bool keep = r.op == kOpChunk || r.op == kOpConnection || r.op == kOpIndexData;
      const auto data = readBlock(in, pos, size, "record data", !keep);
      if (keep) r.data = data;
      if (r.op == kOpConnection) parseFields(r.data, data_at);
      op_at[r.pos] = r.op;
      records.push_back(std::move(r));
    }
    if (records.empty() || records.front().op != kOpBagHeader) fail(kMagic.size(), "the first record is not the bag header");
    const uint64_t index_pos = number<uint64_t>(records.front().fields, "index_pos", records.front().pos);
    if (index_pos != 0 && !op_at.count(index_pos)) fail(records.front().pos, "the index position is not a record");

    std::set<uint64_t> chunk_messages;  // offsets inside the chunk the index records follow
    for (const auto& r : records) {
      if (r.op == kOpChunkInfo) {
        const uint64_t chunk = number<uint64_t>(r.fields, "chunk_pos", r.pos);
        const auto it = op_at.find(chunk);
        if (it == op_at.end() || it->second != kOpChunk) fail(r.pos, "a chunk position that is not a chunk");
      } else if (r.op == kOpChunk) {
        const auto compression = r.fields.find("compression");
        if (compression == r.fields.end()) fail(r.pos, "a chunk without 'compression'");
        chunk_messages.clear();
        const uint32_t chunk_size = number<uint32_t>(r.fields, "size", r.pos);
        if (compression->second == "none") {
          if (chunk_size != r.data.size()) fail(r.pos, "an uncompressed chunk whose size field is not its length");
          chunk_messages = innerRecords(r.data, r.pos);
        } else {
          // rosbag parses the inner records of a compressed chunk as trustingly as any other
          // (found by bag_fuzzer: a heap overflow in roscpp's header parser on a corrupt record
          // inside an lz4 chunk), so they are decompressed and checked here too.
          chunk_messages = innerRecords(decompressChunk(compression->second, r.data, chunk_size, r.pos), r.pos);
        }
      } else if (r.op == kOpIndexData) {
        if (number<uint32_t>(r.fields, "ver", r.pos) != kIndexVersion) fail(r.pos, "an index record of unknown version");
        const uint32_t count = number<uint32_t>(r.fields, "count", r.pos);
        if (static_cast<uint64_t>(count) * kIndexEntryBytes != r.data.size())
          fail(r.pos, "an index record whose count is not its length");
        for (uint32_t i = 0; i < count; ++i) {
          const uint32_t offset = readLe<uint32_t>(r.data.data() + i * kIndexEntryBytes + 2 * sizeof(uint32_t));
          if (!chunk_messages.count(offset)) fail(r.pos, "an index entry that points at no record of its chunk");
        }
      }
    }
  }

 private:
  // A length-prefixed block of the file at `pos` (advanced past it); its bytes unless `skip`.
  std::string readBlock(std::ifstream& in, uint64_t& pos, uint64_t size, const char* what, bool skip = false) const {
    if (size - pos < sizeof(uint32_t)) fail(pos, std::string("the ") + what + " length is cut off");
    char len_bytes[sizeof(uint32_t)];
    in.seekg(static_cast<std::streamoff>(pos));
    in.read(len_bytes, sizeof(len_bytes));
    const uint32_t len = readLe<uint32_t>(len_bytes);
    pos += sizeof(uint32_t);
    if (len > size - pos) fail(pos, std::string("the ") + what + " runs past the end of the file");
    std::string bytes;
    if (!skip) {
      bytes.resize(len);
      in.read(bytes.data(), len);
      if (!in) fail(pos, std::string("cannot read the ") + what);
    }
    pos += len;
    return bytes;
  }

  // The same inside a chunk held in memory.
  std::string take(const std::string& bytes, size_t& pos, uint64_t base, const char* what) const {
    if (bytes.size() - pos < sizeof(uint32_t)) fail(base + pos, std::string("the ") + what + " length is cut off");
    const uint32_t len = readLe<uint32_t>(bytes.data() + pos);
    pos += sizeof(uint32_t);
    if (len > bytes.size() - pos) fail(base + pos, std::string("the ") + what + " runs past its chunk");
    auto out = bytes.substr(pos, len);
    pos += len;
    return out;
  }

  // A compressed chunk's data as rosbag decompresses it (libbz2's and roslz4's one-shot calls,
  // as its streams use), which must fill exactly the `size` the chunk announces.
  std::string decompressChunk(const std::string& compression, const std::string& data, uint32_t size,
                              uint64_t at) const {
    if (size > kMaxChunkBytes)
      fail(at, "a compressed chunk announces " + std::to_string(size) + " bytes, more than the " +
                   std::to_string(kMaxChunkBytes) + " this reader accepts");
    std::string out(size, '\0');
    std::string in = data;  // both decompressors take a non-const input
    if (compression == "bz2") {
      unsigned int out_size = size;
      const int rc = BZ2_bzBuffToBuffDecompress(out.data(), &out_size, in.data(), static_cast<unsigned int>(in.size()), 0, 0);
      if (rc != BZ_OK || out_size != size) fail(at, "a bz2 chunk that does not decompress to its size");
    } else if (compression == "lz4") {
      unsigned int out_size = size;
      const int rc = roslz4_buffToBuffDecompress(in.data(), static_cast<unsigned int>(in.size()), out.data(), &out_size);
      if (rc != ROSLZ4_OK || out_size != size) fail(at, "an lz4 chunk that does not decompress to its size");
    } else {
      fail(at, "a chunk with unknown compression '" + compression + "'");
    }
    return out;
  }

  std::string path_;
};
}  // namespace

void checkBagFraming(const std::string& path) { Checker(path).check(); }

}  // namespace krp::ros1
