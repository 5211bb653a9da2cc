// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace krp {

/// onnxruntime session settings. One intra-op thread by default: a robot's CPU is shared with
/// the rest of the stack, and the latency targets are stated for one core.
struct OnnxRuntimeParams {
  int intra_op_threads = 1;
  int inter_op_threads = 1;
};

/// A tensor in row-major order with its shape.
struct Tensor {
  std::vector<int64_t> shape;
  std::vector<float> values;
};

/// An ONNX model file read whole into memory, and where it came from (for messages). A model is
/// loaded from these bytes, so that bytes checked before loading (requireManifestModelFile) are
/// the bytes that run, even if the file is replaced meanwhile. The project's exported models
/// keep their weights inside the file (no external data files).
struct OnnxModelFile {
  std::string path;
  std::vector<char> bytes;
};

/// Reads `path` whole: InputError naming it when it is missing or cannot be read.
OnnxModelFile readOnnxModelFile(const std::string& path);

/// One ONNX model with a single float input and a single float output, run by onnxruntime.
/// Loading throws InputError naming the file (missing, unreadable, not an ONNX model, or not
/// one input and one output).
class OnnxModel {
 public:
  OnnxModel(const std::string& path, const OnnxRuntimeParams& params = {});
  OnnxModel(const OnnxModelFile& file, const OnnxRuntimeParams& params = {});
  ~OnnxModel();
  OnnxModel(const OnnxModel&) = delete;
  OnnxModel& operator=(const OnnxModel&) = delete;

  const std::string& path() const { return path_; }
  const std::string& inputName() const { return input_name_; }
  const std::string& outputName() const { return output_name_; }
  /// As stored in the model; a dynamic dimension is -1.
  const std::vector<int64_t>& inputShape() const { return input_shape_; }

  /// Runs the model; `input.shape` must match inputShape() where that is fixed.
  Tensor run(const Tensor& input) const;

 private:
  struct Session;
  std::string path_;
  std::string input_name_;
  std::string output_name_;
  std::vector<int64_t> input_shape_;
  std::unique_ptr<Session> session_;
};

}  // namespace krp
